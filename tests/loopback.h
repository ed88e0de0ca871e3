/*
 * loopback.h - a socket bound on 127.0.0.1 at a free port, for the tests that play a GCU or hold
 * a port over loopback: the links' (tests/hal) and the program's (tools/tests). Include it after
 * cmocka.h.
 */
#ifndef XFGCU_TEST_LOOPBACK_H
#define XFGCU_TEST_LOOPBACK_H

#include <arpa/inet.h>
#include <netinet/in.h>
#include <stdint.h>
#include <string.h>
#include <sys/socket.h>

/* A socket of @p type (SOCK_DGRAM, SOCK_STREAM) bound to 127.0.0.1, any free port (in *port); not
 * listening. */
static inline int test_loopback_socket(int type, uint16_t *port)
{
    struct sockaddr_in a;
    socklen_t len = sizeof(a);
    int fd = socket(AF_INET, type, 0);
    assert_true(fd >= 0);
    memset(&a, 0, sizeof(a));
    a.sin_family = AF_INET;
    a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    assert_int_equal(bind(fd, (struct sockaddr *)&a, sizeof(a)), 0);
    assert_int_equal(getsockname(fd, (struct sockaddr *)&a, &len), 0);
    *port = ntohs(a.sin_port);
    return fd;
}

#endif
