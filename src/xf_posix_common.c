/* xf_posix_common.c - clock, error reporting and descriptor helpers for the POSIX links. */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <fcntl.h>
#include <poll.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>
#include <sys/socket.h>
#include <time.h>
#include <unistd.h>

#include "xf_posix_internal.h"

uint32_t xf_posix_now_ms(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (uint32_t)((uint64_t)ts.tv_sec * 1000u + (uint64_t)ts.tv_nsec / 1000000u);
}

xf_err xf__errno_code(int e)
{
    switch (e) {
    case ENOENT:
    case ENODEV:
    case ENXIO:
    case EHOSTUNREACH:
    case ENETUNREACH:
    case EADDRNOTAVAIL: return XF_ERR_NOT_FOUND;
    case EACCES:
    case EPERM: return XF_ERR_PERMISSION;
    case EBUSY:
    case EADDRINUSE: return XF_ERR_BUSY;
    case ECONNREFUSED:
    case ECONNRESET:
    case EPIPE:
    case ENOTCONN:
    case EIO: return XF_ERR_CLOSED; /* EIO on a tty is a hang-up */
    case ETIMEDOUT: return XF_ERR_TIMEOUT;
    case EAGAIN: return XF_ERR_AGAIN;
    default: return XF_ERR_IO;
    }
}

#if defined(__GNUC__)
__attribute__((format(printf, 3, 0)))
#endif
static void
xf__vrecord(xf_os_error *err, int e, const char *fmt, va_list ap)
{
    int n;
    if (err == NULL) {
        return;
    }
    err->os_errno = e;
    n = vsnprintf(err->text, sizeof(err->text), fmt, ap);
    if (e != 0 && n >= 0 && (size_t)n < sizeof(err->text)) {
        snprintf(err->text + n, sizeof(err->text) - (size_t)n, ": %s", strerror(e));
    }
}

xf_err xf__os_fail(xf_os_error *err, int e, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    xf__vrecord(err, e, fmt, ap);
    va_end(ap);
    return xf__errno_code(e);
}

xf_err xf__fail(xf_os_error *err, xf_err code, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    xf__vrecord(err, 0, fmt, ap);
    va_end(ap);
    return code;
}

/* snprintf() that returns a size_t, and never a negative length. */
#if defined(__GNUC__)
__attribute__((format(printf, 3, 4)))
#endif
size_t
xf__print(char *buf, size_t cap, const char *fmt, ...)
{
    va_list ap;
    int n;
    va_start(ap, fmt);
    n = vsnprintf(cap != 0u ? buf : NULL, cap, fmt, ap);
    va_end(ap);
    if (n < 0) {
        if (cap != 0u) {
            buf[0] = '\0';
        }
        return 0u;
    }
    return (size_t)n;
}

int xf__set_nonblock(int fd)
{
    int fl = fcntl(fd, F_GETFL);
    return (fl < 0 || fcntl(fd, F_SETFL, fl | O_NONBLOCK) < 0) ? -1 : 0;
}

int xf__wait_writable(int fd, int timeout_ms)
{
    struct pollfd pfd;
    int r;
    pfd.fd = fd;
    pfd.events = POLLOUT;
    pfd.revents = 0;
    do {
        r = poll(&pfd, 1, timeout_ms);
    } while (r < 0 && errno == EINTR);
    if (r > 0 && (pfd.revents & (POLLERR | POLLHUP | POLLNVAL)) != 0 && (pfd.revents & POLLOUT) == 0) {
        return -1;
    }
    return r;
}

int xf__write_all(int fd, const uint8_t *data, size_t len, int timeout_ms, int is_socket)
{
    size_t done = 0;
    while (done < len) {
        ssize_t w;
#ifdef MSG_NOSIGNAL
        w = is_socket ? send(fd, data + done, len - done, MSG_NOSIGNAL) : write(fd, data + done, len - done);
#else
        (void)is_socket;
        w = write(fd, data + done, len - done);
#endif
        if (w > 0) {
            done += (size_t)w;
            continue;
        }
        if (w < 0 && errno == EINTR) {
            continue;
        }
        if (w < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) {
            /* The driver's buffer is full, so the line is busy: finishing
             * the packet now leaves no idle gap inside it. */
            int r = xf__wait_writable(fd, timeout_ms);
            if (r > 0) {
                continue;
            }
            return (r == 0) ? ETIMEDOUT : EIO;
        }
        return (w < 0) ? errno : EIO;
    }
    return 0;
}
