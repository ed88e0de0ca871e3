/*
 * client_links.h - a client and a simulator on a real link (pty with a
 * symlink in a private directory, loopback UDP, loopback TCP; ephemeral
 * ports), for the real-transport tests of tests/client.
 */
#ifndef XFGCU_CLIENT_LINKS_H
#define XFGCU_CLIENT_LINKS_H

#include <unistd.h>

#include "client_test.h"
#include "xfgcu/posix/xf_posix.h"
#include "xfgcu/posix/xf_poll.h"
#include "xfgcu/posix/xf_simlink.h"

typedef struct tx {
    xf_simlink_kind kind;
    char dir[64];   /* pty: the mkdtemp directory */
    char link[128]; /* pty: the symlink the host opens */
    uint16_t port;  /* udp / tcp: the simulator's port */
    xf_simlink sl;
    xf_hal sim_hal;
    xf_sim sim;
    xf_sim_config scfg;
    xf_serial ser;
    xf_udp udp;
    xf_tcp tcp;
    xf_hal host_hal;
    xf_client c;
    xf_client_config ccfg;
    ct_log log;
    int sim_open; /* the simulator's link is open (restart scenario) */
} tx;

static inline const char *kind_name(xf_simlink_kind k)
{
    return k == XF_SIMLINK_PTY ? "pty" : (k == XF_SIMLINK_UDP ? "udp" : "tcp");
}

static inline uint32_t posix_clock(void *ctx)
{
    (void)ctx;
    return xf_posix_now_ms();
}

static inline uint32_t now(void) { return xf_posix_now_ms(); }

/* ---- links ---------------------------------------------------------------------- */

static inline void sim_link_open(tx *t)
{
    xf_err err = XF_ERR_ARG;
    switch (t->kind) {
    case XF_SIMLINK_PTY: err = xf_simlink_open_pty(&t->sl, t->link); break;
    case XF_SIMLINK_UDP: err = xf_simlink_open_udp(&t->sl, "127.0.0.1", t->port); break;
    case XF_SIMLINK_TCP: err = xf_simlink_open_tcp(&t->sl, "127.0.0.1", t->port); break;
    }
    if (err != XF_OK) {
        print_error("%s simlink: %s\n", kind_name(t->kind), t->sl.error.text);
    }
    assert_xf(err, XF_OK);
    t->port = t->sl.port;
    xf_simlink_hal(&t->sl, &t->sim_hal);
    assert_xf(xf_sim_attach(&t->sim, &t->sim_hal), XF_OK);
    t->sim_open = 1;
}

static inline void sim_link_close(tx *t)
{
    if (t->sim_open) {
        xf_simlink_close(&t->sl);
        assert_xf(xf_sim_attach(&t->sim, NULL), XF_OK);
        t->sim_open = 0;
    }
}

static inline void host_link_open(tx *t)
{
    xf_err err = XF_ERR_ARG;
    switch (t->kind) {
    case XF_SIMLINK_PTY:
        t->ser.force_termios = 1;
        err = xf_serial_open(&t->ser, t->link, 115200);
        if (err != XF_OK) {
            print_error("serial: %s\n", t->ser.error.text);
        }
        xf_serial_hal(&t->ser, &t->host_hal);
        break;
    case XF_SIMLINK_UDP: {
        xf_udp_config cfg;
        xf_udp_config_init(&cfg);
        cfg.gcu_host = "127.0.0.1";
        cfg.gcu_port = t->port;
        cfg.local_host = "127.0.0.1";
        cfg.local_port = 0;
        err = xf_udp_open(&t->udp, &cfg);
        if (err != XF_OK) {
            print_error("udp: %s\n", t->udp.error.text);
        }
        xf_udp_hal(&t->udp, &t->host_hal);
        break;
    }
    case XF_SIMLINK_TCP: {
        xf_tcp_config cfg;
        xf_tcp_config_init(&cfg);
        cfg.host = "127.0.0.1";
        cfg.port = t->port;
        cfg.retry_min_ms = 20;
        cfg.retry_max_ms = 100;
        err = xf_tcp_open(&t->tcp, &cfg);
        if (err != XF_OK) {
            print_error("tcp: %s\n", t->tcp.error.text);
        }
        xf_tcp_hal(&t->tcp, &t->host_hal);
        break;
    }
    }
    assert_xf(err, XF_OK);
}

static inline void host_link_close(tx *t)
{
    switch (t->kind) {
    case XF_SIMLINK_PTY: xf_serial_close(&t->ser); break;
    case XF_SIMLINK_UDP: xf_udp_close(&t->udp); break;
    case XF_SIMLINK_TCP: xf_tcp_close(&t->tcp); break;
    }
}

/* ---- a whole pair ------------------------------------------------------------------------ */

/* Simulator (@p scfg, NULL: defaults) and client (@p ccfg) on a new link of @p kind; 0 or -1. */
static inline int tx_open(tx *t, xf_simlink_kind kind, const xf_sim_config *scfg, const xf_client_config *ccfg)
{
    xf_err err;
    memset(t, 0, sizeof(*t));
    t->kind = kind;
    if (kind == XF_SIMLINK_PTY) {
        snprintf(t->dir, sizeof(t->dir), "/tmp/xfgcu-client-XXXXXX");
        if (mkdtemp(t->dir) == NULL) {
            return -1;
        }
        snprintf(t->link, sizeof(t->link), "%s/gcu", t->dir);
    }
    if (scfg != NULL) {
        t->scfg = *scfg;
    } else {
        xf_sim_config_init(&t->scfg);
    }
    assert_xf(xf_sim_init(&t->sim, &t->scfg), XF_OK);
    sim_link_open(t);
    host_link_open(t);
    if (ccfg != NULL) {
        t->ccfg = *ccfg;
    } else {
        xf_client_config_init(&t->ccfg);
    }
    ct_log_hook(&t->log, &t->ccfg);
    t->log.clock = posix_clock;
    t->log.client = &t->c;
    err = xf_client_init(&t->c, &t->host_hal, &t->ccfg);
    return (err == XF_OK || err == XF_WARN_RATE) ? 0 : -1;
}

static inline void tx_close(tx *t)
{
    host_link_close(t);
    sim_link_close(t);
    if (t->dir[0] != '\0') {
        (void)unlink(t->link);
        (void)rmdir(t->dir);
    }
}

#endif /* XFGCU_CLIENT_LINKS_H */
