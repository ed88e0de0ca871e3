/**
 * @file
 * @brief Streaming parser: bytes in any chunking, whole frames out, each from
 * the call that feeds its last byte.
 *
 * Caller-owned state (300 bytes with the default options), no allocation, no
 * static data, no blocking; use a parser from one thread. It returns each
 * frame whose header (for the configured direction), length (in [72,
 * ::XF_PACKET_MAX_LEN]) and CRC are right.
 *
 * How. A *candidate* is a header pair followed by a valid length. The parser
 * tracks up to ::XF_PARSER_SLOTS candidates at once, in the order in which
 * they end, with one running CRC for all of them, and checks each when its
 * last byte arrives: the first intact one is returned at once, and the
 * others, which overlap it, are dropped. So a frame behind noise, a
 * truncated packet, a false header or a bogus length comes out on time. A
 * candidate that arrives while every slot holds one that ends sooner is
 * given up unchecked (stats.given_up); docs/codec.md states the exact rule.
 *
 * Counters only ever increase (the application may zero them):
 *
 * @code{.unparsed}
 *     bytes_in = bytes of returned frames + bytes_skipped + xf_parser_pending()
 * @endcode
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
 * (::XF_PACKET_MAX_LEN): 256, or 128 when ::XF_PACKET_MAX_LEN is below 128.
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
    uint32_t given_up;      /**< candidates given up unchecked: every slot held one that ends sooner */
} xf_parser_stats;

/** Parser state. Treat the members as private except `stats`. */
typedef struct xf_parser {
    uint8_t ring[XF_PARSER_RING];   /**< private: bytes held, each at ring index = stream position mod XF_PARSER_RING */
    xf_parser_stats stats;          /**< counters, readable at any time; the application may zero them */
    uint16_t want[XF_PARSER_SLOTS]; /**< private: per candidate, what `crc` must be at its end, before the shift
                                       (docs/codec.md) */
    uint16_t crc;                   /**< private: CRC of the bytes from the first pending candidate's start to `sum` */
    uint8_t at[XF_PARSER_SLOTS];    /**< private: ring index of each candidate's first byte, soonest end first */
    uint8_t next;                   /**< private: ring index just past the next byte that needs a look */
    uint8_t head;                   /**< private: ring index of the first byte held */
    uint8_t end;                    /**< private: ring index just past the last byte held */
    uint8_t n;                      /**< private: candidates pending */
    uint8_t h0;                     /**< private: first header byte of the direction parsed */
    uint8_t sum;                    /**< private: ring index up to which `crc` runs */
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

#define XF__RMASK (XF_PARSER_RING - 1u)
#define XF__IX(i) ((uint8_t)((i)&XF__RMASK))
#define XF__MIN   XF_PACKET_MIN_LEN
#define XF__SHORT 4u /* runs shorter than this are searched byte by byte, not through memchr */
/* The CRC of each direction's header pair (tests/test_parser.c checks them). */
#define XF__GCU_PAIR_CRC  0x4F68u
#define XF__HOST_PAIR_CRC 0x395Cu
XF_STATIC_ASSERT(XF_PARSER_RING > XF_PACKET_MAX_LEN && XF_PACKET_MAX_LEN <= 255u, ring_holds_a_packet);
XF_STATIC_ASSERT(XF_GCU_HEADER0 != XF_HOST_HEADER0, h0_names_the_direction);
/* A header's length high byte (0) is neither header byte, and h1 is no h0 (xf__idle's plan). */
XF_STATIC_ASSERT(XF_GCU_HEADER0 != 0u && XF_GCU_HEADER1 != 0u && XF_HOST_HEADER0 != 0u && XF_HOST_HEADER1 != 0u,
                 no_header_byte_is_0);
XF_STATIC_ASSERT(XF_GCU_HEADER0 != XF_GCU_HEADER1 && XF_HOST_HEADER0 != XF_HOST_HEADER1, h1_is_no_h0);

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
    p->h0 = (dir == XF_DIR_HOST) ? XF_HOST_HEADER0 : XF_GCU_HEADER0;
    p->next = 1; /* nothing held: the first byte gets a look */
    return XF_OK;
}

static inline unsigned xf__held(const xf_parser *p) { return (unsigned)XF__IX(p->end - p->head); }

/* Length and end (ring index just past its last byte) of candidate k: its
 * header is held as long as it is pending. */
static inline unsigned xf__len(const xf_parser *p, unsigned k) { return p->ring[XF__IX(p->at[k] + 2u)]; }

