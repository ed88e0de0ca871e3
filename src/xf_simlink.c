/*
 * xf_simlink.c - the GCU's end of a link, for the simulator: pty master,
 * UDP socket on the GCU's port, single-client TCP server.
 */
#define _XOPEN_SOURCE   600 /* posix_openpt, grantpt, unlockpt, ptsname */
#define _DEFAULT_SOURCE     /* cfmakeraw */
#include <errno.h>
#include <fcntl.h>
#include <netdb.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/socket.h>
#include <termios.h>
#include <unistd.h>

#include "xf_posix_internal.h"
#include "xfgcu/posix/xf_simlink.h"

static void xf__simlink_reset(xf_simlink *l, xf_simlink_kind kind)
{
    memset(l, 0, sizeof(*l));
    l->kind = kind;
    l->fd = -1;
    l->slave_fd = -1;
    l->client_fd = -1;
}

static void xf__close_fd(int *fd)
{
    if (*fd >= 0) {
        close(*fd);
        *fd = -1;
    }
}

/* ---- pty ----------------------------------------------------------------------------- */

static xf_err xf__pty_create(xf_simlink *l)
{
    struct termios tio;
    const char *name;
    int m = posix_openpt(O_RDWR | O_NOCTTY);
    if (m < 0) {
        return xf__os_fail(&l->error, errno, "open a pseudo-terminal");
    }
    if (grantpt(m) != 0 || unlockpt(m) != 0 || (name = ptsname(m)) == NULL) {
        int e = errno;
        close(m);
        return xf__os_fail(&l->error, e, "set up a pseudo-terminal");
    }
    snprintf(l->pty_path, sizeof(l->pty_path), "%s", name);
    /* Hold the slave open (raw: no echo, no line editing) so the master
     * never reads EIO while no host has it open. */
    l->slave_fd = open(l->pty_path, O_RDWR | O_NOCTTY | O_NONBLOCK);
    if (l->slave_fd < 0 || tcgetattr(l->slave_fd, &tio) != 0) {
        int e = errno;
        close(m);
        xf__close_fd(&l->slave_fd);
        return xf__os_fail(&l->error, e, "open %s", l->pty_path);
    }
    cfmakeraw(&tio);
    tcsetattr(l->slave_fd, TCSANOW, &tio);
    xf__set_nonblock(m);
    l->fd = m;
    if (l->link_path[0] != '\0' && symlink(l->pty_path, l->link_path) != 0) {
        /* Never over something that is there: it may be a user's file, or another simulator's link. */
        int e = errno;
        if (e == EEXIST) {
            return xf__fail(&l->error, XF_ERR_BUSY, "link %s: it exists; not replaced", l->link_path);
        }
        return xf__os_fail(&l->error, e, "link %s -> %s", l->link_path, l->pty_path);
    }
    l->link_made = (l->link_path[0] != '\0');
    l->stats.opens++;
    return XF_OK;
}

/* Remove the link path if it is still the link this simulator made to its pty. */
static void xf__unlink_ours(xf_simlink *l)
{
    char target[sizeof(l->pty_path)];
    ssize_t n;
    if (!l->link_made) {
        return;
    }
    l->link_made = 0;
    n = readlink(l->link_path, target, sizeof(target) - 1u);
    if (n > 0 && (size_t)n < sizeof(target) - 1u) {
        target[n] = '\0';
        if (strcmp(target, l->pty_path) == 0) {
            unlink(l->link_path);
        }
    }
}

xf_err xf_simlink_open_pty(xf_simlink *l, const char *symlink_path)
{
    if (l == NULL || (symlink_path != NULL && strlen(symlink_path) >= sizeof(l->link_path))) {
        return XF_ERR_ARG;
    }
    xf__simlink_reset(l, XF_SIMLINK_PTY);
    if (symlink_path != NULL) {
        snprintf(l->link_path, sizeof(l->link_path), "%s", symlink_path);
    }
    return xf__pty_create(l);
}

