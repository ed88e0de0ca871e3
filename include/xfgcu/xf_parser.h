/**
 * @file
 * @brief Streaming parser: bytes in any chunking, whole frames out, each from
 * the call that feeds its last byte.
 *
 * Caller-owned state (under 300 bytes with the default options), no
 * allocation, no static data, no blocking; use a parser from one thread. It
 * returns each frame whose header (for the configured direction), length (in
 * [72, ::XF_PACKET_MAX_LEN]) and CRC are right.
 *
 * How. A *candidate* is a header pair followed by a valid length. The parser
 * keeps up to ::XF_PARSER_SLOTS candidates at once, first come, first
 * served, and checks each when its last byte arrives: the first intact one is
 * returned at once, and the others, which overlap it, are dropped. So a frame
 * behind noise, a truncated packet, a false header or a bogus length comes out
 * on time. A valid header that arrives while every slot is taken is not
 * followed (stats.given_up counts them: each may be a lost frame). The slots
 * bound the work any input can cause; docs/codec.md states the rules and the
 * bound.
 *
 * Counters only ever increase (the application may zero them):
 *
 * @code{.unparsed}
 *     bytes_in = bytes of returned frames + bytes_skipped + xf_parser_pending()
 * @endcode
 */
#ifndef XF_PARSER_H
#define XF_PARSER_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include "xf_config.h"
#include "xf_mem.h"
#include "xf_packet.h"
#include "xf_crc.h"
#include "xf_error.h"
#include "xf_protocol.h"

XF_BEGIN_DECLS

/** Counters; each only increases. */
typedef struct xf_parser_stats {
    uint32_t bytes_in;      /**< bytes fed */
    uint32_t frames;        /**< valid frames returned */
    uint32_t crc_errors;    /**< candidates (header and valid length) whose CRC failed */
    uint32_t length_errors; /**< header pairs followed by a length outside [72, XF_PACKET_MAX_LEN] */
    uint32_t bytes_skipped; /**< bytes dropped as part of no valid frame */
    uint32_t given_up;      /**< headers with a valid length not followed because every slot was taken: each
                                 may be a frame lost (docs/codec.md); 0 means no frame was */
} xf_parser_stats;

/* Private: what the parser is doing, stored, and each byte's rules depend on it. HUNT: no
 * candidate, at most the last three bytes held (they may begin a header); BUSY: candidates
 * pending and a slot free, so a valid header becomes a candidate; FULL: every slot taken, so a
 * valid header is given up. */
typedef enum xf__mode { XF__HUNT, XF__BUSY, XF__FULL } xf__mode;

/** Parser state. Treat the members as private except `stats`. */
typedef struct xf_parser {
    xf_parser_stats stats; /**< counters, readable at any time; the application may zero them */
    uint32_t last4;        /**< private: the last four bytes fed since the last frame or reset, the latest in
                                the low byte; zeros before them (no header begins there) */
    uint32_t pair;         /**< private: the header pair of the direction parsed, placed as in last4: h0 h1 0 0 */
    uint8_t buf[XF_PACKET_MAX_LEN]; /**< private: with candidates pending, the bytes held, the first at index 0 */
    uint8_t at[XF_PARSER_SLOTS];    /**< private: where each pending candidate begins in buf, in order of start */
    uint8_t held;                   /**< private: bytes held (xf_parser_pending()); with no candidate at most
                                         three, kept in last4 */
    uint8_t next;                   /**< private: with candidates pending, `held` once the soonest one ends */
    uint8_t n;                      /**< private: candidates pending */
    uint8_t mode;                   /**< private: an xf__mode */
} xf_parser;

/**
 * Start a parser for packets sent in direction @p dir (::XF_DIR_GCU on a
 * host): empty, counters zero. A macro over xf_parser_init_checked(), which
 * checks that the caller and the codec were built with the same layout
 * options (xf_config.h).
 * @param p    the parser's storage
 * @param dir  the direction of the packets to find; others are skipped
 * @return ::XF_OK, ::XF_ERR_ARG (NULL @p p, or @p dir not a direction),
 *   ::XF_ERR_CONFIG (built with other options)
 */
#define xf_parser_init(p, dir) xf_parser_init_checked((p), (dir), XF_OPTIONS_CHECK, sizeof(xf_parser))

