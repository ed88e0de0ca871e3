/*
 * test_tcp.c - the TCP link against a loopback server run by the test.
 *
 * The test listens on 127.0.0.1:<ephemeral> (SO_REUSEADDR, so it can
 * listen again on the same port after a "restart") and plays the GCU's
 * single-client server. Nothing leaves the loopback interface: the connect
 * timeout is provoked with a listener whose accept queue is full (the
 * kernel then drops SYNs), never with an unroutable address.
 */
#define _GNU_SOURCE
#include <arpa/inet.h>
#include <errno.h>
#include <fcntl.h>
#include <net/if.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <sched.h>
#include <signal.h>
#include <stdlib.h>
#include <sys/ioctl.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include "hal_test.h"

typedef struct fixture {
    int lfd; /* listener, -1 while "down" */
    int cfd; /* accepted connection */
    uint16_t port;
    xf_tcp t;
    xf_hal hal;
} fixture;

/* Listen on 127.0.0.1:@p port (0: any) with @p backlog; the port in *bound. */
static int listen_on(uint16_t port, int backlog, uint16_t *bound)
{
    struct sockaddr_in a;
    socklen_t len = sizeof(a);
    int one = 1;
    int fd = socket(AF_INET, SOCK_STREAM | SOCK_NONBLOCK, 0);
    if (fd < 0) {
        return -1;
    }
    (void)setsockopt(fd, SOL_SOCKET, SO_REUSEADDR, &one, sizeof(one));
    memset(&a, 0, sizeof(a));
    a.sin_family = AF_INET;
    a.sin_port = htons(port);
    a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    if (bind(fd, (struct sockaddr *)&a, sizeof(a)) != 0 || listen(fd, backlog) != 0 ||
        getsockname(fd, (struct sockaddr *)&a, &len) != 0) {
        close(fd);
        return -1;
    }
    *bound = ntohs(a.sin_port);
    return fd;
}

/* Accept one connection within @p ms; the fd (TCP_NODELAY) or -1. */
static int accept_within(int lfd, uint32_t ms)
{
    uint32_t t0 = ht_now();
    do {
        int fd = accept(lfd, NULL, NULL);
        if (fd >= 0) {
            int one = 1;
            (void)setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &one, sizeof(one));
            return fd;
        }
        (void)ht_wait_readable(lfd, 10);
    } while (ht_since(t0) < ms);
    return -1;
}

static void link_config(uint16_t port, xf_tcp_config *cfg)
{
    xf_tcp_config_init(cfg);
    cfg->host = "127.0.0.1";
    cfg->port = port;
}

/* Open the link on the fixture's listener and accept it. */
static void connect_link(fixture *f)
{
    xf_tcp_config cfg;
    link_config(f->port, &cfg);
    assert_xf(xf_tcp_open(&f->t, &cfg), XF_OK);
    xf_tcp_hal(&f->t, &f->hal);
    assert_xf(xf_tcp_wait(&f->t, 1000), XF_OK);
    assert_int_equal(f->t.state, XF_TCP_UP);
    f->cfd = accept_within(f->lfd, 5000);
    assert_true(f->cfd >= 0);
    assert_true(xf_hal_fd(&f->hal) >= 0);
    assert_int_equal(f->t.stats.opens, 1);
}

static int setup(void **state)
{
    fixture *f = calloc(1, sizeof(*f));
    if (f == NULL) {
        return -1;
    }
    f->cfd = -1;
    f->t.fd = -1;
    f->lfd = listen_on(0, 4, &f->port);
    if (f->lfd < 0) {
        free(f);
        return -1;
    }
    *state = f;
    return 0;
}

static int teardown(void **state)
{
    fixture *f = *state;
    xf_tcp_close(&f->t);
    if (f->cfd >= 0) {
        close(f->cfd);
    }
    if (f->lfd >= 0) {
        close(f->lfd);
    }
    free(f);
    return 0;
}

static void test_config_defaults(void **state)
{
    xf_tcp_config cfg;
    (void)state;
    memset(&cfg, 0xA5, sizeof(cfg));
    xf_tcp_config_init(&cfg);
    assert_string_equal(cfg.host, "192.168.144.108");
    assert_int_equal(cfg.port, 2332);
    assert_int_equal(cfg.connect_timeout_ms, 1000);
    assert_int_equal(cfg.retry_min_ms, 50);
    assert_int_equal(cfg.retry_max_ms, 500);
}