/* ---- sockets ------------------------------------------------------------------------- */

static xf_err xf__bind(xf_simlink *l, const char *host, uint16_t port, int type)
{
    struct addrinfo hints, *res = NULL;
    struct sockaddr_storage ss;
    socklen_t len = sizeof(ss);
    char service[8];
    int rc, one = 1;
    snprintf(l->bind_host, sizeof(l->bind_host), "%s", host != NULL ? host : "127.0.0.1");
    memset(&hints, 0, sizeof(hints));
    hints.ai_family = AF_UNSPEC;
    hints.ai_socktype = type;
    hints.ai_flags = AI_PASSIVE;
    snprintf(service, sizeof(service), "%u", (unsigned)port);
    rc = getaddrinfo(l->bind_host, service, &hints, &res);
    if (rc != 0 || res == NULL) {
        return xf__fail(&l->error, XF_ERR_NOT_FOUND, "resolve %s: %s", l->bind_host, gai_strerror(rc));
    }
    l->fd = socket(res->ai_family, type, 0);
    if (l->fd < 0) {
        freeaddrinfo(res);
        return xf__os_fail(&l->error, errno, "socket");
    }
    if (type == SOCK_STREAM) {
        setsockopt(l->fd, SOL_SOCKET, SO_REUSEADDR, &one, sizeof(one)); /* restart on the same port at once */
    }
    if (bind(l->fd, res->ai_addr, res->ai_addrlen) != 0) {
        int e = errno;
        freeaddrinfo(res);
        xf__close_fd(&l->fd);
        return xf__os_fail(&l->error, e, "bind %s port %u", type == SOCK_STREAM ? "TCP" : "UDP", (unsigned)port);
    }
    freeaddrinfo(res);
    if (getsockname(l->fd, (struct sockaddr *)&ss, &len) == 0) {
        l->port = ntohs(ss.ss_family == AF_INET6 ? ((struct sockaddr_in6 *)(void *)&ss)->sin6_port
                                                 : ((struct sockaddr_in *)(void *)&ss)->sin_port);
    }
    xf__set_nonblock(l->fd);
    return XF_OK;
}

xf_err xf_simlink_open_udp(xf_simlink *l, const char *host, uint16_t port)
{
    xf_err err;
    if (l == NULL) {
        return XF_ERR_ARG;
    }
    xf__simlink_reset(l, XF_SIMLINK_UDP);
    err = xf__bind(l, host, port, SOCK_DGRAM);
    if (err == XF_OK) {
        l->stats.opens++;
    }
    return err;
}

xf_err xf_simlink_udp_reply_to(xf_simlink *l, const char *host, uint16_t port)
{
    struct addrinfo hints, *res = NULL;
    char service[8];
    int rc, one = 1;
    if (l == NULL || host == NULL || l->kind != XF_SIMLINK_UDP || l->fd < 0) {
        return XF_ERR_ARG;
    }
    memset(&hints, 0, sizeof(hints));
    hints.ai_family = AF_UNSPEC;
    hints.ai_socktype = SOCK_DGRAM;
    snprintf(service, sizeof(service), "%u", (unsigned)port);
    rc = getaddrinfo(host, service, &hints, &res);
    if (rc != 0 || res == NULL || res->ai_addrlen > sizeof(l->peer)) {
        if (res != NULL) {
            freeaddrinfo(res);
        }
        return xf__fail(&l->error, XF_ERR_NOT_FOUND, "resolve %s: %s", host, rc != 0 ? gai_strerror(rc) : "no address");
    }
    if (setsockopt(l->fd, SOL_SOCKET, SO_BROADCAST, &one, sizeof(one)) != 0) {
        int e = errno;
        freeaddrinfo(res);
        return xf__os_fail(&l->error, e, "allow broadcast");
    }
    memcpy(&l->peer, res->ai_addr, res->ai_addrlen);
    l->peer_len = res->ai_addrlen;
    l->fixed_peer = 1;
    l->asked = 0;
    freeaddrinfo(res);
    return XF_OK;
}

