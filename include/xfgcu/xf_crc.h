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
 * The CRC lives in the top half of a 32-bit register, and each table entry
 * goes there as it is read: the next index is then simply the top bits (no
 * mask), and one shift both advances the CRC and drops what leaves it.
 * Data goes in by XOR at the top, a byte or four at a time: four bytes fill
 * the register, the two after the CRC's riding in its low half until they
 * are folded (instruction counts and sizes: docs/performance.md).
 */
#if XF_CRC_TABLE_256
#define XF__CRC_BITS 8u  /* bits folded per lookup */
#define XF__CRC_UP   16u /* its 16-bit entries (512 bytes) go to the top half as they are read */
#else
#define XF__CRC_BITS 4u /* the vendor's table, its entries kept shifted up (64 bytes) */
#define XF__CRC_UP   0u
#endif

/* Fold the top byte of c out through the table: one lookup, or two with
 * the nibble table. */
static inline uint32_t xf__crc_fold(uint32_t c)
{
    c = (c << XF__CRC_BITS) ^ ((uint32_t)xf__crc_table[c >> (32u - XF__CRC_BITS)] << XF__CRC_UP);
#if !XF_CRC_TABLE_256
    c = (c << 4) ^ xf__crc_table[c >> 28];
#endif
    return c;
}

/* One byte, the CRC in the top half of c. */
static inline uint32_t xf__crc_step(uint32_t c, uint8_t b) { return xf__crc_fold(c ^ ((uint32_t)b << 24)); }

/* Four bytes, read big-endian into the whole register. */
static inline uint32_t xf__crc_word(uint32_t c, const uint8_t *d)
{
    c ^= ((uint32_t)d[0] << 24) | ((uint32_t)d[1] << 16) | ((uint32_t)d[2] << 8) | d[3];
    return xf__crc_fold(xf__crc_fold(xf__crc_fold(xf__crc_fold(c))));
}

XF_API uint16_t xf_crc16_update(uint16_t crc, const uint8_t *data, size_t len)
{
    uint32_t c = (uint32_t)crc << 16;
    size_t i = 0;
    for (; i + 16u <= len; i += 16u) { /* (unrolled: the loop costs more than a fold) */
        c = xf__crc_word(xf__crc_word(c, data + i), data + i + 4u);
        c = xf__crc_word(xf__crc_word(c, data + i + 8u), data + i + 12u);
    }
    for (; i + 4u <= len; i += 4u) {
        c = xf__crc_word(c, data + i);
    }
    for (; i < len; i++) {
        c = xf__crc_step(c, data[i]);
    }
    return (uint16_t)(c >> 16);
}

XF_API uint16_t xf_crc16(const uint8_t *data, size_t len) { return xf_crc16_update(0, data, len); }

#endif /* XF_EMIT_DEFINITIONS */

XF_END_DECLS

#endif /* XF_CRC_H */
