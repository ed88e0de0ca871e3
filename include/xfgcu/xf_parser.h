/**
 * @file
 * @brief Streaming parser: bytes in any chunking, whole frames out.
 *
 * Caller-owned state, no allocation, no static data. Feed it whatever the
 * link delivered; it returns each complete frame whose header (for the
 * configured direction), length (in [72, XF_PACKET_MAX_LEN]) and CRC are
 * right.
 *
 * Resynchronisation. A candidate is a header pair followed by a valid
 * length. The earliest candidate is examined first; when its CRC fails, the
 * parser rescans the bytes it already holds from the candidate's second
 * byte on, so an intact frame hidden after noise, a false header or a
 * bogus length is always recovered. A bogus length (a bit flip in a length
 * byte, say) would hold back the frames behind it until that many bytes
 * had arrived; so while the earliest candidate is incomplete, the first
 * candidate after it that would end sooner (a contender) is checked as
 * soon as it is complete, and returned if intact. Which frame comes out
 * never depends on how the bytes were chunked.
 *
 * Cost. On a clean stream a packet that arrives whole in one chunk is
 * checked where it lies (no copy). Every byte that enters the parser's ring
 * is CRC'd once: the parser keeps, for each held byte, the normalised CRC
 * of the stream before it (xf_crc.h), and checks any candidate in constant
 * time from two of those values, so adversarial input costs O(1) per byte,
 * never O(frame length). (XF_PARSER_MEMO=0 keeps no such values and reads
 * each candidate's bytes again.)
 *
 * Counters only ever increase (the application may zero them):
 *
 * @code{.unparsed}
 *     bytes_in = bytes of returned frames + bytes_skipped + xf_parser_pending()
 * @endcode
 *
 * No function blocks. A parser is not thread-safe: use it from one thread.
 */
#ifndef XF_PARSER_H
#define XF_PARSER_H

#include <stddef.h>
#include <stdint.h>
#include "xf_config.h"
#include "xf_mem.h"
#include "xf_packet.h"
#include "xf_crc.h"
#include "xf_error.h"
#include "xf_protocol.h"

XF_BEGIN_DECLS

/**
 * Bytes of the parser's ring: a power of two that holds the longest packet
 * (::XF_PACKET_MAX_LEN) and one more position (the memo keeps a value for
 * the position after the last byte). 256, or 128 when ::XF_PACKET_MAX_LEN is
 * below 128.
 */
#if XF_PACKET_MAX_LEN >= 128
#define XF_PARSER_RING 256u
#else
#define XF_PARSER_RING 128u
#endif

/** Counters; each only increases. */
typedef struct xf_parser_stats {
    uint32_t bytes_in;      /**< bytes fed */
    uint32_t frames;        /**< valid frames returned */
    uint32_t crc_errors;    /**< candidates (header and valid length) whose CRC failed */
    uint32_t length_errors; /**< header pairs followed by a length outside [72, XF_PACKET_MAX_LEN] */
    uint32_t bytes_skipped; /**< bytes dropped as part of no valid frame */
} xf_parser_stats;

/**
 * A frame returned by the parser. The bytes are in the parser or, when a
 * whole packet arrived in one chunk, in the caller's own data; either way
 * they stay valid until the next call on the parser, as long as the caller
 * does not change its data meanwhile.
 */
typedef struct xf_frame {
    const uint8_t *data; /**< the frame's first byte (its header) */
    size_t len;          /**< the frame's length in bytes, CRC included (its length field) */
} xf_frame;

/** Parser state. Treat the members as private except `stats`. */
typedef struct xf_parser {
#if XF_PARSER_MEMO
    uint8_t ring[XF_PARSER_RING + 3]; /**< private: bytes held; the last 3 copy the first 3, so any 4 are adjacent */
#else
    uint8_t ring[XF_PARSER_RING]; /**< private: bytes held */
#endif
#if XF_PARSER_MEMO
    uint16_t memo[XF_PARSER_RING]; /**< private: N(pos), the normalised CRC before pos, for pos in [head, end] */
#endif
    uint32_t head;     /**< private: stream position of the first held byte: the earliest candidate */
    uint32_t end;      /**< private: one past the last held byte */
    uint32_t look;     /**< private: positions in (head, look) are examined: no candidate, or a failed contender */
    uint8_t bulk;      /**< private: a CRC failed since the parser was last empty: take whole chunks */
    uint8_t look_done; /**< private: no contender can follow for this head */
    /** @var xf_parser::h0
     *  private: first header byte of the direction parsed */
    uint8_t h0, h1;        /**< private: second header byte of the direction parsed */
    uint8_t wrapped;       /**< private: the last frame wrapped round the ring and was made contiguous (tests look) */
    xf_parser_stats stats; /**< counters, readable at any time; the application may zero them */
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
    XF_PARSE_MORE = 0,             /**< no frame: every byte given was taken (feed), or nothing is held (flush) */
    XF_PARSE_FRAME = 1             /**< *frame holds a frame */
} xf_parse_status;

