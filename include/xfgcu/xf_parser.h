/*
 * xf_parser.h - streaming parser: bytes in any chunking, whole frames out.
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
 * checked where it lies (no copy); others are copied once; every byte is
 * CRC'd once. After a
 * CRC failure the parser keeps, for each held byte, the CRC of the stream
 * before it (computed once per byte), and checks every further candidate in
 * constant time from two of those values (crc(i..j) = P(j) ^ P(i) * x^(8(j-i))),
 * so adversarial input costs O(1) per byte, never O(frame length).
 *
 * Counters only ever increase (the application may zero them):
 *     bytes_in = bytes of returned frames + bytes_skipped + xf_parser_pending()
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

/* Ring size: a power of two that holds the longest packet. */
#if XF_PACKET_MAX_LEN > 128
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
    const uint8_t *data;
    size_t len;
} xf_frame;

/** Parser state. Treat the members as private except `stats`. */
typedef struct xf_parser {
    uint8_t ring[XF_PARSER_RING];
#if XF_PARSER_MEMO
    uint16_t memo[XF_PARSER_RING]; /* CRC of the stream before each held byte (memo mode) */
#endif
    uint32_t head;     /* stream position of the first held byte: the earliest candidate */
    uint32_t end;      /* one past the last held byte */
    uint32_t look;     /* positions in (head, look) are examined: no candidate, or a failed contender */
    uint16_t memo_crc; /* CRC of the stream before `end` (memo mode) */
    uint8_t memo_on;
    uint8_t look_done; /* no contender can follow for this head */
    uint8_t h0, h1;    /* header bytes of the direction parsed */
    uint8_t rotated;   /* the last frame wrapped round the ring, which was rotated (tests look) */
    xf_parser_stats stats;
} xf_parser;

/** Start a parser for packets sent in direction @p dir (XF_DIR_GCU on a host). */
XF_API xf_err xf_parser_init(xf_parser *p, xf_direction dir);

/** Drop the bytes held (counted as skipped); keep the direction and the counters. */
XF_API void xf_parser_reset(xf_parser *p);

/** Bytes held that belong to no returned frame yet. */
XF_API size_t xf_parser_pending(const xf_parser *p);

#define XF_PARSE_FRAME 1 /**< xf_parser_feed: *frame holds a frame */
#define XF_PARSE_MORE  0 /**< xf_parser_feed: all input taken, no frame */

/**
 * Feed @p len bytes. Stops at the first complete frame: returns
 * XF_PARSE_FRAME with *frame set and *consumed = the bytes of @p data taken
 * so far; call again with the rest (even when the rest is empty: frames
 * can be found in bytes already held). Returns XF_PARSE_MORE when every
 * byte was taken and no frame is complete, or XF_ERR_ARG.
 *
 *     size_t n; xf_frame f;
 *     while (xf_parser_feed(&p, data, len, &n, &f) == XF_PARSE_FRAME) {
 *         handle(f.data, f.len);
 *         data += n; len -= n;
 *     }
 */
XF_API int xf_parser_feed(xf_parser *p, const uint8_t *data, size_t len, size_t *consumed, xf_frame *frame);

/**
 * Decode a frame this parser returned, without computing its CRC again
 * (the parser has checked header, length and CRC; only the header and
 * length are looked at again, cheaply). For bytes from anywhere else use
 * xf_gcu_unpack / xf_host_unpack.
 * @return XF_OK, XF_ERR_ARG, XF_ERR_HEADER (a frame of the other
 *   direction), XF_ERR_LENGTH.
 */
XF_API xf_err xf_frame_gcu(const xf_frame *frame, xf_gcu_packet *pkt);
XF_API xf_err xf_frame_host(const xf_frame *frame, xf_host_packet *pkt);

/**
 * The input has ended (end of file, link closed): give up the candidates
 * that can no longer complete and return the intact frames behind them.
 * Call until it returns XF_PARSE_MORE; then nothing is pending. The bytes
 * given up count as skipped.
 */
XF_API int xf_parser_flush(xf_parser *p, xf_frame *frame);

#if XF_EMIT_DEFINITIONS

