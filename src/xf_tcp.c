/*
 * xf_tcp.c - TCP link, client of the GCU's single-client server (port 2332).
 *
 * Connecting never blocks the client loop: the link is a small state
 * machine (down -> connecting -> up) advanced whenever it is read or
 * written. After a loss or a failed attempt it waits (50 ms, doubling to
 * 500 ms) and tries again, so it is back well within a second of the
 * server's return. TCP is a byte stream: packets may arrive split or
 * merged, which the codec's streaming parser handles.
 */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <netdb.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <stdio.h>
#include <string.h>
#include <sys/socket.h>
#include <unistd.h>

#include "xf_posix_internal.h"

#define XF_TCP_WRITE_TIMEOUT_MS 100

void xf_tcp_config_init(xf_tcp_config *cfg)
{
    if (cfg != NULL) {
        memset(cfg, 0, sizeof(*cfg));
        cfg->host = XF_GCU_DEFAULT_ADDRESS;
        cfg->port = XF_GCU_TCP_PORT;
        cfg->connect_timeout_ms = 1000;
        cfg->retry_min_ms = 50;
        cfg->retry_max_ms = 500;
    }
}

static void xf__tcp_drop(xf_tcp *t)
{
    if (t->fd >= 0) {
        close(t->fd);
        t->fd = -1;
    }
    t->state = XF_TCP_DOWN;
}

/* Give up on this connection or attempt; retry after the back-off. */
static void xf__tcp_backoff(xf_tcp *t, uint32_t now)
{
    xf__tcp_drop(t);
    t->retry_at = now + t->backoff_ms;
    t->backoff_ms = (t->backoff_ms * 2u > t->cfg.retry_max_ms) ? t->cfg.retry_max_ms : t->backoff_ms * 2u;
}

/* Connected to itself? When nobody listens on a port of the ephemeral
 * range, Linux may give the connecting socket that very port as its own,
 * and the SYN meets itself (TCP simultaneous open): "connected", to no
 * server, with nothing ever to read. A GCU simulator on loopback at a
 * high port meets this while it is down. */
static int xf__tcp_self(int fd)
{
    struct sockaddr_storage a, b;
    socklen_t la = sizeof(a), lb = sizeof(b);
    memset(&a, 0, sizeof(a));
    memset(&b, 0, sizeof(b));
    if (getsockname(fd, (struct sockaddr *)&a, &la) != 0 || getpeername(fd, (struct sockaddr *)&b, &lb) != 0) {
        return 0;
    }
    return la == lb && memcmp(&a, &b, la) == 0;
}

static void xf__tcp_up(xf_tcp *t, uint32_t now)
{
    if (xf__tcp_self(t->fd)) {
        xf__fail(&t->error, XF_ERR_CLOSED, "connect to %s:%u: connected to itself (nobody listens there)", t->host,
                 (unsigned)t->cfg.port);
        xf__tcp_backoff(t, now);
        return;
    }
    t->state = XF_TCP_UP;
    t->stats.opens++;
    t->backoff_ms = t->cfg.retry_min_ms;
}

static void xf__tcp_start(xf_tcp *t, uint32_t now)
{
    int one = 1;
    t->fd = socket(t->addr.ss_family, SOCK_STREAM, 0);
    if (t->fd < 0) {
        xf__os_fail(&t->error, errno, "TCP socket");
        xf__tcp_backoff(t, now);
        return;
    }
    /* Small packets at 50 Hz: send each at once. */
    setsockopt(t->fd, IPPROTO_TCP, TCP_NODELAY, &one, sizeof(one));
    if (xf__set_nonblock(t->fd) != 0) {
        xf__os_fail(&t->error, errno, "TCP socket options");
        xf__tcp_backoff(t, now);
        return;
    }
    t->started_at = now;
    if (connect(t->fd, (const struct sockaddr *)&t->addr, t->addr_len) == 0) {
        xf__tcp_up(t, now);
    } else if (errno == EINPROGRESS || errno == EINTR) {
        t->state = XF_TCP_CONNECTING;
    } else {
        xf__os_fail(&t->error, errno, "connect to %s:%u", t->host, (unsigned)t->cfg.port);
        xf__tcp_backoff(t, now);
    }
}

