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

/* Four bytes at once: the CRC's register is 32 bits wide, so the next two
 * bytes ride in its low half while the two before them are folded out of the
 * top. One big-endian load and one XOR put four bytes in, where one byte at
 * a time takes a load, a shift and an XOR each (docs/performance.md). */
static inline uint32_t xf__crc_word(uint32_t c, const uint32_t *table, const uint8_t *d)
{
    c ^= ((uint32_t)d[0] << 24) | ((uint32_t)d[1] << 16) | ((uint32_t)d[2] << 8) | d[3];
#if XF_CRC_TABLE_256
    c = (c << 8) ^ table[c >> 24];
    c = (c << 8) ^ table[c >> 24];
    c = (c << 8) ^ table[c >> 24];
    return (c << 8) ^ table[c >> 24];
#else
    c = (c << 4) ^ table[c >> 28];
    c = (c << 4) ^ table[c >> 28];
    c = (c << 4) ^ table[c >> 28];
    c = (c << 4) ^ table[c >> 28];
    c = (c << 4) ^ table[c >> 28];
    c = (c << 4) ^ table[c >> 28];
    c = (c << 4) ^ table[c >> 28];
    return (c << 4) ^ table[c >> 28];
#endif
}

/* len bytes into a CRC kept in the top half of c (the parser keeps each
 * candidate's CRC in this form). */
static inline uint32_t xf__crc_run(uint32_t c, const uint8_t *data, size_t len)
{
    const uint32_t *table = xf__crc_table();
    size_t i = 0;
    for (; i + 8u <= len; i += 8u) {
        c = xf__crc_word(xf__crc_word(c, table, data + i), table, data + i + 4u);
    }
    if (i + 4u <= len) {
        c = xf__crc_word(c, table, data + i);
        i += 4u;
    }
    for (; i < len; i++) {
        c = xf__crc_step(c, table, data[i]);
    }
    return c;
}

XF_API uint16_t xf_crc16_update(uint16_t crc, const uint8_t *data, size_t len)
{
    return (uint16_t)(xf__crc_run((uint32_t)crc << 16, data, len) >> 16);
}

XF_API uint16_t xf_crc16(const uint8_t *data, size_t len) { return xf_crc16_update(0, data, len); }

/* The CRC state a after n zero bytes, a * x^(8n) mod G: a product by x^128
 * (four lookups) per 16 bytes, the rest one by one. The parser checks a
 * candidate that began behind another with it (docs/codec.md). */
static uint16_t xf__crc_zeros(uint16_t a, unsigned n)
{
    uint32_t c;
    for (; n >= 16u; n -= 16u) {
        const uint16_t(*m)[16] = xf__crc_zero16;
        a = (uint16_t)(m[0][a & 15u] ^ m[1][(a >> 4) & 15u] ^ m[2][(a >> 8) & 15u] ^ m[3][a >> 12]);
    }
    for (c = (uint32_t)a << 16; n > 0u; n--) {
        c = xf__crc_step(c, xf__crc_table(), 0);
    }
    return (uint16_t)(c >> 16);
}

#endif /* XF_EMIT_DEFINITIONS */

XF_END_DECLS

#endif /* XF_CRC_H */