/**
 * Feed @p len bytes. Stops at the first complete frame: returns
 * ::XF_PARSE_FRAME with *frame set and *consumed = the bytes of @p data taken
 * so far; call again with the rest (even when the rest is empty: frames
 * can be found in bytes already held). Returns ::XF_PARSE_MORE when every
 * byte was taken and no frame is complete, or ::XF_PARSE_ERR_ARG.
 *
 * @code
 * size_t n; xf_frame f;
 * while (xf_parser_feed(&p, data, len, &n, &f) == XF_PARSE_FRAME) {
 *     handle(f.data, f.len);
 *     data += n; len -= n;
 * }
 * @endcode
 *
 * The frame's bytes are in the parser or, when a whole packet arrived in
 * one chunk, in @p data itself; they stay valid until the next call on the
 * parser, as long as the caller leaves @p data alone meanwhile.
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
 * Decode a GCU frame the parser returned, without computing its CRC again
 * (the parser has checked header, length and CRC; only the header and
 * length are looked at again, cheaply). For bytes from anywhere else use
 * xf_gcu_unpack(). @p pkt is written only on success.
 * @param frame  the frame, as xf_parser_feed() or xf_parser_flush() gave it
 * @param pkt    receives the decoded packet
 * @return ::XF_OK, ::XF_ERR_ARG (NULL @p frame, frame data or @p pkt),
 *   ::XF_ERR_HEADER (a frame of the other direction), ::XF_ERR_LENGTH (the
 *   length is out of range or disagrees with the length field)
 */
XF_API xf_err xf_frame_gcu(const xf_frame *frame, xf_gcu_packet *pkt);
/**
 * Decode a host frame the parser returned (GCU side: the simulator), as
 * xf_frame_gcu() does for GCU frames. For bytes from anywhere else use
 * xf_host_unpack(). @p pkt is written only on success.
 * @param frame  the frame, as xf_parser_feed() or xf_parser_flush() gave it
 * @param pkt    receives the decoded packet
 * @return ::XF_OK, ::XF_ERR_ARG (NULL @p frame, frame data or @p pkt),
 *   ::XF_ERR_HEADER (a frame of the other direction), ::XF_ERR_LENGTH
 */
XF_API xf_err xf_frame_host(const xf_frame *frame, xf_host_packet *pkt);

/**
 * The input has ended (end of file, link closed): give up the candidates
 * that can no longer complete and return the intact frames behind them.
 * Call until it returns ::XF_PARSE_MORE; then nothing is pending. The bytes
 * given up count as skipped. The frame stays valid until the next call on
 * the parser.
 * @param p      the parser
 * @param frame  receives the frame when ::XF_PARSE_FRAME is returned
 * @return ::XF_PARSE_FRAME, ::XF_PARSE_MORE (nothing held any more), or
 *   ::XF_PARSE_ERR_ARG (NULL @p p or @p frame)
 */
XF_API xf_parse_status xf_parser_flush(xf_parser *p, xf_frame *frame);

#if XF_EMIT_DEFINITIONS

#define XF__RMASK (XF_PARSER_RING - 1u)
/* The contender loop skips a failed candidate's second and fourth bytes. */
XF_STATIC_ASSERT(XF_GCU_HEADER0 != XF_GCU_HEADER1 && XF_HOST_HEADER0 != XF_HOST_HEADER1, header_bytes_differ);
XF_STATIC_ASSERT(XF_GCU_HEADER0 != 0 && XF_HOST_HEADER0 != 0 && XF_PACKET_MAX_LEN < 256, length_high_byte_not_h0);
XF_STATIC_ASSERT((XF_PARSER_RING & XF__RMASK) == 0u, ring_is_power_of_two);
XF_STATIC_ASSERT(XF_PARSER_RING > XF_PACKET_MAX_LEN, ring_holds_a_packet_and_one_more_position);
XF_STATIC_ASSERT(XF_PARSER_RING % 16u == 0u, ring_index_mod_16_is_position_mod_16);
/* Most bytes held at once: the memo needs a slot for the position `end`. */
#define XF__HELD_MAX (XF_PARSER_RING - (unsigned)XF_PARSER_MEMO)

