/**
 * @file
 * @brief Compile-time configuration of xfgcu.
 *
 * Every option has an `#ifndef` default here; override with -D or put your
 * overrides in a header named by `XF_CONFIG_HEADER` (-DXF_CONFIG_HEADER='"my_xf.h"'),
 * which this header includes first. Options shrink or speed up the library;
 * none of them changes a public signature. What each costs or saves in flash,
 * RAM and instructions is measured in docs/performance.md.
 *
 * - ::XF_CRC_TABLE_256: 0 (default) the vendor's 16-entry nibble table, two
 *   lookups per byte; 1 a 256-entry table, one lookup per byte.
 * - ::XF_PACKET_MAX_LEN: largest packet the parser and the packet structs
 *   hold, 84..255 (default 255, the protocol's own limit). An MCU that only
 *   receives GCU replies (72 or 73 bytes) may set 84 to save RAM; longer
 *   packets are then counted as length errors.
 * - ::XF_PARSER_MEMO: 1 (default) the parser keeps, for each byte in its
 *   ring, the (normalised) CRC before it, so checking any candidate costs
 *   O(1) and adversarial input O(1) per byte; 0 keeps no memo (a 16-bit value
 *   less per ring slot, and less flash): candidates after a failure are
 *   checked by re-reading them, still exact, at O(packet length) each on
 *   adversarial input.
 * - `XF_SEPARATE_IMPLEMENTATION`: undefined (default) every function is
 *   `static inline` in the headers (header-only). Defined (in every
 *   translation unit): the headers only declare; compile src/xf_codec.c once
 *   (it defines `XF_IMPLEMENTATION`) so the code exists once in flash.
 * - ::XF_API: storage class of every function; derived from the option above
 *   unless you define it yourself.
 * - ::XF_NO_LIBC: 0 (default) memcpy, memset and memchr from `<string.h>`;
 *   1 for freestanding targets without a C library (riscv64-unknown-elf
 *   -nostdlib, say): small loops of our own, and `<string.h>` is never
 *   included.
 * - ::XF_MEMCPY, ::XF_MEMSET, ::XF_MEMCHR (xf_mem.h): define to use your own
 *   (an optimised or DMA copy).
 *
 * Every option is checked here: a value out of range stops the build with an
 * `#error`, as does a compiler older than C99.
 */
#ifndef XF_CONFIG_H
#define XF_CONFIG_H

#ifdef XF_CONFIG_HEADER
#include XF_CONFIG_HEADER
#endif

#if !defined(__cplusplus) && (!defined(__STDC_VERSION__) || (__STDC_VERSION__ < 199901L))
#error "xfgcu needs ISO C99 or newer"
#endif

/**
 * CRC-16 table of xf_crc.h: 0 (default) the vendor's 16-entry nibble table
 * (two lookups per byte); 1 a 256-entry byte table (one lookup per byte, more
 * flash). The parser's memo tables grow with it. Must be 0 or 1.
 */
#ifndef XF_CRC_TABLE_256
#define XF_CRC_TABLE_256 0
#endif
#if (XF_CRC_TABLE_256 != 0) && (XF_CRC_TABLE_256 != 1)
#error "XF_CRC_TABLE_256 must be 0 or 1"
#endif

/**
 * Largest packet, in bytes, that the parser and the packet structs hold:
 * 84..255, default 255 (::XF_PACKET_LIMIT, the protocol's own bound). 84 is
 * the longest packet of any known order; a host that only receives GCU
 * replies (72 or 73 bytes) may set 84 to save RAM. Longer packets are then
 * counted as length errors by the parser and refused by xf_packet_check()
 * (::XF_ERR_LENGTH).
 */
#ifndef XF_PACKET_MAX_LEN
#define XF_PACKET_MAX_LEN 255
#endif
#if (XF_PACKET_MAX_LEN < 84) || (XF_PACKET_MAX_LEN > 255)
#error "XF_PACKET_MAX_LEN must be in [84, 255]: 84 is the longest packet of the protocol, 255 its limit"
#endif

/**
 * Freestanding build without a C library: 0 (default) memcpy, memset and
 * memchr come from `<string.h>`; 1 the codec and client use small loops of
 * their own and never include `<string.h>` (see ::XF_MEMCPY). The simulator
 * and the POSIX links need a C library either way. Must be 0 or 1.
 */
#ifndef XF_NO_LIBC
#define XF_NO_LIBC 0
#endif
#if (XF_NO_LIBC != 0) && (XF_NO_LIBC != 1)
#error "XF_NO_LIBC must be 0 or 1"
#endif

/**
 * Parser memo: 1 (default) the parser keeps, for each byte it holds, the
 * normalised CRC of the stream before it (xf_crc.h), so any candidate frame
 * is checked in constant time and adversarial input costs O(1) per byte.
 * 0: no memo, less RAM per parser and less flash; a candidate is checked by
 * reading its bytes again, still exact, at O(packet length) per candidate on
 * adversarial input. Must be 0 or 1.
 */
#ifndef XF_PARSER_MEMO
#define XF_PARSER_MEMO 1
#endif
#if (XF_PARSER_MEMO != 0) && (XF_PARSER_MEMO != 1)
#error "XF_PARSER_MEMO must be 0 or 1"
#endif

