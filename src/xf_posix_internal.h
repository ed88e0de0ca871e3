/* xf_posix_internal.h - helpers shared by the POSIX links (not installed). */
#ifndef XF_POSIX_INTERNAL_H
#define XF_POSIX_INTERNAL_H

#include "xfgcu/posix/xf_posix.h"

/* errno -> our code: who is at fault decides the code, the text keeps the detail. */
xf_err xf__errno_code(int e);

/* Record "what: strerror(e)" and return the mapped code. */
xf_err xf__os_fail(xf_os_error *err, int e, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;

/* Record a failure that is not the OS's. */
xf_err xf__fail(xf_os_error *err, xf_err code, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;

/* snprintf() that returns a size_t (the whole text's length) and never a negative length; writes
 * nothing when @p cap is 0 (buf may then be NULL). */
size_t xf__print(char *buf, size_t cap, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;

int xf__set_nonblock(int fd);

/* Wait until fd is writable, at most timeout_ms: 1 ready, 0 timeout, -1 error. */
int xf__wait_writable(int fd, int timeout_ms);

/* Write all of len bytes to a non-blocking fd within timeout_ms; returns 0 or an errno. */
int xf__write_all(int fd, const uint8_t *data, size_t len, int timeout_ms, int is_socket);

#endif
