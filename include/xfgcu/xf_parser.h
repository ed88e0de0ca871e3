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
 * tracks up to ::XF_PARSER_SLOTS candidates at once, with one running CRC
 * for all of them, and checks each when its last byte arrives: the first
 * intact one is returned at once, and the others, which overlap it, are
 * dropped. So a frame behind noise, a truncated packet, a false header or a
 * bogus length comes out on time. First come, first served, within a
 * credit: a candidate that begins behind others costs credit, which the
 * bytes checked earn back (four candidates at once from a full credit, then
 * about one per 63 bytes). While every slot is taken or the credit is short,
 * no header is looked at, so a frame that begins then is lost
 * (stats.given_up counts the times this began). That bounds the work any
 * input can cause; docs/codec.md states the exact rules and the bound.
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
    uint32_t given_up;      /**< times the parser stopped looking at headers: a candidate took the last free slot
                                 or left the credit short (docs/codec.md) */
} xf_parser_stats;

/** Parser state. Treat the members as private except `stats`. */
typedef struct xf_parser {
    uint8_t ring[XF_PARSER_RING];   /**< private: bytes held, in order (a ring: indices wrap) */
    xf_parser_stats stats;          /**< counters, readable at any time; the application may zero them */
    uint16_t want[XF_PARSER_SLOTS]; /**< private: per candidate, what `crc` must be at its end, before the shift
                                       (docs/codec.md) */
    uint16_t crc;                   /**< private: CRC of the bytes from the start of the first candidate admitted
                                       since none was pending, up to `sum` */
    uint8_t at[XF_PARSER_SLOTS];    /**< private: ring index of each candidate's first byte, in order of start */
    uint8_t next;   /**< private: ring index just past the next byte that needs a look: the soonest end of a
                       candidate, or with none the fourth byte held */
    uint8_t end;    /**< private: ring index just past the last byte held */
    uint8_t n;      /**< private: candidates pending */
    uint8_t h0;     /**< private: first header byte of the direction parsed */
    uint8_t sum;    /**< private: ring index up to which `crc` runs */
    uint8_t credit; /**< private: bytes' worth of candidates the parser may still admit (docs/codec.md) */
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
#define XF__K     XF_PARSER_SLOTS
/* Chunks shorter than this go one byte at a time (xf__bytes), unless they
 * begin a packet: a call of the chunk path costs more than their tests. */
#define XF__FEW 12u
/* The credit, in bytes: admitting a candidate behind another costs
 * XF__COST, and each byte CRC'd while candidates are pending earns one, up
 * to XF__CAP. So such candidates are admitted at most once per XF__COST
 * bytes on average, three at once from a full credit (four candidates with
 * the first, as many as the default slots): it bounds the checks
 * a stream can cause (docs/codec.md). */
#define XF__COST 63u
#define XF__CAP  (3u * XF__COST)
/* The CRC of each direction's header pair (tests/test_parser.c checks them). */
#define XF__GCU_PAIR_CRC  0x4F68u
#define XF__HOST_PAIR_CRC 0x395Cu
XF_STATIC_ASSERT(XF_PARSER_RING > XF_PACKET_MAX_LEN && XF_PACKET_MAX_LEN <= 255u, ring_holds_a_packet);
XF_STATIC_ASSERT(XF_GCU_HEADER0 != XF_HOST_HEADER0, h0_names_the_direction);
/* A valid length's high byte (0) and h1 are no h0: a header's last three bytes begin no pair
 * unless its length's low byte is an h0. */
XF_STATIC_ASSERT(XF_GCU_HEADER0 != 0u && XF_HOST_HEADER0 != 0u && XF_GCU_HEADER0 != XF_GCU_HEADER1 &&
                     XF_HOST_HEADER0 != XF_HOST_HEADER1,
                 h1_and_0_are_no_h0);

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
    p->next = 4; /* nothing held: the fourth byte is the first that may complete a header */
    p->credit = XF__CAP;
    return XF_OK;
}

/* Ring index of the first byte held: the earliest candidate's first, or
 * with none four before next. */
static inline unsigned xf__head(const xf_parser *p) { return (p->n > 0u) ? p->at[0] : XF__IX(p->next - 4u); }

