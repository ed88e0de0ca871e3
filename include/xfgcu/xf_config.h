/*
 * xf_config.h - compile-time configuration of xfgcu.
 *
 * Every option has an #ifndef default here; override with -D or put your
 * overrides in a header named by XF_CONFIG_HEADER (-DXF_CONFIG_HEADER='"my_xf.h"').
 * Options shrink or speed up the library; none of them changes a public
 * signature.
 *
 *   XF_CRC_TABLE_256      0 (default): the vendor's 16-entry nibble table
 *                         (64 bytes of flash, two lookups per byte).
 *                         1: a 256-entry table (1 KB of flash, about
 *                         half the instructions per byte).
 *   XF_PACKET_MAX_LEN     largest packet the parser and the packet structs
 *                         hold, 84..255 (default 255, the protocol's own
 *                         limit). An MCU that only receives GCU replies
 *                         (72 or 73 bytes) may set 84 to save RAM; longer
 *                         packets are then counted as length errors.
 *   XF_PARSER_MEMO        1 (default): the parser keeps, for each byte in its
 *                         ring, the (normalised) CRC before it, so checking
 *                         any candidate costs O(1) and adversarial input O(1)
 *                         per byte. 0: 2 bytes per ring slot less RAM (260 B
 *                         with XF_PACKET_MAX_LEN <= 127) and ~4 KB less flash;
 *                         candidates after a failure are checked by re-reading
 *                         them, still exact, at O(packet length) each on
 *                         adversarial input.
 *   XF_SEPARATE_IMPLEMENTATION
 *                         undefined (default): every function is
 *                         `static inline` in the headers (header-only).
 *                         Defined: the headers only declare; compile
 *                         src/xf_codec.c once (it defines XF_IMPLEMENTATION)
 *                         so the code exists once in flash.
 *   XF_API                storage class of every function; derived from the
 *                         option above unless you define it yourself.
 *   XF_NO_LIBC            0 (default): memcpy, memset and memchr from <string.h>.
 *                         1: freestanding targets without a C library (e.g.
 *                         riscv64-unknown-elf -nostdlib): small loops of our
 *                         own, and <string.h> is never included.
 *   XF_MEMCPY, XF_MEMSET, XF_MEMCHR
 *                         define to use your own (an optimised or DMA copy).
 */
#ifndef XF_CONFIG_H
#define XF_CONFIG_H

#ifdef XF_CONFIG_HEADER
#include XF_CONFIG_HEADER
#endif

#if !defined(__cplusplus) && (!defined(__STDC_VERSION__) || (__STDC_VERSION__ < 199901L))
#error "xfgcu needs ISO C99 or newer"
#endif

#ifndef XF_CRC_TABLE_256
#define XF_CRC_TABLE_256 0
#endif
#if (XF_CRC_TABLE_256 != 0) && (XF_CRC_TABLE_256 != 1)
#error "XF_CRC_TABLE_256 must be 0 or 1"
#endif

#ifndef XF_PACKET_MAX_LEN
#define XF_PACKET_MAX_LEN 255
#endif
#if (XF_PACKET_MAX_LEN < 84) || (XF_PACKET_MAX_LEN > 255)
#error "XF_PACKET_MAX_LEN must be in [84, 255]: 84 is the longest packet of the protocol, 255 its limit"
#endif

#ifndef XF_NO_LIBC
#define XF_NO_LIBC 0
#endif
#if (XF_NO_LIBC != 0) && (XF_NO_LIBC != 1)
#error "XF_NO_LIBC must be 0 or 1"
#endif

#ifndef XF_PARSER_MEMO
#define XF_PARSER_MEMO 1
#endif
#if (XF_PARSER_MEMO != 0) && (XF_PARSER_MEMO != 1)
#error "XF_PARSER_MEMO must be 0 or 1"
#endif

#ifndef XF_API
#ifdef XF_SEPARATE_IMPLEMENTATION
#define XF_API
#else
#define XF_API static inline
#endif
#endif

/* Definitions are emitted in header-only mode, or in the one translation
 * unit that defines XF_IMPLEMENTATION. */
#if !defined(XF_SEPARATE_IMPLEMENTATION) || defined(XF_IMPLEMENTATION)
#define XF_EMIT_DEFINITIONS 1
#else
#define XF_EMIT_DEFINITIONS 0
#endif

/* Internal: the parser's per-candidate check is inlined into its hot loop
 * even where the compiler's size heuristics would not (GCC, clang). */
#if defined(__GNUC__)
#define XF__HOT_INLINE __attribute__((always_inline)) static inline
#else
#define XF__HOT_INLINE static inline
#endif

/* C99 has no static_assert: a negative array size fails the build. */
#define XF_STATIC_ASSERT(cond, name) typedef char xf__static_assert_##name[(cond) ? 1 : -1]

#ifdef __cplusplus
#define XF_BEGIN_DECLS extern "C" {
#define XF_END_DECLS   }
#else
#define XF_BEGIN_DECLS
#define XF_END_DECLS
#endif

#endif /* XF_CONFIG_H */
