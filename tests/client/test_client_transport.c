/*
 * test_client_transport.c - the client against the simulator over every
 * transport: a pseudo-terminal (the host opens a stable symlink to the
 * slave), loopback UDP and loopback TCP, ephemeral ports, on the real clock
 * with xf_posix_poll. Each scenario is run as a table over the three.
 *
 * Every wait is bounded by a deadline, and waits for an event rather than
 * for a time. On the real clock a loaded machine (or a sanitizer) can run a
 * step late by any amount, so the timing checks here are lower bounds and
 * orders of events only; the exact timing is tested on the fake clock in
 * the test_client_*.c files of this folder.
 */
#define _XOPEN_SOURCE 700 /* mkdtemp, readlink */
#include <arpa/inet.h>
#include <errno.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <unistd.h>

#include "client_test.h"
#include "client_links.h"

/* Client timing for these tests: short, so the suite stays quick. */
#define T_STALE_MS       100u
#define T_DOWN_MS        500u
#define T_CMD_TIMEOUT_MS 200u
#define T_WATCHDOG_MS    150u

/* ---- driving ------------------------------------------------------------------------- */

/* One round of the poll loop (the simulator only while its link is open). */
static void round_once(tx *t)
{
    xf_client *cs[1];
    xf_sim *ss[1];
    cs[0] = &t->c;
    ss[0] = &t->sim;
    assert_xf(xf_posix_poll(cs, 1, ss, t->sim_open ? 1u : 0u, 5), XF_OK);
}

static void pump(tx *t, uint32_t ms)
{
    uint32_t t0 = now();
    while (xf_ms_since(now(), t0) < ms) {
        round_once(t);
    }
}

static int wait_link(tx *t, xf_link_state want, uint32_t max_ms)
{
    uint32_t t0 = now();
    while (xf_client_link(&t->c) != want && xf_ms_since(now(), t0) < max_ms) {
        round_once(t);
    }
    return xf_client_link(&t->c) == want;
}

static xf_cmd_status wait_cmd(tx *t, uint32_t id, uint32_t max_ms, xf_cmd_result *res)
{
    uint32_t t0 = now();
    xf_cmd_status st = xf_client_command_status(&t->c, id, res);
    while ((st == XF_CMD_QUEUED || st == XF_CMD_SENDING || st == XF_CMD_OPERATING) && xf_ms_since(now(), t0) < max_ms) {
        round_once(t);
        st = xf_client_command_status(&t->c, id, res);
    }
    return st;
}

static uint32_t submit(tx *t, uint8_t order, uint8_t cameras)
{
    xf_command cmd;
    uint32_t id = 0;
    xf_command_init(&cmd, order);
    if (cameras != 0u) {
        cmd.cameras = cameras;
    }
    assert_xf(xf_client_submit(&t->c, &cmd, &id, NULL), XF_OK);
    return id;
}

/* Step until a reply comes later than @p rx_ms (xf_health.last_rx_ms), at most @p max_ms; 1 if one did. */
static int wait_reply_after(tx *t, uint32_t rx_ms, uint32_t max_ms)
{
    uint32_t t0 = now();
    while (xf_client_health(&t->c)->last_rx_ms == rx_ms && xf_ms_since(now(), t0) < max_ms) {
        round_once(t);
    }
    return xf_client_health(&t->c)->last_rx_ms != rx_ms;
}

/* DOWN callbacks from index @p from on. */
static size_t downs_since(const tx *t, size_t from)
{
    size_t i, n = 0;
    for (i = from; i < t->log.n_links; i++) {
        n += (t->log.links[i] == XF_LINK_DOWN);
    }
    return n;
}

/* ---- fixture ------------------------------------------------------------------------- */

/* not const: cmocka hands each test its initial state as a void * */
static xf_simlink_kind kinds[3] = {XF_SIMLINK_PTY, XF_SIMLINK_UDP, XF_SIMLINK_TCP};