static inline unsigned xf__fin(const xf_parser *p, unsigned k) { return XF__IX(p->at[k] + xf__len(p, k)); }

/* Bytes still to come before candidate k ends. */
static inline unsigned xf__left(const xf_parser *p, unsigned k) { return (unsigned)XF__IX(xf__fin(p, k) - p->end); }

static inline int xf__len_ok(unsigned len) { return len >= XF__MIN && len <= XF_PACKET_MAX_LEN; }

XF_API size_t xf_parser_pending(const xf_parser *p) { return (p == NULL) ? 0u : xf__held(p); }

/* Drop everything held. Ring index 0 again, so that frames on a clean link never wrap. */
static inline void xf__clear(xf_parser *p)
{
    p->stats.bytes_skipped += xf__held(p);
    p->n = 0;
    p->head = 0;
    p->end = 0;
    p->next = 1;
}

XF_API void xf_parser_reset(xf_parser *p)
{
    if (p != NULL) {
        xf__clear(p);
    }
}

/* The second header byte of the direction parsed (h0 names it). */
static inline unsigned xf__h1(const xf_parser *p)
{
    return (p->h0 == XF_GCU_HEADER0) ? XF_GCU_HEADER1 : XF_HOST_HEADER1;
}

/* How many of the last bytes held (0..3) run from the earliest h0 whose
 * header is not complete yet (its fourth byte has not come). */
static inline unsigned xf__prefix(const xf_parser *p)
{
    const uint8_t *r = p->ring;
    unsigned e = p->end, held = xf__held(p), h0 = p->h0;
    return (held >= 3u && r[XF__IX(e - 3u)] == h0)   ? 3u
           : (held >= 2u && r[XF__IX(e - 2u)] == h0) ? 2u
           : (held >= 1u && r[XF__IX(e - 1u)] == h0) ? 1u
                                                     : 0u;
}

/* Set next: just past the next byte that needs a look, the soonest of the
 * first candidate's last byte and the fourth byte of a header an h0 among
 * the last three bytes begins (unless the byte after that h0 is here and is
 * not h1: with a candidate pending, such an h0 changes nothing); with no
 * candidate, the fourth byte of head's h0, or with nothing held the next
 * byte. Every byte before it, unless it is an h0, is only stored (the fast
 * paths). */
XF__COLD void xf__plan(xf_parser *p)
{
    const uint8_t *r = p->ring;
    unsigned e = p->end, h0 = p->h0, h1 = xf__h1(p), stop, k;
    if (p->n == 0u) {
        p->next = XF__IX(p->head + ((e == p->head) ? 1u : 4u));
        return;
    }
    /* a candidate is pending, so its four header bytes at least are held */
    stop = xf__left(p, 0);
    k = (r[XF__IX(e - 3u)] == h0 && r[XF__IX(e - 2u)] == h1)   ? 1u
        : (r[XF__IX(e - 2u)] == h0 && r[XF__IX(e - 1u)] == h1) ? 2u
        : (r[XF__IX(e - 1u)] == h0)                            ? 3u
                                                               : stop;
    p->next = XF__IX(e + ((k < stop) ? k : stop));
}

/* Bring crc up to the last byte held: bytes are stored first and CRC'd
 * only when a candidate needs it, four at a time (xf__crc_run). */
static void xf__sum(xf_parser *p)
{
    unsigned s = p->sum, e = p->end;
    uint32_t c = (uint32_t)p->crc << 16;
    if (e < s) {
        c = xf__crc_run(c, p->ring + s, XF_PARSER_RING - s);
        s = 0;
    }
    p->crc = (uint16_t)(xf__crc_run(c, p->ring + s, e - s) >> 16);
    p->sum = (uint8_t)e;
}

/* Move head up to the first byte that can still begin a frame: the earliest
 * candidate's, or else an h0 whose header is not complete yet. */
static void xf__settle(xf_parser *p)
{
    unsigned k, keep = 0;
    for (k = 0; k < p->n; k++) {
        unsigned back = (unsigned)XF__IX(p->end - p->at[k]);
        keep = (back > keep) ? back : keep;
    }
    if (p->n == 0u) {
        keep = xf__prefix(p);
    }
    XF_ASSERT(keep <= xf__held(p) && keep <= XF_PACKET_MAX_LEN);
    if (keep == 0u) {
        xf__clear(p);
        return;
    }
    p->stats.bytes_skipped += xf__held(p) - keep;
    p->head = XF__IX(p->end - keep);
}

