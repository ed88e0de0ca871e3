/*
 * test_udp.c - the UDP link on loopback sockets.
 *
 * A plain socket bound to 127.0.0.1:<ephemeral> plays the GCU; the link
 * binds 127.0.0.1:<ephemeral> (local_port 0) and sends to it. Nothing
 * leaves the loopback interface.
 */
#define _GNU_SOURCE
#include <arpa/inet.h>
#include <errno.h>
#include <netinet/in.h>
#include <sched.h>
#include <signal.h>
#include <stdlib.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include "hal_test.h"

typedef struct fixture {
    int gcu; /* the "GCU" socket */
    uint16_t gcu_port;
    xf_udp u;
    xf_hal hal;
} fixture;

/* A UDP socket bound to @p host (127.0.0.1 or ::1) port 0; its port in *port. */
static int bound_socket(int family, const char *host, uint16_t *port)
{
    struct sockaddr_storage ss;
    socklen_t len;
    int fd = socket(family, SOCK_DGRAM | SOCK_NONBLOCK, 0);
    if (fd < 0) {
        return -1;
    }
    memset(&ss, 0, sizeof(ss));
    if (family == AF_INET6) {
        struct sockaddr_in6 *a = (struct sockaddr_in6 *)(void *)&ss;
        a->sin6_family = AF_INET6;
        (void)inet_pton(AF_INET6, host, &a->sin6_addr);
        len = sizeof(*a);
    } else {
        struct sockaddr_in *a = (struct sockaddr_in *)(void *)&ss;
        a->sin_family = AF_INET;
        (void)inet_pton(AF_INET, host, &a->sin_addr);
        len = sizeof(*a);
    }
    if (bind(fd, (struct sockaddr *)&ss, len) != 0) {
        close(fd);
        return -1;
    }
    len = sizeof(ss);
    if (getsockname(fd, (struct sockaddr *)&ss, &len) != 0) {
        close(fd);
        return -1;
    }
    *port = (family == AF_INET6) ? ntohs(((struct sockaddr_in6 *)(void *)&ss)->sin6_port)
                                 : ntohs(((struct sockaddr_in *)(void *)&ss)->sin_port);
    return fd;
}

/* Send one datagram from @p fd to 127.0.0.1:@p port. */
static void send_to(int fd, uint16_t port, const uint8_t *data, size_t len)
{
    struct sockaddr_in a;
    memset(&a, 0, sizeof(a));
    a.sin_family = AF_INET;
    a.sin_port = htons(port);
    a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    assert_int_equal(sendto(fd, data, len, 0, (const struct sockaddr *)&a, sizeof(a)), (ssize_t)len);
}

static void link_config(const fixture *f, xf_udp_config *cfg)
{
    xf_udp_config_init(cfg);
    cfg->gcu_host = "127.0.0.1";
    cfg->gcu_port = f->gcu_port;
    cfg->local_host = "127.0.0.1";
    cfg->local_port = 0;
}

static int setup(void **state)
{
    fixture *f = calloc(1, sizeof(*f));
    xf_udp_config cfg;
    if (f == NULL) {
        return -1;
    }
    f->u.fd = -1;
    f->gcu = bound_socket(AF_INET, "127.0.0.1", &f->gcu_port);
    if (f->gcu < 0) {
        free(f);
        return -1;
    }
    link_config(f, &cfg);
    if (xf_udp_open(&f->u, &cfg) != XF_OK) {
        print_error("xf_udp_open: %s\n", f->u.error.text);
        close(f->gcu);
        free(f);
        return -1;
    }
    xf_udp_hal(&f->u, &f->hal);
    *state = f;
    return 0;
}

static int teardown(void **state)
{
    fixture *f = *state;
    xf_udp_close(&f->u);
    close(f->gcu);
    free(f);
    return 0;
}