static int setup(void **state)
{
    tx *t = (tx *)calloc(1, sizeof(*t));
    xf_client_config cc;
    if (t == NULL) {
        return -1;
    }
    xf_client_config_init(&cc);
    cc.stale_ms = T_STALE_MS;
    cc.down_ms = T_DOWN_MS;
    cc.command_timeout_ms = T_CMD_TIMEOUT_MS;
    cc.rate_watchdog_ms = T_WATCHDOG_MS;
    if (tx_open(t, *(const xf_simlink_kind *)*state, NULL, &cc) != 0) {
        free(t);
        return -1;
    }
    if (!wait_link(t, XF_LINK_UP, 5000)) {
        print_error("%s: the link did not come up\n", kind_name(t->kind));
        tx_close(t);
        free(t);
        return -1;
    }
    *state = t;
    return 0;
}

static int teardown(void **state)
{
    tx *t = (tx *)*state;
    tx_close(t);
    free(t);
    return 0;
}

/* ---- scenarios ----------------------------------------------------------------------- */

/* Two shutters in a row are executed twice, a null between. */
static void test_two_shutters(void **state)
{
    tx *t = (tx *)*state;
    uint32_t a = submit(t, XF_ORDER_SHUTTER, 0), b = submit(t, XF_ORDER_SHUTTER, 0);
    size_t i, runs = 0;
    assert_status(wait_cmd(t, b, 5000, NULL), XF_CMD_OK);
    assert_status(xf_client_command_status(&t->c, a, NULL), XF_CMD_OK);
    assert_int_equal(t->sim.stats.executed[XF_ORDER_SHUTTER], 2);
    assert_int_equal(t->sim.stats.photos, 2);
    for (i = 0; i < t->log.n_sent; i++) {
        if (t->log.sent_order[i] == XF_ORDER_SHUTTER && (i == 0u || t->log.sent_order[i - 1u] != XF_ORDER_SHUTTER)) {
            runs++;
        }
        if (i > 0u && t->log.sent_order[i - 1u] == XF_ORDER_SHUTTER && t->log.sent_order[i] != XF_ORDER_SHUTTER) {
            assert_int_equal(t->log.sent_order[i], XF_ORDER_NULL);
        }
    }
    assert_int_equal(runs, 2);
}

/* A failing camera mask comes back as such. */
static void test_failing_mask(void **state)
{
    tx *t = (tx *)*state;
    xf_cmd_result res;
    uint32_t id;
    xf_sim_set_failure(&t->sim, XF_ORDER_ZOOM_IN, XF_CAM2);
    id = submit(t, XF_ORDER_ZOOM_IN, XF_CAM1 | XF_CAM2);
    assert_status(wait_cmd(t, id, 5000, &res), XF_CMD_FAILED);
    assert_int_equal(res.failed_cameras, XF_CAM2);
    assert_int_equal(res.state, XF_CAM2);
    assert_int_equal(res.order, XF_ORDER_ZOOM_IN);
}

/* Dropped replies give retries, then a timeout; the GCU ran the command once. */
static void test_drops_retries_timeout(void **state)
{
    tx *t = (tx *)*state;
    xf_cmd_result res;
    uint32_t id;
    t->sim.fault.drop_next = 10000;
    id = submit(t, XF_ORDER_SHUTTER, 0);
    assert_status(wait_cmd(t, id, 5000, &res), XF_CMD_TIMEOUT);
    assert_true(res.packets >= 1u); /* about 10 at 50 Hz in 200 ms, fewer on a loaded machine */
    assert_true(res.elapsed_ms >= T_CMD_TIMEOUT_MS);
    assert_int_equal(t->sim.stats.executed[XF_ORDER_SHUTTER], 1);
    assert_true(t->sim.stats.dropped >= res.packets);
    t->sim.fault.drop_next = 0;
    assert_true(wait_link(t, XF_LINK_UP, 5000));
    id = submit(t, XF_ORDER_SHUTTER, 0);
    assert_status(wait_cmd(t, id, 5000, NULL), XF_CMD_OK);
    assert_int_equal(t->sim.stats.executed[XF_ORDER_SHUTTER], 2);
}