static inline uint8_t xf__rb(const xf_parser *p, uint32_t pos) { return p->ring[pos & XF__RMASK]; }

XF_API size_t xf_parser_size(void) { return sizeof(xf_parser); }

XF_API unsigned long xf_options_word(void) { return XF_OPTIONS_WORD; }

XF_API xf_err xf_parser_init_checked(xf_parser *p, xf_direction dir, unsigned long options, size_t size)
{
    if (options != XF_OPTIONS_WORD || size != sizeof(xf_parser)) {
        return XF_ERR_CONFIG; /* the caller's xf_parser is not ours: writing to it would overrun it */
    }
    if (p == NULL || (dir != XF_DIR_HOST && dir != XF_DIR_GCU)) {
        return XF_ERR_ARG;
    }
    XF_MEMSET(p, 0, sizeof(*p));
    p->look = 1;
    p->h0 = (dir == XF_DIR_HOST) ? XF_HOST_HEADER0 : XF_GCU_HEADER0;
    p->h1 = (dir == XF_DIR_HOST) ? XF_HOST_HEADER1 : XF_GCU_HEADER1;
    return XF_OK;
}

XF_API size_t xf_parser_pending(const xf_parser *p) { return (p == NULL) ? 0u : (size_t)(p->end - p->head); }

/* Nothing held: restart at ring index 0 in fast mode, so clean frames never wrap. */
static inline void xf__parser_empty(xf_parser *p)
{
    p->head = 0;
    p->end = 0;
    p->look = 1;
    p->look_done = 0;
    p->bulk = 0;
#if XF_PARSER_MEMO
    p->memo[0] = 0; /* N(0): nothing before the first byte */
#endif
}

XF_API void xf_parser_reset(xf_parser *p)
{
    if (p != NULL) {
        p->stats.bytes_skipped += (uint32_t)(p->end - p->head);
        xf__parser_empty(p);
    }
}

#if XF_PARSER_MEMO
/* One byte: m[k] = v (N before it), r[k] = b, v advanced past it with the
 * table row t (for s = the position after it mod 16, not 0). */
#define XF__MEMO_BYTE(m, r, k, src, t, v)                                                                              \
    do {                                                                                                               \
        uint8_t b_ = *(src); /* read once: the ring store may alias the caller's data */                               \
        (m)[k] = (v);                                                                                                  \
        (r)[k] = b_;                                                                                                   \
        (v) = xf__crc_norm_step((v), (t), b_);                                                                         \
    } while (0)

/* The byte that ends a block of 16 (s = 0): N is multiplied by x^128 first. */
#define XF__MEMO_BYTE0(m, r, k, src, norm, v)                                                                          \
    do {                                                                                                               \
        uint8_t b_ = *(src);                                                                                           \
        (m)[k] = (v);                                                                                                  \
        (r)[k] = b_;                                                                                                   \
        (v) = xf__crc_norm_step(xf__crc_x128k((v), 1u), (norm), b_);                                                   \
    } while (0)

/* Append n bytes to the ring with N before each, and N(end) after them.
 * The ring index mod 16 is the stream position mod 16, and blocks of 16
 * never straddle the ring's end: whole aligned blocks are unrolled with
 * every table row a constant; the bytes before the first and after the
 * last take a row pointer that steps along. This loop is a large share of
 * the cost of adversarial input (docs/performance.md). */