xf_err xf_simlink_open_tcp(xf_simlink *l, const char *host, uint16_t port)
{
    xf_err err;
    if (l == NULL) {
        return XF_ERR_ARG;
    }
    xf__simlink_reset(l, XF_SIMLINK_TCP);
    err = xf__bind(l, host, port, SOCK_STREAM);
    if (err == XF_OK && listen(l->fd, 4) != 0) {
        err = xf__os_fail(&l->error, errno, "listen on TCP port %u", (unsigned)l->port);
        xf__close_fd(&l->fd);
    }
    return err;
}

/* Accept a waiting host: the first becomes the client, later ones are refused. */
static void xf__tcp_accept(xf_simlink *l)
{
    for (;;) {
        int fd = accept(l->fd, NULL, NULL);
        int one = 1;
        if (fd < 0) {
            return;
        }
        if (l->client_fd >= 0 || l->down) {
            close(fd); /* the GCU serves a single client */
            continue;
        }
        setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &one, sizeof(one));
        xf__set_nonblock(fd);
        l->client_fd = fd;
        l->stats.opens++;
    }
}

/* UDP while disconnected: what the host sends now is lost, as with a GCU
 * that is gone (not kept in the socket to be answered when it is back). */
static void xf__udp_discard(xf_simlink *l)
{
    uint8_t buf[512];
    int i;
    for (i = 0; i < 256; i++) {
        if (recv(l->fd, buf, sizeof(buf), 0) < 0 && errno != EINTR) {
            return; /* EAGAIN: nothing more */
        }
    }
}

/* ---- disconnect fault ------------------------------------------------------------------ */

void xf_simlink_disconnect(xf_simlink *l, uint32_t ms)
{
    if (l == NULL) {
        return;
    }
    l->down = 1;
    l->up_at = xf_posix_now_ms() + ms;
    l->stats.losses++;
    if (l->kind == XF_SIMLINK_PTY) {
        xf__close_fd(&l->slave_fd);
        xf__close_fd(&l->fd); /* the host's side hangs up */
        /* Nothing behind the path while down, like an unplugged adapter:
         * the freed /dev/pts number may be reused by another program's
         * pty, and a host reopening the path must not end up on it. */
        xf__unlink_ours(l);
    } else if (l->kind == XF_SIMLINK_TCP) {
        xf__close_fd(&l->client_fd);
    }
}

/* Back after a disconnect? 1 if the link is usable now. */
static int xf__simlink_up(xf_simlink *l)
{
    if (!l->down) {
        return 1;
    }
    if ((int32_t)(xf_posix_now_ms() - l->up_at) < 0) {
        return 0;
    }
    l->down = 0;
    if (l->kind == XF_SIMLINK_UDP && l->fd >= 0) {
        xf__udp_discard(l); /* sent while down, unread: lost too */
    }
    if (l->kind == XF_SIMLINK_PTY && xf__pty_create(l) != XF_OK) {
        l->down = 1;
        l->up_at = xf_posix_now_ms() + 100u;
        return 0;
    }
    return 1;
}

/* ---- xf_hal ------------------------------------------------------------------------------ */