/* Has the attempt in progress finished? */
static void xf__tcp_check(xf_tcp *t, uint32_t now)
{
    struct pollfd pfd;
    int soerr = 0;
    socklen_t len = sizeof(soerr);
    pfd.fd = t->fd;
    pfd.events = POLLOUT;
    pfd.revents = 0;
    if (poll(&pfd, 1, 0) <= 0) {
        if (xf_ms_since(now, t->started_at) >= t->cfg.connect_timeout_ms) {
            xf__fail(&t->error, XF_ERR_TIMEOUT, "connect to %s:%u: no answer in %u ms", t->host, (unsigned)t->cfg.port,
                     (unsigned)t->cfg.connect_timeout_ms);
            xf__tcp_backoff(t, now);
        }
        return;
    }
    if (getsockopt(t->fd, SOL_SOCKET, SO_ERROR, &soerr, &len) != 0) {
        soerr = errno;
    }
    if (soerr != 0) {
        xf__os_fail(&t->error, soerr, "connect to %s:%u", t->host, (unsigned)t->cfg.port);
        xf__tcp_backoff(t, now);
        return;
    }
    xf__tcp_up(t, now);
}

/* Move the state machine on; 1 if the connection is up. */
static int xf__tcp_service(xf_tcp *t)
{
    uint32_t now = xf_posix_now_ms();
    if (t->state == XF_TCP_DOWN && t->host[0] != '\0' && (int32_t)(now - t->retry_at) >= 0) {
        xf__tcp_start(t, now);
    }
    if (t->state == XF_TCP_CONNECTING) {
        xf__tcp_check(t, now);
    }
    return t->state == XF_TCP_UP;
}

static xf_err xf__tcp_lost(xf_tcp *t, int e, const char *what)
{
    if (e != 0) {
        xf__os_fail(&t->error, e, "%s %s:%u", what, t->host, (unsigned)t->cfg.port);
    } else {
        xf__fail(&t->error, XF_ERR_CLOSED, "%s %s:%u: the GCU closed the connection", what, t->host,
                 (unsigned)t->cfg.port);
    }
    t->stats.losses++;
    t->backoff_ms = t->cfg.retry_min_ms; /* it was up: try again soon */
    xf__tcp_backoff(t, xf_posix_now_ms());
    return XF_ERR_CLOSED;
}

xf_err xf_tcp_open(xf_tcp *t, const xf_tcp_config *cfg)
{
    xf_tcp_config def;
    struct addrinfo hints, *res = NULL;
    char service[8];
    int rc;
    if (t == NULL) {
        return XF_ERR_ARG;
    }
    if (cfg == NULL) {
        xf_tcp_config_init(&def);
        cfg = &def;
    }
    memset(t, 0, sizeof(*t));
    t->fd = -1;
    t->cfg = *cfg;
    if (t->cfg.host == NULL) {
        t->cfg.host = XF_GCU_DEFAULT_ADDRESS;
    }
    if (t->cfg.connect_timeout_ms == 0u) {
        t->cfg.connect_timeout_ms = 1000;
    }
    if (t->cfg.retry_min_ms == 0u) {
        t->cfg.retry_min_ms = 50;
    }
    if (t->cfg.retry_max_ms < t->cfg.retry_min_ms) {
        t->cfg.retry_max_ms = t->cfg.retry_min_ms;
    }
    if (strlen(t->cfg.host) >= sizeof(t->host)) {
        return XF_ERR_ARG;
    }
    snprintf(t->host, sizeof(t->host), "%s", t->cfg.host);
    t->cfg.host = t->host;
    memset(&hints, 0, sizeof(hints));
    hints.ai_family = AF_UNSPEC;
    hints.ai_socktype = SOCK_STREAM;
    snprintf(service, sizeof(service), "%u", (unsigned)t->cfg.port);
    rc = getaddrinfo(t->host, service, &hints, &res);
    if (rc != 0 || res == NULL) {
        xf_err e = xf__fail(&t->error, XF_ERR_NOT_FOUND, "resolve %s: %s", t->host, gai_strerror(rc));
        t->host[0] = '\0';
        return e;
    }
    memcpy(&t->addr, res->ai_addr, res->ai_addrlen);
    t->addr_len = res->ai_addrlen;
    freeaddrinfo(res);
    t->backoff_ms = t->cfg.retry_min_ms;
    t->retry_at = xf_posix_now_ms();
    xf__tcp_service(t);
    return XF_OK;
}