static inline void xf__append_memo(xf_parser *p, const uint8_t *d, size_t n)
{
    const uint16_t *norm = xf__crc_norm_table();
    const uint8_t *de = d + n;
    uint8_t *r = p->ring;
    uint16_t *m = p->memo;
    size_t i = p->end & XF__RMASK;
    uint16_t v = m[i];
    const uint16_t *t = norm + XF__NORM_ROW * ((i + 1u) & 15u);
    /* the rest of a block already begun */
    if ((i & 15u) != 0u) {
        for (; d != de && (i & 15u) != 15u; i++, d++, t += XF__NORM_ROW) {
            XF__MEMO_BYTE(m, r, i, d, t, v);
        }
        if (d != de) {
            XF__MEMO_BYTE0(m, r, i, d, norm, v);
            d++;
            i = (i + 1u) & XF__RMASK;
        }
    }
    for (; de - d >= 16; d += 16, i = (i + 16u) & XF__RMASK) {
        uint16_t *mb = m + i;
        uint8_t *rb = r + i;
        XF__MEMO_BYTE(mb, rb, 0, d + 0, norm + 1 * XF__NORM_ROW, v);
        XF__MEMO_BYTE(mb, rb, 1, d + 1, norm + 2 * XF__NORM_ROW, v);
        XF__MEMO_BYTE(mb, rb, 2, d + 2, norm + 3 * XF__NORM_ROW, v);
        XF__MEMO_BYTE(mb, rb, 3, d + 3, norm + 4 * XF__NORM_ROW, v);
        XF__MEMO_BYTE(mb, rb, 4, d + 4, norm + 5 * XF__NORM_ROW, v);
        XF__MEMO_BYTE(mb, rb, 5, d + 5, norm + 6 * XF__NORM_ROW, v);
        XF__MEMO_BYTE(mb, rb, 6, d + 6, norm + 7 * XF__NORM_ROW, v);
        XF__MEMO_BYTE(mb, rb, 7, d + 7, norm + 8 * XF__NORM_ROW, v);
        XF__MEMO_BYTE(mb, rb, 8, d + 8, norm + 9 * XF__NORM_ROW, v);
        XF__MEMO_BYTE(mb, rb, 9, d + 9, norm + 10 * XF__NORM_ROW, v);
        XF__MEMO_BYTE(mb, rb, 10, d + 10, norm + 11 * XF__NORM_ROW, v);
        XF__MEMO_BYTE(mb, rb, 11, d + 11, norm + 12 * XF__NORM_ROW, v);
        XF__MEMO_BYTE(mb, rb, 12, d + 12, norm + 13 * XF__NORM_ROW, v);
        XF__MEMO_BYTE(mb, rb, 13, d + 13, norm + 14 * XF__NORM_ROW, v);
        XF__MEMO_BYTE(mb, rb, 14, d + 14, norm + 15 * XF__NORM_ROW, v);
        XF__MEMO_BYTE0(mb, rb, 15, d + 15, norm, v);
    }
    /* the start of a block: fewer than 16 bytes, none ends it */
    for (t = norm + XF__NORM_ROW; d != de; i++, d++, t += XF__NORM_ROW) {
        XF__MEMO_BYTE(m, r, i, d, t, v);
    }
    p->end += (uint32_t)n;
    m[p->end & XF__RMASK] = v;
}
#else
/* CRC of held bytes [pos, pos + n) read straight from the ring. */
static inline uint16_t xf__ring_crc(const xf_parser *p, uint32_t pos, size_t n)
{
    size_t i0 = pos & XF__RMASK;
    size_t first = (i0 + n <= XF_PARSER_RING) ? n : (XF_PARSER_RING - i0);
    uint16_t c = xf_crc16_update(0, p->ring + i0, first);
    return xf_crc16_update(c, p->ring, n - first);
}
#endif

static inline void xf__append(xf_parser *p, const uint8_t *data, size_t n)
{
    size_t i0 = p->end & XF__RMASK;
#if XF_PARSER_MEMO
    xf__append_memo(p, data, n);
    if (i0 < 3u || i0 + n > XF_PARSER_RING) { /* wrote some of ring[0..3): keep the copy */
        p->ring[XF_PARSER_RING] = p->ring[0];
        p->ring[XF_PARSER_RING + 1u] = p->ring[1];
        p->ring[XF_PARSER_RING + 2u] = p->ring[2];
    }
#else
    size_t first = (i0 + n <= XF_PARSER_RING) ? n : (XF_PARSER_RING - i0);
    XF_MEMCPY(p->ring + i0, data, first);
    XF_MEMCPY(p->ring, data + first, n - first);
    p->end += (uint32_t)n;
#endif
}

/* Is the complete candidate of length len at pos intact? */
XF__HOT_INLINE int xf__intact(const xf_parser *p, uint32_t pos, size_t len)
{
#if XF_PARSER_MEMO
    /* N(pos + len) == N(pos) * x^(128k): see xf_crc.h */
    unsigned k = (unsigned)(((pos & 15u) + len) >> 4);
    return p->memo[(pos + (uint32_t)len) & XF__RMASK] == xf__crc_x128k(p->memo[pos & XF__RMASK], k);
#else
    uint32_t crc_pos = pos + (uint32_t)len - 2u;
    uint16_t want = (uint16_t)(((uint16_t)xf__rb(p, crc_pos) << 8) | xf__rb(p, crc_pos + 1u));
    return xf__ring_crc(p, pos, len - 2u) == want;
#endif
}

