/*
 * fuzz_common.h - shared checks of the fuzz harnesses.
 *
 * Include it before any xfgcu header: it defines XF_ASSERT (xf_config.h) to
 * report and abort(), so that the codec's internal invariants are checked
 * too.
 *
 * fz_feed_checked() runs one stream through xf_parser_feed in the chunking
 * a chunk plan dictates, then ends the input (xf_parser_flush or
 * xf_parser_reset), and checks it against the reference model of the
 * parser's semantics (tests/parser_ref.h, run on the whole stream with
 * XF_PARSER_SLOTS and XF_PACKET_MAX_LEN). After every call:
 *   - the return value is XF_PARSE_FRAME or XF_PARSE_MORE, consumed <= len,
 *     and XF_PARSE_MORE means every byte was taken;
 *   - every counter, and xf_parser_pending(), equals the model's after the
 *     bytes fed so far (which holds whatever the chunking); the counters
 *     never decrease, and bytes_in == bytes of the frames returned +
 *     bytes_skipped + xf_parser_pending();
 *   - every frame is the model's next frame and ends exactly where the call's
 *     consumed bytes end (no latency: the call that feeds a frame's last
 *     byte returns it); its data is inside the parser struct; xf_packet_check() == XF_OK for
 *     the direction, unpack == check, pack(unpack(frame)) == frame, the other
 *     direction's unpack says XF_ERR_HEADER, command / feedback decode-encode
 *     round trips.
 * xf_parser_flush() never returns a frame; it and xf_parser_reset() leave
 * nothing held and the counters the model's at the end of the input.
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

/* ---- the codec's internal invariants: checked, before any xfgcu header ---- */

#ifdef XF_ASSERT
#error "fuzz_common.h defines XF_ASSERT: include it before any xfgcu header"
#endif
#if defined(__GNUC__)
static inline void fz_assert_failed(const char *cond, const char *file, int line) __attribute__((noreturn));
#endif
static inline void fz_assert_failed(const char *cond, const char *file, int line)
{
    fprintf(stderr, "%s:%d: XF_ASSERT failed: %s\n", file, line, cond);
    abort();
}
#define XF_ASSERT(cond) ((cond) ? (void)0 : fz_assert_failed(#cond, __FILE__, __LINE__))

#include "xfgcu/xfgcu.h"
#include "parser_ref.h" /* tests/: the reference model */

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

/* How the input ends after the last byte (fz_feed_checked). */
#define FZ_END_FLUSH 0 /* xf_parser_flush() */
#define FZ_END_RESET 1 /* xf_parser_reset() */

/* What one checked run found: the frames (equal to the model's) and a few
 * of the model's counters. */
typedef struct fz_result {
    size_t nframes;    /* frames returned, stored in the caller's array */
    size_t pending;    /* bytes held after the last byte, before the input ended */
    uint32_t given_up; /* candidates given up (the parser's and the model's) */
} fz_result;

/* The state of one checked run. */
typedef struct fz_run {
    xf_parser p;
    xf_parser_stats prev;
    xf_direction dir;
    const uint8_t *s; /* the whole stream */
    size_t fed;       /* bytes of it fed so far */
    size_t nframes, frame_bytes;
    pr_frame *out;
    const pr_model *m;
} fz_run;

static inline void fz_stats_monotonic(const xf_parser_stats *a, const xf_parser_stats *b)
{
    FZ_CHECK(b->bytes_in >= a->bytes_in);
    FZ_CHECK(b->frames >= a->frames);
    FZ_CHECK(b->crc_errors >= a->crc_errors);
    FZ_CHECK(b->length_errors >= a->length_errors);
    FZ_CHECK(b->bytes_skipped >= a->bytes_skipped);
    FZ_CHECK(b->given_up >= a->given_up);
}

/* The parser's counters and held bytes are exactly the model's c. */
static inline void fz_same_counts(const fz_run *R, const pr_counts *c)
{
    const xf_parser_stats *st = &R->p.stats;
    if (st->bytes_in != c->bytes_in || st->frames != c->frames || st->crc_errors != c->crc_errors ||
        st->length_errors != c->length_errors || st->bytes_skipped != c->bytes_skipped || st->given_up != c->given_up ||
        xf_parser_pending(&R->p) != c->pending) {
        fprintf(stderr,
                "after %zu bytes: parser in %u frames %u crc %u length %u skipped %u given_up %u pending %zu\n"
                "                 model  in %u frames %u crc %u length %u skipped %u given_up %u pending %u\n",
                R->fed, (unsigned)st->bytes_in, (unsigned)st->frames, (unsigned)st->crc_errors,
                (unsigned)st->length_errors, (unsigned)st->bytes_skipped, (unsigned)st->given_up,
                xf_parser_pending(&R->p), (unsigned)c->bytes_in, (unsigned)c->frames, (unsigned)c->crc_errors,
                (unsigned)c->length_errors, (unsigned)c->bytes_skipped, (unsigned)c->given_up, (unsigned)c->pending);
        FZ_CHECK(0 && "the parser's counters are the reference model's");
    }
}