static void test_config_defaults(void **state)
{
    xf_udp_config cfg;
    (void)state;
    memset(&cfg, 0xA5, sizeof(cfg));
    xf_udp_config_init(&cfg);
    assert_string_equal(cfg.gcu_host, "192.168.144.108");
    assert_int_equal(cfg.gcu_port, 2337);
    assert_int_equal(cfg.local_port, 2338);
    assert_null(cfg.local_host);
    assert_int_equal(cfg.accept_any, 0);
    assert_int_equal(cfg.broadcast, 0);
    xf_udp_config_init(NULL); /* harmless */
}

/* Each write is exactly one datagram, from the link's port, with the bytes. */
static void test_write_one_datagram(void **state)
{
    fixture *f = *state;
    uint8_t pkt[XF_PACKET_LIMIT], got[1024];
    struct sockaddr_in from;
    socklen_t from_len = sizeof(from);
    size_t len = ht_host_packet(pkt, sizeof(pkt), 555);
    ssize_t r;
    assert_true(f->u.local_port != 0);
    assert_int_equal(f->u.stats.opens, 1);
    assert_xf(f->hal.write(f->hal.ctx, pkt, len), XF_OK);
    assert_true(ht_wait_readable(f->gcu, 1000));
    r = recvfrom(f->gcu, got, sizeof(got), 0, (struct sockaddr *)&from, &from_len);
    assert_int_equal(r, (ssize_t)len);
    assert_memory_equal(got, pkt, len);
    assert_int_equal(ntohs(from.sin_port), f->u.local_port);
    assert_int_equal(ntohl(from.sin_addr.s_addr), INADDR_LOOPBACK);
    /* and nothing more */
    r = recv(f->gcu, got, sizeof(got), 0);
    assert_int_equal(r, -1);
    assert_true(errno == EAGAIN || errno == EWOULDBLOCK);
    assert_int_equal(f->u.stats.packets_tx, 1);
    assert_int_equal(f->u.stats.bytes_tx, len);
}

/* Three datagrams waiting: one read returns them all, whole and in order. */
static void test_read_coalesces_datagrams(void **state)
{
    fixture *f = *state;
    uint8_t pkt[3][XF_PACKET_LIMIT], buf[1024];
    size_t len[3], n = 0, i;
    ht_sink sink;
    for (i = 0; i < 3; i++) {
        len[i] = ht_gcu_packet(pkt[i], sizeof(pkt[i]), (uint16_t)(100u + i));
        send_to(f->gcu, f->u.local_port, pkt[i], len[i]);
    }
    assert_true(ht_wait_readable(f->u.fd, 1000));
    assert_xf(f->hal.read(f->hal.ctx, buf, sizeof(buf), &n), XF_OK);
    assert_int_equal(n, len[0] + len[1] + len[2]);
    ht_sink_init(&sink, XF_DIR_GCU);
    ht_sink_feed(&sink, buf, n);
    assert_int_equal(sink.frames, 3);
    for (i = 0; i < 3; i++) {
        ht_assert_frame(&sink, i, pkt[i], len[i]);
    }
    assert_int_equal(sink.parser.stats.bytes_skipped, 0);
    assert_int_equal(f->u.stats.bytes_rx, n);
    /* nothing left */
    assert_xf(f->hal.read(f->hal.ctx, buf, sizeof(buf), &n), XF_OK);
    assert_int_equal(n, 0);
}

/* A buffer with room for less than a packet still gets one datagram per read. */
static void test_read_small_buffer(void **state)
{
    fixture *f = *state;
    uint8_t pkt[2][XF_PACKET_LIMIT], buf[100];
    size_t len[2], n = 0;
    len[0] = ht_gcu_packet(pkt[0], sizeof(pkt[0]), 1);
    len[1] = ht_gcu_packet(pkt[1], sizeof(pkt[1]), 2);
    send_to(f->gcu, f->u.local_port, pkt[0], len[0]);
    send_to(f->gcu, f->u.local_port, pkt[1], len[1]);
    assert_true(ht_wait_readable(f->u.fd, 1000));
    assert_xf(f->hal.read(f->hal.ctx, buf, sizeof(buf), &n), XF_OK);
    assert_int_equal(n, len[0]);
    assert_memory_equal(buf, pkt[0], len[0]);
    assert_xf(f->hal.read(f->hal.ctx, buf, sizeof(buf), &n), XF_OK);
    assert_int_equal(n, len[1]);
    assert_memory_equal(buf, pkt[1], len[1]);
}