/**
 * What xf_parser_init() calls, with the caller's build options: use the
 * macro (a foreign-function interface passes xf_options_word() and
 * xf_parser_size()).
 * @param p        the parser's storage
 * @param dir      the direction of the packets to find
 * @param options  the caller's ::XF_OPTIONS_WORD
 * @param size     the caller's sizeof(xf_parser)
 * @return as xf_parser_init(); ::XF_ERR_CONFIG when @p options or @p size
 *   differ from the codec's (nothing is written to @p p)
 */
XF_API xf_err xf_parser_init_checked(xf_parser *p, xf_direction dir, unsigned long options, size_t size);

/**
 * sizeof(xf_parser) in the compiled codec (for a foreign-function interface).
 * @return the size in bytes
 */
XF_API size_t xf_parser_size(void);

/**
 * ::XF_OPTIONS_WORD of the compiled codec (for a foreign-function interface).
 * @return the layout options the codec was built with
 */
XF_API unsigned long xf_options_word(void);

/**
 * Drop the bytes held (counted as skipped); keep the direction and the
 * counters. Does nothing for a NULL @p p.
 * @param p  the parser
 */
XF_API void xf_parser_reset(xf_parser *p);

/**
 * Bytes held that belong to no returned frame yet.
 * @param p  the parser
 * @return the number of bytes, 0 for a NULL @p p
 */
XF_API size_t xf_parser_pending(const xf_parser *p);

/**
 * What xf_parser_feed() and xf_parser_flush() return: a frame, no frame, or
 * an error. Its own type, not an ::xf_err: the results are not errors, and
 * no ::xf_err value equals ::XF_PARSE_FRAME. Its negative values are exactly
 * the ::xf_err codes the two functions can return, with the same values
 * (today only ::XF_ERR_ARG), so `r < 0` is an error and `xf_strerror(r)`
 * describes it.
 */
typedef enum xf_parse_status {
    XF_PARSE_ERR_ARG = XF_ERR_ARG, /**< ::XF_ERR_ARG: a NULL parser or frame, or NULL data with a length */
    XF_PARSE_MORE = 0, /**< no frame: every byte given was taken (feed), or nothing is held any more (flush) */
    XF_PARSE_FRAME = 1 /**< *frame holds a frame */
} xf_parse_status;

/**
 * Feed @p len bytes. Stops right after the first frame's last byte: returns
 * ::XF_PARSE_FRAME with *frame set and *consumed = the bytes of @p data taken
 * up to and including that byte; call again with the rest. Returns
 * ::XF_PARSE_MORE when every byte was taken and no frame is complete, or
 * ::XF_PARSE_ERR_ARG. A frame is always returned by the call that feeds its
 * last byte (no frame waits in the parser for more input).
 *
 * @code
 * size_t n; xf_frame f;
 * while (xf_parser_feed(&p, data, len, &n, &f) == XF_PARSE_FRAME) {
 *     handle(f.data, f.len);
 *     data += n; len -= n;
 * }
 * @endcode
 *
 * The frame's bytes are in the parser; they stay valid until the next call
 * on it.
 *
 * Cost: linear in the bytes taken, whatever they are: each byte is stored
 * once and, with K = ::XF_PARSER_SLOTS, CRC'd and moved at most K + 1 times
 * each, besides a fixed amount per call (docs/codec.md; the measured ceiling
 * is in docs/performance.md). It never allocates and never blocks.
 * @param p         the parser
 * @param data      the bytes received; may be NULL when @p len is 0
 * @param len       number of bytes at @p data
 * @param consumed  receives how many bytes of @p data were taken (may be NULL)
 * @param frame     receives the frame when ::XF_PARSE_FRAME is returned
 * @return ::XF_PARSE_FRAME, ::XF_PARSE_MORE, or ::XF_PARSE_ERR_ARG (NULL @p p
 *   or @p frame, or NULL @p data with @p len > 0; nothing is done)
 */
XF_API xf_parse_status xf_parser_feed(xf_parser *p, const uint8_t *data, size_t len, size_t *consumed, xf_frame *frame);

/**
 * The input has ended (end of file, link closed): drop the candidates that
 * can no longer complete; the bytes held count as skipped and the next byte
 * fed starts afresh. Every intact frame has already been returned by the
 * feed that completed it, so this returns ::XF_PARSE_MORE; a loop written
 * for parsers that hold frames back (`while (flush == XF_PARSE_FRAME)`)
 * works unchanged.
 * @param p      the parser
 * @param frame  would receive a frame; never written
 * @return ::XF_PARSE_MORE (nothing held any more), or ::XF_PARSE_ERR_ARG
 *   (NULL @p p or @p frame)
 */