static inline unsigned xf__held(const xf_parser *p) { return (unsigned)XF__IX(p->end - xf__head(p)); }

/* Whether fewer than three bytes are held (only with no candidate: the
 * ring bytes before end are then stale, and begin no header). */
static inline int xf__few(const xf_parser *p) { return p->n == 0u && XF__IX(p->next - p->end) > 1u; }

/* Length and end (ring index just past its last byte) of candidate k: its
 * header is held as long as it is pending. */
static inline unsigned xf__len(const xf_parser *p, unsigned k) { return p->ring[XF__IX(p->at[k] + 2u)]; }

static inline unsigned xf__fin(const xf_parser *p, unsigned k) { return XF__IX(p->at[k] + xf__len(p, k)); }

/* Bytes still to come before candidate k ends, its last one included. */
static inline unsigned xf__left(const xf_parser *p, unsigned k) { return (unsigned)XF__IX(xf__fin(p, k) - p->end); }

/* Bytes still to come before the soonest end of a candidate, with one
 * pending: next is that end. */
static inline unsigned xf__left0(const xf_parser *p)
{
    XF_ASSERT(p->n > 0u && p->next != p->end && XF__IX(p->next - p->end) <= xf__left(p, 0));
    return (unsigned)XF__IX(p->next - p->end);
}

static inline int xf__len_ok(unsigned len) { return len >= XF_PACKET_MIN_LEN && len <= XF_PACKET_MAX_LEN; }

/* The second header byte of the direction parsed (h0 names it). */
static inline unsigned xf__h1(const xf_parser *p)
{
    return (p->h0 == XF_GCU_HEADER0) ? XF_GCU_HEADER1 : XF_HOST_HEADER1;
}

XF_API size_t xf_parser_pending(const xf_parser *p) { return (p == NULL) ? 0u : xf__held(p); }

/* Nothing held, no candidate, from ring index 0 (a frame held from there cannot wrap); the
 * fourth byte is the first that may complete a header. Counts nothing. */
static inline void xf__empty(xf_parser *p)
{
    p->n = 0;
    p->end = 0;
    p->next = 4;
}

/* Drop everything held: the next byte starts afresh, with a full credit. */
static inline void xf__clear(xf_parser *p)
{
    p->stats.bytes_skipped += xf__held(p);
    xf__empty(p);
    p->credit = XF__CAP;
}

XF_API void xf_parser_reset(xf_parser *p)
{
    if (p != NULL) {
        xf__clear(p);
    }
}

/* Whether headers are not looked at: candidates are pending and the credit
 * is short (always, when every slot is taken: xf__admit). */
static inline int xf__deaf(const xf_parser *p) { return p->credit < XF__COST && p->n > 0u; }

/* The credit once a candidate took the last slot: short of another's. */
static inline unsigned xf__full(unsigned credit) { return (credit < XF__COST) ? credit : XF__COST - 1u; }

/* A candidate was just taken, the n-th pending: taking the last slot leaves
 * the credit short of another's. When the credit is short, given_up counts
 * it: no header is looked at until a check earns enough or nothing is
 * pending. */
static inline void xf__taken(xf_parser *p, unsigned n)
{
    if (n == XF__K) {
        p->credit = (uint8_t)xf__full(p->credit);
    }
    if (p->credit < XF__COST) {
        p->stats.given_up++;
    }
}

/* Credit for m bytes CRC'd. */
static inline void xf__earn(xf_parser *p, unsigned m)
{
    unsigned c = p->credit + m;
    if (p->credit != XF__CAP) { /* (full on a clean stream: no store) */
        p->credit = (uint8_t)((c < XF__CAP) ? c : XF__CAP);
    }
}

/* Bring crc up to the last byte held: bytes are stored first and CRC'd
 * only when a candidate needs it, sixteen at a time (xf__crc_run). */
static inline void xf__sum(xf_parser *p)
{
    unsigned s = p->sum, e = p->end;
    uint32_t c = (uint32_t)p->crc << 16;
    xf__earn(p, (unsigned)XF__IX(e - s));
    if (e < s) {
        c = xf__crc_run(c, p->ring + s, XF_PARSER_RING - s);
        s = 0;
    }
    p->crc = (uint16_t)(xf__crc_run(c, p->ring + s, e - s) >> 16);
    p->sum = (uint8_t)e;
}