/* Drop the held bytes before pos (they belong to no frame). */
static inline void xf__drop_to(xf_parser *p, uint32_t pos)
{
    p->stats.bytes_skipped += (uint32_t)(pos - p->head);
    p->head = pos;
    p->look = pos + 1u;
    p->look_done = 0;
}

#if XF_PARSER_MEMO
/* A frame at ring index i0 that wraps round the ring's end: copy it, whole,
 * where the memo kept the values of its own positions, which no check
 * needs again (every later candidate starts at its end or after). Those
 * entries are indices [i0, RING) and [0, len - first), as bytes [2 i0, 2 RING)
 * and [0, 2 (len - first)); the two parts add up to len entries, so the
 * larger holds len bytes. The copy costs no RAM and lives, like any frame,
 * until the next call. */
static inline const uint8_t *xf__unwrap(xf_parser *p, size_t i0, size_t len)
{
    size_t first = XF_PARSER_RING - i0;
    uint8_t *dst = (uint8_t *)p->memo + ((2u * first >= len) ? 2u * i0 : 0u);
    XF_MEMCPY(dst, p->ring + i0, first);
    XF_MEMCPY(dst + first, p->ring, len - first);
    return dst;
}
#else
/* Reverse ring[i..j). */
static inline void xf__reverse(xf_parser *p, size_t i, size_t j)
{
    while (i + 1u < j) {
        uint8_t t = p->ring[i];
        j--;
        p->ring[i] = p->ring[j];
        p->ring[j] = t;
        i++;
    }
}

/* Without a memo to copy into: make the frame's first byte sit at ring
 * index 0 by rotating the ring left by that index (three reversals), and
 * renumber every position by as much, so held bytes keep index = position
 * mod ring. Rare: frames wrap only after noise has left the ring
 * misaligned, and a scratch copy would cost a whole packet of RAM. */
static inline const uint8_t *xf__unwrap(xf_parser *p, size_t i0, size_t len)
{
    (void)len;
    xf__reverse(p, 0, i0);
    xf__reverse(p, i0, XF_PARSER_RING);
    xf__reverse(p, 0, XF_PARSER_RING);
    p->head -= (uint32_t)i0;
    p->end -= (uint32_t)i0;
    p->look -= (uint32_t)i0;
    return p->ring;
}
#endif

/* Return the frame of length len at pos and drop everything before it. */
static inline void xf__emit(xf_parser *p, uint32_t pos, size_t len, xf_frame *frame)
{
    size_t i0 = pos & XF__RMASK;
    p->wrapped = (uint8_t)(i0 + len > XF_PARSER_RING);
    if (p->wrapped) {
        frame->data = xf__unwrap(p, i0, len);
#if !XF_PARSER_MEMO
        pos -= (uint32_t)i0; /* renumbered */
#endif
    } else {
        frame->data = p->ring + i0;
    }
    frame->len = len;
    xf__drop_to(p, pos);
    p->head = pos + (uint32_t)len;
    p->look = p->head + 1u;
    p->stats.frames++;
}

#define XF__NO   0 /* not a candidate */
#define XF__YES  1 /* a candidate; *len set */
#define XF__WAIT 2 /* cannot tell yet; *need more bytes */

/* Held bytes pos .. pos + 3 as a little-endian word: the header pair in
 * the low half, the length in the high half. In memo builds the ring ends
 * with a copy of its first three bytes, so the four are adjacent (one load
 * where the target allows it). */
static inline uint32_t xf__word(const xf_parser *p, uint32_t pos)
{
#if XF_PARSER_MEMO
    const uint8_t *b = p->ring + (pos & XF__RMASK);
    return (uint32_t)b[0] | ((uint32_t)b[1] << 8) | ((uint32_t)b[2] << 16) | ((uint32_t)b[3] << 24);
#else
    return (uint32_t)xf__rb(p, pos) | ((uint32_t)xf__rb(p, pos + 1u) << 8) | ((uint32_t)xf__rb(p, pos + 2u) << 16) |
           ((uint32_t)xf__rb(p, pos + 3u) << 24);
#endif
}