XF_API xf_parse_status xf_parser_flush(xf_parser *p, xf_frame *frame);

#if XF_EMIT_DEFINITIONS

/* Chunks shorter than this go byte by byte: for so few bytes the accelerator's search and copy
 * cost more than the rule path's tests. */
#define XF__BULK 8u
/* last4 starts at zero, and its zeros stand for no byte at all: right only because no header
 * begins with a zero. */
XF_STATIC_ASSERT(XF_GCU_HEADER0 != 0u && XF_HOST_HEADER0 != 0u, zeros_begin_no_header);

XF_API size_t xf_parser_size(void) { return sizeof(xf_parser); }

XF_API unsigned long xf_options_word(void) { return XF_OPTIONS_WORD; }

/* The mode that n candidates pending make (rule 3). */
static uint8_t xf__mode_of(unsigned n) { return (uint8_t)(!n ? XF__HUNT : n < XF_PARSER_SLOTS ? XF__BUSY : XF__FULL); }

/* Nothing held, no candidate, and no byte before this point begins a header (rule 1's floor):
 * without the zeroed window, a frame's last bytes could begin a false candidate that would then
 * claim the next frame's bytes and hold its slot. */
static void xf__empty(xf_parser *p)
{
    p->last4 = 0;
    p->held = 0;
    p->n = 0;
    p->mode = XF__HUNT;
}

XF_API xf_err xf_parser_init_checked(xf_parser *p, xf_direction dir, unsigned long options, size_t size)
{
    if (options != XF_OPTIONS_WORD || size != sizeof(xf_parser)) {
        return XF_ERR_CONFIG; /* the caller's xf_parser is not ours: writing to it would overrun it */
    }
    if (p == NULL || (dir != XF_DIR_HOST && dir != XF_DIR_GCU)) {
        return XF_ERR_ARG;
    }
    XF_MEMSET(p, 0, sizeof(*p));
    p->pair = (dir == XF_DIR_HOST) ? (XF_HOST_HEADER0 << 24 | XF_HOST_HEADER1 << 16)
                                   : (XF_GCU_HEADER0 << 24 | XF_GCU_HEADER1 << 16);
    return XF_OK; /* (all zero: empty and hunting, as xf__empty leaves it) */
}

XF_API size_t xf_parser_pending(const xf_parser *p) { return (p == NULL) ? 0u : p->held; }

XF_API void xf_parser_reset(xf_parser *p)
{
    if (p != NULL) {
        p->stats.bytes_skipped += p->held;
        xf__empty(p);
    }
}

/* Length and end (in buf) of pending candidate k: its header is held as long as it is pending. */
static unsigned xf__len(const xf_parser *p, unsigned k) { return p->buf[p->at[k] + 2u]; }

static unsigned xf__end(const xf_parser *p, unsigned k) { return p->at[k] + xf__len(p, k); }

/* Rule 3: the last byte completed a valid header (w: the last four bytes) and a slot is free: a
 * candidate, the last in order of start. The first since none was pending gets its header
 * written at index 0 (hunting, the bytes are in last4 only). */
static void xf__admit(xf_parser *p, uint32_t w)
{
    const unsigned k = (p->n < XF_PARSER_SLOTS) ? p->n : XF_PARSER_SLOTS - 1u; /* (the bound is for the compiler) */
    unsigned j;
    XF_ASSERT(p->mode != XF__FULL && p->n < XF_PARSER_SLOTS && p->held >= ((k == 0u) ? 4u : 8u));
    for (j = 0; k == 0u && j < 4u; j++) { /* the first: the window is its header */
        p->buf[j] = (uint8_t)(w >> (24u - 8u * j));
    }
    p->at[k] = (uint8_t)(p->held - 4u);
    p->n = (uint8_t)(k + 1u);
    p->next = (k == 0u || xf__end(p, k) < p->next) ? (uint8_t)xf__end(p, k) : p->next;
    p->mode = xf__mode_of(k + 1u);
}

/* After failed checks: the bytes before the earliest candidate left are skipped, and it moves to
 * index 0; with none left, the last four bytes stay (rule 4 then drops the first unless they are
 * a header). next: the soonest end. */
