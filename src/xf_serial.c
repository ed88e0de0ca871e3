/*
 * xf_serial.c - serial link: libserialport for real ports, termios for
 * pseudo-terminals (libserialport 0.1.1 cannot open those: it looks the
 * port up under /sys/class/tty and fails the modem-line ioctls).
 */
#define _DEFAULT_SOURCE /* realpath, cfmakeraw */
#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <poll.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/ioctl.h>
#include <sys/stat.h>
#include <termios.h>
#include <unistd.h>
#if defined(__linux__)
#include <sys/sysmacros.h>
#endif

#include <libserialport.h>

#include "xf_posix_internal.h"

#define XF_SERIAL_WRITE_TIMEOUT_MS 100
#define XF_SERIAL_RETRY_MIN_MS     50u
#define XF_SERIAL_RETRY_MAX_MS     1000u

bool xf_serial_baud_ok(uint32_t baud)
{
    return baud == 115200u || baud == 250000u || baud == 500000u || baud == 1000000u;
}

/* A Unix98 pseudo-terminal slave? (libserialport refuses these.) */
static int xf__is_pty(const char *path)
{
    char real[PATH_MAX];
    if (realpath(path, real) != NULL && strncmp(real, "/dev/pts/", 9) == 0) {
        return 1;
    }
#if defined(__linux__)
    {
        /* Pty slaves have majors 136..143 on Linux, wherever their node lives. */
        struct stat st;
        if (stat(path, &st) == 0 && S_ISCHR(st.st_mode) && major(st.st_rdev) >= 136u && major(st.st_rdev) <= 143u) {
            return 1;
        }
    }
#endif
    return 0;
}

/* The OS's own verdict on the path, so errors name the real cause
 * (no such file, permission) rather than libserialport's paraphrase. */
static xf_err xf__serial_preflight(xf_serial *s)
{
    int fd = open(s->path, O_RDWR | O_NOCTTY | O_NONBLOCK);
    int tty;
    if (fd < 0) {
        return xf__os_fail(&s->error, errno, "open %s", s->path);
    }
    tty = isatty(fd);
    close(fd);
    if (!tty) {
        return xf__fail(&s->error, XF_ERR_NOT_FOUND, "open %s: not a serial port (not a terminal device)", s->path);
    }
    return XF_OK;
}

static speed_t xf__speed(uint32_t baud)
{
    switch (baud) {
#ifdef B500000
    case 500000u: return B500000;
#endif
#ifdef B1000000
    case 1000000u: return B1000000;
#endif
    default: return B115200; /* a pty has no line speed; 250000 has no Bxxx constant */
    }
}

static xf_err xf__open_termios(xf_serial *s)
{
    struct termios tio;
    int fd = open(s->path, O_RDWR | O_NOCTTY | O_NONBLOCK);
    if (fd < 0) {
        return xf__os_fail(&s->error, errno, "open %s", s->path);
    }
    if (tcgetattr(fd, &tio) != 0) {
        int e = errno;
        close(fd);
        return xf__os_fail(&s->error, e, "configure %s", s->path);
    }
    cfmakeraw(&tio);
    tio.c_cflag &= (tcflag_t) ~(CSTOPB | PARENB | CSIZE);
#ifdef CRTSCTS
    tio.c_cflag &= (tcflag_t)~CRTSCTS;
#endif
    tio.c_cflag |= CS8 | CLOCAL | CREAD;
    tio.c_iflag &= (tcflag_t) ~(IXON | IXOFF | IXANY);
    tio.c_cc[VMIN] = 0;
    tio.c_cc[VTIME] = 0;
    cfsetispeed(&tio, xf__speed(s->baud));
    cfsetospeed(&tio, xf__speed(s->baud));
    if (tcsetattr(fd, TCSANOW, &tio) != 0) {
        int e = errno;
        close(fd);
        return xf__os_fail(&s->error, e, "configure %s", s->path);
    }
    s->fd = fd;
    s->via_termios = 1;
    return XF_OK;
}

/* libserialport's message for its last failure, into s->error. */
static xf_err xf__lsp_fail(xf_serial *s, enum sp_return r, const char *what)
{
    if (r == SP_ERR_FAIL) {
        char *msg = sp_last_error_message();
        int code = sp_last_error_code();
        xf__fail(&s->error, XF_ERR_IO, "%s %s: %s", what, s->path, msg != NULL ? msg : "failed");
        s->error.os_errno = code;
        sp_free_error_message(msg);
        return (code != 0) ? xf__errno_code(code) : XF_ERR_IO;
    }
    return xf__fail(&s->error, XF_ERR_IO, "%s %s: libserialport refused (code %d)", what, s->path, (int)r);
}