/* Is the word at a held position a candidate? 0 when not; else its length. */
static inline size_t xf__word_len(xf_parser *p, uint32_t w, uint32_t hdr)
{
    size_t len = (size_t)(w >> 16);
    if ((w & 0xFFFFu) != hdr) {
        return 0;
    }
    if (len - XF_PACKET_MIN_LEN > XF_PACKET_MAX_LEN - XF_PACKET_MIN_LEN) {
        p->stats.length_errors++; /* each position is examined once, so counted once */
        return 0;
    }
    return len;
}

/* Is there a candidate (header pair, valid length) at pos? */
static inline int xf__candidate(xf_parser *p, uint32_t pos, size_t *len, size_t *need)
{
    size_t avail = (size_t)(p->end - pos);
    if (xf__rb(p, pos) != p->h0) {
        return XF__NO;
    }
    if (avail >= 4u) {
        *len = xf__word_len(p, xf__word(p, pos), (uint32_t)p->h0 | ((uint32_t)p->h1 << 8));
        return (*len != 0u) ? XF__YES : XF__NO;
    }
    if (avail >= 2u && xf__rb(p, pos + 1u) != p->h1) {
        return XF__NO;
    }
    *need = 4u - avail; /* the header or the length is incomplete */
    return XF__WAIT;
}

/* Examine positions after head for a contender: the first candidate that
 * ends before head's candidate (ending at pend). Each position is examined
 * once per head. Returns 1 with a frame, 0 when done or *need > 0. */
static inline int xf__contend(xf_parser *p, uint32_t pend, xf_frame *frame, size_t *need)
{
    /* The parser's hot spot on adversarial input: every position after a
     * failed candidate is examined here, so the loop keeps its state in
     * locals and jumps from one header byte to the next. A contender
     * starts at least 72 bytes before pend (at a position before lim): a
     * clean reply of 72 or 73 bytes never has one, so the fast path costs
     * nothing. */
    const uint32_t end = p->end;
    const uint32_t lim = pend - XF_PACKET_MIN_LEN;
    const uint32_t h0 = p->h0;
    const uint32_t hdr = h0 | ((uint32_t)p->h1 << 8);
    uint32_t look = p->look;
    uint32_t stop;      /* end or lim, whichever comes first */
    uint32_t fails = 0; /* counted here, stored once */
    size_t len = 0;
    int found = 0;
    *need = 0;
    if (p->look_done || (uint32_t)(pend - look) <= XF_PACKET_MIN_LEN) {
        p->look_done = 1;
        return 0;
    }
    stop = ((uint32_t)(end - look) < (uint32_t)(lim - look)) ? end : lim;
    /* After a candidate, look may pass stop by a position or three: they
     * are that candidate's own bytes, which cannot start one. */
    while ((int32_t)(stop - look) > 0) {
        uint32_t w;
        if ((uint32_t)(end - look) < 4u) {
            if (xf__candidate(p, look, &len, need) == XF__WAIT) {
                break; /* the header or the length is incomplete */
            }
            look++;
            continue;
        }
        w = xf__word(p, look);
        if ((w & 0xFFFFu) != hdr) {
            look++;
            continue;
        }
        len = (size_t)(w >> 16);
        /* One test for the usual case, a valid length that ends before
         * pend (lim - look = pend - look - 72, less than 255 - 72). */
        if (len - XF_PACKET_MIN_LEN >= (size_t)(uint32_t)(lim - look)) {
            if (xf__word_len(p, w, hdr) == 0u) { /* a length out of range, counted there */
                look += 2u;                      /* its second byte is h1 */
                continue;
            }
            break; /* the first candidate that ends no sooner: leave it to the rescan */
        }
        if ((uint32_t)(end - look) < len) {
            *need = len - (size_t)(end - look);
            break;
        }
        if (xf__intact(p, look, len)) {
            found = 1;
            break;
        }
        fails++;
        /* Its second byte is h1 and its fourth the length's high byte, 0:
         * neither can start a candidate, so only the third is looked at. */
        look += (len == h0) ? 2u : 4u;
    }
    p->look = look;
    if (fails != 0u) {
        p->stats.crc_errors += fails;
        p->bulk = 1;
    }
    if (found) {
        xf__emit(p, look, len, frame);
        return 1;
    }
    if (*need != 0u) {
        return 0;
    }
    if (look == end && (int32_t)(lim - look) > 0) {
        *need = 1; /* every held position examined; later ones may hold a contender */
        return 0;
    }
    p->look_done = 1;
    return 0;
}

