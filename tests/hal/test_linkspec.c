/*
 * test_linkspec.c - links from spec strings with xfgcu::linkspec alone.
 *
 * This program links xfgcu::linkspec and nothing above it (no client, no simulator, no poll loop),
 * so it builds only while a spec link needs the links alone. Plain loopback sockets play the GCU;
 * packets go both ways through the xf_hal that xf_link_hal() gives.
 */
#define _GNU_SOURCE
#include "hal_test.h"
#include "xfgcu/posix/xf_link.h"

#include "../loopback.h" /* after cmocka.h, which hal_test.h includes */

/* A socket of @p type on 127.0.0.1, any free port (in *port); listening when a stream. */
static int loopback_socket(int type, uint16_t *port)
{
    int fd = test_loopback_socket(type, port);
    if (type == SOCK_STREAM) {
        assert_int_equal(listen(fd, 1), 0);
    }
    return fd;
}

/* A host packet through the link's hal reaches @p gcu_fd whole. */
static void check_host_to_gcu(const xf_hal *hal, int gcu_fd)
{
    uint8_t pkt[XF_PACKET_MAX_LEN], got[XF_PACKET_MAX_LEN];
    size_t len = ht_host_packet(pkt, sizeof(pkt), 1234);
    assert_true(len > 0u);
    assert_int_equal(hal->write(hal->ctx, pkt, len), XF_OK);
    assert_int_equal(ht_read_fd_until(gcu_fd, got, len, 2000u), len);
    assert_memory_equal(got, pkt, len);
}

/* A GCU packet sent to the link arrives through its hal whole. */
static void check_gcu_to_host(const xf_hal *hal, int gcu_fd, const struct sockaddr *to, socklen_t to_len)
{
    uint8_t pkt[XF_PACKET_MAX_LEN], got[XF_PACKET_MAX_LEN];
    size_t len = ht_gcu_packet(pkt, sizeof(pkt), 77);
    assert_true(len > 0u);
    assert_int_equal(sendto(gcu_fd, pkt, len, 0, to, to_len), (ssize_t)len);
    assert_int_equal(ht_hal_read_until(hal, got, len, 2000u, NULL), len);
    assert_memory_equal(got, pkt, len);
}

static void test_udp_spec(void **state)
{
    char spec[64];
    uint16_t port = 0;
    int gcu = loopback_socket(SOCK_DGRAM, &port);
    xf_link l;
    xf_hal hal;
    struct sockaddr_in host;
    (void)state;
    memset(&l, 0, sizeof(l));
    (void)snprintf(spec, sizeof(spec), "udp:127.0.0.1:%u,local=0", (unsigned)port);
    assert_int_equal(xf_link_open(&l, spec), XF_OK);
    assert_int_equal(xf_link_hal(&l, &hal), XF_OK);
    check_host_to_gcu(&hal, gcu);
    memset(&host, 0, sizeof(host));
    host.sin_family = AF_INET;
    host.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    host.sin_port = htons(l.as.udp.local_port);
    check_gcu_to_host(&hal, gcu, (const struct sockaddr *)&host, sizeof(host));
    xf_link_close(&l);
    close(gcu);
}

static void test_tcp_spec(void **state)
{
    char spec[64];
    uint16_t port = 0;
    int server = loopback_socket(SOCK_STREAM, &port);
    int conn;
    xf_link l;
    xf_hal hal;
    (void)state;
    memset(&l, 0, sizeof(l));
    (void)snprintf(spec, sizeof(spec), "tcp:127.0.0.1:%u", (unsigned)port);
    assert_int_equal(xf_link_open(&l, spec), XF_OK);
    assert_int_equal(xf_link_wait(&l, 2000u), XF_OK);
    assert_true(ht_wait_readable(server, 2000));
    conn = accept(server, NULL, NULL);
    assert_true(conn >= 0);
    assert_int_equal(xf_link_hal(&l, &hal), XF_OK);
    check_host_to_gcu(&hal, conn);
    check_gcu_to_host(&hal, conn, NULL, 0);
    xf_link_close(&l);
    close(conn);
    close(server);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_udp_spec),
        cmocka_unit_test(test_tcp_spec),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