static xf_err xf__simlink_read(void *ctx, uint8_t *buf, size_t cap, size_t *out_len)
{
    xf_simlink *l = (xf_simlink *)ctx;
    ssize_t r = -1;
    *out_len = 0;
    if (!xf__simlink_up(l)) {
        if (l->kind == XF_SIMLINK_TCP) {
            xf__tcp_accept(l); /* refuse while down */
        } else if (l->kind == XF_SIMLINK_UDP && l->fd >= 0) {
            xf__udp_discard(l);
        }
        return XF_ERR_CLOSED;
    }
    switch (l->kind) {
    case XF_SIMLINK_PTY: r = read(l->fd, buf, cap); break;
    case XF_SIMLINK_UDP: {
        struct sockaddr_storage from;
        socklen_t flen = sizeof(from);
        r = recvfrom(l->fd, buf, cap, 0, (struct sockaddr *)&from, &flen);
        if (r > 0 && !l->fixed_peer) {
            l->peer = from; /* answer whoever asked */
            l->peer_len = flen;
        }
        l->asked |= (r > 0);
        break;
    }
    case XF_SIMLINK_TCP:
        xf__tcp_accept(l);
        if (l->client_fd < 0) {
            return XF_ERR_CLOSED;
        }
        r = recv(l->client_fd, buf, cap, 0);
        if (r == 0) {
            xf__close_fd(&l->client_fd); /* the host left; wait for the next */
            l->stats.losses++;
            return XF_ERR_CLOSED;
        }
        break;
    }
    if (r < 0) {
        if (errno == EAGAIN || errno == EWOULDBLOCK || errno == EINTR || errno == EIO) {
            return XF_OK; /* EIO on a pty master: no host has the slave open */
        }
        if (l->kind == XF_SIMLINK_TCP) {
            xf__close_fd(&l->client_fd);
            l->stats.losses++;
            return XF_ERR_CLOSED;
        }
        return xf__os_fail(&l->error, errno, "read");
    }
    *out_len = (size_t)r;
    l->stats.bytes_rx += (uint32_t)r;
    return XF_OK;
}

static xf_err xf__simlink_write(void *ctx, const uint8_t *data, size_t len)
{
    xf_simlink *l = (xf_simlink *)ctx;
    int e = 0;
    if (!xf__simlink_up(l)) {
        return XF_ERR_CLOSED;
    }
    switch (l->kind) {
    case XF_SIMLINK_PTY: e = xf__write_all(l->fd, data, len, 100, 0); break;
    case XF_SIMLINK_UDP:
        if (l->peer_len == 0u || !l->asked) {
            return XF_ERR_CLOSED; /* no host has spoken yet */
        }
        if (sendto(l->fd, data, len, 0, (struct sockaddr *)&l->peer, l->peer_len) != (ssize_t)len) {
            e = errno;
        }
        break;
    case XF_SIMLINK_TCP:
        if (l->client_fd < 0) {
            return XF_ERR_CLOSED;
        }
        e = xf__write_all(l->client_fd, data, len, 100, 1);
        if (e != 0) {
            xf__close_fd(&l->client_fd);
            l->stats.losses++;
            return XF_ERR_CLOSED;
        }
        break;
    }
    if (e != 0) {
        return xf__os_fail(&l->error, e, "write");
    }
    l->stats.bytes_tx += (uint32_t)len;
    l->stats.packets_tx++;
    return XF_OK;
}

static int xf__simlink_fd(void *ctx)
{
    xf_simlink *l = (xf_simlink *)ctx;
    if (l->down) {
        return -1;
    }
    return (l->kind == XF_SIMLINK_TCP && l->client_fd >= 0) ? l->client_fd : l->fd;
}

void xf_simlink_hal(xf_simlink *l, xf_hal *hal)
{
    if (hal != NULL) {
        hal->ctx = l;
        hal->read = xf__simlink_read;
        hal->write = xf__simlink_write;
        hal->fd = xf__simlink_fd;
    }
}

/* ---- wire faults ------------------------------------------------------------------------- */

#define XF__WIRE_CHUNK 256u

static uint32_t xf__wire_rand(xf_simlink_wire *w)
{
    w->rng ^= w->rng << 13;
    w->rng ^= w->rng >> 17;
    w->rng ^= w->rng << 5;
    return w->rng;
}

static int xf__wire_chance(xf_simlink_wire *w, uint16_t permille)
{
    return permille > 0u && xf__wire_rand(w) % 1000u < permille;
}