/* After candidates went: next is the soonest end of those left; with none,
 * the last three bytes are held (they may begin a header), the rest
 * skipped, and next is the fourth. */
static void xf__settle(xf_parser *p)
{
    unsigned k, held = xf__held(p), soon = 0;
    if (p->n == 0u) {
        if (held > 3u) {
            p->stats.bytes_skipped += held - 3u;
            held = 3;
        }
        p->next = XF__IX(p->end - held + 4u);
        return;
    }
    for (k = 1; k < p->n && k < XF__K; k++) { /* (the bound is for the compiler) */
        soon = (xf__left(p, k) < xf__left(p, soon)) ? k : soon;
    }
    p->next = (uint8_t)xf__fin(p, soon);
}

/* Drop candidate k: it ended and its CRC failed. The bytes before the next
 * candidate's are skipped; the last one's first byte stays the first held
 * until xf__settle. */
static void xf__drop(xf_parser *p, unsigned k)
{
    p->stats.crc_errors++;
    if (k == 0u && p->n > 1u) {
        p->stats.bytes_skipped += (unsigned)XF__IX(p->at[XF__K > 1 ? 1 : 0] - p->at[0]); /* (one slot: never) */
    } else if (p->n == 1u) {
        p->next = XF__IX(p->at[0] + 4u); /* (xf__head: four before next) */
    }
    for (p->n--; k < p->n && k + 1u < XF__K; k++) { /* (the bound is for the compiler) */
        p->want[k] = p->want[k + 1u];
        p->at[k] = p->at[k + 1u];
    }
}

/* The first candidate since none was pending, its header held at ring index
 * 0: its frame cannot wrap, the running CRC restarts at it, and want is 0. */
static inline void xf__first(xf_parser *p)
{
    p->crc = 0;
    p->sum = 0;
    p->want[0] = 0;
    p->at[0] = 0;
}

/* A header with a valid length ends with the last byte held, and the credit
 * allows a candidate: a new one, the last in order of start. Its `want` is
 * what the CRC of everything before it contributes at its end: the frame is
 * intact exactly when the running CRC then equals want * x^(8 (len - 4))
 * (xf__crc_zeros). Alone, it moves to ring index 0 (xf__first) and costs
 * nothing; behind others it costs XF__COST; then xf__taken. */
static void xf__admit(xf_parser *p, unsigned len)
{
    unsigned k = p->n, pair = (p->h0 == XF_GCU_HEADER0) ? XF__GCU_PAIR_CRC : XF__HOST_PAIR_CRC;
    uint32_t c;
    XF_ASSERT(k < XF__K && !xf__deaf(p));
    if (k == 0u) {
        p->stats.bytes_skipped += xf__held(p) - 4u;
        p->ring[0] = p->h0;
        p->ring[1] = (uint8_t)xf__h1(p);
        p->ring[2] = (uint8_t)len;
        p->ring[3] = 0;
        p->end = 4;
        xf__first(p);
        p->next = (uint8_t)len;
    } else if (k < XF__K) { /* (always; the bound is for the compiler) */
        c = xf__crc_step(xf__crc_step((uint32_t)pair << 16, xf__crc_table(), (uint8_t)len), xf__crc_table(), 0);
        xf__sum(p);
        p->credit = (uint8_t)(p->credit - XF__COST);
        p->want[k] = (uint16_t)(p->crc ^ (c >> 16));
        p->at[k] = XF__IX(p->end - 4u);
        if (len - 4u < (unsigned)XF__IX(p->next - p->end - 1u) + 1u) { /* (next == end: xf__look settles it) */
            p->next = (uint8_t)xf__fin(p, k);
        }
    }
    p->n++;
    xf__taken(p, p->n);
    XF_ASSERT(p->n <= XF__K && xf__len(p, k) == len);
}

/* The last byte held completes a header pair, and the credit allows a
 * candidate: a bad length is counted; a valid one is admitted. */
static void xf__header(xf_parser *p)
{
    unsigned len = p->ring[XF__IX(p->end - 2u)] | ((unsigned)p->ring[XF__IX(p->end - 1u)] << 8);
    if (xf__len_ok(len)) {
        xf__admit(p, len);
    } else {
        p->stats.length_errors++;
    }
}