/* Work through the held bytes. Returns 1 with a frame, or 0 with *need =
 * how many more bytes progress needs (0: nothing held). */
static inline int xf__scan(xf_parser *p, xf_frame *frame, size_t *need)
{
    for (;;) {
        size_t held = (size_t)(p->end - p->head);
        size_t len = 0, cneed = 0;
        int r;
        if (held == 0u) {
            xf__parser_empty(p);
            *need = 0;
            return 0;
        }
        r = xf__candidate(p, p->head, &len, need);
        if (r == XF__WAIT) {
            return 0;
        }
        if (r == XF__NO) {
            /* positions that hold no header byte are no candidate either */
            uint32_t pos = p->head + 1u;
            while (pos != p->end && p->ring[pos & XF__RMASK] != p->h0) {
                pos++;
            }
            xf__drop_to(p, pos);
            continue;
        }
        if (p->look == p->head + 1u) {
            /* the head's second byte is h1, its fourth the length's high byte: no candidates */
            p->look = p->head + ((xf__rb(p, p->head + 2u) == p->h0) ? 2u : 4u);
        }
        if (xf__contend(p, p->head + (uint32_t)len, frame, &cneed)) {
            return 1;
        }
        if (held < len) {
            /* Ask for no more than the nearer of the two ends, so that
             * `consumed` stops exactly at the end of whichever frame wins. */
            *need = (cneed != 0u && cneed < len - held) ? cneed : len - held;
            return 0;
        }
        if (xf__intact(p, p->head, len)) {
            xf__emit(p, p->head, len, frame);
            return 1;
        }
        p->stats.crc_errors++;
        p->bulk = 1;
        /* Positions up to `look` were examined already: no candidate there,
         * or a contender that failed. Jump over them. */
        xf__drop_to(p, (p->look_done || p->look > p->head + 1u) ? p->look : p->head + 1u);
    }
}

/* Header and length of a frame the parser returned, before decoding it. */
static inline xf_err xf__frame_ok(const xf_frame *f, uint8_t h0, uint8_t h1)
{
    if (f == NULL || f->data == NULL) {
        return XF_ERR_ARG;
    }
    if (f->len < XF_PACKET_MIN_LEN || f->len > XF_PACKET_MAX_LEN ||
        ((size_t)f->data[2] | ((size_t)f->data[3] << 8)) != f->len) {
        return XF_ERR_LENGTH;
    }
    return (f->data[0] == h0 && f->data[1] == h1) ? XF_OK : XF_ERR_HEADER;
}

XF_API xf_err xf_frame_gcu(const xf_frame *frame, xf_gcu_packet *pkt)
{
    xf_err err = (pkt == NULL) ? XF_ERR_ARG : xf__frame_ok(frame, XF_GCU_HEADER0, XF_GCU_HEADER1);
    if (err == XF_OK) {
        xf__gcu_fields(frame->data, frame->len, pkt);
    }
    return err;
}

XF_API xf_err xf_frame_host(const xf_frame *frame, xf_host_packet *pkt)
{
    xf_err err = (pkt == NULL) ? XF_ERR_ARG : xf__frame_ok(frame, XF_HOST_HEADER0, XF_HOST_HEADER1);
    if (err == XF_OK) {
        xf__host_fields(frame->data, frame->len, pkt);
    }
    return err;
}

XF_API xf_parse_status xf_parser_flush(xf_parser *p, xf_frame *frame)
{
    if (p == NULL || frame == NULL) {
        return XF_PARSE_ERR_ARG;
    }
    for (;;) {
        size_t need = 0;
        if (xf__scan(p, frame, &need)) {
            return XF_PARSE_FRAME;
        }
        if (p->end == p->head) {
            return XF_PARSE_MORE;
        }
        /* The earliest candidate needs bytes that will never come. */
        xf__drop_to(p, (p->look > p->head + 1u) ? p->look : p->head + 1u);
    }
}

/* Nothing held, and the caller's bytes at d hold a whole intact packet that
 * no contender could beat (no header byte where one would have to start):
 * return it from there, with no copy (the common case on a clean link). */
