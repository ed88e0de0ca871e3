/*
 * pty_util.h - real pseudo-terminals for the serial tests: the master plays
 * the GCU, the link opens the slave.
 */
#ifndef XFGCU_PTY_UTIL_H
#define XFGCU_PTY_UTIL_H

#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

typedef struct ht_pty {
    int master;      /* non-blocking */
    char slave[128]; /* /dev/pts/N */
} ht_pty;

/* A new pty pair; 0 or -1. The slave stays closed until the link opens it. */
static inline int ht_pty_open(ht_pty *p)
{
    const char *name;
    p->master = posix_openpt(O_RDWR | O_NOCTTY);
    p->slave[0] = '\0';
    if (p->master < 0) {
        return -1;
    }
    if (grantpt(p->master) != 0 || unlockpt(p->master) != 0 || (name = ptsname(p->master)) == NULL ||
        strlen(name) >= sizeof(p->slave)) {
        close(p->master);
        p->master = -1;
        return -1;
    }
    snprintf(p->slave, sizeof(p->slave), "%s", name);
    (void)fcntl(p->master, F_SETFL, fcntl(p->master, F_GETFL) | O_NONBLOCK);
    return 0;
}

/* Close the master: the slave side sees a hang-up. */
static inline void ht_pty_close(ht_pty *p)
{
    if (p->master >= 0) {
        close(p->master);
        p->master = -1;
    }
}

/* Point the symlink @p link at @p target atomically (new link, then rename over). */
static inline int ht_repoint(const char *link, const char *target)
{
    char tmp[512];
    snprintf(tmp, sizeof(tmp), "%s.new", link);
    (void)unlink(tmp);
    if (symlink(target, tmp) != 0) {
        return -1;
    }
    if (rename(tmp, link) != 0) {
        (void)unlink(tmp);
        return -1;
    }
    return 0;
}

#endif /* XFGCU_PTY_UTIL_H */
