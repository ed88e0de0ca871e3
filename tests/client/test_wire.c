/*
 * test_wire.c - the wire faults of the simulator's links (xf_simlink_wire in
 * xfgcu/posix/xf_simlink.h), over an in-memory link that records its writes.
 *
 *   clean        no fault: each write goes through unchanged, in one inner write
 *   noise        every byte followed by a random one at 1000 per mille; some at 100
 *   drop         every byte lost at 1000 per mille (nothing written); some at 300
 *   seeded       the same seed gives the same faults, another seed other ones
 *   refused      an inner XF_ERR_AGAIN is returned, and nothing is counted
 *   long         a write over 256 bytes goes in chunks, each whole
 *   passthrough  read and fd are the inner link's; NULL arguments change nothing
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>
#include <cmocka.h>

#include "xfgcu/posix/xf_simlink.h"

typedef struct sink {
    uint8_t bytes[4096];
    size_t len;
    int writes;
    size_t sizes[16];
    xf_err answer; /* what write returns */
} sink;

static xf_err sink_write(void *ctx, const uint8_t *data, size_t len)
{
    sink *s = (sink *)ctx;
    if (s->answer != XF_OK) {
        return s->answer;
    }
    assert_true(s->len + len <= sizeof(s->bytes));
    memcpy(s->bytes + s->len, data, len);
    s->len += len;
    if (s->writes < 16) {
        s->sizes[s->writes] = len;
    }
    s->writes++;
    return XF_OK;
}

static xf_err sink_read(void *ctx, uint8_t *buf, size_t cap, size_t *out_len)
{
    (void)ctx;
    assert_true(cap >= 3u);
    memcpy(buf, "abc", 3);
    *out_len = 3;
    return XF_ERR_IO; /* passed through as it is */
}

static int sink_fd(void *ctx)
{
    (void)ctx;
    return 42;
}

/* A wrapped sink: what the faulty link wrote lands in sink. */
typedef struct rig {
    sink sink;
    xf_simlink_wire wire;
    xf_hal hal;
} rig;

static rig *rig_new(rig *r, uint32_t seed, uint16_t noise, uint16_t drop)
{
    xf_hal inner = {NULL, sink_write, sink_read, sink_fd};
    memset(r, 0, sizeof(*r));
    inner.ctx = &r->sink;
    xf_simlink_wire_init(&r->wire, &inner, seed, &r->hal);
    r->wire.noise_permille = noise;
    r->wire.drop_permille = drop;
    return r;
}

static const uint8_t packet[72] = {0xA8, 0xE5, 0x48, 0x00, 0x01, 0x02, 0x03, 0x04};

/* n packets, each taken whole */
static void send_packets(rig *r, int n)
{
    int i;
    for (i = 0; i < n; i++) {
        assert_int_equal(r->hal.write(r->hal.ctx, packet, sizeof(packet)), XF_OK);
    }
}

static void test_clean(void **state)
{
    static rig r;
    (void)state;
    send_packets(rig_new(&r, 7u, 0u, 0u), 2);
    assert_int_equal(r.sink.writes, 2);
    assert_int_equal(r.sink.len, 2u * sizeof(packet));
    assert_memory_equal(r.sink.bytes, packet, sizeof(packet));
    assert_memory_equal(r.sink.bytes + sizeof(packet), packet, sizeof(packet));
    assert_int_equal(r.wire.noise_bytes, 0);
    assert_int_equal(r.wire.dropped_bytes, 0);
}

static void test_noise(void **state)
{
    static rig r;
    size_t i;
    (void)state;
    send_packets(rig_new(&r, 7u, 1000u, 0u), 1);
    assert_int_equal(r.sink.writes, 1); /* still one write: no idle gap the faults did not make */
    assert_int_equal(r.sink.len, 2u * sizeof(packet));
    for (i = 0; i < sizeof(packet); i++) {
        assert_int_equal(r.sink.bytes[2u * i], packet[i]); /* each byte, then the noise after it */
    }
    assert_int_equal(r.wire.noise_bytes, sizeof(packet));
    send_packets(rig_new(&r, 7u, 100u, 0u), 20);
    assert_int_equal(r.sink.len, 20u * sizeof(packet) + r.wire.noise_bytes);
    assert_in_range(r.wire.noise_bytes, 80u, 220u); /* 144 expected of 1440 bytes; a fixed seed */
}