/* A dead link is reported within its timeout: STALE, then DOWN at down_ms. */
static void test_dead_link(void **state)
{
    tx *t = (tx *)*state;
    size_t mark;
    uint32_t last_rx, t_down = 0, t_stale = 0;
    size_t i, i_stale = 0, i_down = 0;
    pump(t, 50);
    mark = t->log.n_links;
    t->sim.fault.silent = 1;
    last_rx = t->c.health.last_rx_ms;
    assert_true(wait_link(t, XF_LINK_DOWN, T_DOWN_MS + 5000u));
    for (i = mark; i < t->log.n_links; i++) {
        if (t->log.links[i] == XF_LINK_STALE && t_stale == 0u) {
            t_stale = t->log.link_ms[i];
            i_stale = i;
        }
        if (t->log.links[i] == XF_LINK_DOWN) {
            t_down = t->log.link_ms[i];
            i_down = i;
        }
    }
    /* down at down_ms, never sooner; stale before it, never sooner than stale_ms (a step later than
     * down_ms - stale_ms on a loaded machine goes from up to down at once) */
    assert_true(t_down != 0u);
    assert_true(xf_ms_since(t_down, last_rx) >= T_DOWN_MS);
    assert_true(t_stale == 0u || (xf_ms_since(t_stale, last_rx) >= T_STALE_MS && i_stale < i_down));
    assert_int_equal(t->c.health.last_rx_ms, last_rx);
    t->sim.fault.silent = 0;
    assert_true(wait_link(t, XF_LINK_UP, 5000));
}

/* The watchdog zeroes rates that are not refreshed. */
static void test_watchdog(void **state)
{
    tx *t = (tx *)*state;
    const xf_host_main *m = &t->sim.host.main;
    uint32_t t0 = now(), t_zero;
    xf_client_set_rates(&t->c, 0.0f, 0.0f, 30.0f, xf_posix_now_ms());
    while (m->yaw_ctrl != 300 && xf_ms_since(now(), t0) < 1000u) {
        round_once(t);
    }
    assert_int_equal(m->yaw_ctrl, 300);
    assert_int_equal(m->status & XF_STATUS_CTRL_VALID, XF_STATUS_CTRL_VALID);
    while (m->yaw_ctrl != 0 && xf_ms_since(now(), t0) < 2000u) {
        round_once(t);
    }
    t_zero = now();
    assert_int_equal(m->yaw_ctrl, 0);
    assert_int_equal(m->status & XF_STATUS_CTRL_VALID, XF_STATUS_CTRL_VALID);
    assert_true(xf_ms_since(t_zero, t0) >= T_WATCHDOG_MS);
    assert_int_equal(t->c.health.watchdog_active, 1);
    assert_int_equal(t->c.health.watchdog_trips, 1);
    pump(t, 30);
    assert_near(t->sim.rate[2], 0.0, 1e-6);
}

/* Telemetry ages: timestamps stay while nothing arrives. */
static void test_telemetry_ages(void **state)
{
    tx *t = (tx *)*state;
    const xf_telemetry *tel = xf_client_telemetry(&t->c);
    uint32_t seen;
    seen = xf_client_health(&t->c)->last_rx_ms;
    assert_true(wait_reply_after(t, seen, 5000)); /* replies keep coming, each stamped */
    assert_true(tel->have_main && tel->have_sub);
    assert_int_equal(tel->sub_ms, xf_client_health(&t->c)->last_rx_ms);
    assert_string_equal(xf_gimbal_model(tel->gimbal_code), "Z-9B_V4(T)");
    assert_int_equal(tel->gimbal_mode, XF_MODE_HEAD_LOCK);
    t->sim.fault.silent = 1;
    pump(t, 30);
    seen = xf_client_health(&t->c)->last_rx_ms;
    pump(t, 300);
    assert_int_equal(xf_client_health(&t->c)->last_rx_ms, seen);
    assert_true(xf_ms_since(now(), xf_client_health(&t->c)->last_rx_ms) >= 300u);
    t->sim.fault.silent = 0;
    assert_true(wait_reply_after(t, seen, 5000));
    assert_int_equal(tel->sub_ms, xf_client_health(&t->c)->last_rx_ms);
}

/*
 * The simulator drops the host (xf_simlink_disconnect) for longer than
 * down_ms: the link is reported down once (no flapping while the
 * transport reconnects to a GCU that does not answer), comes back up with
 * a reply, and commands run again. A command sent meanwhile ends (timeout
 * or link lost) and is not run later from stale packets.
 */