/* A GCU packet sent one byte per send() is parsed whole, after its last byte. */
static void test_byte_by_byte(void **state)
{
    fixture *f = *state;
    uint8_t pkt[XF_PACKET_LIMIT], b;
    size_t len = ht_gcu_packet(pkt, sizeof(pkt), 2024), i;
    ht_sink sink;
    connect_link(f);
    ht_sink_init(&sink, XF_DIR_GCU);
    for (i = 0; i < len; i++) {
        xf_err err = XF_OK;
        assert_int_equal(send(f->cfd, pkt + i, 1, MSG_NOSIGNAL), 1);
        assert_int_equal(ht_hal_read_until(&f->hal, &b, 1, 5000, &err), 1);
        assert_xf(err, XF_OK);
        ht_sink_feed(&sink, &b, 1);
        assert_int_equal(sink.frames, (i + 1 == len) ? 1u : 0u);
    }
    ht_assert_frame(&sink, 0, pkt, len);
    assert_int_equal(f->t.stats.bytes_rx, len);
}

/* Five packets in one send() come out as five frames, in order. */
static void test_five_in_one_send(void **state)
{
    fixture *f = *state;
    uint8_t pkt[5][XF_PACKET_LIMIT], all[5 * XF_PACKET_LIMIT], buf[2048];
    size_t len[5], total = 0, i, first = 0;
    uint32_t t0;
    ht_sink sink;
    connect_link(f);
    for (i = 0; i < 5; i++) {
        len[i] = ht_gcu_packet(pkt[i], sizeof(pkt[i]), (uint16_t)(500u + i));
        memcpy(all + total, pkt[i], len[i]);
        total += len[i];
    }
    assert_int_equal(send(f->cfd, all, total, MSG_NOSIGNAL), (ssize_t)total);
    ht_sink_init(&sink, XF_DIR_GCU);
    t0 = ht_now();
    while (sink.frames < 5 && ht_since(t0) < 5000u) {
        size_t n = 0;
        (void)ht_wait_readable(xf_hal_fd(&f->hal), 10);
        assert_xf(f->hal.read(f->hal.ctx, buf, sizeof(buf), &n), XF_OK);
        if (first == 0) {
            first = n;
        }
        ht_sink_feed(&sink, buf, n);
    }
    assert_int_equal(sink.frames, 5);
    for (i = 0; i < 5; i++) {
        ht_assert_frame(&sink, i, pkt[i], len[i]);
    }
    assert_true(first > len[0]); /* the first read already held more than one packet */
    assert_int_equal(sink.parser.stats.bytes_skipped, 0);
}

/* Host writes arrive at the server byte-exact. */
static void test_host_writes_arrive(void **state)
{
    fixture *f = *state;
    uint8_t pkt[3][XF_PACKET_LIMIT], got[3 * XF_PACKET_LIMIT], want[3 * XF_PACKET_LIMIT];
    size_t len, total = 0, i;
    connect_link(f);
    for (i = 0; i < 3; i++) {
        len = ht_host_packet(pkt[i], sizeof(pkt[i]), (int16_t)(i * 1000));
        assert_xf(f->hal.write(f->hal.ctx, pkt[i], len), XF_OK);
        memcpy(want + total, pkt[i], len);
        total += len;
    }
    assert_int_equal(ht_read_fd_until(f->cfd, got, total, 1000), total);
    assert_memory_equal(got, want, total);
    assert_int_equal(f->t.stats.packets_tx, 3);
    assert_int_equal(f->t.stats.bytes_tx, total);
}

/* Read until the link reports XF_ERR_CLOSED, at most @p ms: 1 if it did. */
static int read_until_closed(fixture *f, uint32_t ms)
{
    uint32_t t0 = ht_now();
    while (ht_since(t0) < ms) {
        uint8_t buf[64];
        size_t n = 99;
        xf_err err = f->hal.read(f->hal.ctx, buf, sizeof(buf), &n);
        if (err == XF_ERR_CLOSED) {
            assert_int_equal(n, 0);
            return 1;
        }
        assert_xf(err, XF_OK);
        ht_sleep_ms(2);
    }
    return 0;
}

/* The server closes the connection: XF_ERR_CLOSED, one loss, the reason in the text. */
static void test_server_closes(void **state)
{
    fixture *f = *state;
    uint8_t pkt[XF_PACKET_LIMIT];
    size_t len = ht_host_packet(pkt, sizeof(pkt), 1);
    connect_link(f);
    close(f->cfd);
    f->cfd = -1;
    assert_true(read_until_closed(f, 1000));
    assert_int_equal(f->t.stats.losses, 1);
    assert_contains(f->t.error.text, "closed the connection");
    assert_int_equal(xf_hal_fd(&f->hal), -1);
    assert_int_not_equal(f->t.state, XF_TCP_UP);
    /* down until it reconnects: writes say so */
    assert_xf(f->hal.write(f->hal.ctx, pkt, len), XF_ERR_CLOSED);
}