#define XF__RMASK (XF_PARSER_RING - 1u)
/* The contender loop skips a failed candidate's second and fourth bytes. */
XF_STATIC_ASSERT(XF_GCU_HEADER0 != XF_GCU_HEADER1 && XF_HOST_HEADER0 != XF_HOST_HEADER1, header_bytes_differ);
XF_STATIC_ASSERT(XF_GCU_HEADER0 != 0 && XF_HOST_HEADER0 != 0 && XF_PACKET_MAX_LEN < 256, length_high_byte_not_h0);
XF_STATIC_ASSERT((XF_PARSER_RING & XF__RMASK) == 0u, ring_is_power_of_two);
XF_STATIC_ASSERT(XF_PARSER_RING >= XF_PACKET_MAX_LEN, ring_holds_a_packet);

static inline uint8_t xf__rb(const xf_parser *p, uint32_t pos) { return p->ring[pos & XF__RMASK]; }

XF_API xf_err xf_parser_init(xf_parser *p, xf_direction dir)
{
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
    p->memo_on = 0;
}

XF_API void xf_parser_reset(xf_parser *p)
{
    if (p != NULL) {
        p->stats.bytes_skipped += (uint32_t)(p->end - p->head);
        xf__parser_empty(p);
    }
}

/* CRC of held bytes [pos, pos + n) read straight from the ring (fast mode). */
static inline uint16_t xf__ring_crc(const xf_parser *p, uint32_t pos, size_t n)
{
    size_t i0 = pos & XF__RMASK;
    size_t first = (i0 + n <= XF_PARSER_RING) ? n : (XF_PARSER_RING - i0);
    uint16_t c = xf_crc16_update(0, p->ring + i0, first);
    return xf_crc16_update(c, p->ring, n - first);
}

/* Enter memo mode: record the CRC before each held byte, from `head` on.
 * Without XF_PARSER_MEMO the parser stays in fast mode: every candidate's
 * CRC is read from the ring (still exact, but O(length) per candidate). */
static inline void xf__memo_start(xf_parser *p)
{
#if !XF_PARSER_MEMO
    (void)p;
#else
    const uint32_t *table = xf__crc_table();
    uint32_t pos, c = 0;
    for (pos = p->head; pos != p->end; pos++) {
        p->memo[pos & XF__RMASK] = (uint16_t)(c >> 16);
        c = xf__crc_step(c, table, xf__rb(p, pos));
    }
    p->memo_crc = (uint16_t)(c >> 16);
    p->memo_on = 1;
#endif
}

#if XF_PARSER_MEMO
/* Memo mode: store n bytes at ring index i0 (no wrap) with the CRC before each. */
static inline uint32_t xf__append_memo(xf_parser *p, size_t i0, const uint8_t *data, size_t n, uint32_t c)
{
    const uint32_t *table = xf__crc_table();
    uint8_t *r = p->ring + i0;
    uint16_t *m = p->memo + i0;
    size_t i;
    for (i = 0; i < n; i++) {
        uint8_t b = data[i]; /* read once: the ring store may alias data */
        m[i] = (uint16_t)(c >> 16);
        r[i] = b;
        c = xf__crc_step(c, table, b);
    }
    return c;
}
#endif

static inline void xf__append(xf_parser *p, const uint8_t *data, size_t n)
{
    size_t i0 = p->end & XF__RMASK;
    size_t first = (i0 + n <= XF_PARSER_RING) ? n : (XF_PARSER_RING - i0);
#if XF_PARSER_MEMO
    if (p->memo_on) {
        uint32_t c = xf__append_memo(p, i0, data, first, (uint32_t)p->memo_crc << 16);
        c = xf__append_memo(p, 0, data + first, n - first, c);
        p->memo_crc = (uint16_t)(c >> 16);
    } else
#endif
    {
        XF_MEMCPY(p->ring + i0, data, first);
        XF_MEMCPY(p->ring, data + first, n - first);
    }
    p->end += (uint32_t)n;
}