xf_err xf_tcp_wait(xf_tcp *t, uint32_t timeout_ms)
{
    uint32_t start = xf_posix_now_ms();
    if (t == NULL || t->host[0] == '\0') {
        return XF_ERR_ARG;
    }
    while (!xf__tcp_service(t)) {
        struct pollfd pfd;
        if (xf_ms_since(xf_posix_now_ms(), start) >= timeout_ms) {
            /* A refusal says more than "no answer"; an attempt still in progress does not. */
            if (t->state == XF_TCP_CONNECTING || t->error.text[0] == '\0') {
                xf__fail(&t->error, XF_ERR_TIMEOUT, "connect to %s:%u: no answer in %u ms", t->host,
                         (unsigned)t->cfg.port, (unsigned)timeout_ms);
            }
            return (t->state == XF_TCP_CONNECTING) ? XF_ERR_TIMEOUT : XF_ERR_CLOSED;
        }
        pfd.fd = t->fd;
        pfd.events = POLLOUT;
        pfd.revents = 0;
        poll(t->fd >= 0 ? &pfd : NULL, t->fd >= 0 ? 1u : 0u, 5);
    }
    return XF_OK;
}

void xf_tcp_close(xf_tcp *t)
{
    if (t != NULL) {
        xf__tcp_drop(t);
        t->host[0] = '\0'; /* no reconnecting */
    }
}

static xf_err xf__tcp_write(void *ctx, const uint8_t *data, size_t len)
{
    xf_tcp *t = (xf_tcp *)ctx;
    int e;
    if (!xf__tcp_service(t)) {
        return XF_ERR_CLOSED;
    }
    e = xf__write_all(t->fd, data, len, XF_TCP_WRITE_TIMEOUT_MS, 1);
    if (e != 0) {
        return xf__tcp_lost(t, e, "send to");
    }
    t->stats.bytes_tx += (uint32_t)len;
    t->stats.packets_tx++;
    return XF_OK;
}

static xf_err xf__tcp_read(void *ctx, uint8_t *buf, size_t cap, size_t *out_len)
{
    xf_tcp *t = (xf_tcp *)ctx;
    ssize_t r;
    *out_len = 0;
    if (!xf__tcp_service(t)) {
        return XF_ERR_CLOSED;
    }
    do {
        r = recv(t->fd, buf, cap, 0);
    } while (r < 0 && errno == EINTR);
    if (r < 0) {
        return (errno == EAGAIN || errno == EWOULDBLOCK) ? XF_OK : xf__tcp_lost(t, errno, "receive from");
    }
    if (r == 0 && cap > 0) {
        return xf__tcp_lost(t, 0, "receive from");
    }
    *out_len = (size_t)r;
    t->stats.bytes_rx += (uint32_t)r;
    return XF_OK;
}

static int xf__tcp_fd(void *ctx)
{
    xf_tcp *t = (xf_tcp *)ctx;
    return (t->state == XF_TCP_UP) ? t->fd : -1;
}

void xf_tcp_hal(xf_tcp *t, xf_hal *hal)
{
    if (hal != NULL) {
        hal->ctx = t;
        hal->write = xf__tcp_write;
        hal->read = xf__tcp_read;
        hal->fd = xf__tcp_fd;
    }
}
