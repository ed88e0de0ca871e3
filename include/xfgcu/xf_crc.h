/*
 * xf_crc.h - CRC-16/XMODEM (poly 0x1021, init 0, no reflection, no final
 * XOR), the protocol's checksum, stored big-endian at the end of a packet.
 *
 * Default: the vendor's 16-entry nibble table (32 bytes of flash).
 * XF_CRC_TABLE_256=1: a 256-entry byte table (512 bytes, faster).
 * Check value: xf_crc16("123456789", 9) == 0x31C3.
 */
#ifndef XF_CRC_H
#define XF_CRC_H

#include <stddef.h>
#include <stdint.h>
#include "xf_config.h"

XF_BEGIN_DECLS

/** Continue a CRC over @p len bytes; start with @p crc = 0. NULL with len 0 is allowed. */
XF_API uint16_t xf_crc16_update(uint16_t crc, const uint8_t *data, size_t len);

/** The CRC of @p len bytes. */
XF_API uint16_t xf_crc16(const uint8_t *data, size_t len);

/*
 * Internal: crc * x^(8*nbytes) mod G, i.e. what a CRC state becomes after
 * nbytes zero bytes, in O(1) (two 16-bit carry-less products with 16-entry
 * tables). With prefix CRCs P(i) of a stream (init 0, no final XOR):
 *     crc(bytes i..j) = P(j) ^ xf__crc_shift(P(i), j - i)
 * which lets the streaming parser test any candidate frame inside bytes it
 * already holds in constant time instead of re-reading them.
 */
XF_API uint16_t xf__crc_shift(uint16_t crc, unsigned nbytes);

#if XF_EMIT_DEFINITIONS

/*
 * The byte-table loop keeps the CRC in 32 bits and never masks it inside the
 * loop: only bits 8..15 feed the next index, and the bits shifted above 15
 * are dropped once at the end; four bytes per iteration cut the loop
 * overhead (10.3 -> 8.3 instructions per byte with gcc -O2).
 */
#if XF_CRC_TABLE_256
#define XF__CRC_STEP(c, b) (((c) << 8) ^ table[(((c) >> 8) ^ (b)) & 0xFFu])
XF_API uint16_t xf_crc16_update(uint16_t crc, const uint8_t *data, size_t len)
{
    static const uint16_t table[256] = {
        0x0000, 0x1021, 0x2042, 0x3063, 0x4084, 0x50A5, 0x60C6, 0x70E7, 0x8108, 0x9129, 0xA14A, 0xB16B, 0xC18C, 0xD1AD,
        0xE1CE, 0xF1EF, 0x1231, 0x0210, 0x3273, 0x2252, 0x52B5, 0x4294, 0x72F7, 0x62D6, 0x9339, 0x8318, 0xB37B, 0xA35A,
        0xD3BD, 0xC39C, 0xF3FF, 0xE3DE, 0x2462, 0x3443, 0x0420, 0x1401, 0x64E6, 0x74C7, 0x44A4, 0x5485, 0xA56A, 0xB54B,
        0x8528, 0x9509, 0xE5EE, 0xF5CF, 0xC5AC, 0xD58D, 0x3653, 0x2672, 0x1611, 0x0630, 0x76D7, 0x66F6, 0x5695, 0x46B4,
        0xB75B, 0xA77A, 0x9719, 0x8738, 0xF7DF, 0xE7FE, 0xD79D, 0xC7BC, 0x48C4, 0x58E5, 0x6886, 0x78A7, 0x0840, 0x1861,
        0x2802, 0x3823, 0xC9CC, 0xD9ED, 0xE98E, 0xF9AF, 0x8948, 0x9969, 0xA90A, 0xB92B, 0x5AF5, 0x4AD4, 0x7AB7, 0x6A96,
        0x1A71, 0x0A50, 0x3A33, 0x2A12, 0xDBFD, 0xCBDC, 0xFBBF, 0xEB9E, 0x9B79, 0x8B58, 0xBB3B, 0xAB1A, 0x6CA6, 0x7C87,
        0x4CE4, 0x5CC5, 0x2C22, 0x3C03, 0x0C60, 0x1C41, 0xEDAE, 0xFD8F, 0xCDEC, 0xDDCD, 0xAD2A, 0xBD0B, 0x8D68, 0x9D49,
        0x7E97, 0x6EB6, 0x5ED5, 0x4EF4, 0x3E13, 0x2E32, 0x1E51, 0x0E70, 0xFF9F, 0xEFBE, 0xDFDD, 0xCFFC, 0xBF1B, 0xAF3A,
        0x9F59, 0x8F78, 0x9188, 0x81A9, 0xB1CA, 0xA1EB, 0xD10C, 0xC12D, 0xF14E, 0xE16F, 0x1080, 0x00A1, 0x30C2, 0x20E3,
        0x5004, 0x4025, 0x7046, 0x6067, 0x83B9, 0x9398, 0xA3FB, 0xB3DA, 0xC33D, 0xD31C, 0xE37F, 0xF35E, 0x02B1, 0x1290,
        0x22F3, 0x32D2, 0x4235, 0x5214, 0x6277, 0x7256, 0xB5EA, 0xA5CB, 0x95A8, 0x8589, 0xF56E, 0xE54F, 0xD52C, 0xC50D,
        0x34E2, 0x24C3, 0x14A0, 0x0481, 0x7466, 0x6447, 0x5424, 0x4405, 0xA7DB, 0xB7FA, 0x8799, 0x97B8, 0xE75F, 0xF77E,
        0xC71D, 0xD73C, 0x26D3, 0x36F2, 0x0691, 0x16B0, 0x6657, 0x7676, 0x4615, 0x5634, 0xD94C, 0xC96D, 0xF90E, 0xE92F,
        0x99C8, 0x89E9, 0xB98A, 0xA9AB, 0x5844, 0x4865, 0x7806, 0x6827, 0x18C0, 0x08E1, 0x3882, 0x28A3, 0xCB7D, 0xDB5C,
        0xEB3F, 0xFB1E, 0x8BF9, 0x9BD8, 0xABBB, 0xBB9A, 0x4A75, 0x5A54, 0x6A37, 0x7A16, 0x0AF1, 0x1AD0, 0x2AB3, 0x3A92,
        0xFD2E, 0xED0F, 0xDD6C, 0xCD4D, 0xBDAA, 0xAD8B, 0x9DE8, 0x8DC9, 0x7C26, 0x6C07, 0x5C64, 0x4C45, 0x3CA2, 0x2C83,
        0x1CE0, 0x0CC1, 0xEF1F, 0xFF3E, 0xCF5D, 0xDF7C, 0xAF9B, 0xBFBA, 0x8FD9, 0x9FF8, 0x6E17, 0x7E36, 0x4E55, 0x5E74,
        0x2E93, 0x3EB2, 0x0ED1, 0x1EF0,
    };
    uint32_t c = crc;
    size_t i = 0;
    for (; i + 4u <= len; i += 4u) {
        c = XF__CRC_STEP(c, data[i]);
        c = XF__CRC_STEP(c, data[i + 1u]);
        c = XF__CRC_STEP(c, data[i + 2u]);
        c = XF__CRC_STEP(c, data[i + 3u]);
    }
    for (; i < len; i++) {
        c = XF__CRC_STEP(c, data[i]);
    }
    return (uint16_t)c;
}
#undef XF__CRC_STEP
#else
/* The vendor's routine: a nibble at a time, high nibble first (kept in 16
 * bits: in 32, the compiler's code is longer here). */