/* Is the candidate of length len at pos intact? Needs memo mode unless pos is head. */
XF__HOT_INLINE int xf__intact(const xf_parser *p, uint32_t pos, size_t len)
{
    uint32_t crc_pos = pos + (uint32_t)len - 2u;
    uint16_t want = (uint16_t)(((uint16_t)xf__rb(p, crc_pos) << 8) | xf__rb(p, crc_pos + 1u));
    uint16_t got;
#if XF_PARSER_MEMO
    if (p->memo_on) {
        got = (uint16_t)(p->memo[crc_pos & XF__RMASK] ^ xf__crc_shift(p->memo[pos & XF__RMASK], (unsigned)(len - 2u)));
    } else
#endif
    {
        got = xf__ring_crc(p, pos, len - 2u);
    }
    return got == want;
}

/* Drop the held bytes before pos (they belong to no frame). */
static inline void xf__drop_to(xf_parser *p, uint32_t pos)
{
    p->stats.bytes_skipped += (uint32_t)(pos - p->head);
    p->head = pos;
    p->look = pos + 1u;
    p->look_done = 0;
}

/* Reverse ring[i..j) (and the memo alongside). */
static inline void xf__reverse(xf_parser *p, size_t i, size_t j)
{
    while (i + 1u < j) {
        uint8_t t = p->ring[i];
        j--;
        p->ring[i] = p->ring[j];
        p->ring[j] = t;
#if XF_PARSER_MEMO
        {
            uint16_t m = p->memo[i];
            p->memo[i] = p->memo[j];
            p->memo[j] = m;
        }
#endif
        i++;
    }
}

/* Make position pos sit at ring index 0: rotate the ring left by pos's
 * index (three reversals) and renumber every position by as much, so
 * held bytes keep their index = position mod ring. Rare: frames wrap only
 * after noise has left the ring misaligned, and this costs less than a
 * scratch copy of a whole packet would in RAM. */
static inline void xf__rotate(xf_parser *p, uint32_t pos)
{
    size_t s = pos & XF__RMASK;
    xf__reverse(p, 0, s);
    xf__reverse(p, s, XF_PARSER_RING);
    xf__reverse(p, 0, XF_PARSER_RING);
    p->head -= (uint32_t)s;
    p->end -= (uint32_t)s;
    p->look -= (uint32_t)s;
}

/* Return the frame of length len at pos and drop everything before it. */
static inline void xf__emit(xf_parser *p, uint32_t pos, size_t len, xf_frame *frame)
{
    p->rotated = 0;
    if ((pos & XF__RMASK) + len > XF_PARSER_RING) {
        xf__rotate(p, pos);
        pos -= pos & XF__RMASK;
        p->rotated = 1;
    }
    frame->data = p->ring + (pos & XF__RMASK);
    frame->len = len;
    xf__drop_to(p, pos);
    p->head = pos + (uint32_t)len;
    p->look = p->head + 1u;
    p->stats.frames++;
}

#define XF__NO   0 /* not a candidate */
#define XF__YES  1 /* a candidate; *len set */
#define XF__WAIT 2 /* cannot tell yet; *need more bytes */