static void test_reconnect_after_disconnect(void **state)
{
    tx *t = (tx *)*state;
    size_t mark = t->log.n_links;
    uint32_t id, replies;
    xf_cmd_status st;
    xf_simlink_disconnect(&t->sl, T_DOWN_MS + 1500u); /* longer than a late step on a loaded machine */
    id = submit(t, XF_ORDER_SHUTTER, 0);
    st = wait_cmd(t, id, 5000, NULL);
    assert_true(st == XF_CMD_TIMEOUT || st == XF_CMD_LINK_LOST);
    assert_true(wait_link(t, XF_LINK_DOWN, T_DOWN_MS + 5000u));
    replies = t->c.health.replies;
    assert_true(wait_link(t, XF_LINK_UP, 5000));
    assert_true(t->c.health.replies > replies);
    pump(t, 100);
    if (downs_since(t, mark) != 1u) {
        size_t i;
        for (i = mark; i < t->log.n_links; i++) {
            print_error("link %s at +%u ms\n", xf_link_state_name((xf_link_state)t->log.links[i]),
                        (unsigned)xf_ms_since(t->log.link_ms[i], t->log.link_ms[mark]));
        }
    }
    assert_int_equal(downs_since(t, mark), 1);
    assert_int_equal(t->log.links[t->log.n_links - 1u], XF_LINK_UP);
    assert_int_equal(t->sim.stats.photos, 0); /* the lost shutter never ran */
    id = submit(t, XF_ORDER_SHUTTER, 0);
    assert_status(wait_cmd(t, id, 5000, NULL), XF_CMD_OK);
    assert_int_equal(t->sim.stats.photos, 1);
}

/* The simulator restarts: link closed, a new simulator on the same port / path. */
static void test_reconnect_after_restart(void **state)
{
    tx *t = (tx *)*state;
    size_t mark = t->log.n_links;
    uint32_t id, t0;
    id = submit(t, XF_ORDER_SHUTTER, 0);
    assert_status(wait_cmd(t, id, 5000, NULL), XF_CMD_OK);
    sim_link_close(t);
    t0 = now();
    assert_true(wait_link(t, XF_LINK_DOWN, T_DOWN_MS + 5000u));
    while (xf_ms_since(now(), t0) < T_DOWN_MS + 100u) {
        round_once(t);
    }
    assert_int_equal(xf_client_link(&t->c), XF_LINK_DOWN);
    assert_xf(xf_sim_init(&t->sim, &t->scfg), XF_OK); /* a fresh GCU */
    sim_link_open(t);
    assert_true(wait_link(t, XF_LINK_UP, 5000));
    id = submit(t, XF_ORDER_SHUTTER, 0);
    assert_status(wait_cmd(t, id, 5000, NULL), XF_CMD_OK);
    assert_int_equal(t->sim.stats.photos, 1);
    assert_int_equal(downs_since(t, mark), 1);
}

/* ---- the simulator's links on their own ------------------------------------------------ */

/*
 * While a pty simlink is disconnected, its symlink points nowhere: the
 * freed /dev/pts number can be taken by any other program's new pty, and a
 * host reopening the path (as xf_serial does after a hang-up) must not end
 * up talking to it. Back up, the symlink points to the new pty.
 */
static void test_simlink_pty_disconnect_unlinks(void **state)
{
    char dir[64], link[128], target[128];
    xf_simlink l;
    xf_hal hal;
    struct stat st;
    uint8_t buf[64];
    size_t n = 0;
    ssize_t len;
    uint32_t t0;
    xf_err err = XF_ERR_CLOSED;
    (void)state;
    snprintf(dir, sizeof(dir), "/tmp/xfgcu-simlink-XXXXXX");
    assert_non_null(mkdtemp(dir));
    snprintf(link, sizeof(link), "%s/gcu", dir);
    assert_xf(xf_simlink_open_pty(&l, link), XF_OK);
    xf_simlink_hal(&l, &hal);
    len = readlink(link, target, sizeof(target) - 1u);
    assert_true(len > 0);
    target[len] = '\0';
    assert_string_equal(target, l.pty_path);
    xf_simlink_disconnect(&l, 100);
    assert_int_equal(lstat(link, &st), -1);
    assert_int_equal(errno, ENOENT);
    assert_int_equal(xf_hal_fd(&hal), -1);
    assert_xf(hal.read(hal.ctx, buf, sizeof(buf), &n), XF_ERR_CLOSED);
    t0 = now();
    while (xf_ms_since(now(), t0) < 2000u && (err = hal.read(hal.ctx, buf, sizeof(buf), &n)) == XF_ERR_CLOSED) {
        (void)poll(NULL, 0, 5);
    }
    assert_xf(err, XF_OK);
    assert_true(xf_ms_since(now(), t0) >= 80u);
    len = readlink(link, target, sizeof(target) - 1u);
    assert_true(len > 0);
    target[len] = '\0';
    assert_string_equal(target, l.pty_path);
    assert_int_equal(l.stats.opens, 2);
    xf_simlink_close(&l);
    assert_int_equal(lstat(link, &st), -1);
    (void)rmdir(dir);
}

