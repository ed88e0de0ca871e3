/*
 * test_util.h - helpers shared by the xfgcu unit tests.
 *
 * Everything here is written from the protocol description
 * (docs/protocol.md), not from the codec: a bit-by-bit CRC, a
 * little-endian writer and a packet finisher, so that expected bytes never
 * come from the code under test. Also a seeded PRNG (xorshift64*) so that
 * every "random" test is reproducible, and a few assertion helpers that
 * print signed values and byte diffs readably.
 */
#ifndef XFGCU_TEST_UTIL_H
#define XFGCU_TEST_UTIL_H

/* cmocka needs these before its own header. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>
#include <cmocka.h>

/* The codec's internal invariants are checked in every codec test (each is
 * the codec's implementation unit): a broken one fails the test. */
#define XF_ASSERT(cond) mock_assert((int)(cond), #cond, __FILE__, __LINE__)

#include "xf_test_assert.h"

#include "xfgcu/xfgcu.h"

#define ARRAY_LEN(a) (sizeof(a) / sizeof((a)[0]))

/* ---- assertions ----------------------------------------------------------- */

/* cmocka's assert_int_equal prints through uintmax_t, so -1 shows as
 * 18446744073709551615; this one keeps the sign. */
#define assert_sint_equal(a, b)                                                                                        \
    do {                                                                                                               \
        long long got_ = (long long)(a), want_ = (long long)(b);                                                       \
        if (got_ != want_) {                                                                                           \
            print_error("%s == %lld, expected %s == %lld\n", #a, got_, #b, want_);                                     \
            fail();                                                                                                    \
        }                                                                                                              \
    } while (0)

/* An xf_err (or parser return) compared with its expected value, by name. */
#define assert_err assert_xf

/* |a - b| <= eps in double precision (cmocka's assert_float_equal works in
 * float); NaN never passes. */
#define assert_near(a, b, eps)                                                                                         \
    do {                                                                                                               \
        double got_ = (double)(a), want_ = (double)(b), d_ = got_ - want_;                                             \
        if (d_ < 0.0) {                                                                                                \
            d_ = -d_;                                                                                                  \
        }                                                                                                              \
        if (!(d_ <= (double)(eps))) {                                                                                  \
            print_error("%s == %.9g, expected %s == %.9g (+- %g)\n", #a, got_, #b, want_, (double)(eps));              \
            fail();                                                                                                    \
        }                                                                                                              \
    } while (0)

static inline void test_hexdump(const char *what, const uint8_t *p, size_t n)
{
    size_t i;
    print_error("%s (%zu bytes):", what, n);
    for (i = 0; i < n; i++) {
        print_error("%s%02X", (i % 24u == 0u) ? "\n  " : " ", p[i]);
    }
    print_error("\n");
}

/* Byte-for-byte comparison that shows both buffers and the first difference. */
static inline void test_bytes_equal(const uint8_t *got, const uint8_t *want, size_t n, const char *file, int line)
{
    size_t i;
    for (i = 0; i < n; i++) {
        if (got[i] != want[i]) {
            print_error("first difference at byte %zu: got %02X, expected %02X\n", i, got[i], want[i]);
            test_hexdump("got", got, n);
            test_hexdump("expected", want, n);
            _fail(file, line);
        }
    }
}
#define assert_bytes_equal(got, want, n) test_bytes_equal((got), (want), (n), __FILE__, __LINE__)

/* ---- PRNG: xorshift64* (Vigna), seeded, so failures reproduce ------------ */

typedef struct test_rng {
    uint64_t s;
} test_rng;

static inline void rng_seed(test_rng *r, uint64_t seed) { r->s = (seed != 0u) ? seed : 0x9E3779B97F4A7C15ull; }

static inline uint64_t rng_next(test_rng *r)
{
    r->s ^= r->s >> 12;
    r->s ^= r->s << 25;
    r->s ^= r->s >> 27;
    return r->s * 0x2545F4914F6CDD1Dull;
}

static inline uint32_t rng_u32(test_rng *r) { return (uint32_t)(rng_next(r) >> 32); }
static inline uint8_t rng_u8(test_rng *r) { return (uint8_t)(rng_next(r) >> 56); }

/* Uniform-enough integer in [0, n) for the small n used here (n > 0). */
static inline uint32_t rng_below(test_rng *r, uint32_t n) { return (uint32_t)(((uint64_t)rng_u32(r) * n) >> 32); }

/* Integer in [lo, hi]. */
static inline int32_t rng_range(test_rng *r, int32_t lo, int32_t hi)
{
    return (int32_t)((int64_t)lo + (int64_t)rng_below(r, (uint32_t)((int64_t)hi - (int64_t)lo + 1)));
}

static inline void rng_fill(test_rng *r, uint8_t *p, size_t n)
{
    size_t i;
    for (i = 0; i < n; i++) {
        p[i] = rng_u8(r);
    }
}

/* ---- reference implementations, from the spec ---------------------------- */

/* CRC-16/XMODEM bit by bit: poly 0x1021, init 0, MSB first, no final XOR (docs/protocol.md §2). */
static inline uint16_t ref_crc16(const uint8_t *p, size_t n)
{
    uint32_t crc = 0;
    size_t i;
    int bit;
    for (i = 0; i < n; i++) {
        crc ^= (uint32_t)p[i] << 8;
        for (bit = 0; bit < 8; bit++) {
            crc = (crc & 0x8000u) ? ((crc << 1) ^ 0x1021u) : (crc << 1);
            crc &= 0xFFFFu;
        }
    }
    return (uint16_t)crc;
}

/* The vendor's CalculateCrc16 (vendor text, "CRC Function"), transcribed with
 * its uint8_t length: a second, differently built reference. */
static inline uint16_t vendor_crc16(const uint8_t *ptr, uint8_t len)
{
    static const uint16_t crc_ta[16] = {
        0x0000, 0x1021, 0x2042, 0x3063, 0x4084, 0x50a5, 0x60c6, 0x70e7,
        0x8108, 0x9129, 0xa14a, 0xb16b, 0xc18c, 0xd1ad, 0xe1ce, 0xf1ef,
    };
    uint16_t crc = 0;
    uint8_t da;
    while (len-- != 0) {
        da = (uint8_t)(crc >> 12);
        crc = (uint16_t)(crc << 4);
        crc = (uint16_t)(crc ^ crc_ta[da ^ (*ptr >> 4)]);
        da = (uint8_t)(crc >> 12);
        crc = (uint16_t)(crc << 4);
        crc = (uint16_t)(crc ^ crc_ta[da ^ (*ptr & 0x0F)]);
        ptr++;
    }
    return crc;
}

/* Little-endian: the low @p n bytes of @p v at @p p. */
static inline void le_put(uint8_t *p, uint64_t v, size_t n)
{
    size_t i;
    for (i = 0; i < n; i++) {
        p[i] = (uint8_t)(v >> (8u * i));
    }
}

static inline uint64_t le_get(const uint8_t *p, size_t n)
{
    uint64_t v = 0;
    size_t i;
    for (i = 0; i < n; i++) {
        v |= (uint64_t)p[i] << (8u * i);
    }
    return v;
}

/* Two's complement of an n-byte little-endian image, as the spec's S8/S16/S32. */
static inline int64_t le_get_signed(const uint8_t *p, size_t n)
{
    uint64_t u = le_get(p, n);
    uint64_t sign = 1ull << (8u * n - 1u);
    return (u & sign) ? (int64_t)u - (int64_t)(sign << 1) : (int64_t)u;
}

/* Make buf[0 .. len) a well-formed packet of direction @p dir: header bytes,
 * length field (LE) and the CRC of bytes 0 .. len-3, big-endian (docs/protocol.md §2).
 * The caller fills the rest (version, frames, order, params). */
static inline void ref_finish_packet(uint8_t *buf, size_t len, xf_direction dir)
{
    uint16_t crc;
    buf[0] = (dir == XF_DIR_HOST) ? 0xA8 : 0x8A;
    buf[1] = (dir == XF_DIR_HOST) ? 0xE5 : 0x5E;
    le_put(buf + 2, len, 2);
    crc = ref_crc16(buf, len - 2u);
    buf[len - 2u] = (uint8_t)(crc >> 8);
    buf[len - 1u] = (uint8_t)(crc & 0xFFu);
}

/* The vendor's appendix-1 host packet, exactly as printed (docs/protocol.md §9.1). */
static const uint8_t appendix1_packet[72] = {
    0xA8, 0xE5, 0x48, 0x00, 0x01, 0x00, 0x00, 0x64, 0x00, 0x9C, 0xFF, 0x05, 0x94, 0xFB, 0x65, 0x00, 0xC0, 0x5D,
    0x70, 0x00, 0x90, 0xFF, 0x70, 0x00, 0x40, 0x80, 0xC0, 0xF7, 0x40, 0x80, 0x01, 0x00, 0x00, 0x00, 0x00, 0x00,
    0x00, 0x01, 0x24, 0xF2, 0xDF, 0x65, 0x16, 0xEE, 0xAA, 0x16, 0xA3, 0xA0, 0x00, 0x00, 0x13, 0xB0, 0x0C, 0x06,
    0x15, 0xE6, 0x08, 0x58, 0x2F, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0xE9, 0xD4,
};

#endif /* XFGCU_TEST_UTIL_H */