/* Server down ~300 ms, then back on the same port: the link is back within 1 s. */
static void test_server_restart(void **state)
{
    fixture *f = *state;
    uint8_t pkt[XF_PACKET_LIMIT], buf[XF_PACKET_LIMIT];
    size_t len, n;
    uint32_t t0, took;
    uint16_t again = 0;
    xf_err err;
    connect_link(f);

    /* down: no listener, and the connection closed */
    close(f->lfd);
    f->lfd = -1;
    close(f->cfd);
    f->cfd = -1;
    assert_true(read_until_closed(f, 1000));
    assert_int_equal(f->t.stats.losses, 1);
    t0 = ht_now();
    while (ht_since(t0) < 300u) {
        n = 0;
        assert_xf(f->hal.read(f->hal.ctx, buf, sizeof(buf), &n), XF_ERR_CLOSED);
        ht_sleep_ms(10);
    }
    assert_int_equal(f->t.stats.opens, 1);
    assert_contains(f->t.error.text, "refused"); /* the attempts meanwhile */

    /* back: measure from listen() until accept() succeeds, polling the link every 10 ms */
    f->lfd = listen_on(f->port, 4, &again);
    assert_true(f->lfd >= 0);
    assert_int_equal(again, f->port);
    t0 = ht_now();
    while (f->cfd < 0 && ht_since(t0) < 5000u) {
        n = 0;
        err = f->hal.read(f->hal.ctx, buf, sizeof(buf), &n);
        assert_true(err == XF_OK || err == XF_ERR_CLOSED);
        f->cfd = accept(f->lfd, NULL, NULL);
        if (f->cfd < 0) {
            ht_sleep_ms(10);
        }
    }
    took = ht_since(t0);
    assert_true(f->cfd >= 0);
    if (took >= 3000u) { /* the back-off is at most retry_max_ms (500); the rest is the machine's load */
        fail_msg("reconnected after %u ms, expected < 3000 ms", (unsigned)took);
    }
    print_message("reconnected %u ms after the server listened again\n", (unsigned)took);
    /* the link sees its connection up on its next call */
    len = ht_gcu_packet(pkt, sizeof(pkt), 31);
    assert_int_equal(send(f->cfd, pkt, len, MSG_NOSIGNAL), (ssize_t)len);
    n = ht_hal_read_until(&f->hal, buf, len, 1000, &err);
    assert_xf(err, XF_OK);
    assert_int_equal(n, len);
    assert_memory_equal(buf, pkt, len);
    assert_int_equal(f->t.stats.opens, 2);
    assert_int_equal(f->t.stats.losses, 1);
    len = ht_host_packet(pkt, sizeof(pkt), 32);
    assert_xf(f->hal.write(f->hal.ctx, pkt, len), XF_OK);
    assert_int_equal(ht_read_fd_until(f->cfd, buf, len, 1000), len);
    assert_memory_equal(buf, pkt, len);
}

/* No listener: the wait fails and says "refused". */
static void test_connection_refused(void **state)
{
    fixture *f = *state;
    xf_tcp_config cfg;
    uint32_t t0;
    xf_err err;
    close(f->lfd); /* the port is now free: nobody listens */
    f->lfd = -1;
    link_config(f->port, &cfg);
    assert_xf(xf_tcp_open(&f->t, &cfg), XF_OK);
    xf_tcp_hal(&f->t, &f->hal);
    t0 = ht_now();
    err = xf_tcp_wait(&f->t, 200);
    /* refused attempts leave the link down; a retry may be in flight at the deadline */
    if (err != XF_ERR_CLOSED && err != XF_ERR_TIMEOUT) {
        fail_msg("xf_tcp_wait: %d (%s), expected XF_ERR_CLOSED", (int)err, xf_strerror(err));
    }
    assert_true(ht_since(t0) < 3000u); /* 200 ms, and whatever a loaded machine adds */
    assert_int_equal(f->t.error.os_errno, ECONNREFUSED);
    assert_contains(f->t.error.text, "refused");
    assert_contains(f->t.error.text, "127.0.0.1");
    assert_int_equal(f->t.stats.opens, 0);
    assert_int_equal(f->t.stats.losses, 0); /* never up: nothing lost */
}