/* A datagram from any other source (same address, other port) is dropped and counted. */
static void test_foreign_source_ignored(void **state)
{
    fixture *f = *state;
    uint8_t pkt[XF_PACKET_LIMIT], other[XF_PACKET_LIMIT], buf[1024];
    size_t len = ht_gcu_packet(pkt, sizeof(pkt), 77), olen = ht_gcu_packet(other, sizeof(other), 66), n = 99;
    uint16_t foreign_port = 0;
    int foreign = bound_socket(AF_INET, "127.0.0.1", &foreign_port);
    assert_true(foreign >= 0);

    send_to(foreign, f->u.local_port, other, olen);
    assert_true(ht_wait_readable(f->u.fd, 1000));
    assert_xf(f->hal.read(f->hal.ctx, buf, sizeof(buf), &n), XF_OK);
    assert_int_equal(n, 0);
    assert_int_equal(f->u.stats.foreign, 1);
    assert_int_equal(f->u.stats.bytes_rx, 0);

    /* foreign, then the GCU: only the GCU's bytes come out */
    send_to(foreign, f->u.local_port, other, olen);
    send_to(f->gcu, f->u.local_port, pkt, len);
    n = ht_hal_read_until(&f->hal, buf, len, 5000, NULL);
    assert_int_equal(n, len);
    assert_memory_equal(buf, pkt, len);
    assert_int_equal(f->u.stats.foreign, 2);
    close(foreign);
}

/* With accept_any, the same foreign datagram is delivered. */
static void test_accept_any(void **state)
{
    fixture *f = *state;
    xf_udp any;
    xf_udp_config cfg;
    xf_hal hal;
    uint8_t other[XF_PACKET_LIMIT], buf[1024];
    size_t olen = ht_gcu_packet(other, sizeof(other), 66), n = 0;
    uint16_t foreign_port = 0;
    int foreign = bound_socket(AF_INET, "127.0.0.1", &foreign_port);
    assert_true(foreign >= 0);
    link_config(f, &cfg);
    cfg.accept_any = 1;
    assert_xf(xf_udp_open(&any, &cfg), XF_OK);
    xf_udp_hal(&any, &hal);
    send_to(foreign, any.local_port, other, olen);
    n = ht_hal_read_until(&hal, buf, olen, 5000, NULL);
    assert_int_equal(n, olen);
    assert_memory_equal(buf, other, olen);
    assert_int_equal(any.stats.foreign, 0);
    xf_udp_close(&any);
    close(foreign);
}

/* A UDP socket bound to 127.0.0.2:@p port (the loopback net is all of 127/8 on Linux). */
static int socket_at_127_0_0_2(uint16_t port)
{
    struct sockaddr_in a;
    int fd = socket(AF_INET, SOCK_DGRAM | SOCK_NONBLOCK, 0);
    if (fd < 0) {
        return -1;
    }
    memset(&a, 0, sizeof(a));
    a.sin_family = AF_INET;
    a.sin_port = htons(port);
    (void)inet_pton(AF_INET, "127.0.0.2", &a.sin_addr);
    if (bind(fd, (struct sockaddr *)&a, sizeof(a)) != 0) {
        close(fd);
        return -1;
    }
    return fd;
}

/* With `broadcast` the GCU's address is unknown (the host sends to a
 * broadcast address): a reply from any address is the GCU's when it comes
 * from the GCU's port, and foreign otherwise. */