static void xf__settle(xf_parser *p)
{
    const unsigned shift = (p->n > 0u) ? p->at[0] : p->held - 4u;
    unsigned k, soon = 2u * XF_PACKET_MAX_LEN;
    p->stats.bytes_skipped += shift;
    XF_MEMMOVE(p->buf, p->buf + shift, p->held - shift);
    p->held = (uint8_t)(p->held - shift);
    for (k = 0; k < p->n && k < XF_PARSER_SLOTS; k++) { /* (the bound is for the compiler) */
        p->at[k] = (uint8_t)(p->at[k] - shift);
        soon = (xf__end(p, k) < soon) ? xf__end(p, k) : soon;
    }
    XF_ASSERT(p->n == 0u || (soon > p->held && soon <= XF_PACKET_MAX_LEN));
    p->next = (uint8_t)soon;
    p->mode = xf__mode_of(p->n);
}

/* Rule 2: the last byte held ends one candidate or more: check them, earliest start first. The
 * first intact one is returned (1) and everything held goes with it (it all overlaps the frame),
 * the bytes before it skipped; a failed one goes, and the others keep their order. */
static int xf__ends(xf_parser *p, xf_frame *frame)
{
    unsigned k = 0, j;
    XF_ASSERT(p->mode != XF__HUNT && p->n > 0u && p->held == p->next);
    while (k < p->n) {
        const bool ends_here = xf__end(p, k) == p->held;
        const bool intact = ends_here && xf_crc16(p->buf + p->at[k], xf__len(p, k)) == 0u;
        if (intact) {
            frame->data = p->buf + p->at[k];
            frame->len = xf__len(p, k);
            p->stats.frames++;
            p->stats.bytes_skipped += p->at[k];
            xf__empty(p);
            return 1;
        }
        if (!ends_here) {
            k++;
            continue;
        }
        p->stats.crc_errors++;
        for (p->n--, j = k; j < p->n && j + 1u < XF_PARSER_SLOTS; j++) { /* (the bound is for the compiler) */
            p->at[j] = p->at[j + 1u];
        }
    }
    xf__settle(p);
    return 0;
}

/* A byte that needs a look (w: the last four bytes, the byte stored), the rules in their order:
 * 2, the candidates that end with it; 1 and 3, the header pair it completes; 4, hunting, three
 * bytes held at most. 1 when it completes a frame. Why the checks come first: a candidate that
 * fails on this byte frees its slot for a header this byte completes (looked at first, that
 * header would be given up with every slot taken, and its frame lost), and a frame returned
 * here drops whatever its last bytes begin. */
XF__NOINLINE int xf__look(xf_parser *p, uint32_t w, xf_frame *frame)
{
    const unsigned len = (w >> 8) & 0xFFu;
    const bool pair = (w & 0xFFFF0000u) == p->pair;
    const bool valid = pair && (w & 0xFFu) == 0u && len >= XF_PACKET_MIN_LEN && len <= XF_PACKET_MAX_LEN;
    XF_ASSERT(p->mode == xf__mode_of(p->n) && p->held <= XF_PACKET_MAX_LEN && p->last4 == w);
    if (p->mode != XF__HUNT && p->held == p->next && xf__ends(p, frame)) {
        return 1;
    }
    if (pair && !valid) {
        p->stats.length_errors++;
    } else if (valid && p->mode == XF__FULL) {
        p->stats.given_up++; /* a frame that begins here is lost */
    } else if (valid) {
        xf__admit(p, w);
    }
    if (p->mode == XF__HUNT && p->held > 3u) {
        p->held = 3;
        p->stats.bytes_skipped++;
    }
    return 0;
}

/* The rule path: one byte through every rule (docs/codec.md). It is stored (with candidates
 * pending) or counted, and looked at when it may end a candidate, complete a header pair, or
 * make four bytes held while hunting. 1 when it completes a frame. */
static inline int xf__byte(xf_parser *p, uint8_t b, xf_frame *frame)
{
    const uint32_t w = (p->last4 << 8) | b;
    const bool busy = p->mode != XF__HUNT;
    p->last4 = w;
    if (busy) {
        p->buf[p->held] = b;
    }
    p->held++;
    if ((busy && p->held == p->next) || (w & 0xFFFF0000u) == p->pair || (!busy && p->held > 3u)) {
        return xf__look(p, w, frame);
    }
    return 0;
}