static void test_unresolvable_host(void **state)
{
    fixture *f = *state;
    xf_tcp_config cfg;
    link_config(f->port, &cfg);
    /* Spaces and '!' make glibc reject the name itself: no DNS query leaves the machine. */
    cfg.host = "no such gcu!.invalid";
    assert_xf(xf_tcp_open(&f->t, &cfg), XF_ERR_NOT_FOUND);
    assert_contains(f->t.error.text, "no such gcu!.invalid");
    assert_int_equal(f->t.fd, -1);
    /* nothing to wait for, and it never tries */
    assert_xf(xf_tcp_wait(&f->t, 50), XF_ERR_ARG);
    xf_tcp_hal(&f->t, &f->hal);
    assert_xf(f->hal.write(f->hal.ctx, (const uint8_t *)"x", 1), XF_ERR_CLOSED);
    assert_int_equal(f->t.fd, -1);
    assert_xf(xf_tcp_open(NULL, &cfg), XF_ERR_ARG);
}

/*
 * Connect timeout, on loopback: a listener with backlog 0 whose accept
 * queue is filled by other clients drops further SYNs, so the link's
 * attempt gets no answer. Then the queue is drained and the link connects.
 */
static void test_connect_timeout_full_backlog(void **state)
{
    fixture *f = *state;
    int fillers[8];
    size_t nfill = 0, i;
    int full = 0;
    xf_tcp_config cfg;
    uint32_t t0;
    uint16_t port = 0;
    int cfd;
    close(f->lfd);
    f->lfd = listen_on(0, 0, &port);
    assert_true(f->lfd >= 0);

    /* fill the accept queue: connect until a connection stays unanswered */
    while (nfill < sizeof(fillers) / sizeof(fillers[0]) && !full) {
        struct sockaddr_in a;
        int fd = socket(AF_INET, SOCK_STREAM | SOCK_NONBLOCK, 0);
        assert_true(fd >= 0);
        memset(&a, 0, sizeof(a));
        a.sin_family = AF_INET;
        a.sin_port = htons(port);
        a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
        if (connect(fd, (struct sockaddr *)&a, sizeof(a)) != 0) {
            struct pollfd pfd;
            assert_int_equal(errno, EINPROGRESS);
            pfd.fd = fd;
            pfd.events = POLLOUT;
            pfd.revents = 0;
            if (poll(&pfd, 1, 100) == 0) {
                full = 1; /* its SYN was dropped: the queue is full */
                close(fd);
                break;
            }
        }
        fillers[nfill++] = fd;
    }
    if (!full) {
        for (i = 0; i < nfill; i++) {
            close(fillers[i]);
        }
        skip(); /* this kernel does not drop SYNs on a full queue */
    }

    xf_tcp_config_init(&cfg);
    cfg.host = "127.0.0.1";
    cfg.port = port;
    cfg.connect_timeout_ms = 250;
    t0 = ht_now();
    assert_xf(xf_tcp_open(&f->t, &cfg), XF_OK);
    xf_tcp_hal(&f->t, &f->hal);
    /* waiting less than the connect timeout: still connecting */
    assert_xf(xf_tcp_wait(&f->t, 100), XF_ERR_TIMEOUT);
    assert_int_equal(f->t.state, XF_TCP_CONNECTING);
    assert_contains(f->t.error.text, "no answer in 100 ms");
    /* driven by reads, the attempt itself times out after 250 ms */
    while (strstr(f->t.error.text, "no answer in 250 ms") == NULL && ht_since(t0) < 5000u) {
        uint8_t b;
        size_t n = 0;
        assert_xf(f->hal.read(f->hal.ctx, &b, 1, &n), XF_ERR_CLOSED);
        ht_sleep_ms(5);
    }
    assert_contains(f->t.error.text, "no answer in 250 ms");
    assert_true(ht_since(t0) >= 240u);
    assert_int_equal(f->t.stats.opens, 0);

    /* drain the queue: the link's next attempt goes through */
    for (i = 0; i < nfill; i++) {
        cfd = accept_within(f->lfd, 200);
        if (cfd >= 0) {
            close(cfd);
        }
        close(fillers[i]);
    }
    assert_xf(xf_tcp_wait(&f->t, 2000), XF_OK);
    f->cfd = accept_within(f->lfd, 5000);
    assert_true(f->cfd >= 0);
    assert_int_equal(f->t.stats.opens, 1);
}