/* Drop candidate 0 (its end has come), keeping the others in order. */
static void xf__shift(xf_parser *p)
{
    unsigned k;
    for (p->n--, k = 0; k < p->n && k + 1u < XF_PARSER_SLOTS; k++) { /* (the bound is for the compiler) */
        p->want[k] = p->want[k + 1u];
        p->at[k] = p->at[k + 1u];
    }
}

/* A header pair and a valid length end with the last byte held: a new
 * candidate, placed in order of end (after those that end with it: they
 * started earlier). Its `want` is what the CRC of everything before it
 * contributes at its end: the frame is intact exactly when the running CRC
 * then equals want * x^(8 (len - 4)) (xf__crc_zeros); with no other
 * candidate the running CRC restarts at the candidate, and want is 0. When
 * every slot is taken, the pending one that ends last is given up (it ends
 * after the new one: xf__open). 1, or 3 when it held the first byte held. */
static int xf__admit(xf_parser *p, unsigned len)
{
    unsigned left = len - 4u, k = p->n, pair = (p->h0 == XF_GCU_HEADER0) ? XF__GCU_PAIR_CRC : XF__HOST_PAIR_CRC;
    uint32_t c;
    int moved = 1;
    if (k == 0u) {
        /* The running CRC restarts at the candidate: its pair's CRC is a
         * constant, and xf__sum() takes it on from the length byte. */
        p->crc = (uint16_t)pair;
        p->sum = XF__IX(p->end - 2u);
        p->want[0] = 0;
        p->at[0] = XF__IX(p->end - 4u);
        p->n = 1;
        return 1;
    }
    if (k == XF_PARSER_SLOTS) {
        k--; /* the candidate that ends last makes room (xf__open counted it) */
        moved = (p->at[k] == p->head) ? 3 : 1;
    }
    c = xf__crc_step(xf__crc_step((uint32_t)pair << 16, xf__crc_table(), (uint8_t)len), xf__crc_table(), 0);
    xf__sum(p);
    p->n = (uint8_t)(k + 1u);
    for (; k > 0u && k < XF_PARSER_SLOTS && xf__left(p, k - 1u) > left; k--) {
        p->want[k] = p->want[k - 1u];
        p->at[k] = p->at[k - 1u];
    }
    p->want[k] = (uint16_t)(p->crc ^ (c >> 16));
    p->at[k] = XF__IX(p->end - 4u);
    XF_ASSERT(p->n <= XF_PARSER_SLOTS && k < XF_PARSER_SLOTS && (k == 0u || xf__left(p, k - 1u) <= left) &&
              xf__len(p, k) == len);
    return moved;
}

/* The last byte held may be the fourth of a header: a candidate, a length
 * error, or nothing. When every slot is taken, the candidate that ends last
 * is given up, the new one included. Returns as xf__admit(), 8 when the
 * new header was given up, or 0 when it is no header. */
static inline int xf__open(xf_parser *p)
{
    const uint8_t *r = p->ring;
    unsigned s = XF__IX(p->end - 4u), len;
    if (xf__held(p) < 4u || r[s] != p->h0 || r[XF__IX(s + 1u)] != xf__h1(p)) {
        return 0;
    }
    len = (unsigned)r[XF__IX(s + 2u)] | ((unsigned)r[XF__IX(s + 3u)] << 8);
    if (!xf__len_ok(len)) {
        p->stats.length_errors++;
        return 0;
    }
    if (p->n == XF_PARSER_SLOTS) {
        p->stats.given_up++; /* the new candidate, or the pending one that ends last */
        if (len - 4u >= xf__left(p, XF_PARSER_SLOTS - 1u)) {
            return 8;
        }
    }
    return xf__admit(p, len);
}

/* Reverse r[i, j). Three reversals rotate the ring: a frame that wraps round
 * its end becomes contiguous at index 0. Rare: only after noise has left
 * the ring misaligned, at most once per XF_PARSER_RING bytes taken. */
static void xf__reverse(uint8_t *r, unsigned i, unsigned j)
{
    for (; i + 1u < j; i++) {
        uint8_t t = r[i];
        r[i] = r[--j];
        r[j] = t;
    }
}

