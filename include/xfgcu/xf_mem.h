/**
 * @file
 * @brief The four byte-block functions the codec and client use, from
 * `<string.h>` or, with ::XF_NO_LIBC, from small loops of our own.
 *
 * Each can be replaced by defining the macro before any xfgcu header (or in
 * the `XF_CONFIG_HEADER`): an optimised or DMA copy, say. A replacement must
 * have the standard function's signature and meaning.
 */
#ifndef XF_MEM_H
#define XF_MEM_H

#include <stddef.h>
#include <stdint.h>
#include "xf_config.h"

#if XF_NO_LIBC
static inline void *xf__memcpy(void *dst, const void *src, size_t n)
{
    uint8_t *d = (uint8_t *)dst;
    const uint8_t *s = (const uint8_t *)src;
    while (n-- > 0u) {
        *d++ = *s++;
    }
    return dst;
}

/* Overlapping blocks, the destination first (the only way the parser moves bytes). */
static inline void *xf__memmove(void *dst, const void *src, size_t n)
{
    uint8_t *d = (uint8_t *)dst;
    const uint8_t *s = (const uint8_t *)src;
    if (d <= s) {
        while (n-- > 0u) {
            *d++ = *s++;
        }
    } else {
        while (n-- > 0u) {
            d[n] = s[n];
        }
    }
    return dst;
}

static inline void *xf__memset(void *dst, int v, size_t n)
{
    uint8_t *d = (uint8_t *)dst;
    while (n-- > 0u) {
        *d++ = (uint8_t)v;
    }
    return dst;
}

static inline void *xf__memchr(const void *src, int v, size_t n)
{
    const uint8_t *s = (const uint8_t *)src;
    for (; n > 0u; n--, s++) {
        if (*s == (uint8_t)v) {
            return (void *)(uintptr_t)s;
        }
    }
    return NULL;
}
#ifndef XF_MEMCPY
#define XF_MEMCPY xf__memcpy
#endif
#ifndef XF_MEMMOVE
#define XF_MEMMOVE xf__memmove
#endif
#ifndef XF_MEMSET
#define XF_MEMSET xf__memset
#endif
#ifndef XF_MEMCHR
#define XF_MEMCHR xf__memchr
#endif
#else
#include <string.h>
/** The memcpy the codec and client use: memcpy, or a loop of ours with ::XF_NO_LIBC; define it to use your own. */
#ifndef XF_MEMCPY
#define XF_MEMCPY memcpy
#endif
/** The memmove the parser uses: memmove, or a loop of ours with ::XF_NO_LIBC; define it to use your own. */
#ifndef XF_MEMMOVE
#define XF_MEMMOVE memmove
#endif
/** The memset the codec and client use: memset, or a loop of ours with ::XF_NO_LIBC; define it to use your own. */
#ifndef XF_MEMSET
#define XF_MEMSET memset
#endif
/** The memchr the parser uses: memchr, or a loop of ours with ::XF_NO_LIBC; define it to use your own. */
#ifndef XF_MEMCHR
#define XF_MEMCHR memchr
#endif
#endif

#endif /* XF_MEM_H */
