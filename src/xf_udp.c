/*
 * xf_udp.c - UDP link. The GCU listens on 2337 and sends from 2337 to the
 * host's 2338 (by default to the LAN broadcast address), so the host binds
 * 2338 and sends to the GCU's 2337. Datagrams from any other source are
 * dropped unless accept_any is set: a LAN may carry other traffic to 2338.
 */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <netdb.h>
#include <netinet/in.h>
#include <stdio.h>
#include <string.h>
#include <sys/socket.h>
#include <unistd.h>

#include "xf_posix_internal.h"
#include "xfgcu/xf_protocol.h"

#define XF_UDP_READS_MAX 64u /* datagrams one read may take, foreign ones included */

void xf_udp_config_init(xf_udp_config *cfg)
{
    if (cfg != NULL) {
        memset(cfg, 0, sizeof(*cfg));
        cfg->gcu_host = XF_GCU_DEFAULT_ADDRESS;
        cfg->gcu_port = XF_GCU_UDP_PORT;
        cfg->local_port = XF_HOST_UDP_PORT;
    }
}

static xf_err xf__resolve(xf_os_error *err, const char *host, uint16_t port, int family, int passive,
                          struct sockaddr_storage *out, socklen_t *out_len)
{
    struct addrinfo hints, *res = NULL;
    char service[8];
    int rc;
    memset(&hints, 0, sizeof(hints));
    hints.ai_family = family;
    hints.ai_socktype = SOCK_DGRAM;
    hints.ai_flags = passive ? AI_PASSIVE : 0;
    snprintf(service, sizeof(service), "%u", (unsigned)port);
    rc = getaddrinfo(host, service, &hints, &res);
    if (rc != 0 || res == NULL) {
        return xf__fail(err, XF_ERR_NOT_FOUND, "resolve %s: %s", host != NULL ? host : "(any)", gai_strerror(rc));
    }
    memcpy(out, res->ai_addr, res->ai_addrlen);
    *out_len = res->ai_addrlen;
    freeaddrinfo(res);
    return XF_OK;
}

static uint16_t xf__port_of(const struct sockaddr_storage *ss)
{
    if (ss->ss_family == AF_INET6) {
        return ntohs(((const struct sockaddr_in6 *)(const void *)ss)->sin6_port);
    }
    return ntohs(((const struct sockaddr_in *)(const void *)ss)->sin_port);
}

/* Same address and port? */
static int xf__same_peer(const struct sockaddr_storage *a, const struct sockaddr_storage *b)
{
    if (a->ss_family != b->ss_family) {
        return 0;
    }
    if (a->ss_family == AF_INET) {
        const struct sockaddr_in *x = (const struct sockaddr_in *)(const void *)a;
        const struct sockaddr_in *y = (const struct sockaddr_in *)(const void *)b;
        return x->sin_port == y->sin_port && x->sin_addr.s_addr == y->sin_addr.s_addr;
    }
    if (a->ss_family == AF_INET6) {
        const struct sockaddr_in6 *x = (const struct sockaddr_in6 *)(const void *)a;
        const struct sockaddr_in6 *y = (const struct sockaddr_in6 *)(const void *)b;
        return x->sin6_port == y->sin6_port && memcmp(&x->sin6_addr, &y->sin6_addr, sizeof(x->sin6_addr)) == 0;
    }
    return 0;
}

/* From the GCU? With `broadcast` the host sends to a broadcast address, so
 * the GCU's own address is not known: its source port says it is the GCU. */
static int xf__from_gcu(const xf_udp *u, const struct sockaddr_storage *from)
{
    if (u->broadcast) {
        return from->ss_family == u->gcu.ss_family && xf__port_of(from) == xf__port_of(&u->gcu);
    }
    return xf__same_peer(from, &u->gcu);
}

