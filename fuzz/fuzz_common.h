/*
 * fuzz_common.h - shared checks of the libFuzzer harnesses.
 *
 * fz_feed_checked() runs one stream through xf_parser_feed in the chunking
 * a chunk plan dictates, then (optionally) xf_parser_flush, and checks after
 * every call:
 *   - the return value is XF_PARSE_FRAME or XF_PARSE_MORE, consumed <= len,
 *     and XF_PARSE_MORE means every byte was taken;
 *   - the counters never decrease, bytes_in == bytes fed so far,
 *     bytes_in == sum(frame lengths) + bytes_skipped + xf_parser_pending(),
 *     frames == frames returned;
 *   - every frame: len in [72, XF_PACKET_MAX_LEN], data inside the parser
 *     struct or exactly the last bytes of the caller's data that the call
 *     consumed, xf_packet_check() == XF_OK for the direction, and its bytes
 *     are exactly the fed bytes ending `pending` bytes before the end of
 *     what was fed (the parser holds a suffix of the stream), starting at
 *     or after the previous frame's end;
 *   - unpack == check, pack(unpack(frame)) == frame, the other direction's
 *     unpack says XF_ERR_HEADER, command / feedback decode-encode round trips.
 * At the end of the stream the frames, pending bytes, crc_errors and
 * length_errors must equal those of an independent reference model (a
 * naive whole-stream model of the documented semantics, with its own
 * bitwise-derived CRC table), which also proves the output does not
 * depend on the chunking; likewise after xf_parser_flush() (end of input).
 *
 * Any violation prints a message and abort()s.
 */
#ifndef XF_FUZZ_COMMON_H
#define XF_FUZZ_COMMON_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "xfgcu/xfgcu.h"

/* ASan: poison the unused front of the chunk buffer (see fz_feed_checked). */
#if defined(__has_feature)
#if __has_feature(address_sanitizer)
#include <sanitizer/asan_interface.h>
#define FZ_POISON(p, n)   ASAN_POISON_MEMORY_REGION((p), (n))
#define FZ_UNPOISON(p, n) ASAN_UNPOISON_MEMORY_REGION((p), (n))
#endif
#endif
#ifndef FZ_POISON
#define FZ_POISON(p, n)   ((void)(p), (void)(n))
#define FZ_UNPOISON(p, n) ((void)(p), (void)(n))
#endif