static void test_drop(void **state)
{
    static rig r;
    (void)state;
    send_packets(rig_new(&r, 7u, 0u, 1000u), 1);
    assert_int_equal(r.sink.writes, 0); /* nothing left to write */
    assert_int_equal(r.wire.dropped_bytes, sizeof(packet));
    send_packets(rig_new(&r, 7u, 0u, 300u), 20);
    assert_int_equal(r.sink.len + r.wire.dropped_bytes, 20u * sizeof(packet));
    assert_in_range(r.wire.dropped_bytes, 330u, 530u); /* 432 expected */
}

static void test_seeded(void **state)
{
    static rig a, b, c;
    (void)state;
    send_packets(rig_new(&a, 99u, 50u, 50u), 10);
    send_packets(rig_new(&b, 99u, 50u, 50u), 10);
    send_packets(rig_new(&c, 100u, 50u, 50u), 10);
    assert_int_equal(a.sink.len, b.sink.len);
    assert_memory_equal(a.sink.bytes, b.sink.bytes, a.sink.len);
    assert_true(a.wire.noise_bytes > 0u && a.wire.dropped_bytes > 0u);
    assert_true(a.sink.len != c.sink.len || memcmp(a.sink.bytes, c.sink.bytes, a.sink.len) != 0);
    send_packets(rig_new(&a, 0u, 50u, 50u), 10); /* 0 is taken as 1 */
    send_packets(rig_new(&b, 1u, 50u, 50u), 10);
    assert_int_equal(a.sink.len, b.sink.len);
    assert_memory_equal(a.sink.bytes, b.sink.bytes, a.sink.len);
}

static void test_refused(void **state)
{
    static rig r;
    (void)state;
    rig_new(&r, 7u, 1000u, 500u);
    r.sink.answer = XF_ERR_AGAIN;
    assert_int_equal(r.hal.write(r.hal.ctx, packet, sizeof(packet)), XF_ERR_AGAIN);
    assert_int_equal(r.wire.noise_bytes, 0);
    assert_int_equal(r.wire.dropped_bytes, 0);
}

static void test_long(void **state)
{
    static rig r;
    static uint8_t big[600];
    size_t i;
    (void)state;
    for (i = 0; i < sizeof(big); i++) {
        big[i] = (uint8_t)i;
    }
    rig_new(&r, 7u, 0u, 0u);
    assert_int_equal(r.hal.write(r.hal.ctx, big, sizeof(big)), XF_OK);
    assert_int_equal(r.sink.writes, 3);
    assert_int_equal(r.sink.sizes[0], 256u);
    assert_int_equal(r.sink.sizes[1], 256u);
    assert_int_equal(r.sink.sizes[2], 88u);
    assert_memory_equal(r.sink.bytes, big, sizeof(big));
}

static void test_passthrough(void **state)
{
    static rig r;
    xf_hal before, no_fd = {NULL, sink_write, sink_read, NULL};
    uint8_t buf[8];
    size_t n = 0;
    (void)state;
    rig_new(&r, 7u, 1000u, 0u); /* what is read is never touched */
    assert_int_equal(r.hal.read(r.hal.ctx, buf, sizeof(buf), &n), XF_ERR_IO);
    assert_int_equal(n, 3u);
    assert_memory_equal(buf, "abc", 3);
    assert_int_equal(r.hal.fd(r.hal.ctx), 42);
    no_fd.ctx = &r.sink;
    xf_simlink_wire_init(&r.wire, &no_fd, 7u, &r.hal);
    assert_int_equal(r.hal.fd(r.hal.ctx), -1);
    before = r.hal;
    xf_simlink_wire_init(NULL, &no_fd, 7u, &r.hal);
    xf_simlink_wire_init(&r.wire, NULL, 7u, &r.hal);
    xf_simlink_wire_init(&r.wire, &no_fd, 7u, NULL);
    assert_memory_equal(&before, &r.hal, sizeof(r.hal));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_clean),       cmocka_unit_test(test_noise),   cmocka_unit_test(test_drop),
        cmocka_unit_test(test_seeded),      cmocka_unit_test(test_refused), cmocka_unit_test(test_long),
        cmocka_unit_test(test_passthrough),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
