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

static void wrap(sink *s, xf_simlink_wire *w, xf_hal *out, uint32_t seed)
{
    xf_hal inner = {NULL, sink_write, sink_read, sink_fd};
    memset(s, 0, sizeof(*s));
    inner.ctx = s;
    xf_simlink_wire_init(w, &inner, seed, out);
}

static const uint8_t packet[72] = {0xA8, 0xE5, 0x48, 0x00, 0x01, 0x02, 0x03, 0x04};

static void test_clean(void **state)
{
    sink s;
    xf_simlink_wire w;
    xf_hal hal;
    (void)state;
    wrap(&s, &w, &hal, 7u);
    assert_int_equal(hal.write(hal.ctx, packet, sizeof(packet)), XF_OK);
    assert_int_equal(hal.write(hal.ctx, packet, sizeof(packet)), XF_OK);
    assert_int_equal(s.writes, 2);
    assert_int_equal(s.len, 2u * sizeof(packet));
    assert_memory_equal(s.bytes, packet, sizeof(packet));
    assert_memory_equal(s.bytes + sizeof(packet), packet, sizeof(packet));
    assert_int_equal(w.noise_bytes, 0);
    assert_int_equal(w.dropped_bytes, 0);
}

static void test_noise(void **state)
{
    sink s;
    xf_simlink_wire w;
    xf_hal hal;
    size_t i;
    (void)state;
    wrap(&s, &w, &hal, 7u);
    w.noise_permille = 1000u;
    assert_int_equal(hal.write(hal.ctx, packet, sizeof(packet)), XF_OK);
    assert_int_equal(s.writes, 1); /* still one write: no idle gap the faults did not make */
    assert_int_equal(s.len, 2u * sizeof(packet));
    for (i = 0; i < sizeof(packet); i++) {
        assert_int_equal(s.bytes[2u * i], packet[i]); /* each byte, then the noise after it */
    }
    assert_int_equal(w.noise_bytes, sizeof(packet));
    wrap(&s, &w, &hal, 7u);
    w.noise_permille = 100u;
    for (i = 0; i < 20u; i++) {
        assert_int_equal(hal.write(hal.ctx, packet, sizeof(packet)), XF_OK);
    }
    assert_int_equal(s.len, 20u * sizeof(packet) + w.noise_bytes);
    assert_in_range(w.noise_bytes, 80u, 220u); /* 144 expected of 1440 bytes; a fixed seed */
}

static void test_drop(void **state)
{
    sink s;
    xf_simlink_wire w;
    xf_hal hal;
    int i;
    (void)state;
    wrap(&s, &w, &hal, 7u);
    w.drop_permille = 1000u;
    assert_int_equal(hal.write(hal.ctx, packet, sizeof(packet)), XF_OK);
    assert_int_equal(s.writes, 0); /* nothing left to write */
    assert_int_equal(w.dropped_bytes, sizeof(packet));
    wrap(&s, &w, &hal, 7u);
    w.drop_permille = 300u;
    for (i = 0; i < 20; i++) {
        assert_int_equal(hal.write(hal.ctx, packet, sizeof(packet)), XF_OK);
    }
    assert_int_equal(s.len + w.dropped_bytes, 20u * sizeof(packet));
    assert_in_range(w.dropped_bytes, 330u, 530u); /* 432 expected */
}

static void run_faults(sink *s, xf_simlink_wire *w, uint32_t seed)
{
    xf_hal hal;
    int i;
    wrap(s, w, &hal, seed);
    w->noise_permille = 50u;
    w->drop_permille = 50u;
    for (i = 0; i < 10; i++) {
        assert_int_equal(hal.write(hal.ctx, packet, sizeof(packet)), XF_OK);
    }
}

static void test_seeded(void **state)
{
    static sink a, b, c;
    xf_simlink_wire wa, wb, wc;
    (void)state;
    run_faults(&a, &wa, 99u);
    run_faults(&b, &wb, 99u);
    run_faults(&c, &wc, 100u);
    assert_int_equal(a.len, b.len);
    assert_memory_equal(a.bytes, b.bytes, a.len);
    assert_true(wa.noise_bytes > 0u && wa.dropped_bytes > 0u);
    assert_true(a.len != c.len || memcmp(a.bytes, c.bytes, a.len) != 0);
    run_faults(&a, &wa, 0u); /* 0 is taken as 1 */
    run_faults(&b, &wb, 1u);
    assert_int_equal(a.len, b.len);
    assert_memory_equal(a.bytes, b.bytes, a.len);
}

static void test_refused(void **state)
{
    sink s;
    xf_simlink_wire w;
    xf_hal hal;
    (void)state;
    wrap(&s, &w, &hal, 7u);
    w.noise_permille = 1000u;
    w.drop_permille = 500u;
    s.answer = XF_ERR_AGAIN;
    assert_int_equal(hal.write(hal.ctx, packet, sizeof(packet)), XF_ERR_AGAIN);
    assert_int_equal(w.noise_bytes, 0);
    assert_int_equal(w.dropped_bytes, 0);
}

static void test_long(void **state)
{
    static sink s;
    static uint8_t big[600];
    xf_simlink_wire w;
    xf_hal hal;
    size_t i;
    (void)state;
    for (i = 0; i < sizeof(big); i++) {
        big[i] = (uint8_t)i;
    }
    wrap(&s, &w, &hal, 7u);
    assert_int_equal(hal.write(hal.ctx, big, sizeof(big)), XF_OK);
    assert_int_equal(s.writes, 3);
    assert_int_equal(s.sizes[0], 256u);
    assert_int_equal(s.sizes[1], 256u);
    assert_int_equal(s.sizes[2], 88u);
    assert_memory_equal(s.bytes, big, sizeof(big));
}

static void test_passthrough(void **state)
{
    sink s;
    xf_simlink_wire w;
    xf_hal hal, before, no_fd = {NULL, sink_write, sink_read, NULL};
    uint8_t buf[8];
    size_t n = 0;
    (void)state;
    wrap(&s, &w, &hal, 7u);
    w.noise_permille = 1000u; /* what is read is never touched */
    assert_int_equal(hal.read(hal.ctx, buf, sizeof(buf), &n), XF_ERR_IO);
    assert_int_equal(n, 3u);
    assert_memory_equal(buf, "abc", 3);
    assert_int_equal(hal.fd(hal.ctx), 42);
    no_fd.ctx = &s;
    xf_simlink_wire_init(&w, &no_fd, 7u, &hal);
    assert_int_equal(hal.fd(hal.ctx), -1);
    before = hal;
    xf_simlink_wire_init(NULL, &no_fd, 7u, &hal);
    xf_simlink_wire_init(&w, NULL, 7u, &hal);
    xf_simlink_wire_init(&w, &no_fd, 7u, NULL);
    assert_memory_equal(&before, &hal, sizeof(hal));
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