#ifndef XF_CLIENT_QUEUE
/** Commands waiting to run, per client, 1..64 (default 8). */
#define XF_CLIENT_QUEUE 8
#endif
#ifndef XF_CLIENT_RESULTS
/** Finished commands kept per client for polling by id, 1..64 (default 8). */
#define XF_CLIENT_RESULTS 8
#endif
#if XF_CLIENT_QUEUE < 1 || XF_CLIENT_QUEUE > 64 || XF_CLIENT_RESULTS < 1 || XF_CLIENT_RESULTS > 64
#error "XF_CLIENT_QUEUE and XF_CLIENT_RESULTS must be in [1, 64]"
#endif

/*
 * Options that change the size or layout of a public struct (xf_parser,
 * xf_sim, xf_client): XF_PACKET_MAX_LEN, XF_PARSER_MEMO, XF_CLIENT_QUEUE and
 * XF_CLIENT_RESULTS. A compiled library and the code that calls it must agree
 * on them, or a struct allocated by one is overrun by the other. So that they
 * cannot silently disagree:
 *  - the library defines one symbol per option, named after the option and
 *    the value it was built with (xf_option_XF_PACKET_MAX_LEN_is_255, ...);
 *  - xf_client_init() and xf_sim_init() are macros that refer to the symbols
 *    of the caller's values: built with other values, a program fails to link,
 *    and the linker names the option ("undefined reference to
 *    `xf_option_XF_PACKET_MAX_LEN_is_84'");
 *  - the same macros pass the caller's option word and struct size, and init
 *    returns XF_ERR_CONFIG when they differ from the library's (for callers
 *    that reach the functions some other way, such as a foreign-function
 *    interface).
 * The values of these four options must therefore be plain decimal numbers
 * (84, not 84u or (84)).
 */

/** The layout options packed in one word, as init compares them. */
#define XF_OPTIONS_WORD                                                                                                \
    ((unsigned long)XF_PACKET_MAX_LEN | ((unsigned long)XF_PARSER_MEMO << 8) | ((unsigned long)XF_CLIENT_QUEUE << 9) | \
     ((unsigned long)XF_CLIENT_RESULTS << 16))

/* Internal: the symbol of one option's value, and the list of the options. */
#define XF__OPTION_SYM(name, value)  XF__OPTION_SYM_(name, value)
#define XF__OPTION_SYM_(name, value) xf_option_XF_##name##_is_##value
#define XF__OPTIONS(X)                                                                                                 \
    X(PACKET_MAX_LEN, XF_PACKET_MAX_LEN)                                                                               \
    X(PARSER_MEMO, XF_PARSER_MEMO)                                                                                     \
    X(CLIENT_QUEUE, XF_CLIENT_QUEUE)                                                                                   \
    X(CLIENT_RESULTS, XF_CLIENT_RESULTS)
#define XF__OPTION_DECLARE(name, value) extern const unsigned char XF__OPTION_SYM(name, value);
#define XF__OPTION_READ(name, value)    +XF__OPTION_SYM(name, value)

/**
 * The option word passed by the init macros: XF_OPTIONS_WORD, plus the
 * library's option symbols (each 0), read so that the linker must find them.
 */
#define XF_OPTIONS_CHECK ((unsigned long)(XF_OPTIONS_WORD XF__OPTIONS(XF__OPTION_READ)))

/**
 * Storage class of every codec function. Header-only builds (the default)
 * get `static inline`; with `XF_SEPARATE_IMPLEMENTATION` defined it is empty
 * (external linkage, the definitions compiled once in src/xf_codec.c).
 * Define it yourself to override both.
 */
#ifndef XF_API
#ifdef XF_SEPARATE_IMPLEMENTATION
#define XF_API
#else
#define XF_API static inline
#endif
#endif

/**
 * 1 where the headers emit the codec's function definitions: in header-only
 * builds, and in the one translation unit that defines `XF_IMPLEMENTATION`
 * (src/xf_codec.c) when `XF_SEPARATE_IMPLEMENTATION` is defined. 0 elsewhere:
 * the headers only declare.
 */
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

/**
 * Compile-time assertion for C99, which has no static_assert: a typedef of an
 * array whose size is negative, and the build fails, when @p cond is false.
 * Usable at file scope.
 * @param cond  an integer constant expression that must be true
 * @param name  an identifier unique in the translation unit, naming the check
 */
#define XF_STATIC_ASSERT(cond, name) typedef char xf__static_assert_##name[(cond) ? 1 : -1]

#ifdef __cplusplus
#define XF_BEGIN_DECLS extern "C" {
#define XF_END_DECLS   }
#else
/** Opens the declarations of a header: `extern "C" {` in C++, nothing in C. */
#define XF_BEGIN_DECLS
/** Closes what ::XF_BEGIN_DECLS opened: `}` in C++, nothing in C. */
#define XF_END_DECLS
#endif

XF_BEGIN_DECLS
XF__OPTIONS(XF__OPTION_DECLARE)
XF_END_DECLS

#endif /* XF_CONFIG_H */