#define FZ_CHECK(cond)                                                                                                 \
    do {                                                                                                               \
        if (!(cond)) {                                                                                                 \
            fprintf(stderr, "%s:%d: invariant violated: %s\n", __FILE__, __LINE__, #cond);                             \
            abort();                                                                                                   \
        }                                                                                                              \
    } while (0)

/* ---- reference model -------------------------------------------------- */

static inline uint16_t fz_ref_crc(const uint8_t *d, size_t n)
{
    /* CRC-16/XMODEM, byte table derived bit by bit here (not the codec's tables). */
    static uint16_t table[256];
    static int ready = 0;
    size_t i;
    uint16_t c = 0;
    if (!ready) {
        unsigned b, k;
        for (b = 0; b < 256u; b++) {
            uint16_t r = (uint16_t)(b << 8);
            for (k = 0; k < 8u; k++) {
                r = (uint16_t)((r & 0x8000u) ? ((uint16_t)(r << 1) ^ 0x1021u) : (uint16_t)(r << 1));
            }
            table[b] = r;
        }
        ready = 1;
    }
    for (i = 0; i < n; i++) {
        c = (uint16_t)((uint16_t)(c << 8) ^ table[(uint8_t)((c >> 8) ^ d[i])]);
    }
    return c;
}

typedef struct fz_span {
    size_t start;
    size_t len;
} fz_span;

typedef struct fz_ref {
    fz_span *frames;
    size_t nframes;
    size_t pending;
    uint32_t crc_errors;
    uint32_t length_errors;
} fz_ref;

/* What sits at position i of s[0..n): */
#define FZ_NOT    0 /* no header pair */
#define FZ_BADLEN 1 /* header pair, length out of range */
#define FZ_WAIT   2 /* the stream ends before the length is known */
#define FZ_CAND   3 /* a candidate; *len set */

static inline int fz_ref_cand(const uint8_t *s, size_t n, size_t i, uint8_t h0, uint8_t h1, size_t *len)
{
    if (s[i] != h0) {
        return FZ_NOT;
    }
    if (i + 1u >= n) {
        return FZ_WAIT;
    }
    if (s[i + 1u] != h1) {
        return FZ_NOT;
    }
    if (i + 3u >= n) {
        return FZ_WAIT;
    }
    *len = (size_t)s[i + 2u] | ((size_t)s[i + 3u] << 8);
    return (*len < XF_PACKET_MIN_LEN || *len > XF_PACKET_MAX_LEN) ? FZ_BADLEN : FZ_CAND;
}

static inline int fz_ref_intact(const uint8_t *s, size_t i, size_t len)
{
    return fz_ref_crc(s + i, len - 2u) == (uint16_t)(((unsigned)s[i + len - 2u] << 8) | s[i + len - 1u]);
}

/*
 * The parser's documented semantics (xf_parser.h, docs/codec.md), naively,
 * on the whole stream at once. The earliest candidate H (length L, end E)
 * is decided after its contenders: the positions q after H, in order, while
 * E - q > 72; a candidate at q that ends before E is returned if intact,
 * else counted as a CRC error; the first candidate that ends no sooner
 * stops the look-ahead. Then H itself, once complete: returned if intact,
 * else a CRC error, and the scan goes on from the first position the
 * look-ahead did not rule out. Each position is examined (and a bad length
 * counted) once.
 *
 * flush == 0: the scan stops at the first thing that needs bytes past the
 * end (what xf_parser_feed holds). flush == 1: the input has ended
 * (xf_parser_flush): whatever needs bytes past the end is given up, the
 * scan going on from the first position not yet ruled out, and nothing
 * stays pending. `frames` must hold n / 72 + 1 entries.
 */
static inline void fz_ref_scan(const uint8_t *s, size_t n, xf_direction dir, int flush, fz_ref *out)
{
    uint8_t h0 = (dir == XF_DIR_HOST) ? XF_HOST_HEADER0 : XF_GCU_HEADER0;
    uint8_t h1 = (dir == XF_DIR_HOST) ? XF_HOST_HEADER1 : XF_GCU_HEADER1;
    size_t h = 0;
    out->nframes = 0;
    out->crc_errors = 0;
    out->length_errors = 0;
    while (h < n) {
        size_t len = 0, end, q;
        int r = fz_ref_cand(s, n, h, h0, h1, &len), waiting = 0, emitted = 0;
        if (r == FZ_WAIT) {
            if (!flush) {
                break;
            }
            h++;
            continue;
        }
        if (r != FZ_CAND) {
            if (r == FZ_BADLEN) {
                out->length_errors++;
            }
            h++;
            continue;
        }
        end = h + len;
        for (q = h + 1u; q + XF_PACKET_MIN_LEN < end; q++) {
            size_t ql = 0;
            int rq;
            if (q >= n) {
                waiting = 1;
                break;
            }
            rq = fz_ref_cand(s, n, q, h0, h1, &ql);
            if (rq == FZ_WAIT) {
                waiting = 1;
                break;
            }
            if (rq == FZ_BADLEN) {
                out->length_errors++;
            }
            if (rq != FZ_CAND) {
                continue;
            }
            if (q + ql >= end) {
                break; /* ends no sooner: the look-ahead stops here */
            }
            if (q + ql > n) {
                waiting = 1;
                break;
            }
            if (fz_ref_intact(s, q, ql)) {
                out->frames[out->nframes].start = q;
                out->frames[out->nframes].len = ql;
                out->nframes++;
                h = q + ql;
                emitted = 1;
                break;
            }
            out->crc_errors++;
        }
        if (emitted) {
            continue;
        }
        if (waiting || end > n) {
            if (!flush) {
                break;
            }
            h = q; /* give H up (no CRC error): on from the first position not ruled out */
            continue;
        }
        if (fz_ref_intact(s, h, len)) {
            out->frames[out->nframes].start = h;
            out->frames[out->nframes].len = len;
            out->nframes++;
            h = end;
            continue;
        }
        out->crc_errors++;
        h = q; /* h + 1, or past the positions the look-ahead examined */
    }
    out->pending = n - h;
}

/* ---- codec checks on one buffer ------------------------------------------ */

/* Command and feedback decoding of an order and its parameter bytes. */
static inline void fz_check_order(uint8_t order, const uint8_t *params, size_t plen, uint8_t version)
{
    const xf_order_info *info = xf_order_lookup(order);
    xf_command cmd;
    xf_feedback fb;
    xf_field bad = XF_F_ALTITUDE;
    xf_err e;

    e = xf_command_decode(order, params, plen, version, &cmd, &bad);
    if (info == NULL) {
        FZ_CHECK(e == XF_ERR_NOT_FOUND);
        FZ_CHECK(bad == XF_F_NONE);
        FZ_CHECK(xf_order_name(order) == NULL);
    } else if (plen != xf_order_params_len(order)) {
        FZ_CHECK(e == XF_ERR_PARAMS);
        FZ_CHECK(bad == XF_F_NONE);
    } else if (e == XF_OK) {
        uint8_t out[XF_PARAMS_MAX + 1u];
        size_t olen = 9999;
        xf_field bad2 = XF_F_ALTITUDE;
        FZ_CHECK(bad == XF_F_NONE);
        FZ_CHECK(cmd.order == order);
        FZ_CHECK(xf_command_check(&cmd, version, &bad2) == XF_OK);
        FZ_CHECK(xf_command_encode(&cmd, version, out, sizeof(out), &olen, &bad2) == XF_OK);
        FZ_CHECK(olen == plen);
        FZ_CHECK(plen == 0u || memcmp(out, params, plen) == 0);
        if (plen > 0u) {
            /* one byte short must be refused, not overflow */
            FZ_CHECK(xf_command_encode(&cmd, version, out, plen - 1u, &olen, &bad2) == XF_ERR_NO_SPACE);
        }
    } else {
        FZ_CHECK(e == XF_ERR_RANGE);
        FZ_CHECK(bad != XF_F_NONE && xf_field_size(bad) != 0u);
    }

    e = xf_feedback_decode(order, params, plen, &fb);
    FZ_CHECK(e == XF_OK);
    FZ_CHECK(fb.order == order);
    if (plen == 0u) {
        FZ_CHECK(fb.has_state == 0u);
    } else {
        uint8_t flags = (info != NULL) ? info->flags : 0u;
        uint8_t st;
        FZ_CHECK(fb.has_state == 1u);
        FZ_CHECK(fb.state == params[0]);
        FZ_CHECK(fb.result == XF_RESULT_OK || fb.result == XF_RESULT_FAILED || fb.result == XF_RESULT_OPERATING);
        st = xf_feedback_state(order, fb.result, fb.failed_cameras);
        if (fb.result == XF_RESULT_FAILED && (flags & XF_ORDER_MASK_FAILURE) == 0u) {
            /* a plain failure is re-encoded as the canonical 0x01 */
            FZ_CHECK(st == XF_STATE_FAILURE);
            FZ_CHECK(fb.failed_cameras == 0u);
        } else {
            FZ_CHECK(st == fb.state);
        }
    }
}

/* unpack must agree with xf_packet_check for both directions, and a
 * successful unpack must pack back to the same bytes. */
static inline void fz_check_buffer(const uint8_t *buf, size_t len)
{
    uint8_t out[XF_PACKET_MAX_LEN + 8u];
    xf_gcu_packet g;
    xf_host_packet h;
    size_t olen;
    xf_err ck, un;

    ck = xf_packet_check(buf, len, XF_DIR_GCU);
    un = xf_gcu_unpack(buf, len, &g);
    FZ_CHECK(ck == un);
    if (un == XF_OK) {
        olen = 0;
        FZ_CHECK(xf_gcu_packet_size(&g) == len);
        FZ_CHECK(xf_gcu_pack(&g, out, sizeof(out), &olen) == XF_OK);
        FZ_CHECK(olen == len);
        FZ_CHECK(memcmp(out, buf, len) == 0);
        FZ_CHECK(xf_gcu_pack(&g, out, len - 1u, &olen) == XF_ERR_NO_SPACE);
        fz_check_order(buf[XF_OFF_ORDER], buf + XF_OFF_PARAMS, len - XF_PACKET_MIN_LEN, buf[XF_OFF_VERSION]);
    }

    ck = xf_packet_check(buf, len, XF_DIR_HOST);
    un = xf_host_unpack(buf, len, &h);
    FZ_CHECK(ck == un);
    if (un == XF_OK) {
        olen = 0;
        FZ_CHECK(xf_host_packet_size(&h) == len);
        FZ_CHECK(xf_host_pack(&h, out, sizeof(out), &olen) == XF_OK);
        FZ_CHECK(olen == len);
        FZ_CHECK(memcmp(out, buf, len) == 0);
        FZ_CHECK(xf_host_pack(&h, out, len - 1u, &olen) == XF_ERR_NO_SPACE);
        fz_check_order(buf[XF_OFF_ORDER], buf + XF_OFF_PARAMS, len - XF_PACKET_MIN_LEN, buf[XF_OFF_VERSION]);
    }
}

/* A frame the parser returned for direction dir. */
static inline void fz_check_frame(const uint8_t *buf, size_t len, xf_direction dir)
{
    xf_gcu_packet g;
    xf_host_packet h;
    FZ_CHECK(xf_packet_check(buf, len, dir) == XF_OK);
    if (dir == XF_DIR_GCU) {
        FZ_CHECK(xf_host_unpack(buf, len, &h) == XF_ERR_HEADER);
        FZ_CHECK(xf_gcu_unpack(buf, len, &g) == XF_OK);
    } else {
        FZ_CHECK(xf_gcu_unpack(buf, len, &g) == XF_ERR_HEADER);
        FZ_CHECK(xf_host_unpack(buf, len, &h) == XF_OK);
    }
    fz_check_buffer(buf, len);
    /* one byte more or less is never a valid packet of this length */
    FZ_CHECK(xf_packet_check(buf, len - 1u, dir) == XF_ERR_TRUNCATED);
}

/* ---- chunk plan ---------------------------------------------------------- */

/* Chunk sizes cycle through `sizes`: 0 = an empty feed, 255 = all the rest,
 * anything else that many bytes. An all-zero plan feeds one byte at a time. */
typedef struct fz_plan {
    const uint8_t *sizes;
    size_t n;
    size_t next;
    int all_zero;
} fz_plan;

static inline void fz_plan_init(fz_plan *pl, const uint8_t *sizes, size_t n)
{
    size_t i;
    pl->sizes = sizes;
    pl->n = n;
    pl->next = 0;
    pl->all_zero = 1;
    for (i = 0; i < n; i++) {
        if (sizes[i] != 0u) {
            pl->all_zero = 0;
        }
    }
}

static inline size_t fz_plan_chunk(fz_plan *pl, size_t left)
{
    size_t c;
    if (pl->n == 0u) {
        return left;
    }
    if (pl->all_zero) {
        return (left > 0u) ? 1u : 0u;
    }
    c = pl->sizes[pl->next % pl->n];
    pl->next++;
    if (c == 255u) {
        c = left;
    }
    return (c < left) ? c : left;
}

/* ---- the checked feed ---------------------------------------------------- */

static inline void fz_stats_monotonic(const xf_parser_stats *a, const xf_parser_stats *b)
{
    FZ_CHECK(b->bytes_in >= a->bytes_in);
    FZ_CHECK(b->frames >= a->frames);
    FZ_CHECK(b->crc_errors >= a->crc_errors);
    FZ_CHECK(b->length_errors >= a->length_errors);
    FZ_CHECK(b->bytes_skipped >= a->bytes_skipped);
}

/* The state of one checked run. */
typedef struct fz_run {
    xf_parser p;
    xf_parser_stats prev;
    xf_direction dir;
    const uint8_t *s; /* the whole stream */
    size_t fed;       /* bytes of it fed so far */
    size_t nframes, sum_len, prev_end;
    fz_span *out;
} fz_run;

/* After every call: counters and the byte balance. */
static inline void fz_after_call(fz_run *R)
{
    fz_stats_monotonic(&R->prev, &R->p.stats);
    R->prev = R->p.stats;
    FZ_CHECK(R->p.stats.bytes_in == (uint32_t)R->fed);
    FZ_CHECK(R->p.stats.frames == (uint32_t)R->nframes);
    FZ_CHECK(R->p.stats.bytes_in == (uint32_t)(R->sum_len + R->p.stats.bytes_skipped + xf_parser_pending(&R->p)));
    FZ_CHECK(xf_parser_pending(&R->p) <= XF_PACKET_MAX_LEN);
}

/* A frame returned by xf_parser_feed (d, used: its data and consumed) or
 * xf_parser_flush (d NULL). */
static inline void fz_take_frame(fz_run *R, const xf_frame *f, const uint8_t *d, size_t used)
{
    size_t pend = xf_parser_pending(&R->p);
    size_t end, start;
    const uint8_t *lo = (const uint8_t *)&R->p;
    FZ_CHECK(f->data != NULL);
    FZ_CHECK(f->len >= XF_PACKET_MIN_LEN && f->len <= XF_PACKET_MAX_LEN);
    /* In the parser, or (a packet that arrived whole) exactly the bytes of
     * the caller's data that this call consumed last. */
    if (!(f->data >= lo && f->data + f->len <= lo + sizeof(R->p))) {
        FZ_CHECK(d != NULL && used >= f->len);
        FZ_CHECK(f->data == d + used - f->len);
    }
    /* The parser holds a suffix of what was fed: the frame ends just before it. */
    FZ_CHECK(pend <= R->fed);
    end = R->fed - pend;
    FZ_CHECK(end >= f->len);
    start = end - f->len;
    FZ_CHECK(start >= R->prev_end);
    FZ_CHECK(memcmp(R->s + start, f->data, f->len) == 0);
    fz_check_frame(f->data, f->len, R->dir);
    R->out[R->nframes].start = start;
    R->out[R->nframes].len = f->len;
    R->nframes++;
    R->sum_len += f->len;
    R->prev_end = end;
}

/* The frames and counters so far must be exactly the reference's. */
static inline void fz_compare_ref(fz_run *R, size_t n, int flush)
{
    fz_ref ref;
    size_t i;
    ref.frames = (fz_span *)malloc((n / XF_PACKET_MIN_LEN + 1u) * sizeof(fz_span));
    FZ_CHECK(ref.frames != NULL);
    fz_ref_scan(R->s, n, R->dir, flush, &ref);
    FZ_CHECK(ref.nframes == R->nframes);
    for (i = 0; i < R->nframes; i++) {
        FZ_CHECK(ref.frames[i].start == R->out[i].start);
        FZ_CHECK(ref.frames[i].len == R->out[i].len);
    }
    FZ_CHECK(ref.pending == xf_parser_pending(&R->p));
    FZ_CHECK(ref.crc_errors == R->p.stats.crc_errors);
    FZ_CHECK(ref.length_errors == R->p.stats.length_errors);
    free(ref.frames);
}

/*
 * Feed s[0..n) to a fresh parser for dir, chunked by *plan; check every
 * invariant; compare with the reference model. Then, if flush, call
 * xf_parser_flush until it says XF_PARSE_MORE, checking the same, and
 * compare with the reference model of the ended input. The frames found
 * are stored in out (capacity n / 72 + 1); returns their number.
 * *pending_out (may be NULL) gets the bytes held before the flush.
 */
static inline size_t fz_feed_checked(const uint8_t *s, size_t n, xf_direction dir, fz_plan *plan, int flush,
                                     fz_span *out, size_t *pending_out)
{
    fz_run R;
    uint8_t *cbuf;
    int first = 1;

    memset(&R, 0, sizeof(R));
    R.dir = dir;
    R.s = s;
    R.out = out;
    FZ_CHECK(xf_parser_init(&R.p, dir) == XF_OK);
    FZ_CHECK(xf_parser_pending(&R.p) == 0u);
    R.prev = R.p.stats;

    /* Each chunk is copied to the very end of a heap block of n bytes and
     * the bytes before it are poisoned, so ASan catches any read outside
     * the chunk given to xf_parser_feed (and any later use of it). */
    cbuf = (uint8_t *)malloc((n > 0u) ? n : 1u);
    FZ_CHECK(cbuf != NULL);
    while (R.fed < n || first) {
        size_t c = fz_plan_chunk(plan, n - R.fed);
        const uint8_t *d = NULL;
        size_t left = c;
        first = 0;
        FZ_UNPOISON(cbuf, n);
        if (c > 0u) {
            memcpy(cbuf + (n - c), s + R.fed, c);
            d = cbuf + (n - c);
        }
        FZ_POISON(cbuf, n - c);
        for (;;) {
            size_t used = (size_t)-1;
            xf_frame f;
            xf_parse_status r;
            f.data = NULL;
            f.len = 0;
            r = xf_parser_feed(&R.p, d, left, &used, &f);
            FZ_CHECK(r == XF_PARSE_FRAME || r == XF_PARSE_MORE);
            FZ_CHECK(used <= left);
            if (r == XF_PARSE_MORE) {
                FZ_CHECK(used == left);
            }
            R.fed += used;
            left -= used;
            if (r == XF_PARSE_FRAME) {
                fz_take_frame(&R, &f, d, used);
            }
            if (d != NULL) {
                d += used;
            }
            fz_after_call(&R);
            if (r == XF_PARSE_MORE) {
                break;
            }
        }
        FZ_POISON(cbuf, n);
    }
    FZ_UNPOISON(cbuf, n);
    free(cbuf);

    /* Everything fed: the reference model must agree exactly. */
    fz_compare_ref(&R, n, 0);
    if (pending_out != NULL) {
        *pending_out = xf_parser_pending(&R.p);
    }

    if (flush) {
        size_t calls = 0;
        for (;;) {
            xf_frame f;
            xf_parse_status r;
            f.data = NULL;
            f.len = 0;
            r = xf_parser_flush(&R.p, &f);
            FZ_CHECK(r == XF_PARSE_FRAME || r == XF_PARSE_MORE);
            if (r == XF_PARSE_FRAME) {
                fz_take_frame(&R, &f, NULL, 0);
            }
            fz_after_call(&R);
            if (r == XF_PARSE_MORE) {
                break;
            }
            FZ_CHECK(++calls <= n / XF_PACKET_MIN_LEN + 1u);
        }
        FZ_CHECK(xf_parser_pending(&R.p) == 0u);
        fz_compare_ref(&R, n, 1);
        /* flushed again: nothing more */
        {
            xf_frame f;
            FZ_CHECK(xf_parser_flush(&R.p, &f) == XF_PARSE_MORE);
            fz_after_call(&R);
        }
    }

    /* reset drops what is held, as skipped bytes */
    xf_parser_reset(&R.p);
    FZ_CHECK(xf_parser_pending(&R.p) == 0u);
    fz_stats_monotonic(&R.prev, &R.p.stats);
    FZ_CHECK(R.p.stats.bytes_in == (uint32_t)(R.sum_len + R.p.stats.bytes_skipped));
    return R.nframes;
}

#endif /* XF_FUZZ_COMMON_H */
