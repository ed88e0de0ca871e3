/*
 * xf_bytes.h - explicit little-endian put/get helpers.
 *
 * Wire fields are read and written byte by byte with shifts, never through
 * packed structs or pointer casts, so the same code is correct on
 * big-endian and alignment-strict targets. Signed values go through their
 * unsigned two's-complement image, which C99's exact-width types guarantee.
 */
#ifndef XF_BYTES_H
#define XF_BYTES_H

#include <stdint.h>
#include "xf_config.h"

XF_BEGIN_DECLS

static inline void xf_put_u16le(uint8_t *p, uint16_t v)
{
    p[0] = (uint8_t)(v & 0xFFu);
    p[1] = (uint8_t)(v >> 8);
}

static inline void xf_put_u32le(uint8_t *p, uint32_t v)
{
    p[0] = (uint8_t)(v & 0xFFu);
    p[1] = (uint8_t)((v >> 8) & 0xFFu);
    p[2] = (uint8_t)((v >> 16) & 0xFFu);
    p[3] = (uint8_t)(v >> 24);
}

static inline void xf_put_s16le(uint8_t *p, int16_t v) { xf_put_u16le(p, (uint16_t)v); }
static inline void xf_put_s32le(uint8_t *p, int32_t v) { xf_put_u32le(p, (uint32_t)v); }

static inline uint16_t xf_get_u16le(const uint8_t *p)
{
    return (uint16_t)((uint16_t)p[0] | (uint16_t)((uint16_t)p[1] << 8));
}

static inline uint32_t xf_get_u32le(const uint8_t *p)
{
    return (uint32_t)p[0] | ((uint32_t)p[1] << 8) | ((uint32_t)p[2] << 16) | ((uint32_t)p[3] << 24);
}

/* Converting an out-of-range unsigned value to a signed type is
 * implementation-defined, so the sign is rebuilt arithmetically. */
static inline int16_t xf_get_s16le(const uint8_t *p)
{
    uint16_t u = xf_get_u16le(p);
    return (u < 0x8000u) ? (int16_t)u : (int16_t)((int32_t)u - 65536);
}

static inline int32_t xf_get_s32le(const uint8_t *p)
{
    uint32_t u = xf_get_u32le(p);
    return (u < 0x80000000u) ? (int32_t)u : (int32_t)((int64_t)u - 4294967296LL);
}

static inline int8_t xf_u8_to_s8(uint8_t u) { return (u < 0x80u) ? (int8_t)u : (int8_t)((int)u - 256); }

XF_END_DECLS

#endif /* XF_BYTES_H */