xf_err xf_udp_open(xf_udp *u, const xf_udp_config *cfg)
{
    xf_udp_config def;
    struct sockaddr_storage local;
    socklen_t local_len = 0;
    xf_err err;
    int one = 1;
    if (u == NULL) {
        return XF_ERR_ARG;
    }
    if (cfg == NULL) {
        xf_udp_config_init(&def);
        cfg = &def;
    }
    memset(u, 0, sizeof(*u));
    u->fd = -1;
    u->accept_any = cfg->accept_any;
    u->broadcast = cfg->broadcast;
    err = xf__resolve(&u->error, cfg->gcu_host != NULL ? cfg->gcu_host : XF_GCU_DEFAULT_ADDRESS, cfg->gcu_port,
                      AF_UNSPEC, 0, &u->gcu, &u->gcu_len);
    if (err != XF_OK) {
        return err;
    }
    err = xf__resolve(&u->error, cfg->local_host, cfg->local_port, u->gcu.ss_family, 1, &local, &local_len);
    if (err != XF_OK) {
        return err;
    }
    u->fd = socket(u->gcu.ss_family, SOCK_DGRAM, 0);
    if (u->fd < 0) {
        return xf__os_fail(&u->error, errno, "UDP socket");
    }
    if (xf__set_nonblock(u->fd) != 0 ||
        (cfg->broadcast && setsockopt(u->fd, SOL_SOCKET, SO_BROADCAST, &one, sizeof(one)) != 0)) {
        err = xf__os_fail(&u->error, errno, "UDP socket options");
        xf_udp_close(u);
        return err;
    }
    if (bind(u->fd, (struct sockaddr *)&local, local_len) != 0) {
        int e = errno;
        err = xf__os_fail(&u->error, e, "bind UDP port %u%s", (unsigned)cfg->local_port,
                          e == EADDRINUSE ? " (another program, or another client, uses it)" : "");
        xf_udp_close(u);
        return err;
    }
    local_len = sizeof(local);
    if (getsockname(u->fd, (struct sockaddr *)&local, &local_len) == 0) {
        u->local_port = xf__port_of(&local);
    }
    u->stats.opens++;
    return XF_OK;
}

void xf_udp_close(xf_udp *u)
{
    if (u != NULL && u->fd >= 0) {
        close(u->fd);
        u->fd = -1;
    }
}

static xf_err xf__udp_write(void *ctx, const uint8_t *data, size_t len)
{
    xf_udp *u = (xf_udp *)ctx;
    ssize_t w;
    if (u->fd < 0) {
        return XF_ERR_CLOSED;
    }
    do {
        w = sendto(u->fd, data, len, 0, (const struct sockaddr *)&u->gcu, u->gcu_len);
    } while (w < 0 && errno == EINTR);
    if (w < 0) {
        if (errno == EAGAIN || errno == EWOULDBLOCK) {
            return XF_ERR_AGAIN;
        }
        /* An ICMP error from an earlier datagram (nobody on 2337 yet) is
         * reported here; it says nothing about this one, which is gone. */
        if (errno == ECONNREFUSED) {
            return XF_OK;
        }
        /* xf_hal allows XF_ERR_IO here, whatever the errno maps to. */
        (void)xf__os_fail(&u->error, errno, "send UDP datagram");
        return XF_ERR_IO;
    }
    if ((size_t)w != len) {
        return xf__fail(&u->error, XF_ERR_IO, "send UDP datagram: %zd of %zu bytes", w, len);
    }
    u->stats.bytes_tx += (uint32_t)len;
    u->stats.packets_tx++;
    return XF_OK;
}

static xf_err xf__udp_read(void *ctx, uint8_t *buf, size_t cap, size_t *out_len)
{
    xf_udp *u = (xf_udp *)ctx;
    size_t n = 0;
    unsigned tries;
    *out_len = 0;
    if (u->fd < 0) {
        return XF_ERR_CLOSED;
    }
    /* Whole datagrams, while a whole packet still fits (at least one: a
     * caller with a small buffer gets the datagram's first cap bytes), and
     * a bounded number of them, so a flood cannot hold the caller here. */
    for (tries = 0; tries < XF_UDP_READS_MAX && ((n == 0 && cap > 0) || cap - n >= XF_PACKET_LIMIT); tries++) {
        struct sockaddr_storage from;
        socklen_t from_len = sizeof(from);
        ssize_t r = recvfrom(u->fd, buf + n, cap - n, 0, (struct sockaddr *)&from, &from_len);
        if (r < 0) {
            if (errno == EINTR) {
                continue;
            }
            if (errno == EAGAIN || errno == EWOULDBLOCK || errno == ECONNREFUSED) {
                break;
            }
            (void)xf__os_fail(&u->error, errno, "receive UDP datagram");
            return XF_ERR_IO;
        }
        if (!u->accept_any && !xf__from_gcu(u, &from)) {
            u->stats.foreign++;
            continue;
        }
        n += (size_t)r;
    }
    *out_len = n;
    u->stats.bytes_rx += (uint32_t)n;
    return XF_OK;
}

static int xf__udp_fd(void *ctx) { return ((xf_udp *)ctx)->fd; }

void xf_udp_hal(xf_udp *u, xf_hal *hal)
{
    if (hal != NULL) {
        hal->ctx = u;
        hal->write = xf__udp_write;
        hal->read = xf__udp_read;
        hal->fd = xf__udp_fd;
    }
}