static void test_broadcast_takes_gcu_port_from_any_address(void **state)
{
    fixture *f = *state;
    xf_udp bc;
    xf_udp_config cfg;
    xf_hal hal;
    uint8_t pkt[XF_PACKET_LIMIT], other[XF_PACKET_LIMIT], buf[1024];
    size_t len = ht_gcu_packet(pkt, sizeof(pkt), 12), olen = ht_gcu_packet(other, sizeof(other), 34), n = 0;
    uint16_t foreign_port = 0;
    int gcu_elsewhere = socket_at_127_0_0_2(f->gcu_port);
    int foreign = bound_socket(AF_INET, "127.0.0.1", &foreign_port);
    assert_true(gcu_elsewhere >= 0);
    assert_true(foreign >= 0);
    link_config(f, &cfg);
    cfg.broadcast = 1;
    assert_xf(xf_udp_open(&bc, &cfg), XF_OK);
    xf_udp_hal(&bc, &hal);

    send_to(foreign, bc.local_port, other, olen);    /* right address, wrong port */
    send_to(gcu_elsewhere, bc.local_port, pkt, len); /* other address, the GCU's port */
    n = ht_hal_read_until(&hal, buf, len, 5000, NULL);
    assert_int_equal(n, len);
    assert_memory_equal(buf, pkt, len);
    assert_int_equal(bc.stats.foreign, 1);
    xf_udp_close(&bc);
    close(gcu_elsewhere);
    close(foreign);
}

/* A second link on a port in use: XF_ERR_BUSY, and the text names the port. */
static void test_port_in_use(void **state)
{
    fixture *f = *state;
    xf_udp second;
    xf_udp_config cfg;
    char port[16];
    link_config(f, &cfg);
    cfg.local_port = f->u.local_port;
    assert_xf(xf_udp_open(&second, &cfg), XF_ERR_BUSY);
    assert_int_equal(second.error.os_errno, EADDRINUSE);
    snprintf(port, sizeof(port), "%u", (unsigned)f->u.local_port);
    assert_contains(second.error.text, port);
    assert_contains(second.error.text, "in use");
    assert_int_equal(second.fd, -1);
    assert_int_equal(second.stats.opens, 0);
}

static void test_bad_host(void **state)
{
    fixture *f = *state;
    xf_udp bad;
    xf_udp_config cfg;
    link_config(f, &cfg);
    /* Spaces and '!' make glibc reject the name itself: no DNS query leaves the machine. */
    cfg.gcu_host = "no such gcu!.invalid";
    assert_xf(xf_udp_open(&bad, &cfg), XF_ERR_NOT_FOUND);
    assert_contains(bad.error.text, "no such gcu!.invalid");
    assert_int_equal(bad.fd, -1);
    link_config(f, &cfg);
    cfg.local_host = "bad local host!";
    assert_xf(xf_udp_open(&bad, &cfg), XF_ERR_NOT_FOUND);
    assert_contains(bad.error.text, "bad local host!");
    assert_int_equal(bad.fd, -1);
    assert_xf(xf_udp_open(NULL, &cfg), XF_ERR_ARG);
}

static void test_closed(void **state)
{
    fixture *f = *state;
    uint8_t buf[8] = {0};
    size_t n = 3;
    xf_udp_close(&f->u);
    assert_int_equal(xf_hal_fd(&f->hal), -1);
    assert_xf(f->hal.write(f->hal.ctx, buf, sizeof(buf)), XF_ERR_CLOSED);
    assert_xf(f->hal.read(f->hal.ctx, buf, sizeof(buf), &n), XF_ERR_CLOSED);
    assert_int_equal(n, 0);
    xf_udp_close(&f->u); /* twice is harmless */
}

/* The same over IPv6 loopback (skipped where ::1 is not configured). */
static void test_ipv6_loopback(void **state)
{
    xf_udp u;
    xf_udp_config cfg;
    xf_hal hal;
    uint8_t pkt[XF_PACKET_LIMIT], buf[1024];
    struct sockaddr_in6 to;
    size_t len = ht_gcu_packet(pkt, sizeof(pkt), 6), n;
    uint16_t gport = 0;
    int g = bound_socket(AF_INET6, "::1", &gport);
    (void)state;
    if (g < 0) {
        skip();
    }
    xf_udp_config_init(&cfg);
    cfg.gcu_host = "::1";
    cfg.gcu_port = gport;
    cfg.local_host = "::1";
    cfg.local_port = 0;
    assert_xf(xf_udp_open(&u, &cfg), XF_OK);
    xf_udp_hal(&u, &hal);
    assert_xf(hal.write(hal.ctx, pkt, len), XF_OK);
    assert_true(ht_wait_readable(g, 1000));
    assert_int_equal(recv(g, buf, sizeof(buf), 0), (ssize_t)len);
    assert_memory_equal(buf, pkt, len);
    memset(&to, 0, sizeof(to));
    to.sin6_family = AF_INET6;
    to.sin6_port = htons(u.local_port);
    to.sin6_addr = in6addr_loopback;
    assert_int_equal(sendto(g, pkt, len, 0, (const struct sockaddr *)&to, sizeof(to)), (ssize_t)len);
    n = ht_hal_read_until(&hal, buf, len, 5000, NULL);
    assert_int_equal(n, len);
    assert_memory_equal(buf, pkt, len);
    assert_int_equal(u.stats.foreign, 0);
    xf_udp_close(&u);
    close(g);
}