XF_API uint16_t xf_crc16_update(uint16_t crc, const uint8_t *data, size_t len)
{
    /* The vendor's table: the CRC of each 4-bit value. */
    static const uint16_t table[16] = {
        0x0000, 0x1021, 0x2042, 0x3063, 0x4084, 0x50A5, 0x60C6, 0x70E7,
        0x8108, 0x9129, 0xA14A, 0xB16B, 0xC18C, 0xD1AD, 0xE1CE, 0xF1EF,
    };
    size_t i;
    for (i = 0; i < len; i++) {
        uint8_t b = data[i];
        crc = (uint16_t)((uint16_t)(crc << 4) ^ table[(uint8_t)((crc >> 12) ^ (b >> 4))]);
        crc = (uint16_t)((uint16_t)(crc << 4) ^ table[(uint8_t)((crc >> 12) ^ (b & 0x0Fu))]);
    }
    return crc;
}
#endif

XF_API uint16_t xf_crc16(const uint8_t *data, size_t len) { return xf_crc16_update(0, data, len); }

/* a * b mod G, nibble by nibble over b: 4 steps of "multiply by x^4, add a*nibble". */
static inline uint16_t xf__crc_mulmod(uint16_t a, uint16_t b)
{
    uint16_t mult[16];
    uint16_t r = 0;
    unsigned k;
    mult[0] = 0;
    mult[1] = a;
    for (k = 2; k < 16; k += 2) {
        uint16_t h = mult[k / 2];
        mult[k] = (uint16_t)((uint16_t)(h << 1) ^ ((h & 0x8000u) ? 0x1021u : 0u));
        mult[k + 1] = (uint16_t)(mult[k] ^ a);
    }
    for (k = 0; k < 4u; k++) {
        /* r * x^4 mod G: the top nibble of r wraps round through the polynomial. */
        uint16_t top = (uint16_t)(r >> 12);
        r = (uint16_t)((uint16_t)(r << 4) ^ (uint16_t)(top << 12) ^ (uint16_t)(top << 5) ^ top);
        r = (uint16_t)(r ^ mult[((unsigned)b >> (12u - 4u * k)) & 0x0Fu]);
    }
    return r;
}

XF_API uint16_t xf__crc_shift(uint16_t crc, unsigned nbytes)
{
    /* x^(8k) and x^(128k) mod G for k = 0..15, so any nbytes < 256 is two products. */
    static const uint16_t x8[16] = {
        0x0001, 0x0100, 0x1021, 0x3331, 0x3730, 0x76B4, 0xAA51, 0x45A0,
        0xB861, 0x47D3, 0xEB23, 0x6F45, 0xD849, 0x0375, 0x4563, 0x7B61,
    };
    static const uint16_t x128[16] = {
        0x0001, 0xAEFC, 0x8E29, 0xCDE2, 0x13FC, 0xDA35, 0x106F, 0xCBC5,
        0x36C4, 0x400C, 0x30DF, 0x0A5D, 0x2764, 0x0224, 0x46CF, 0x6D5A,
    };
    uint16_t r = crc;
    if ((nbytes & 0x0Fu) != 0u) {
        r = xf__crc_mulmod(r, x8[nbytes & 0x0Fu]);
    }
    if ((nbytes >> 4) != 0u) {
        r = xf__crc_mulmod(r, x128[(nbytes >> 4) & 0x0Fu]);
    }
    return r;
}

#endif /* XF_EMIT_DEFINITIONS */

XF_END_DECLS

#endif /* XF_CRC_H */
