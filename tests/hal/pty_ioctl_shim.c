/*
 * pty_ioctl_shim.c - TEST-ONLY LD_PRELOAD shim: modem-control ioctls on ptys.
 *
 * libserialport's sp_open() reads and sets the modem lines (TIOCMGET,
 * TIOCMSET, TIOCMBIS, TIOCMBIC), which a pseudo-terminal does not have:
 * the kernel answers ENOTTY and sp_open() fails. test_serial_lsp preloads
 * this library so that libserialport's own code path can run against a
 * real pty: on a Unix98 pty slave those four requests succeed and act on a
 * simulated set of lines; every other request, and every other
 * descriptor, goes to the real ioctl() unchanged.
 *
 * Setting XFGCU_PTY_SHIM_OFF in the environment turns the shim off (the
 * test uses it to see the termios fallback). Built without sanitizers:
 * it runs inside whatever process preloads it. Never installed.
 */
#define _GNU_SOURCE /* RTLD_NEXT */
#include <dlfcn.h>
#include <errno.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <sys/ioctl.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <sys/types.h>

/* glibc's signature: int ioctl(int fd, unsigned long request, ...). */
int ioctl(int fd, unsigned long request, ...);

/* Looked up by the test (dlsym) to make sure the shim is in the process. */
int xfgcu_pty_shim_marker(void);
int xfgcu_pty_shim_marker(void) { return 1; }

typedef int (*ioctl_fn)(int, unsigned long, ...);

static int lines = TIOCM_DTR | TIOCM_RTS | TIOCM_CTS | TIOCM_DSR;

/* A Unix98 pty slave (majors 136..143 on Linux)? */
static int is_pty_slave(int fd)
{
    struct stat st;
    if (fstat(fd, &st) != 0 || !S_ISCHR(st.st_mode)) {
        return 0;
    }
    return major(st.st_rdev) >= 136u && major(st.st_rdev) <= 143u;
}

int ioctl(int fd, unsigned long request, ...)
{
    static ioctl_fn real = NULL;
    va_list ap;
    void *arg;
    va_start(ap, request);
    arg = va_arg(ap, void *);
    va_end(ap);
    if (real == NULL) {
        /* POSIX makes dlsym's answer a function's address; ISO C has no conversion from an
         * object pointer to a function pointer, so its bits are copied. */
        void *sym = dlsym(RTLD_NEXT, "ioctl");
        memcpy(&real, &sym, sizeof(real));
        if (sym == NULL) {
            errno = ENOSYS;
            return -1;
        }
    }
    if ((request == TIOCMGET || request == TIOCMSET || request == TIOCMBIS || request == TIOCMBIC) &&
        getenv("XFGCU_PTY_SHIM_OFF") == NULL && is_pty_slave(fd)) {
        int *bits = (int *)arg;
        if (bits == NULL) {
            errno = EFAULT;
            return -1;
        }
        switch (request) {
        case TIOCMGET: *bits = lines; break;
        case TIOCMSET: lines = *bits | TIOCM_CTS | TIOCM_DSR; break;
        case TIOCMBIS: lines |= *bits; break;
        default: lines &= ~*bits; break;
        }
        return 0;
    }
    return real(fd, request, arg);
}