/* Is there a candidate (header pair, valid length) at pos? */
static inline int xf__candidate(xf_parser *p, uint32_t pos, size_t *len, size_t *need)
{
    size_t avail = (size_t)(p->end - pos);
    if (xf__rb(p, pos) != p->h0) {
        return XF__NO;
    }
    if (avail < 2u) {
        *need = 2u - avail;
        return XF__WAIT;
    }
    if (xf__rb(p, pos + 1u) != p->h1) {
        return XF__NO;
    }
    if (avail < 4u) {
        *need = 4u - avail;
        return XF__WAIT;
    }
    *len = (size_t)xf__rb(p, pos + 2u) | ((size_t)xf__rb(p, pos + 3u) << 8);
    if (*len < XF_PACKET_MIN_LEN || *len > XF_PACKET_MAX_LEN) {
        p->stats.length_errors++; /* each position is examined once, so counted once */
        return XF__NO;
    }
    return XF__YES;
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
    const uint8_t h0 = p->h0;
    uint32_t look = p->look;
    uint32_t stop; /* end or lim, whichever comes first */
    *need = 0;
    if (p->look_done || (uint32_t)(pend - look) <= XF_PACKET_MIN_LEN) {
        p->look_done = 1;
        return 0;
    }
    stop = ((uint32_t)(end - look) < (uint32_t)(lim - look)) ? end : lim;
    while (look != stop) {
        size_t len = 0, avail;
        if (p->ring[look & XF__RMASK] != h0) {
            look++;
            continue;
        }
        if (xf__candidate(p, look, &len, need) != XF__YES) {
            if (*need != 0u) {
                p->look = look; /* XF__WAIT: the header or length is incomplete */
                return 0;
            }
            look++;
            continue;
        }
        if ((uint32_t)(pend - look) <= len) {
            break; /* the first candidate ends no sooner: leave it to the rescan */
        }
        avail = (size_t)(end - look);
        if (avail < len) {
            *need = len - avail;
            p->look = look;
            return 0;
        }
        if (!p->memo_on) {
            xf__memo_start(p); /* from here on every check is O(1) */
        }
        if (xf__intact(p, look, len)) {
            p->look = look;
            xf__emit(p, look, len, frame);
            return 1;
        }
        p->stats.crc_errors++;
        /* Its second byte is h1 and its fourth the length's high byte, 0:
         * neither can start a candidate, so only the third is looked at. */
        if ((uint32_t)(stop - look) > 4u && p->ring[(look + 2u) & XF__RMASK] != h0) {
            look += 4u;
        } else {
            look += ((uint32_t)(stop - look) > 2u) ? 2u : 1u;
        }
    }
    p->look = look;
    if (look == end && look != lim) {
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
        if (!p->memo_on) {
            xf__memo_start(p);
        }
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

XF_API int xf_parser_flush(xf_parser *p, xf_frame *frame)
{
    if (p == NULL || frame == NULL) {
        return XF_ERR_ARG;
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
        if (!p->memo_on) {
            xf__memo_start(p);
        }
        xf__drop_to(p, (p->look > p->head + 1u) ? p->look : p->head + 1u);
    }
}

/* Nothing held, and the caller's bytes at d hold a whole intact packet that
 * no contender could beat (no header byte where one would have to start):
 * return it from there, with no copy (the common case on a clean link). */
static inline int xf__direct(xf_parser *p, const uint8_t *d, size_t avail, xf_frame *frame)
{
    size_t len;
    uint16_t want;
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
    want = (uint16_t)(((uint16_t)d[len - 2u] << 8) | d[len - 1u]);
    if (xf_crc16(d, len - 2u) != want) {
        return 0; /* the general path rescans it */
    }
    frame->data = d;
    frame->len = len;
    p->rotated = 0;
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
    *used -= back;
#if XF_PARSER_MEMO
    if (p->memo_on) {
        p->memo_crc = p->memo[p->end & XF__RMASK]; /* the CRC before the first byte given back */
    }
#endif
}

XF_API int xf_parser_feed(xf_parser *p, const uint8_t *data, size_t len, size_t *consumed, xf_frame *frame)
{
    size_t used = 0, appended = 0;
    int found = 0;
    if (p == NULL || frame == NULL || (data == NULL && len > 0u)) {
        return XF_ERR_ARG;
    }
    for (;;) {
        size_t need;
        size_t take;
        if (xf__scan(p, frame, &need)) {
            found = 1;
            break;
        }
        if (used == len) {
            break;
        }
        if (need == 0u) {
            /* Nothing held: jump over noise to the next possible header. */
            const uint8_t *hit = (const uint8_t *)XF_MEMCHR(data + used, p->h0, len - used);
            size_t skip = (hit != NULL) ? (size_t)(hit - (data + used)) : (len - used);
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
        if (p->memo_on) {
            /* After a CRC failure: take all the ring can hold, so the scan
             * works through many candidates per call instead of asking for
             * a few bytes at a time; what lies past a frame found is given
             * back below. */
            size_t room = XF_PARSER_RING - (size_t)(p->end - p->head);
            if (room > take) {
                take = (room < len - used) ? room : (len - used);
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
