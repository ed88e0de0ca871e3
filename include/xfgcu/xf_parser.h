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

/* Private: what the parser is doing, stored; each byte's rules depend on it. */
typedef enum xf__mode {
    XF__HUNT = 0, /* no candidate: at most the last three bytes held (they may begin a header) */
    XF__BUSY,     /* candidates pending, a slot free: a valid header becomes a candidate */
    XF__FULL      /* every slot taken: a valid header is given up */
} xf__mode;

/** Parser state. Treat the members as private except `stats`. */
typedef struct xf_parser {
    xf_parser_stats stats;          /**< counters, readable at any time; the application may zero them */
    uint32_t last4;                 /**< private: the last four bytes fed since the last frame or reset, the latest in
                                         the low byte; zeros before them (no header begins there) */
    uint16_t pair;                  /**< private: the header pair of the direction parsed, h0 in the high byte */
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

#define XF__K XF_PARSER_SLOTS
/* Chunks shorter than this go byte by byte: for so few bytes the accelerator's search and copy
 * cost more than the rule path's tests. */
#define XF__BULK 8u
XF_STATIC_ASSERT(XF_PACKET_MAX_LEN <= 255u && XF_PARSER_SLOTS <= 255, indices_fit_a_byte);
/* No header pair begins inside another's first four bytes (h1 and a valid length's high byte
 * are no h0), so the rule path looks at most one pair every four bytes... every byte may still
 * complete one: the pair test runs on each. */
XF_STATIC_ASSERT(XF_GCU_HEADER0 != 0u && XF_HOST_HEADER0 != 0u, zeros_begin_no_header);

XF_API size_t xf_parser_size(void) { return sizeof(xf_parser); }

XF_API unsigned long xf_options_word(void) { return XF_OPTIONS_WORD; }

/* Nothing held, no candidate, no byte before this point begins a header (rule 1's floor). */
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
    p->pair = (dir == XF_DIR_HOST) ? (XF_HOST_HEADER0 << 8 | XF_HOST_HEADER1) : (XF_GCU_HEADER0 << 8 | XF_GCU_HEADER1);
    xf__empty(p);
    return XF_OK;
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

/* The mode that n candidates pending leave (rule 3). */
static uint8_t xf__busy(unsigned n) { return (uint8_t)((n < XF__K) ? XF__BUSY : XF__FULL); }

/* The last byte completed a valid header (w: the last four bytes) with nothing pending: the first
 * candidate, its header written at index 0. */
static void xf__first(xf_parser *p, uint32_t w)
{
    XF_ASSERT(p->mode == XF__HUNT && p->held == 4u);
    p->buf[0] = (uint8_t)(w >> 24);
    p->buf[1] = (uint8_t)(w >> 16);
    p->buf[2] = (uint8_t)(w >> 8);
    p->buf[3] = 0;
    p->at[0] = 0;
    p->n = 1;
    p->next = (uint8_t)(w >> 8);
    p->mode = xf__busy(1);
}

/* The last byte completed a valid header behind the candidates pending, with a slot free: the
 * last candidate in order of start. */
static void xf__behind(xf_parser *p)
{
    const unsigned k = p->n;
    XF_ASSERT(p->mode == XF__BUSY && k > 0u && k < XF__K && p->held >= 8u);
    p->at[k] = (uint8_t)(p->held - 4u);
    p->n = (uint8_t)(k + 1u);
    if (xf__end(p, k) < p->next) {
        p->next = (uint8_t)xf__end(p, k);
    }
    p->mode = xf__busy(k + 1u);
}

/* The last byte completed a header pair (w: the last four bytes), after the checks of rule 2:
 * rules 1 and 3. */
XF__NOINLINE void xf__header(xf_parser *p, uint32_t w)
{
    const unsigned len = (w >> 8) & 0xFFu;
    const bool valid = (w & 0xFFu) == 0u && len >= XF_PACKET_MIN_LEN && len <= XF_PACKET_MAX_LEN;
    XF_ASSERT((w >> 16) == p->pair);
    if (!valid) {
        p->stats.length_errors++;
    } else if (p->mode == XF__HUNT) {
        xf__first(p, w);
    } else if (p->mode == XF__BUSY) {
        xf__behind(p);
    } else {
        p->stats.given_up++; /* XF__FULL: a frame that begins here is lost */
    }
}

/* Candidate k ended intact: return it; everything else held overlaps it and goes (rule 2), the
 * bytes before it skipped. */
static void xf__emit(xf_parser *p, unsigned k, xf_frame *frame)
{
    XF_ASSERT(k < p->n && xf__end(p, k) == p->held && xf_crc16(p->buf + p->at[k], xf__len(p, k)) == 0u);
    frame->data = p->buf + p->at[k];
    frame->len = xf__len(p, k);
    p->stats.frames++;
    p->stats.bytes_skipped += p->at[k];
    xf__empty(p);
}

/* Candidate k ended and its CRC failed: it goes; the others keep their order. */
static void xf__drop(xf_parser *p, unsigned k)
{
    XF_ASSERT(k < p->n && xf__end(p, k) == p->held);
    p->stats.crc_errors++;
    for (p->n--; k < p->n && k + 1u < XF__K; k++) { /* (the bound is for the compiler) */
        p->at[k] = p->at[k + 1u];
    }
}

/* After failed checks: with no candidate left, hunting with the last four bytes held (the rule
 * path drops the first unless they are a header); else the bytes before the earliest candidate
 * are skipped, it moves to index 0, and next is the soonest end. */
static void xf__settle(xf_parser *p)
{
    const unsigned shift = (p->n > 0u) ? p->at[0] : p->held - 4u;
    unsigned k, soon = 2u * XF_PACKET_MAX_LEN;
    p->stats.bytes_skipped += shift;
    if (p->n == 0u) {
        p->held = 4;
        p->mode = XF__HUNT;
        return;
    }
    XF_MEMMOVE(p->buf, p->buf + shift, p->held - shift);
    p->held = (uint8_t)(p->held - shift);
    for (k = 0; k < p->n && k < XF__K; k++) { /* (the bound is for the compiler) */
        p->at[k] = (uint8_t)(p->at[k] - shift);
        soon = (xf__end(p, k) < soon) ? xf__end(p, k) : soon;
    }
    XF_ASSERT(soon > p->held && soon <= XF_PACKET_MAX_LEN);
    p->next = (uint8_t)soon;
    p->mode = xf__busy(p->n);
}

/* The last byte held ends one candidate or more: check them, earliest start first (rule 2); the
 * first intact one is returned (1), the failed ones go. */
XF__NOINLINE int xf__ends(xf_parser *p, xf_frame *frame)
{
    unsigned k = 0;
    XF_ASSERT(p->mode != XF__HUNT && p->n > 0u && p->held == p->next);
    while (k < p->n) {
        const bool ends_here = xf__end(p, k) == p->held;
        if (!ends_here) {
            k++;
        } else if (xf_crc16(p->buf + p->at[k], xf__len(p, k)) == 0u) {
            xf__emit(p, k, frame);
            return 1;
        } else {
            xf__drop(p, k);
        }
    }
    xf__settle(p);
    return 0;
}

/* The rule path: one byte through every rule, in their order (docs/codec.md). 1 when it completes
 * a frame. */
static inline int xf__byte(xf_parser *p, uint8_t b, xf_frame *frame)
{
    const uint32_t w = (p->last4 << 8) | b;
    p->last4 = w;
    if (p->mode == XF__HUNT) {
        p->held++; /* (in last4 only) */
    } else {
        p->buf[p->held++] = b;
        if (p->held == p->next && xf__ends(p, frame)) { /* rule 2: the candidates that end here */
            return 1;
        }
    }
    if ((w >> 16) == p->pair) { /* then the header pair it completes */
        xf__header(p, w);
    }
    if (p->mode == XF__HUNT && p->held > 3u) { /* rule 4: the last three bytes held, the one before goes */
        p->held = 3;
        p->stats.bytes_skipped++;
    }
    return 0;
}

/* The accelerator, which decides nothing: how many of the n bytes at d the rule path would only
 * store, since none of them ends a candidate (they come before the soonest end's last byte) and
 * none can complete a header pair (no h0 three bytes before it). */
static size_t xf__quiet(const xf_parser *p, const uint8_t *d, size_t n)
{
    const unsigned h0 = p->pair >> 8u;
    const uint32_t w = p->last4;
    const uint8_t *hit;
    size_t m = n;
    if (p->mode != XF__HUNT && (size_t)(p->next - p->held - 1u) < m) {
        m = (size_t)(p->next - p->held - 1u);
    }
    if (((w >> 16) & 0xFFu) == h0 || m == 0u) {
        return 0;
    }
    if (((w >> 8) & 0xFFu) == h0 || (w & 0xFFu) == h0) {
        return (((w >> 8) & 0xFFu) == h0 || m == 1u) ? 1u : 2u;
    }
    hit = (const uint8_t *)XF_MEMCHR(d, (int)h0, m);
    return (hit == NULL || (size_t)(hit - d) + 3u > m) ? m : (size_t)(hit - d) + 3u;
}

/* Store the m bytes at d as the rule path would, in bulk. */
static void xf__keep(xf_parser *p, const uint8_t *d, size_t m)
{
    uint32_t w = p->last4;
    size_t i;
    if (p->mode == XF__HUNT) { /* rule 4 */
        const size_t keep = (p->held + m < 3u) ? p->held + m : 3u;
        p->stats.bytes_skipped += (uint32_t)(p->held + m - keep);
        p->held = (uint8_t)keep;
    } else {
        XF_ASSERT(p->held + m < p->next);
        XF_MEMCPY(p->buf + p->held, d, m);
        p->held = (uint8_t)(p->held + m);
    }
    for (i = (m > 4u) ? m - 4u : 0u; i < m; i++) {
        w = (w << 8) | d[i];
    }
    p->last4 = w;
}

/* The accelerator on the n bytes at d: the bytes it took. */
static inline size_t xf__bulk(xf_parser *p, const uint8_t *d, size_t n)
{
    const size_t m = xf__quiet(p, d, n);
    if (m > 0u) {
        xf__keep(p, d, m);
    }
    return m;
}

/* Any number of bytes but one: each through the rule path, up to a frame's last byte, the
 * accelerator taking what it can first while XF__BULK or more are left. */
XF__NOINLINE xf_parse_status xf__feed(xf_parser *p, const uint8_t *data, size_t len, size_t *consumed, xf_frame *frame)
{
    size_t i = 0;
    int found = 0;
    while (i < len && !found) {
        if (len - i >= XF__BULK) {
            i += xf__bulk(p, data + i, len - i);
            if (i == len) {
                break;
            }
        }
        found = xf__byte(p, data[i++], frame);
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
    /* A byte fed alone (an interrupt handler's feed) goes to the rule path with no loop around it,
     * and so with no stack frame. */
    p->stats.bytes_in++;
    if (consumed != NULL) {
        *consumed = 1;
    }
    return xf__byte(p, data[0], frame) ? XF_PARSE_FRAME : XF_PARSE_MORE;
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