/* Datagrams sent to a disconnected UDP simlink are lost, read or not meanwhile. */
static void test_simlink_udp_drops_while_down(void **state)
{
    xf_simlink l;
    xf_hal hal;
    struct sockaddr_in to;
    uint8_t pkt[XF_PACKET_MAX_LEN], buf[1024];
    size_t len = 0, n = 0;
    xf_host_packet p;
    uint32_t t0;
    int fd, k;
    xf_err err = XF_ERR_CLOSED;
    (void)state;
    assert_xf(xf_simlink_open_udp(&l, "127.0.0.1", 0), XF_OK);
    xf_simlink_hal(&l, &hal);
    fd = socket(AF_INET, SOCK_DGRAM, 0);
    assert_true(fd >= 0);
    memset(&to, 0, sizeof(to));
    to.sin_family = AF_INET;
    to.sin_port = htons(l.port);
    to.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    xf_host_packet_init(&p, 1);
    assert_xf(xf_host_pack(&p, pkt, sizeof(pkt), &len), XF_OK);
    for (k = 0; k < 2; k++) { /* k = 0: read while down; k = 1: not read until back */
        assert_true(sendto(fd, pkt, len, 0, (const struct sockaddr *)&to, sizeof(to)) == (ssize_t)len);
        (void)poll(NULL, 0, 20);
        assert_xf(hal.read(hal.ctx, buf, sizeof(buf), &n), XF_OK);
        assert_int_equal(n, len); /* up: delivered */
        xf_simlink_disconnect(&l, 100);
        assert_true(sendto(fd, pkt, len, 0, (const struct sockaddr *)&to, sizeof(to)) == (ssize_t)len);
        assert_true(sendto(fd, pkt, len, 0, (const struct sockaddr *)&to, sizeof(to)) == (ssize_t)len);
        (void)poll(NULL, 0, 20);
        if (k == 0) {
            assert_xf(hal.read(hal.ctx, buf, sizeof(buf), &n), XF_ERR_CLOSED);
            assert_int_equal(n, 0);
        }
        (void)poll(NULL, 0, 120);
        t0 = now();
        while (xf_ms_since(now(), t0) < 1000u && (err = hal.read(hal.ctx, buf, sizeof(buf), &n)) == XF_ERR_CLOSED) {
            (void)poll(NULL, 0, 5);
        }
        assert_xf(err, XF_OK);
        assert_int_equal(n, 0);                         /* what was sent while down is gone */
        assert_xf(hal.write(hal.ctx, pkt, len), XF_OK); /* and the peer is still known */
    }
    close(fd);
    xf_simlink_close(&l);
}

/* The table: every scenario over every transport, named scenario/transport. */
#define ON(fn, k, kn)                                                                                                  \
    {                                                                                                                  \
#fn "/" kn, fn, setup, teardown, (void *)&kinds[k]                                                             \
    }
#define ON_ALL(fn) ON(fn, 0, "pty"), ON(fn, 1, "udp"), ON(fn, 2, "tcp")

int main(void)
{
    const struct CMUnitTest tests[] = {
        ON_ALL(test_two_shutters),
        ON_ALL(test_failing_mask),
        ON_ALL(test_drops_retries_timeout),
        ON_ALL(test_dead_link),
        ON_ALL(test_watchdog),
        ON_ALL(test_telemetry_ages),
        ON_ALL(test_reconnect_after_disconnect),
        ON_ALL(test_reconnect_after_restart),
        cmocka_unit_test(test_simlink_pty_disconnect_unlinks),
        cmocka_unit_test(test_simlink_udp_drops_while_down),
    };
    if (getenv("XFGCU_TEST_FILTER") != NULL) { /* a cmocka pattern, e.g. test_dead_link?pty */
        cmocka_set_test_filter(getenv("XFGCU_TEST_FILTER"));
    }
    return cmocka_run_group_tests(tests, NULL, NULL);
}