/* Candidate 0 has ended intact: return it; everything else held overlaps it. */
static void xf__emit(xf_parser *p, xf_frame *frame)
{
    unsigned i0 = p->at[0], len = xf__len(p, 0);
    XF_ASSERT(xf__len_ok(len) && p->ring[i0] == p->h0 &&
              xf_crc16(p->ring + i0, (i0 + len <= XF_PARSER_RING) ? len : 0u) == 0u);
    p->stats.bytes_skipped += (unsigned)XF__IX(i0 - p->head);
    p->stats.frames++;
    if (i0 + len > XF_PARSER_RING) {
        xf__reverse(p->ring, 0, i0);
        xf__reverse(p->ring, i0, XF_PARSER_RING);
        xf__reverse(p->ring, 0, XF_PARSER_RING);
        i0 = 0;
    }
    frame->data = p->ring + i0;
    frame->len = len;
    p->n = 0;
    p->head = 0;
    p->end = 0;
    p->next = 1;
}

/* Candidates that end with the last byte held, in order of start: the first
 * intact one is returned (4), failed ones go (1, or 3 when one of them held
 * the first byte held). */
XF__COLD int xf__ends(xf_parser *p, xf_frame *frame)
{
    int moved = 1;
    if (p->n == 0u || xf__fin(p, 0) != p->end) {
        return 1;
    }
    xf__sum(p);
    do {
        uint16_t w = p->want[0];
        if (p->crc == ((w == 0u) ? 0u : xf__crc_zeros(w, xf__len(p, 0) - 4u))) {
            xf__emit(p, frame);
            return 4;
        }
        p->stats.crc_errors++;
        moved |= (p->at[0] == p->head) ? 3 : 1;
        xf__shift(p);
    } while (p->n > 0u && xf__fin(p, 0) == p->end);
    return moved;
}

/* After a look that changed something (look: as xf__admit() returns), or
 * with no candidate: move head up when the first byte held may have lost
 * its candidate, then set next. */
XF__COLD void xf__after(xf_parser *p, int look)
{
    if ((look & 2) || p->n == 0u) {
        xf__settle(p);
    }
    xf__plan(p);
}

/* No candidate, and the last byte held is the fourth after head's h0 (or
 * comes before it): a header there opens a candidate; else head moves to
 * the next h0 among the three bytes after it, or nothing is held. */
XF__COLD int xf__hunt(xf_parser *p)
{
    unsigned k = 1;
    XF_ASSERT(xf__held(p) <= 4u && p->ring[p->head] == p->h0);
    if (xf__held(p) == 4u && p->ring[XF__IX(p->head + 1u)] != xf__h1(p)) {
        /* No header pair at head, the commonest case of a run of h0 bytes:
         * what xf__settle() and xf__plan() would do, without their generality. */
        while (k < 4u && p->ring[XF__IX(p->head + k)] != p->h0) {
            k++;
        }
        if (k == 4u) {
            xf__clear(p);
            return 0;
        }
        p->stats.bytes_skipped += k;
        p->head = XF__IX(p->head + k);
        p->next = XF__IX(p->head + 4u);
        return 0;
    }
    if (xf__held(p) == 4u && xf__open(p) == 0) {
        xf__settle(p);
    }
    xf__plan(p);
    return 0;
}

/* The byte at next: the end of candidate 0 (and maybe others), which are
 * checked before the byte is looked at as a header's fourth. */
XF__COLD int xf__at_next(xf_parser *p, xf_frame *frame)
{
    int look = xf__ends(p, frame);
    if (look == 4) {
        return 1;
    }
    xf__after(p, look | xf__open(p));
    return 0;
}

/* Store an h0 that comes before next: it only brings next to its own
 * fourth byte. */
static inline void xf__h0(xf_parser *p)
{
    XF_ASSERT(p->head != p->end);
    p->ring[p->end] = (uint8_t)p->h0;
    p->end = XF__IX(p->end + 1u);
    if (XF__IX(p->next - p->end) > 3u) {
        p->next = XF__IX(p->end + 3u);
    }
}

/* The byte at next is the fourth after an h0, and no candidate's end: a
 * header (admitted, or given up), or nothing. */
XF__COLD int xf__fourth(xf_parser *p)
{
    int look = xf__open(p);
    if (look & 2) {
        xf__settle(p);
    }
    if (look != 0) {
        /* a header, admitted or given up: its last three bytes (h1, the length's low byte, 0)
         * begin no pair, so next is candidate 0's last byte (xf__plan's answer) */
        p->next = XF__IX(p->end + xf__left(p, 0));
    } else {
        xf__plan(p);
    }
    return 0;
}