/* After every call: the counters, against the model and among themselves. */
static inline void fz_after_call(fz_run *R, const pr_counts *want)
{
    fz_stats_monotonic(&R->prev, &R->p.stats);
    R->prev = R->p.stats;
    FZ_CHECK(R->p.stats.bytes_in == (uint32_t)R->fed);
    FZ_CHECK(R->p.stats.frames == (uint32_t)R->nframes);
    FZ_CHECK(R->p.stats.bytes_in == (uint32_t)(R->frame_bytes + R->p.stats.bytes_skipped + xf_parser_pending(&R->p)));
    FZ_CHECK(xf_parser_pending(&R->p) < XF_PACKET_MAX_LEN);
    fz_same_counts(R, want);
}

/* A frame returned by xf_parser_feed. */
static inline void fz_take_frame(fz_run *R, const xf_frame *f)
{
    const uint8_t *lo = (const uint8_t *)&R->p;
    const pr_frame *want;
    FZ_CHECK(f->data != NULL);
    FZ_CHECK(f->len >= XF_PACKET_MIN_LEN && f->len <= XF_PACKET_MAX_LEN);
    /* In the parser: a frame's bytes never point into the caller's data. */
    FZ_CHECK(f->data >= lo && f->data + f->len <= lo + sizeof(R->p));
    /* The model's next frame, returned by the call that fed its last byte. */
    FZ_CHECK(R->nframes < R->m->nframes);
    want = &R->m->frames[R->nframes];
    if (want->start + want->len != R->fed || want->len != f->len) {
        fprintf(stderr, "frame of %zu bytes ending at %zu; the model's next is [%zu, %zu)\n", f->len, R->fed,
                want->start, want->start + want->len);
        FZ_CHECK(0 && "every frame is the model's next, at its own last byte");
    }
    FZ_CHECK(memcmp(R->s + want->start, f->data, f->len) == 0);
    fz_check_frame(f->data, f->len, R->dir);
    R->out[R->nframes] = *want;
    R->nframes++;
    R->frame_bytes += f->len;
}

/*
 * Feed s[0..n) to a fresh parser for dir, chunked by *plan, then end the
 * input (FZ_END_FLUSH or FZ_END_RESET); check every invariant above. The
 * frames found are stored in out (capacity n / 72 + 1); *res gets what the
 * run found.
 */
static inline void fz_feed_checked(const uint8_t *s, size_t n, xf_direction dir, fz_plan *plan, int end, pr_frame *out,
                                   fz_result *res)
{
    fz_run R;
    pr_model model;
    uint8_t *cbuf;
    int first = 1;

    FZ_CHECK(pr_run(s, n, dir, XF_PARSER_SLOTS, XF_PACKET_MAX_LEN, 1, &model) == 0);
    memset(&R, 0, sizeof(R));
    R.dir = dir;
    R.s = s;
    R.out = out;
    R.m = &model;
    FZ_CHECK(xf_parser_init(&R.p, dir) == XF_OK);
    R.prev = R.p.stats;
    fz_after_call(&R, &model.at[0]);

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
                fz_take_frame(&R, &f);
            }
            if (d != NULL) {
                d += used;
            }
            fz_after_call(&R, &model.at[R.fed]);
            if (r == XF_PARSE_MORE) {
                break;
            }
        }
        FZ_POISON(cbuf, n);
    }
    FZ_UNPOISON(cbuf, n);
    free(cbuf);
    FZ_CHECK(R.nframes == model.nframes);
    res->nframes = R.nframes;
    res->pending = xf_parser_pending(&R.p);
    res->given_up = R.p.stats.given_up;

    /* The input ends: nothing held any more, no frame. */
    if (end == FZ_END_FLUSH) {
        xf_frame f;
        FZ_CHECK(xf_parser_flush(&R.p, &f) == XF_PARSE_MORE);
        fz_after_call(&R, &model.final);
        FZ_CHECK(xf_parser_flush(&R.p, &f) == XF_PARSE_MORE); /* again: nothing */
        fz_after_call(&R, &model.final);
    }
    xf_parser_reset(&R.p);
    fz_after_call(&R, &model.final);
    FZ_CHECK(xf_parser_pending(&R.p) == 0u);
    pr_free(&model);
}

#endif /* XF_FUZZ_COMMON_H */