static xf_err xf__open_lsp(xf_serial *s)
{
    struct sp_port *port = NULL;
    enum sp_return r = sp_get_port_by_name(s->path, &port);
    xf_err err;
    if (r != SP_OK) {
        return xf__lsp_fail(s, r, "look up");
    }
    r = sp_open(port, SP_MODE_READ_WRITE);
    if (r != SP_OK) {
        err = xf__lsp_fail(s, r, "open");
        sp_free_port(port);
        return err;
    }
    if ((r = sp_set_baudrate(port, (int)s->baud)) != SP_OK || (r = sp_set_bits(port, 8)) != SP_OK ||
        (r = sp_set_parity(port, SP_PARITY_NONE)) != SP_OK || (r = sp_set_stopbits(port, 1)) != SP_OK ||
        (r = sp_set_flowcontrol(port, SP_FLOWCONTROL_NONE)) != SP_OK ||
        (r = sp_get_port_handle(port, &s->fd)) != SP_OK) {
        err = xf__lsp_fail(s, r, "configure");
        sp_close(port);
        sp_free_port(port);
        s->fd = -1;
        return err;
    }
    s->port = port;
    s->via_termios = 0;
    return XF_OK;
}

static xf_err xf__serial_try_open(xf_serial *s)
{
    xf_err err = xf__serial_preflight(s);
    if (err != XF_OK) {
        return err;
    }
    if (!s->force_termios) {
        err = xf__open_lsp(s);
        if (err == XF_OK || !xf__is_pty(s->path)) {
            return err;
        }
    }
    return xf__open_termios(s);
}

static void xf__serial_drop(xf_serial *s)
{
    if (s->port != NULL) {
        sp_close(s->port);
        sp_free_port(s->port);
        s->port = NULL;
    } else if (s->fd >= 0) {
        close(s->fd);
    }
    s->fd = -1;
}

xf_err xf_serial_open(xf_serial *s, const char *path, uint32_t baud)
{
    uint8_t force;
    xf_err err;
    if (s == NULL || path == NULL || strlen(path) >= sizeof(s->path)) {
        return XF_ERR_ARG;
    }
    force = s->force_termios;
    memset(s, 0, sizeof(*s));
    s->fd = -1;
    s->force_termios = force;
    snprintf(s->path, sizeof(s->path), "%s", path);
    s->baud = baud;
    if (!xf_serial_baud_ok(baud)) {
        err = xf__fail(&s->error, XF_ERR_RANGE, "baud %u: the GCU speaks 115200, 250000, 500000 or 1000000",
                       (unsigned)baud);
    } else {
        err = xf__serial_try_open(s);
    }
    if (err != XF_OK) {
        /* A link that failed to open is closed, like after xf_serial_close:
         * only a hang-up of an open link arms the reopening. */
        s->path[0] = '\0';
        return err;
    }
    s->stats.opens++;
    s->backoff_ms = XF_SERIAL_RETRY_MIN_MS;
    return XF_OK;
}

void xf_serial_close(xf_serial *s)
{
    if (s != NULL) {
        xf__serial_drop(s);
        s->path[0] = '\0';
    }
}

const char *xf_serial_backend(const xf_serial *s)
{
    if (s == NULL || s->fd < 0) {
        return "closed";
    }
    return s->via_termios ? "termios" : "libserialport";
}

/* The line was hung up (pty master gone, adapter unplugged): close, and
 * try the same path again later. */
static xf_err xf__serial_lost(xf_serial *s, int e)
{
    xf__serial_drop(s);
    s->stats.losses++;
    s->retry_at = xf_posix_now_ms() + s->backoff_ms;
    xf__os_fail(&s->error, e, "serial %s hung up", s->path);
    return XF_ERR_CLOSED;
}

/* Closed after a hang-up: reopen when the back-off has passed. */
static int xf__serial_ready(xf_serial *s)
{
    uint32_t now;
    xf_os_error keep;
    if (s->fd >= 0) {
        return 1;
    }
    if (s->path[0] == '\0') {
        return 0; /* closed by the application */
    }
    now = xf_posix_now_ms();
    if ((int32_t)(now - s->retry_at) < 0) {
        return 0;
    }
    keep = s->error;
    if (xf__serial_try_open(s) == XF_OK) {
        s->stats.opens++;
        s->backoff_ms = XF_SERIAL_RETRY_MIN_MS;
        return 1;
    }
    s->error = keep; /* keep the hang-up as the reason; a failed retry is expected */
    s->backoff_ms = (s->backoff_ms * 2u > XF_SERIAL_RETRY_MAX_MS) ? XF_SERIAL_RETRY_MAX_MS : s->backoff_ms * 2u;
    s->retry_at = now + s->backoff_ms;
    return 0;
}

/* A transfer failed, but the line is not gone. xf_hal allows XF_ERR_IO
 * here, not the errno's own code (ETIMEDOUT would become XF_ERR_TIMEOUT). */