static void test_closed_by_application(void **state)
{
    fixture *f = *state;
    uint8_t b = 0;
    size_t n = 4;
    connect_link(f);
    xf_tcp_close(&f->t);
    assert_int_equal(xf_hal_fd(&f->hal), -1);
    ht_sleep_ms(60); /* past the first back-off: still no reconnecting */
    assert_xf(f->hal.read(f->hal.ctx, &b, 1, &n), XF_ERR_CLOSED);
    assert_int_equal(n, 0);
    assert_xf(f->hal.write(f->hal.ctx, &b, 1), XF_ERR_CLOSED);
    assert_int_equal(f->t.stats.opens, 1);
    assert_int_equal(f->t.stats.losses, 0);
    assert_xf(xf_tcp_wait(&f->t, 10), XF_ERR_ARG);
}

/*
 * Self-connect: with nobody listening on a port of the ephemeral range,
 * Linux may hand the connecting socket that same port, and it connects to
 * itself. Forced here in a private network namespace (only its own
 * loopback) whose ephemeral range is that one port; run in a child so the
 * test process keeps its namespace. The link must not count that as up.
 */
enum { SELF_OK = 0, SELF_CONNECTED = 1, SELF_OTHER = 2, SELF_SKIP = 3 };

static int self_connect_child(void)
{
    static const char range[] = "40000 40000\n";
    struct ifreq ifr;
    xf_tcp t;
    xf_tcp_config cfg;
    xf_err err;
    int fd, s;
    if (unshare(CLONE_NEWNET) != 0) {
        return SELF_SKIP;
    }
    s = socket(AF_INET, SOCK_DGRAM, 0);
    memset(&ifr, 0, sizeof(ifr));
    snprintf(ifr.ifr_name, sizeof(ifr.ifr_name), "lo");
    if (s < 0 || ioctl(s, SIOCGIFFLAGS, &ifr) != 0) {
        return SELF_SKIP;
    }
    ifr.ifr_flags = (short)(ifr.ifr_flags | IFF_UP);
    if (ioctl(s, SIOCSIFFLAGS, &ifr) != 0) {
        return SELF_SKIP;
    }
    close(s);
    fd = open("/proc/sys/net/ipv4/ip_local_port_range", O_WRONLY);
    if (fd < 0 || write(fd, range, sizeof(range) - 1) != (ssize_t)(sizeof(range) - 1)) {
        return SELF_SKIP;
    }
    close(fd);
    link_config(40000, &cfg);
    if (xf_tcp_open(&t, &cfg) != XF_OK) {
        return SELF_OTHER;
    }
    /* the first attempt meets itself at once on loopback */
    err = xf_tcp_wait(&t, 30);
    if (err == XF_OK) {
        fprintf(stderr, "child: the link is up, connected to itself\n");
        return SELF_CONNECTED;
    }
    if (strstr(t.error.text, "itself") == NULL || t.stats.opens != 0) {
        fprintf(stderr, "child: %d (%s): %s\n", (int)err, xf_strerror(err), t.error.text);
        return SELF_OTHER;
    }
    /* and never comes up later (the one port may now be in TIME_WAIT) */
    err = xf_tcp_wait(&t, 300);
    if (err == XF_OK || t.stats.opens != 0) {
        fprintf(stderr, "child: later attempt: %d (%s): %s\n", (int)err, xf_strerror(err), t.error.text);
        return SELF_CONNECTED;
    }
    xf_tcp_close(&t);
    return SELF_OK;
}

static void test_self_connect_is_not_up(void **state)
{
    int code;
    (void)state;
    code = ht_run_child(self_connect_child);
    if (code == SELF_SKIP) {
        skip(); /* no network namespace here (not root): nothing to test */
    }
    assert_int_equal(code, SELF_OK);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_config_defaults),
        cmocka_unit_test_setup_teardown(test_byte_by_byte, setup, teardown),
        cmocka_unit_test_setup_teardown(test_five_in_one_send, setup, teardown),
        cmocka_unit_test_setup_teardown(test_host_writes_arrive, setup, teardown),
        cmocka_unit_test_setup_teardown(test_server_closes, setup, teardown),
        cmocka_unit_test_setup_teardown(test_server_restart, setup, teardown),
        cmocka_unit_test_setup_teardown(test_connection_refused, setup, teardown),
        cmocka_unit_test_setup_teardown(test_unresolvable_host, setup, teardown),
        cmocka_unit_test_setup_teardown(test_connect_timeout_full_backlog, setup, teardown),
        cmocka_unit_test_setup_teardown(test_closed_by_application, setup, teardown),
        cmocka_unit_test(test_self_connect_is_not_up),
    };
    return cmocka_run_group_tests_name("tcp (loopback server)", tests, NULL, NULL);
}