/* Reverse r[i, j). Three reversals rotate the ring: a frame that wraps round
 * its end becomes contiguous at index 0. Rare: only a candidate that began
 * behind another can wrap. */
static void xf__reverse(uint8_t *r, unsigned i, unsigned j)
{
    for (; i + 1u < j; i++) {
        uint8_t t = r[i];
        r[i] = r[--j];
        r[j] = t;
    }
}

/* Candidate k has ended intact: return it; everything else held overlaps it. */
static void xf__emit(xf_parser *p, unsigned k, xf_frame *frame)
{
    unsigned i0 = p->at[k], len = xf__len(p, k);
    XF_ASSERT(xf__len_ok(len) && p->ring[i0] == p->h0 &&
              xf_crc16(p->ring + i0, (i0 + len <= XF_PARSER_RING) ? len : 0u) == 0u);
    if (k > 0u) { /* the bytes before it (from the first held: xf__head) */
        p->stats.bytes_skipped += (unsigned)XF__IX(i0 - p->at[0]);
    }
    p->stats.frames++;
    if (i0 + len > XF_PARSER_RING) {
        xf__reverse(p->ring, 0, i0);
        xf__reverse(p->ring, i0, XF_PARSER_RING);
        xf__reverse(p->ring, 0, XF_PARSER_RING);
        i0 = 0;
    }
    frame->data = p->ring + i0;
    frame->len = len;
    xf__empty(p);
}

/* The last byte held ends one candidate or more: check them in order of
 * start; the first intact one is returned (1), failed ones go. */
static int xf__ends(xf_parser *p, xf_frame *frame)
{
    unsigned k = 0;
    xf__sum(p);
    do {
        uint16_t w = p->want[k];
        if (xf__fin(p, k) != p->end) {
            k++;
        } else if (p->crc == ((w == 0u) ? 0u : xf__crc_zeros(w, xf__len(p, k) - 4u))) {
            xf__emit(p, k, frame);
            return 1;
        } else {
            xf__drop(p, k);
        }
    } while (k < p->n);
    return 0;
}

/* The last byte held ends a candidate: the candidates that end with it
 * come first (a frame returned drops whatever its last bytes begin), then
 * a header pair it completes (pair), if the credit their check earned
 * allows. 1 when it completes a frame. */
XF__COLD int xf__look(xf_parser *p, int pair, xf_frame *frame)
{
    if (xf__ends(p, frame)) {
        return 1;
    }
    if (pair && !xf__deaf(p)) {
        xf__header(p);
    }
    xf__settle(p);
    return 0;
}

/* No candidate, and the byte that makes four held: the first can begin no
 * header now. */
static inline void xf__trim(xf_parser *p)
{
    p->next = XF__IX(p->next + 1u); /* (and so the first byte held: xf__head) */
    p->stats.bytes_skipped++;
}

/* After a byte that ends no candidate: the header pair it completes
 * (pair), then, with no candidate and four bytes held, the first goes. */
static inline void xf__no_end(xf_parser *p, int pair)
{
    XF_ASSERT(!pair || !xf__deaf(p)); /* callers give a pair only when headers are looked at */
    if (pair) {
        xf__header(p);
    }
    if (p->n == 0u && p->end == p->next) {
        xf__trim(p); /* no candidate (a bad length, or none): four bytes held */
    }
}

/* One byte, through every rule (pair: it completes a header pair). 1 when
 * it completes a frame. */
static inline int xf__step(xf_parser *p, uint8_t b, int pair, xf_frame *frame)
{
    p->ring[p->end] = b;
    p->end = XF__IX(p->end + 1u);
    if (p->end == p->next && p->n > 0u) {
        return xf__look(p, pair, frame);
    }
    xf__no_end(p, pair);
    return 0;
}

/* Whether the next byte completes a header pair (h0 h1 among the bytes held). */
static inline int xf__pair(const xf_parser *p)
{
    unsigned e = p->end;
    return p->ring[XF__IX(e - 3u)] == p->h0 && p->ring[XF__IX(e - 2u)] == xf__h1(p) && !xf__few(p);
}