/* One chunk of at most XF__WIRE_CHUNK bytes, faults applied, in one inner write. */
static xf_err xf__wire_chunk(xf_simlink_wire *w, const uint8_t *data, size_t len)
{
    uint8_t out[2u * XF__WIRE_CHUNK];
    size_t i, n = 0;
    uint32_t noise = 0, dropped = 0;
    xf_err err;
    for (i = 0; i < len; i++) {
        if (xf__wire_chance(w, w->drop_permille)) {
            dropped++;
        } else {
            out[n++] = data[i];
        }
        if (xf__wire_chance(w, w->noise_permille)) {
            out[n++] = (uint8_t)xf__wire_rand(w);
            noise++;
        }
    }
    err = (n > 0u) ? w->inner.write(w->inner.ctx, out, n) : XF_OK;
    if (err == XF_OK) {
        w->noise_bytes += noise;
        w->dropped_bytes += dropped;
    }
    return err;
}

static xf_err xf__wire_write(void *ctx, const uint8_t *data, size_t len)
{
    xf_simlink_wire *w = (xf_simlink_wire *)ctx;
    xf_err err = XF_OK;
    size_t done = 0;
    while (err == XF_OK && done < len) {
        size_t n = (len - done < XF__WIRE_CHUNK) ? len - done : XF__WIRE_CHUNK;
        err = xf__wire_chunk(w, data + done, n);
        done += n;
    }
    return err;
}

static xf_err xf__wire_read(void *ctx, uint8_t *buf, size_t cap, size_t *out_len)
{
    xf_simlink_wire *w = (xf_simlink_wire *)ctx;
    return w->inner.read(w->inner.ctx, buf, cap, out_len);
}

static int xf__wire_fd(void *ctx)
{
    xf_simlink_wire *w = (xf_simlink_wire *)ctx;
    return (w->inner.fd != NULL) ? w->inner.fd(w->inner.ctx) : -1;
}

void xf_simlink_wire_init(xf_simlink_wire *w, const xf_hal *inner, uint32_t seed, xf_hal *out)
{
    if (w == NULL || inner == NULL || out == NULL) {
        return;
    }
    memset(w, 0, sizeof(*w));
    w->inner = *inner;
    w->rng = (seed != 0u) ? seed : 1u;
    out->ctx = w;
    out->write = xf__wire_write;
    out->read = xf__wire_read;
    out->fd = xf__wire_fd;
}

void xf_simlink_close(xf_simlink *l)
{
    if (l == NULL) {
        return;
    }
    xf__unlink_ours(l); /* before the pty goes: its path is what tells ours apart */
    xf__close_fd(&l->client_fd);
    xf__close_fd(&l->slave_fd);
    xf__close_fd(&l->fd);
    l->link_path[0] = '\0';
}

/* ---- the host's spec for this link --------------------------------------------------- */

size_t xf_simlink_host_spec(const xf_simlink *gcu, char *buf, size_t cap)
{
    const char *host;
    if (buf == NULL) {
        cap = 0;
    }
    if (gcu != NULL && gcu->kind == XF_SIMLINK_PTY && (gcu->link_path[0] != '\0' || gcu->pty_path[0] != '\0')) {
        return xf__print(buf, cap, "serial:%s", gcu->link_path[0] != '\0' ? gcu->link_path : gcu->pty_path);
    }
    if (gcu == NULL || (gcu->kind != XF_SIMLINK_UDP && gcu->kind != XF_SIMLINK_TCP) || gcu->port == 0u ||
        memchr(gcu->bind_host, '\0', sizeof(gcu->bind_host)) == NULL) {
        return xf__print(buf, cap, "%s", "");
    }
    host = gcu->bind_host;
    if (host[0] == '\0' || strcmp(host, "0.0.0.0") == 0) {
        host = "127.0.0.1";
    } else if (strcmp(host, "::") == 0) {
        host = "::1";
    }
    if (gcu->kind == XF_SIMLINK_TCP) {
        return xf__print(buf, cap, strchr(host, ':') != NULL ? "tcp:[%s]:%u" : "tcp:%s:%u", host, (unsigned)gcu->port);
    }
    return xf__print(buf, cap, strchr(host, ':') != NULL ? "udp:[%s]:%u,local=0" : "udp:%s:%u,local=0", host,
                     (unsigned)gcu->port);
}