static xf_err xf__serial_io(xf_serial *s, int e, const char *what)
{
    if (e == ETIMEDOUT) {
        return xf__fail(&s->error, XF_ERR_IO, "%s %s: driver buffer full for %d ms", what, s->path,
                        XF_SERIAL_WRITE_TIMEOUT_MS);
    }
    (void)xf__os_fail(&s->error, e, "%s %s", what, s->path);
    return XF_ERR_IO;
}

static xf_err xf__serial_write(void *ctx, const uint8_t *data, size_t len)
{
    xf_serial *s = (xf_serial *)ctx;
    int e;
    if (!xf__serial_ready(s)) {
        return XF_ERR_CLOSED;
    }
    if (s->port != NULL) {
        enum sp_return r = sp_blocking_write(s->port, data, len, XF_SERIAL_WRITE_TIMEOUT_MS);
        if (r < 0) {
            e = sp_last_error_code();
            return (e == EIO || e == ENXIO) ? xf__serial_lost(s, e) : xf__serial_io(s, e, "write");
        }
        if ((size_t)r != len) {
            return xf__fail(&s->error, XF_ERR_IO, "write %s: driver buffer full for %d ms", s->path,
                            XF_SERIAL_WRITE_TIMEOUT_MS);
        }
    } else {
        e = xf__write_all(s->fd, data, len, XF_SERIAL_WRITE_TIMEOUT_MS, 0);
        if (e != 0) {
            return (e == EIO || e == ENXIO) ? xf__serial_lost(s, e) : xf__serial_io(s, e, "write");
        }
    }
    s->stats.bytes_tx += (uint32_t)len;
    s->stats.packets_tx++;
    return XF_OK;
}

static xf_err xf__serial_read(void *ctx, uint8_t *buf, size_t cap, size_t *out_len)
{
    xf_serial *s = (xf_serial *)ctx;
    struct pollfd pfd;
    ssize_t n;
    *out_len = 0;
    if (!xf__serial_ready(s)) {
        return XF_ERR_CLOSED;
    }
    /* With VMIN = 0 a read of 0 bytes cannot tell "nothing yet" from a
     * hang-up; poll can. */
    pfd.fd = s->fd;
    pfd.events = POLLIN;
    pfd.revents = 0;
    if (poll(&pfd, 1, 0) < 0) {
        return (errno == EINTR) ? XF_OK : xf__serial_io(s, errno, "poll");
    }
    if ((pfd.revents & POLLIN) == 0) {
        return (pfd.revents & (POLLHUP | POLLERR | POLLNVAL)) ? xf__serial_lost(s, EIO) : XF_OK;
    }
    if (s->port != NULL) {
        enum sp_return r = sp_nonblocking_read(s->port, buf, cap);
        if (r < 0) {
            int e = sp_last_error_code();
            return (e == EIO || e == ENXIO) ? xf__serial_lost(s, e) : xf__serial_io(s, e, "read");
        }
        n = (ssize_t)r;
    } else {
        n = read(s->fd, buf, cap);
        if (n < 0) {
            if (errno == EAGAIN || errno == EINTR) {
                return XF_OK;
            }
            return (errno == EIO || errno == ENXIO) ? xf__serial_lost(s, errno) : xf__serial_io(s, errno, "read");
        }
    }
    if (n == 0) {
        return xf__serial_lost(s, EIO); /* readable but empty: end of file, the line is gone */
    }
    *out_len = (size_t)n;
    s->stats.bytes_rx += (uint32_t)n;
    return XF_OK;
}

static int xf__serial_fd(void *ctx)
{
    xf_serial *s = (xf_serial *)ctx;
    return s->fd;
}

void xf_serial_hal(xf_serial *s, xf_hal *hal)
{
    if (hal != NULL) {
        hal->ctx = s;
        hal->write = xf__serial_write;
        hal->read = xf__serial_read;
        hal->fd = xf__serial_fd;
    }
}

xf_err xf_serial_list(void (*cb)(const xf_serial_port_info *info, void *user), void *user)
{
    struct sp_port **ports = NULL;
    size_t i;
    if (cb == NULL) {
        return XF_ERR_ARG;
    }
    if (sp_list_ports(&ports) != SP_OK) {
        return XF_ERR_IO;
    }
    for (i = 0; ports[i] != NULL; i++) {
        xf_serial_port_info info;
        const char *name = sp_get_port_name(ports[i]);
        const char *desc = sp_get_port_description(ports[i]);
        memset(&info, 0, sizeof(info));
        snprintf(info.path, sizeof(info.path), "%s", name != NULL ? name : "");
        snprintf(info.description, sizeof(info.description), "%s", desc != NULL ? desc : "");
        info.usb_vid = -1;
        info.usb_pid = -1;
        if (sp_get_port_transport(ports[i]) == SP_TRANSPORT_USB) {
            sp_get_port_usb_vid_pid(ports[i], &info.usb_vid, &info.usb_pid);
        }
        cb(&info, user);
    }
    sp_free_port_list(ports);
    return XF_OK;
}