/* The accelerator, which decides nothing: how many of the n bytes at d the rule path would only
 * store, since none of them ends a candidate (they come before the soonest end's last byte) and
 * none can complete a header pair (no h0 three bytes before it). It stops at any h0, not only at
 * h0 h1: a stricter search would have to re-state the pair test, and one that misses a pair lets
 * a frame's header go by unseen (the fuzzers compare every chunking with the model). */
static size_t xf__quiet(const xf_parser *p, const uint8_t *d, size_t n)
{
    const unsigned h0 = p->pair >> 24u, w = p->last4;
    size_t near; /* the first byte of d that a pair begun among the last three bytes held could complete */
    for (near = 0; near < 3u && ((w >> (16u - 8u * near)) & 0xFFu) != h0; near++) {
    }
    const size_t left = (p->mode == XF__HUNT) ? n : (size_t)(p->next - p->held - 1u); /* before the soonest end */
    const size_t m = (left < n) ? left : n;
    const uint8_t *hit;
    XF_ASSERT(p->mode == XF__HUNT || p->next > p->held);
    if (m <= near || near < 3u) {
        return (near < m) ? near : m;
    }
    hit = (const uint8_t *)XF_MEMCHR(d, (int)h0, m);
    return (hit == NULL || (size_t)(hit - d) + 3u > m) ? m : (size_t)(hit - d) + 3u;
}

/* The accelerator's copy: store the m bytes at d as the rule path would, in bulk (hunting, the
 * last three held and the others skipped, rule 4); returns m. */
static size_t xf__keep(xf_parser *p, const uint8_t *d, size_t m)
{
    const size_t keep = (p->held + m < 3u) ? p->held + m : 3u;
    uint32_t w = p->last4;
    size_t i;
    if (p->mode == XF__HUNT) {
        p->stats.bytes_skipped += (uint32_t)(p->held + m - keep);
        p->held = (uint8_t)keep;
    } else if (m > 0u) {
        XF_ASSERT(p->held + m < p->next);
        XF_MEMCPY(p->buf + p->held, d, m);
        p->held = (uint8_t)(p->held + m);
    }
    for (i = (m > 4u) ? m - 4u : 0u; i < m; i++) { /* the window: the last four bytes */
        w = (w << 8) | d[i];
    }
    p->last4 = w;
    return m;
}

/* Any number of bytes but one: each through the rule path, up to a frame's last byte, the
 * accelerator taking what it can first while XF__BULK bytes or more are left. */
XF__NOINLINE xf_parse_status xf__feed(xf_parser *p, const uint8_t *data, size_t len, size_t *consumed, xf_frame *frame)
{
    size_t i = 0;
    int found = 0;
    while (i < len && !found) {
        i += (len - i >= XF__BULK) ? xf__keep(p, data + i, xf__quiet(p, data + i, len - i)) : 0u;
        found = i < len && xf__byte(p, data[i++], frame);
    }
    p->stats.bytes_in += (uint32_t)i;
    if (consumed != NULL) {
        *consumed = i;
    }
    return found ? XF_PARSE_FRAME : XF_PARSE_MORE;
}

XF_API xf_parse_status xf_parser_feed(xf_parser *p, const uint8_t *data, size_t len, size_t *consumed, xf_frame *frame)
{
    if (p == NULL || frame == NULL || (data == NULL && len > 0u)) {
        return XF_PARSE_ERR_ARG;
    }
    if (len != 1u) {
        return xf__feed(p, data, len, consumed, frame);
    }
    /* A byte fed alone (an interrupt handler's feed) takes the rule path with no loop around it,
     * and so with no stack frame. */
    p->stats.bytes_in++;
    if (consumed != NULL) {
        *consumed = 1;
    }
    return (xf_parse_status)xf__byte(p, data[0], frame); /* 1 is XF_PARSE_FRAME, 0 XF_PARSE_MORE */
}

/* cppcheck-suppress constParameter ; frame stays writable: a parser that holds frames back may fill it */
XF_API xf_parse_status xf_parser_flush(xf_parser *p, xf_frame *frame)
{
    if (p == NULL || frame == NULL) {
        return XF_PARSE_ERR_ARG;
    }
    xf_parser_reset(p);
    return XF_PARSE_MORE;
}

#endif /* XF_EMIT_DEFINITIONS */

XF_END_DECLS

#endif /* XF_PARSER_H */