static inline int xf__byte(xf_parser *p, uint8_t b, xf_frame *frame) { return xf__step(p, b, xf__pair(p), frame); }

/* Store d[0, m) after the bytes held (no byte of it needs the byte path). */
static void xf__copy(xf_parser *p, const uint8_t *d, size_t m)
{
    unsigned e = p->end;
    size_t first = XF_PARSER_RING - e;
    XF_MEMCPY(p->ring + e, d, (m < first) ? m : first);
    if (m > first) {
        XF_MEMCPY(p->ring, d + first, m - first);
    }
    p->end = XF__IX(e + m);
}

/* The first index in [i + 3, r) of d that completes a header with a valid
 * length begun in d at or after i, or r; the bad lengths completed before
 * it are counted in *errors. A header is h0 h1 and two length bytes: an h0
 * followed by another byte begins none, and after a pair the next h0 may
 * be its length's low byte. */
static size_t xf__scan(const xf_parser *p, const uint8_t *d, size_t i, size_t r, uint32_t *errors)
{
    unsigned h1 = xf__h1(p);
    while (i + 3u < r) {
        if (d[i] != p->h0) { /* (after a pair, the length's low byte often is one) */
            const uint8_t *hit = (const uint8_t *)XF_MEMCHR(d + i, p->h0, r - i - 3u);
            if (hit == NULL) {
                break;
            }
            i = (size_t)(hit - d);
        }
        if (d[i + 1u] != h1) {
            i++;
        } else if (d[i + 3u] != 0u || !xf__len_ok(d[i + 2u])) {
            ++*errors;
            i += 2u;
        } else {
            return i + 3u;
        }
    }
    return r;
}

/* No candidate: hold the last three bytes of what is held followed by
 * d[0, m) (they may begin a header), skip the rest. */
static void xf__keep(xf_parser *p, const uint8_t *d, size_t m)
{
    if (m >= 3u) {
        p->stats.bytes_skipped += xf__held(p) + (uint32_t)(m - 3u);
        xf__empty(p);
        d += m - 3u;
        m = 3;
    }
    xf__copy(p, d, m);
    xf__settle(p);
}

/* Nothing held, no candidate, and d begins with a header with a valid
 * length (len): its candidate, the first. When no other header pair
 * completes among its packet's bytes in d, they are taken at once: a packet
 * whole in d is CRC'd where it lies and returned from d (1) or, damaged,
 * counted and skipped but for its last three bytes; else its candidate
 * opens at ring index 0 with all of d. When one does, the candidate opens
 * with its header alone and the main loop takes the rest. *used: the bytes
 * taken. */
static inline int xf__fresh(xf_parser *p, const uint8_t *d, size_t n, size_t *used, xf_frame *frame)
{
    unsigned len = d[2], h1 = xf__h1(p);
    size_t m = (len < n) ? len : n;
    const uint8_t *hit = d, *stop = d + m - 3u; /* a pair begun before stop completes among them */
    while ((hit = (const uint8_t *)XF_MEMCHR(hit + 1, p->h0, (size_t)(stop - hit - 1))) != NULL) {
        if (hit[1] == h1) {
            m = 4; /* the main loop takes the rest */
            break;
        }
    }
    *used = m;
    xf__taken(p, 1); /* the packet's candidate, as if admitted */
    if (m < len) {
        XF_MEMCPY(p->ring, d, m);
        xf__first(p);
        p->end = (uint8_t)m;
        p->n = 1;
        p->next = (uint8_t)len;
        return 0;
    }
    xf__earn(p, len); /* as xf__sum at its end */
    if ((xf__crc_run(0, d, len) >> 16) == 0u) {
        frame->data = d;
        frame->len = len;
        p->stats.frames++;
        return 1;
    }
    p->stats.crc_errors++;
    xf__keep(p, d, len);
    return 0;
}

/* Whether d[0, n) begins with a header with a valid length. */
static inline int xf__starts(const xf_parser *p, const uint8_t *d, size_t n)
{
    return n >= 4u && d[0] == p->h0 && d[1] == xf__h1(p) && d[3] == 0u && xf__len_ok(d[2]);
}

