/**
 * @file
 * @brief Explicit little-endian put/get helpers.
 *
 * Wire fields are read and written byte by byte with shifts, never through
 * packed structs or pointer casts, so the same code is correct on
 * big-endian and alignment-strict targets. Signed values go through their
 * unsigned two's-complement image, which C99's exact-width types guarantee.
 *
 * No function checks its pointer: each reads or writes exactly the 1, 2 or 4
 * bytes its name says, at any alignment. None blocks.
 */
#ifndef XF_BYTES_H
#define XF_BYTES_H

#include <stdint.h>
#include "xf_config.h"

XF_BEGIN_DECLS

/**
 * Store a 16-bit unsigned value little-endian.
 * @param p  where the 2 bytes go (any alignment)
 * @param v  the value
 */
static inline void xf_put_u16le(uint8_t *p, uint16_t v)
{
    p[0] = (uint8_t)(v & 0xFFu);
    p[1] = (uint8_t)(v >> 8);
}

/**
 * Store a 32-bit unsigned value little-endian.
 * @param p  where the 4 bytes go (any alignment)
 * @param v  the value
 */
static inline void xf_put_u32le(uint8_t *p, uint32_t v)
{
    p[0] = (uint8_t)(v & 0xFFu);
    p[1] = (uint8_t)((v >> 8) & 0xFFu);
    p[2] = (uint8_t)((v >> 16) & 0xFFu);
    p[3] = (uint8_t)(v >> 24);
}

/**
 * Store a 16-bit signed value little-endian, as its two's-complement image.
 * @param p  where the 2 bytes go (any alignment)
 * @param v  the value
 */
static inline void xf_put_s16le(uint8_t *p, int16_t v) { xf_put_u16le(p, (uint16_t)v); }
/**
 * Store a 32-bit signed value little-endian, as its two's-complement image.
 * @param p  where the 4 bytes go (any alignment)
 * @param v  the value
 */
static inline void xf_put_s32le(uint8_t *p, int32_t v) { xf_put_u32le(p, (uint32_t)v); }

/**
 * Load a 16-bit unsigned little-endian value.
 * @param p  the 2 bytes (any alignment)
 * @return the value
 */
static inline uint16_t xf_get_u16le(const uint8_t *p)
{
    return (uint16_t)((uint16_t)p[0] | (uint16_t)((uint16_t)p[1] << 8));
}

/**
 * Load a 32-bit unsigned little-endian value.
 * @param p  the 4 bytes (any alignment)
 * @return the value
 */
static inline uint32_t xf_get_u32le(const uint8_t *p)
{
    return (uint32_t)p[0] | ((uint32_t)p[1] << 8) | ((uint32_t)p[2] << 16) | ((uint32_t)p[3] << 24);
}

/**
 * Load a 16-bit signed little-endian value (two's complement).
 *
 * Converting an out-of-range unsigned value to a signed type is
 * implementation-defined, so the sign is rebuilt arithmetically.
 * @param p  the 2 bytes (any alignment)
 * @return the value, in [-32768, 32767]
 */
static inline int16_t xf_get_s16le(const uint8_t *p)
{
    uint16_t u = xf_get_u16le(p);
    return (u < 0x8000u) ? (int16_t)u : (int16_t)((int32_t)u - 65536);
}

/**
 * Load a 32-bit signed little-endian value (two's complement), the sign
 * rebuilt arithmetically as in xf_get_s16le().
 * @param p  the 4 bytes (any alignment)
 * @return the value
 */
static inline int32_t xf_get_s32le(const uint8_t *p)
{
    uint32_t u = xf_get_u32le(p);
    return (u < 0x80000000u) ? (int32_t)u : (int32_t)((int64_t)u - 4294967296LL);
}

/**
 * Reinterpret a byte as a signed 8-bit value (two's complement), without
 * implementation-defined conversion.
 * @param u  the byte as received
 * @return the value, in [-128, 127]
 */
static inline int8_t xf_u8_to_s8(uint8_t u) { return (u < 0x80u) ? (int8_t)u : (int8_t)((int)u - 256); }

XF_END_DECLS

#endif /* XF_BYTES_H */