/*
 * A send the kernel refuses returns XF_ERR_IO, the only failure xf_hal
 * allows a write besides AGAIN and CLOSED (not the errno's own mapping,
 * e.g. XF_ERR_NOT_FOUND for ENETUNREACH), with the reason in the text.
 * Provoked in a child in a fresh network namespace, whose loopback is
 * down: sending to 127.0.0.1 there fails with ENETUNREACH, and nothing can
 * leave the namespace.
 */
enum { SEND_OK = 0, SEND_WRONG_CODE = 1, SEND_WRONG_TEXT = 2, SEND_SKIP = 3 };

static int send_error_child(void)
{
    xf_udp u;
    xf_udp_config cfg;
    xf_hal hal;
    uint8_t pkt[XF_PACKET_LIMIT];
    size_t len = ht_host_packet(pkt, sizeof(pkt), 1);
    xf_err err;
    if (unshare(CLONE_NEWNET) != 0) {
        return SEND_SKIP;
    }
    xf_udp_config_init(&cfg);
    cfg.gcu_host = "127.0.0.1";
    cfg.local_port = 0; /* any address: 127.0.0.1 is not up in here */
    if (xf_udp_open(&u, &cfg) != XF_OK) {
        fprintf(stderr, "child: xf_udp_open: %s\n", u.error.text);
        return SEND_SKIP;
    }
    xf_udp_hal(&u, &hal);
    err = hal.write(hal.ctx, pkt, len);
    if (err != XF_ERR_IO) {
        fprintf(stderr, "child: write: %d (%s): %s\n", (int)err, xf_strerror(err), u.error.text);
        return SEND_WRONG_CODE;
    }
    if (u.error.os_errno != ENETUNREACH || strstr(u.error.text, "send UDP datagram") == NULL) {
        fprintf(stderr, "child: error text: %s\n", u.error.text);
        return SEND_WRONG_TEXT;
    }
    xf_udp_close(&u);
    return SEND_OK;
}

static void test_send_error_is_io(void **state)
{
    int code;
    (void)state;
    code = ht_run_child(send_error_child);
    if (code == SEND_SKIP) {
        skip(); /* no network namespace here (not root): nothing to test */
    }
    assert_int_equal(code, SEND_OK);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_config_defaults),
        cmocka_unit_test_setup_teardown(test_write_one_datagram, setup, teardown),
        cmocka_unit_test_setup_teardown(test_read_coalesces_datagrams, setup, teardown),
        cmocka_unit_test_setup_teardown(test_read_small_buffer, setup, teardown),
        cmocka_unit_test_setup_teardown(test_foreign_source_ignored, setup, teardown),
        cmocka_unit_test_setup_teardown(test_accept_any, setup, teardown),
        cmocka_unit_test_setup_teardown(test_broadcast_takes_gcu_port_from_any_address, setup, teardown),
        cmocka_unit_test_setup_teardown(test_port_in_use, setup, teardown),
        cmocka_unit_test_setup_teardown(test_bad_host, setup, teardown),
        cmocka_unit_test_setup_teardown(test_closed, setup, teardown),
        cmocka_unit_test(test_ipv6_loopback),
        cmocka_unit_test(test_send_error_is_io),
    };
    return cmocka_run_group_tests_name("udp (loopback)", tests, NULL, NULL);
}