/* No candidate, and no h0 among the bytes held: the first header in
 * d[*i, n) with a valid length (the bad ones before it counted). None: d's
 * last bytes are held (0). Else what is held and the bytes before it are
 * skipped, and the fresh path takes it from there (1 with a frame). */
static int xf__idle(xf_parser *p, const uint8_t *d, size_t n, size_t *i, xf_frame *frame)
{
    size_t k = xf__scan(p, d, *i, n, &p->stats.length_errors), s = k - 3u, used;
    int found;
    if (k == n) {
        xf__keep(p, d + *i, n - *i);
        *i = n;
        return 0;
    }
    p->stats.bytes_skipped += xf__held(p) + (uint32_t)(s - *i);
    xf__empty(p);
    found = xf__fresh(p, d + s, n - s, &used, frame);
    *i = s + used;
    return found;
}

/* An h0 among the last three bytes held: the next byte may complete a pair
 * begun before d, so it takes the byte path. */
static inline int xf__tail(const xf_parser *p)
{
    const uint8_t *r = p->ring;
    unsigned e = p->end, h0 = p->h0;
    return r[XF__IX(e - 1u)] == h0 || r[XF__IX(e - 2u)] == h0 || r[XF__IX(e - 3u)] == h0;
}

/* No candidate, at d[i]: when the bytes held are d's last three, give
 * them back (the new i), so that the idle path sees whatever header they
 * begin. */
static size_t xf__give_back(xf_parser *p, size_t i)
{
    if (i >= 3u) {
        XF_ASSERT(xf__held(p) <= 3u);
        i -= xf__held(p);
        xf__empty(p); /* (nothing skipped: those bytes are taken again) */
    }
    return i;
}

/* Candidates pending, at d[i]: store the bytes before the soonest end's
 * last byte and before the first valid header among them (its bad lengths
 * counted), and return the index of the byte that needs the byte path, or
 * n. While headers are not looked at (every slot taken, or the credit
 * short), none is searched for. The search begins three bytes back, at
 * pairs begun before i. */
static size_t xf__run(xf_parser *p, const uint8_t *d, size_t i, size_t n)
{
    size_t r = n - i, left = xf__left0(p) - 1u, k; /* up to the soonest end's last */
    r = i + ((r < left) ? r : left);
    k = xf__deaf(p) ? r : xf__scan(p, d, (i < 3u) ? i : i - 3u, r, &p->stats.length_errors);
    xf__copy(p, d + i, k - i);
    return k;
}

/* The main loop: take bytes until a frame is complete (1) or all are taken
 * (0). A byte goes through the byte path when it ends a candidate, completes
 * a valid header, or may complete a pair begun among the bytes held; runs
 * between are searched for pairs in d and copied. */
static int xf__take(xf_parser *p, const uint8_t *d, size_t n, size_t *used, xf_frame *frame)
{
    size_t i = 0, k;
    while (i < n) {
        if (i < 3u && !xf__deaf(p) && xf__tail(p)) {
            k = i; /* a pair begun before d may end here: the byte path */
        } else if (p->n > 0u) {
            k = xf__run(p, d, i, n);
        } else {
            i = xf__give_back(p, i);
            if (xf__idle(p, d, n, &i, frame)) {
                *used = i;
                return 1;
            }
            continue;
        }
        if (k == n) {
            break;
        }
        i = k + 1u;
        if (xf__byte(p, d[k], frame)) {
            *used = i;
            return 1;
        }
    }
    *used = n;
    return 0;
}

/* A chunk: twelve bytes or more, or a packet's start with nothing held
 * (xf__many). */