/* Take one byte that needs a look: an h0, or the byte before next. Every
 * rule applies to the latter, ends before headers (a frame returned drops
 * whatever its last bytes begin); an h0 before next only brings next to
 * its own fourth byte. 1 when it completes a frame. */
static int xf__byte(xf_parser *p, uint8_t b, xf_frame *frame)
{
    if (p->next != XF__IX(p->end + 1u)) {
        XF_ASSERT(b == p->h0);
        xf__h0(p);
        return 0;
    }
    p->ring[p->end] = b;
    p->end = XF__IX(p->end + 1u);
    if (p->n == 0u) {
        return xf__hunt(p);
    }
    if (xf__fin(p, 0) == p->end) {
        return xf__at_next(p, frame);
    }
    return xf__fourth(p);
}

/* Bytes of d before the first h0, at most len. */
static inline size_t xf__to_h0(const xf_parser *p, const uint8_t *d, size_t len)
{
    const uint8_t *hit = (const uint8_t *)XF_MEMCHR(d, p->h0, len);
    return (hit != NULL) ? (size_t)(hit - d) : len;
}

/* Store the bytes of d before the first h0, at most len (none of them needs
 * a look); return how many. A short run in one loop, a long one through
 * memchr and memcpy. */
static size_t xf__quiet(xf_parser *p, const uint8_t *d, size_t len)
{
    uint8_t *r = p->ring;
    unsigned e = p->end, h0 = p->h0;
    size_t m = 0, first = XF_PARSER_RING - e;
    if (len < XF__SHORT) {
        for (; m < len && d[m] != h0; m++) {
            r[e] = d[m];
            e = XF__IX(e + 1u);
        }
    } else {
        m = xf__to_h0(p, d, len);
        XF_MEMCPY(r + e, d, (m < first) ? m : first);
        if (m > first) {
            XF_MEMCPY(r, d + first, m - first);
        }
        e = XF__IX(e + m);
    }
    p->end = (uint8_t)e;
    return m;
}

/* Nothing held, d starts with a header and holds the whole packet with no
 * other header pair inside, so no other candidate can begin or end before
 * its end: intact, it is returned from d itself, with no copy (1); damaged,
 * it is counted and skipped but for its last three bytes, which may begin a
 * header (-1). Else the general path applies every rule (0). */
static int xf__direct(xf_parser *p, const uint8_t *d, xf_frame *frame)
{
    size_t len = d[2], i = 1;
    while ((i += xf__to_h0(p, d + i, len - 1u - i)) < len - 1u) {
        if (d[++i] == xf__h1(p)) {
            return 0; /* a header pair inside: the general path applies every rule */
        }
    }
    if ((xf__crc_run(0, d, len) >> 16) != 0u) {
        p->stats.crc_errors++;
        p->stats.bytes_skipped += (uint32_t)len - 3u;
        return -1;
    }
    frame->data = d;
    frame->len = len;
    p->stats.frames++;
    return 1;
}

/* Nothing held: skip to the next h0 and look at the header it begins when
 * all of it is in view. A whole packet there is returned in place (1, *i
 * past it); a valid header opens its candidate at once. */
static int xf__idle(xf_parser *p, const uint8_t *d, size_t len, size_t *i, xf_frame *frame)
{
    size_t k = (d[*i] == p->h0) ? 0u : xf__to_h0(p, d + *i, len - *i); /* after a frame, the next is here */
    unsigned n;
    p->stats.bytes_skipped += (uint32_t)k;
    *i += k;
    d += *i;
    len -= *i;
    if (len == 0u) {
        return 0;
    }
    if (len < 4u) {
        (void)xf__byte(p, d[0], frame); /* no whole header in view: every rule applies from here */
        *i += 1u;
        return 0;
    }
    n = (unsigned)d[2] | ((unsigned)d[3] << 8);
    if (d[1] != xf__h1(p) || !xf__len_ok(n)) {
        /* A whole header in view, and no candidate: the h0 begins nothing, so it is skipped at
         * once (a header pair's bad length counted), with no look and nothing held. */
        p->stats.length_errors += (d[1] == xf__h1(p));
        p->stats.bytes_skipped++;
        *i += 1u;
        return 0;
    }
    k = (n <= len) ? (size_t)(xf__direct(p, d, frame) + 2) : 2u; /* 1, 2 or 3: damaged, general, whole */
    if (k != 2u) {
        *i += (k == 3u) ? n : n - 3u;
        return k == 3u;
    }
    XF_ASSERT(p->end == 0u && p->n == 0u); /* empty: at ring index 0 */
    XF_MEMCPY(p->ring, d, 4u);             /* the running CRC starts at this candidate (xf__admit) */
    p->end = 4;
    (void)xf__admit(p, n);
    /* What xf__plan() finds: no h0 among h1 and a length byte that, like its
     * high byte 0, are no h0 followed by h1 (ring index 0: no wrap). */
    p->next = (uint8_t)n;
    *i += 4u;
    return 0;
}

