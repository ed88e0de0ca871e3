/**
 * @file
 * @brief CRC-16/XMODEM (poly 0x1021, init 0, no reflection, no final
 * XOR), the protocol's checksum, stored big-endian at the end of a packet.
 *
 * Default: the vendor's 16-entry nibble table. ::XF_CRC_TABLE_256 = 1: a
 * 256-entry byte table, faster and larger (sizes and speeds:
 * docs/performance.md). Check value: xf_crc16("123456789", 9) == 0x31C3.
 * The functions keep no state and never block. See docs/protocol.md §2.
 */
#ifndef XF_CRC_H
#define XF_CRC_H

#include <stddef.h>
#include <stdint.h>
#include "xf_config.h"

XF_BEGIN_DECLS

/**
 * Continue a CRC over more bytes, so a CRC can be computed piece by piece.
 * @param crc   the CRC of the bytes so far; 0 to start
 * @param data  the next bytes; may be NULL when @p len is 0
 * @param len   number of bytes at @p data
 * @return the CRC of the bytes so far followed by @p data
 */
XF_API uint16_t xf_crc16_update(uint16_t crc, const uint8_t *data, size_t len);

/**
 * The CRC-16/XMODEM of a block of bytes, as a packet carries it in its last
 * two bytes (high byte first) over all the bytes before them.
 * @param data  the bytes; may be NULL when @p len is 0
 * @param len   number of bytes
 * @return the CRC (0 for no bytes)
 */
XF_API uint16_t xf_crc16(const uint8_t *data, size_t len);

/*
 * Internal, for the streaming parser's memo (xf_parser.h). With P(i) the
 * CRC of a stream's first i bytes (init 0, no final XOR), the parser keeps
 * the *normalised prefix*
 *     N(i) = P(i) * x^(-8 (i mod 16)) mod G
 * (x is invertible mod G). A frame of bytes [i, j), its CRC included, is
 * intact exactly when its CRC residue is 0, i.e. P(j) = P(i) * x^(8(j-i)),
 * i.e.
 *     N(j) == N(i) * x^(128 k),   k = ((i mod 16) + (j - i)) / 16
 * one product by one of 17 constants (xf__crc_x128k), where the plain
 * prefix would need a product by x^(8(j-i)) for each length. Advancing N by
 * one byte b at stream position i (s = (i + 1) mod 16) is
 *     N = N * x^128 (only when s = 0),  N ^= b * x^(16 - 8s)
 * two lookups in xf__crc_norm_table (one lookup in a larger table with
 * XF_CRC_TABLE_256; sizes in docs/performance.md), and no chain through the CRC.
 * scripts/gen_crc_tables.py generates every table (xf_crc_tables.h); tests/test_crc.c checks them.
 */

#if XF_EMIT_DEFINITIONS

#include "xf_crc_tables.h" /* generated: scripts/gen_crc_tables.py */

/*
 * Both loops keep the CRC in the top half of a 32-bit word, with the table
 * entries pre-shifted to match: the next index is then simply the top bits
 * (no mask), and one shift both advances the CRC and drops what leaves it:
 * fewer instructions per step (a nibble, or a byte with the big table) than
 * the textbook 16-bit forms, for tables twice as wide (instruction counts and
 * sizes: docs/performance.md). Four bytes per iteration cut the loop overhead.
 */
#if XF_CRC_TABLE_256
static inline const uint32_t *xf__crc_table(void) { return xf__crc_table256; }

/* One byte, the CRC in the top half of c. */
static inline uint32_t xf__crc_step(uint32_t c, const uint32_t *table, uint8_t b)
{
    return (c << 8) ^ table[(c >> 24) ^ b];
}
#else
/* The vendor's table: the CRC of each 4-bit value, times 2^16. */
static inline const uint32_t *xf__crc_table(void) { return xf__crc_table16; }

/* The vendor's routine for one byte, the CRC in the top half of c: the
 * byte goes into the CRC's high byte, then two shifts by four bits fold
 * each nibble that leaves back in through the table. */
static inline uint32_t xf__crc_step(uint32_t c, const uint32_t *table, uint8_t b)
{
    c ^= (uint32_t)b << 24;
    c = (c << 4) ^ table[c >> 28];
    return (c << 4) ^ table[c >> 28];
}
#endif

XF_API uint16_t xf_crc16_update(uint16_t crc, const uint8_t *data, size_t len)
{
    const uint32_t *table = xf__crc_table();
    uint32_t c = (uint32_t)crc << 16;
    size_t i = 0;
    for (; i + 4u <= len; i += 4u) {
        c = xf__crc_step(c, table, data[i]);
        c = xf__crc_step(c, table, data[i + 1u]);
        c = xf__crc_step(c, table, data[i + 2u]);
        c = xf__crc_step(c, table, data[i + 3u]);
    }
    for (; i < len; i++) {
        c = xf__crc_step(c, table, data[i]);
    }
    return (uint16_t)(c >> 16);
}

XF_API uint16_t xf_crc16(const uint8_t *data, size_t len) { return xf_crc16_update(0, data, len); }

/* a * b mod G for a fixed b, given mul[i][n] = (n * x^(4i)) * b mod G:
 * the product is linear in a, so it is the XOR of one multiple per nibble
 * of a, four independent lookups (no chain of reductions). */
static inline uint16_t xf__crc_mul_tab(uint16_t a, const uint16_t mul[4][16])
{
    return (uint16_t)(mul[0][a & 0x0Fu] ^ mul[1][(a >> 4) & 0x0Fu] ^ mul[2][(a >> 8) & 0x0Fu] ^ mul[3][a >> 12]);
}

/* a * x^(128k) mod G, k in 0..16. Only the parser's memo calls this; with
 * --gc-sections an image that never does keeps none of its table. */
XF__HOT_INLINE uint16_t xf__crc_x128k(uint16_t a, unsigned k) { return xf__crc_mul_tab(a, xf__crc_x128k_table[k]); }

#if XF_CRC_TABLE_256
/* norm + 256 s: b * x^(16 - 8s) mod G for every byte b (the builds that
 * chose the big CRC table for speed get one lookup a byte here too). */
static inline const uint16_t *xf__crc_norm_table(void) { return &xf__crc_norm256[0][0]; }

/* Entries per row s of xf__crc_norm_table(). */
#define XF__NORM_ROW ((size_t)256u)

/* N after byte b, where s is the position after b mod 16 and t is
 * xf__crc_norm_table() + XF__NORM_ROW * s. */
XF__HOT_INLINE uint16_t xf__crc_norm_step(uint16_t n, const uint16_t *t, uint8_t b) { return (uint16_t)(n ^ t[b]); }
#else
/* norm + 32 s: b * x^(16 - 8s) mod G for the low nibble of b (16 entries),
 * then for the high nibble (16 more). */
static inline const uint16_t *xf__crc_norm_table(void) { return &xf__crc_norm16[0][0]; }

/* Entries per row s of xf__crc_norm_table(). */
#define XF__NORM_ROW ((size_t)32u)

/* N after byte b, where s is the position after b mod 16 and t is
 * xf__crc_norm_table() + XF__NORM_ROW * s. */
XF__HOT_INLINE uint16_t xf__crc_norm_step(uint16_t n, const uint16_t *t, uint8_t b)
{
    unsigned x = b; /* a full-width index: no re-zero-extension after the shift */
    return (uint16_t)(n ^ t[x & 0x0Fu] ^ (t + 16)[x >> 4]);
}
#endif

#endif /* XF_EMIT_DEFINITIONS */

XF_END_DECLS

#endif /* XF_CRC_H */