XF__COLD xf_parse_status xf__feed(xf_parser *p, const uint8_t *data, size_t len, size_t *consumed, xf_frame *frame)
{
    size_t used = 0, m = 0;
    int found = 0;
    if (len > 0u && p->n > 0u && !xf__tail(p)) {
        /* Inside a frame, the commonest chunk: the bytes before the soonest
         * end's last and before the first h0 are only stored (no pair can end
         * among them); with no h0, the last byte is stored with them and the
         * candidates that end there are checked at once. The main loop takes
         * the rest from the h0 on, with no second search. */
        size_t left = xf__left0(p);
        const uint8_t *hit;
        m = (len < left) ? len : left - 1u;
        hit = (const uint8_t *)XF_MEMCHR(data, p->h0, m);
        if (hit != NULL) {
            m = (size_t)(hit - data);
        } else if (len >= left) {
            m = left; /* its last byte completes no pair: no h0 three back (this search, or xf__tail) */
        }
        xf__copy(p, data, m);
        if (m == left) {
            found = xf__look(p, 0, frame);
        }
    } else if (p->n == 0u && xf__held(p) == 0u && xf__starts(p, data, len)) {
        found = xf__fresh(p, data, len, &m, frame); /* the commonest chunk after a frame */
    }
    if (!found && m < len) {
        found = xf__take(p, data + m, len - m, &used, frame);
    }
    used = !found ? len : used + m; /* (a frame from the in-frame or fresh path: used is 0) */
    p->stats.bytes_in += (uint32_t)used;
    if (consumed != NULL) {
        *consumed = used;
    }
    return found ? XF_PARSE_FRAME : XF_PARSE_MORE;
}

/* Store one byte that needs no look. */
static inline void xf__store(xf_parser *p, uint8_t b)
{
    p->ring[p->end] = b;
    p->end = XF__IX(p->end + 1u);
}

/* Store one byte fed alone that needs no look. */
static inline xf_parse_status xf__store1(xf_parser *p, uint8_t b, size_t *consumed, size_t used)
{
    xf__store(p, b);
    p->stats.bytes_in++;
    if (consumed != NULL) {
        *consumed = used;
    }
    return XF_PARSE_MORE;
}

/* One byte fed alone that may need a look. */
XF__COLD xf_parse_status xf__feed1(xf_parser *p, uint8_t b, size_t *consumed, size_t used, xf_frame *frame)
{
    p->stats.bytes_in++;
    if (consumed != NULL) {
        *consumed = used;
    }
    return (xf_parse_status)xf__byte(p, b, frame); /* 1 is XF_PARSE_FRAME, 0 XF_PARSE_MORE */
}

/* One byte, the last of a call, that completes a pair of the bytes held,
 * h0 h1, while headers are looked at, and that xf__one() did not settle: a
 * valid length, a candidate's end too, or stale ring bytes. */
XF__COLD xf_parse_status xf__pair1(xf_parser *p, uint8_t b, size_t *consumed, size_t used, xf_frame *frame)
{
    xf_parse_status r;
    if ((XF__IX(p->end + 1u) == p->next && p->n > 0u) || xf__few(p)) {
        return xf__feed1(p, b, consumed, used, frame); /* a candidate's end first, or stale ring bytes */
    }
    r = xf__store1(p, b, consumed, used); /* the byte path without its tests for an end and a pair */
    xf__no_end(p, 1);
    return r;
}

/* A byte of a few fed together: when it needs no look, it is stored (the
 * first of four held goes when hunting, a bad length is counted), 1; when
 * it ends a candidate or completes a header pair to look at, nothing is
 * done, 0 (xf__rest). The tests of xf__one(), which also keeps the call's
 * counters and hands the byte on at once. */
static inline int xf__plain(xf_parser *p, uint8_t b)
{
    unsigned e = p->end;
    if (p->ring[XF__IX(e - 3u)] == p->h0 && p->ring[XF__IX(e - 2u)] == xf__h1(p) && !xf__deaf(p)) {
        if ((b == 0u && xf__len_ok(p->ring[XF__IX(e - 1u)])) || xf__few(p) ||
            (XF__IX(e + 1u) == p->next && p->n > 0u)) {
            return 0; /* a valid length, stale ring bytes, or a candidate's end too */
        }
        p->stats.length_errors++;
    } else if (XF__IX(e + 1u) == p->next && p->n > 0u) {
        return 0; /* a candidate's end */
    }
    if (XF__IX(e + 1u) == p->next) {
        xf__trim(p); /* no candidate: the first of four goes */
    }
    xf__store(p, b);
    return 1;
}

/* A few bytes from d[i], which needs a look: it takes the byte path, the
 * rest xf__plain() or the byte path, up to a frame's last byte. */