/* The main loop: take bytes until a frame is complete (1) or all are taken
 * (0). Bytes before the next h0 and before next are only stored; each of
 * the others gets a look of its own. */
static int xf__take(xf_parser *p, const uint8_t *d, size_t len, size_t *used, xf_frame *frame)
{
    size_t i = 0;
    while (i < len) {
        if (p->end == p->head) {
            if (xf__idle(p, d, len, &i, frame)) {
                *used = i;
                return 1;
            }
            continue;
        } else {
            size_t m = len - i, quiet = (unsigned)XF__IX(p->next - p->end) - 1u;
            if (quiet > 0u && d[i] != p->h0) {
                i += xf__quiet(p, d + i, (m < quiet) ? m : quiet);
            }
        }
        if (i < len && xf__byte(p, d[i++], frame)) {
            *used = i;
            return 1;
        }
    }
    *used = len;
    return 0;
}

/* Everything but one byte, out of line so that the one-byte path in
 * xf_parser_feed() needs no stack frame. */
XF__COLD xf_parse_status xf__feed(xf_parser *p, const uint8_t *data, size_t len, size_t *consumed, xf_frame *frame)
{
    size_t used = len;
    int found = xf__take(p, data, len, &used, frame);
    p->stats.bytes_in += (uint32_t)used;
    if (consumed != NULL) {
        *consumed = used;
    }
    return found ? XF_PARSE_FRAME : XF_PARSE_MORE;
}

/* One byte that needs a look, or comes while nothing is held. */
XF__COLD xf_parse_status xf__feed1(xf_parser *p, uint8_t b, size_t *consumed, xf_frame *frame)
{
    p->stats.bytes_in++;
    if (consumed != NULL) {
        *consumed = 1;
    }
    if (p->end == p->head && b != p->h0) {
        p->stats.bytes_skipped++; /* nothing held, and no header begins here */
        return XF_PARSE_MORE;
    }
    return (xf_parse_status)xf__byte(p, b, frame); /* 1 is XF_PARSE_FRAME, 0 XF_PARSE_MORE */
}

/* One h0 before next. */
XF__COLD xf_parse_status xf__feed_h0(xf_parser *p, size_t *consumed)
{
    p->stats.bytes_in++;
    if (consumed != NULL) {
        *consumed = 1;
    }
    xf__h0(p);
    return XF_PARSE_MORE;
}

XF_API xf_parse_status xf_parser_feed(xf_parser *p, const uint8_t *data, size_t len, size_t *consumed, xf_frame *frame)
{
    if (p == NULL || frame == NULL || (data == NULL && len > 0u)) {
        return XF_PARSE_ERR_ARG;
    }
    if (len == 1u) {
        unsigned e = p->end, b = data[0];
        if (p->next != XF__IX(e + 1u)) {
            /* A UART's byte that needs no look (xf__plan): store it; an h0
             * brings next to its fourth byte (out of line: no stack frame). */
            if (b == p->h0) {
                return xf__feed_h0(p, consumed);
            }
            p->ring[e] = (uint8_t)b;
            p->end = XF__IX(e + 1u);
            p->stats.bytes_in++;
            if (consumed != NULL) {
                *consumed = 1;
            }
            return XF_PARSE_MORE;
        }
        return xf__feed1(p, (uint8_t)b, consumed, frame);
    }
    return xf__feed(p, data, len, consumed, frame);
}

/* cppcheck-suppress constParameter ; frame stays writable: a parser that holds frames back may fill it */
XF_API xf_parse_status xf_parser_flush(xf_parser *p, xf_frame *frame)
{
    if (p == NULL || frame == NULL) {
        return XF_PARSE_ERR_ARG;
    }
    xf__clear(p);
    return XF_PARSE_MORE;
}

#endif /* XF_EMIT_DEFINITIONS */

XF_END_DECLS

#endif /* XF_PARSER_H */
