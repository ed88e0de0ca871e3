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
 * - ::XF_PACKET_MAX_LEN: largest packet the parser accepts and holds,
 *   84..255 (default 255, the protocol's own limit). An MCU that only
 *   receives GCU replies (72 or 73 bytes) may set 84 to save RAM; longer
 *   packets are then counted as length errors.
 * - ::XF_PARSER_SLOTS: candidates the parser checks at once, 1..16
 *   (default 4): more resist more crafted false headers, at 1 byte of RAM
 *   each and more work per byte on such a stream (docs/codec.md).
 * - ::XF_ASSERT: define to check the internal invariants and preconditions
 *   of the codec, the client and the simulator (the tests, the fuzzers and
 *   the project's own Debug builds of the libraries do); by default it
 *   compiles to nothing.
 * - `XF_IMPLEMENTATION`: defined in exactly one translation unit (the
 *   library's src/xf_codec.c, or one file of yours), before the first
 *   include, where the codec's functions and tables are defined (::XF_API).
 * - ::XF_NO_LIBC: 0 (default) memcpy, memset and memchr from `<string.h>`;
 *   1 for freestanding targets without a C library (riscv64-unknown-elf
 *   -nostdlib, say): small loops of our own, and `<string.h>` is never
 *   included.
 * - ::XF_MEMCPY, ::XF_MEMMOVE, ::XF_MEMSET, ::XF_MEMCHR (xf_mem.h): define to use your own
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
 * flash). Must be 0 or 1.
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

#ifdef XF_PARSER_MEMO
#error                                                                                                                 \
    "XF_PARSER_MEMO is gone: the parser has no memo any more; XF_PARSER_SLOTS sets how many candidates it checks at once"
#endif
/**
 * Candidates (a header pair and a valid length) the parser checks at once,
 * 1..16 (default 4). A valid header that arrives while this many are pending
 * is not followed (xf_parser_stats::given_up counts them); the parser's
 * worst cost per byte grows with it (docs/codec.md). Each slot costs 1 byte
 * of RAM.
 */
#ifndef XF_PARSER_SLOTS
#define XF_PARSER_SLOTS 4
#endif
#if XF_PARSER_SLOTS < 1 || XF_PARSER_SLOTS > 16
#error "XF_PARSER_SLOTS must be in [1, 16]"
#endif

/**
 * Check an internal invariant or precondition (of the codec, and of the
 * client's and the simulator's internal functions). By default nothing is
 * compiled; the tests and fuzzers define it (before any xfgcu header, in the
 * translation unit that defines `XF_IMPLEMENTATION`), and the project's own
 * Debug builds define it for the libraries (src/CMakeLists.txt), to stop on
 * a broken one. @p cond has no side effects.
 */
#ifndef XF_ASSERT
#define XF_ASSERT(cond) ((void)0)
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
 * xf_sim, xf_client): XF_PACKET_MAX_LEN, XF_PARSER_SLOTS, XF_CLIENT_QUEUE and
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
    ((unsigned long)XF_PACKET_MAX_LEN | ((unsigned long)XF_PARSER_SLOTS << 8) |                                        \
     ((unsigned long)XF_CLIENT_QUEUE << 13) | ((unsigned long)XF_CLIENT_RESULTS << 20))

/* Internal: the symbol of one option's value, and the list of the options. */
#define XF__OPTION_SYM(name, value)  XF__OPTION_SYM_(name, value)
#define XF__OPTION_SYM_(name, value) xf_option_XF_##name##_is_##value
#define XF__OPTIONS(X)                                                                                                 \
    X(PACKET_MAX_LEN, XF_PACKET_MAX_LEN)                                                                               \
    X(PARSER_SLOTS, XF_PARSER_SLOTS)                                                                                   \
    X(CLIENT_QUEUE, XF_CLIENT_QUEUE)                                                                                   \
    X(CLIENT_RESULTS, XF_CLIENT_RESULTS)
#define XF__OPTION_DECLARE(name, value) extern const unsigned char XF__OPTION_SYM(name, value);
/* a term of the sum in XF_OPTIONS_CHECK, so it cannot be parenthesised */
#define XF__OPTION_READ(name, value) +XF__OPTION_SYM(name, value) /* NOLINT(bugprone-macro-parentheses) */

/**
 * The option word passed by the init macros: XF_OPTIONS_WORD, plus the
 * library's option symbols (each 0), read so that the linker must find them.
 */
#define XF_OPTIONS_CHECK ((unsigned long)(XF_OPTIONS_WORD XF__OPTIONS(XF__OPTION_READ)))

/**
 * Storage class of every codec function: external linkage, so that each
 * function and each table is defined once in a program, in the one
 * translation unit that defines `XF_IMPLEMENTATION` (the stb way). The
 * compiled library (src/xf_codec.c, the `xfgcu::codec` target) is that
 * translation unit; without it, put
 * @code
 *   #define XF_IMPLEMENTATION
 *   #include "xfgcu/xfgcu.h"
 * @endcode
 * in one .c file of yours. Define `XF_API` yourself to add attributes.
 */
#ifndef XF_API
#define XF_API
#endif

/**
 * 1 in the translation unit that defines `XF_IMPLEMENTATION`, where the
 * headers emit the codec's definitions (functions, tables, the option
 * symbols); 0 elsewhere, where they only declare.
 */
#ifdef XF_IMPLEMENTATION
#define XF_EMIT_DEFINITIONS 1
#else
#define XF_EMIT_DEFINITIONS 0
#endif

/* Internal: a function kept out of line (GCC, clang), so that its caller stays small: the
 * parser's rare and bulk work, away from the byte it takes most often. */
#if defined(__GNUC__)
#define XF__NOINLINE __attribute__((noinline)) static
#else
#define XF__NOINLINE static
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
#if XF_EMIT_DEFINITIONS
#define XF__OPTION_DEFINE(name, value) const unsigned char XF__OPTION_SYM(name, value) = 0;
XF__OPTIONS(XF__OPTION_DEFINE)
#endif
XF_END_DECLS

#endif /* XF_CONFIG_H */