XF__COLD xf_parse_status xf__rest(xf_parser *p, const uint8_t *d, size_t len, size_t i, size_t *consumed,
                                  xf_frame *frame)
{
    int found = xf__byte(p, d[i++], frame);
    for (; !found && i < len; i++) {
        found = !xf__plain(p, d[i]) && xf__byte(p, d[i], frame);
    }
    p->stats.bytes_in += (uint32_t)i;
    if (consumed != NULL) {
        *consumed = i;
    }
    return found ? XF_PARSE_FRAME : XF_PARSE_MORE;
}

/* A few bytes (4 to XF__FEW - 1), not a packet's start: one at a time, as
 * in the one-byte path, for the chunk path's call costs more than their
 * tests (docs/codec.md). */
XF__COLD xf_parse_status xf__bytes(xf_parser *p, const uint8_t *d, size_t len, size_t *consumed, xf_frame *frame)
{
    size_t i;
    for (i = 0; i < len; i++) {
        if (!xf__plain(p, d[i])) {
            return xf__rest(p, d, len, i, consumed, frame);
        }
    }
    p->stats.bytes_in += (uint32_t)len;
    if (consumed != NULL) {
        *consumed = len;
    }
    return XF_PARSE_MORE;
}

/* One byte, the last of the call's used bytes (*consumed = used, when not
 * NULL): most need two tests and a store, and no stack frame. */
XF__INLINE xf_parse_status xf__one(xf_parser *p, const uint8_t *d, size_t *consumed, size_t used, xf_frame *frame)
{
    unsigned e = p->end;
    if (p->ring[XF__IX(e - 3u)] != p->h0 || p->ring[XF__IX(e - 2u)] != xf__h1(p) || xf__deaf(p)) {
        /* A UART's byte that completes no header pair to look at. */
        if (XF__IX(e + 1u) != p->next) {
            return xf__store1(p, d[0], consumed, used);
        }
        if (p->n == 0u) {
            xf__trim(p);
            return xf__store1(p, d[0], consumed, used);
        }
        return xf__feed1(p, d[0], consumed, used, frame); /* a candidate's end */
    }
    if ((d[0] != 0u || !xf__len_ok(p->ring[XF__IX(e - 1u)])) && !xf__few(p) &&
        (XF__IX(e + 1u) != p->next || p->n == 0u)) {
        /* A bad length (a flood of pairs has a high byte other than 0),
         * where the byte ends no candidate. */
        p->stats.length_errors++;
        if (XF__IX(e + 1u) == p->next) {
            xf__trim(p); /* no candidate: the first of four goes */
        }
        return xf__store1(p, d[0], consumed, used);
    }
    return xf__pair1(p, d[0], consumed, used, frame);
}

/* Two or three bytes: the first ones, then the last as if alone (no stack
 * frame). */
XF__COLD xf_parse_status xf__two(xf_parser *p, const uint8_t *data, size_t len, size_t *consumed, xf_frame *frame)
{
    if (!xf__plain(p, data[0])) {
        return xf__rest(p, data, len, 0, consumed, frame);
    }
    if (len == 3u && !xf__plain(p, data[1])) {
        return xf__rest(p, data, len, 1, consumed, frame);
    }
    p->stats.bytes_in += (uint32_t)(len - 1u);
    return xf__one(p, data + len - 1u, consumed, len, frame);
}

/* Any number of bytes but one: two, a few, or a chunk. */
XF__COLD xf_parse_status xf__many(xf_parser *p, const uint8_t *data, size_t len, size_t *consumed, xf_frame *frame)
{
    if (len == 2u || len == 3u) {
        return xf__two(p, data, len, consumed, frame);
    }
    if (len < XF__FEW && (p->n > 0u || xf__held(p) > 0u || !xf__starts(p, data, len))) {
        return xf__bytes(p, data, len, consumed, frame); /* (a packet's start: the fresh path) */
    }
    return xf__feed(p, data, len, consumed, frame);
}

XF_API xf_parse_status xf_parser_feed(xf_parser *p, const uint8_t *data, size_t len, size_t *consumed, xf_frame *frame)
{
    if (p == NULL || frame == NULL || (data == NULL && len > 0u)) {
        return XF_PARSE_ERR_ARG;
    }
    if (len != 1u) {
        return xf__many(p, data, len, consumed, frame);
    }
    return xf__one(p, data, consumed, 1, frame);
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