static inline int xf__direct(xf_parser *p, const uint8_t *d, size_t avail, xf_frame *frame)
{
    size_t len;
    if (avail < 4u || d[1] != p->h1) {
        return 0;
    }
    len = (size_t)d[2] | ((size_t)d[3] << 8);
    if (len < XF_PACKET_MIN_LEN || len > XF_PACKET_MAX_LEN || len > avail) {
        return 0;
    }
    /* A contender starts at offset 1 .. len - 73 (see xf__contend). */
    if (len > XF_PACKET_MIN_LEN + 1u && XF_MEMCHR(d + 1, p->h0, len - XF_PACKET_MIN_LEN - 1u) != NULL) {
        return 0;
    }
    /* The CRC (no reflection, no final XOR) of a packet with its own CRC
     * appended big-endian is zero. */
    if (xf_crc16(d, len) != 0u) {
        return 0; /* the general path rescans it */
    }
    frame->data = d;
    frame->len = len;
    p->wrapped = 0;
    p->stats.frames++;
    p->stats.bytes_in += (uint32_t)len;
    return 1;
}

/* A frame came from the ring: the bytes held past its end that were taken
 * in this call go back to the caller, who still has them, so `consumed`
 * ends at the frame whatever was appended (and when nothing else is held,
 * the parser is empty again and the next packets take the fast path).
 * Nothing past a frame's end has been examined yet: the scan goes in order
 * of position and stops at the first frame. */
static inline void xf__give_back(xf_parser *p, size_t *used, size_t appended)
{
    size_t past = (size_t)(p->end - p->head);
    size_t back = (past < appended) ? past : appended;
    if (back == 0u) {
        return;
    }
    p->end -= (uint32_t)back;
    p->stats.bytes_in -= (uint32_t)back;
    *used -= back; /* the memo already holds N(end), the value before the first byte given back */
}

XF_API xf_parse_status xf_parser_feed(xf_parser *p, const uint8_t *data, size_t len, size_t *consumed, xf_frame *frame)
{
    size_t used = 0, appended = 0;
    int found = 0;
    if (p == NULL || frame == NULL || (data == NULL && len > 0u)) {
        return XF_PARSE_ERR_ARG;
    }
    for (;;) {
        size_t need;
        size_t take;
        if (xf__scan(p, frame, &need)) {
            found = 1;
            break;
        }
        if (used >= len) { /* used never passes len; >= lets the compiler know */
            break;
        }
        if (need == 0u) {
            /* Nothing held: jump over noise to the next possible header. */
            const uint8_t *hit = (const uint8_t *)XF_MEMCHR(data + used, p->h0, len - used);
            size_t skip = (hit != NULL) ? (size_t)(hit - (data + used)) : (len - used);
#if defined(__GNUC__)
            /* memchr's guarantee, told to the compiler (no code emitted):
             * with it and the >= above, gcc 12 -O3 sees that xf__direct()
             * reads nothing past a caller's array of 1 to 3 bytes (no
             * -Warray-bounds, -Wstringop-overread: tests/matrix/user_tu.c) */
            if (skip > len - used) {
                __builtin_unreachable();
            }
#endif
            p->stats.bytes_skipped += (uint32_t)skip;
            p->stats.bytes_in += (uint32_t)skip;
            used += skip;
            if (hit == NULL) {
                break;
            }
            if (xf__direct(p, hit, len - used, frame)) {
                used += frame->len;
                found = 2; /* in the caller's data */
                break;
            }
            need = 4; /* header and length: every packet is longer than that */
        }
        take = (need < len - used) ? need : (len - used);
#if XF_PARSER_MEMO
        if (p->bulk) {
            /* After a CRC failure: take all the ring can hold, so the scan
             * works through many candidates per call instead of asking for
             * a few bytes at a time; what lies past a frame found is given
             * back below. (Not without the memo, where each check re-reads
             * its candidate anyway: the code would only cost flash.) */
            size_t room = XF__HELD_MAX - (size_t)(p->end - p->head);
            size_t most = (room < len - used) ? room : (len - used);
            /* ending on a multiple of 16 lets the next append start on a
             * whole block of the memo's unrolled loop */
            size_t cut = (size_t)((p->end + (uint32_t)most) & 15u);
            if (most > take) {
                take = (most >= take + cut) ? most - cut : most;
            }
        }
#endif
        xf__append(p, data + used, take);
        p->stats.bytes_in += (uint32_t)take;
        used += take;
        appended += take;
    }
    if (found == 1) {
        xf__give_back(p, &used, appended);
    }
    if (consumed != NULL) {
        *consumed = used;
    }
    return found ? XF_PARSE_FRAME : XF_PARSE_MORE;
}

#endif /* XF_EMIT_DEFINITIONS */

XF_END_DECLS

#endif /* XF_PARSER_H */
