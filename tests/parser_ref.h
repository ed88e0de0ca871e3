/*
 * parser_ref.h - the reference model of the streaming parser (xf_parser.h).
 *
 * The documented semantics, written as naively as possible, run on a whole
 * stream at once: the specification in code. Header-only C99; it uses no
 * code of the codec (its own bit-by-bit CRC), only the protocol's constants.
 * For the cmocka tests (tests/test_parser_ref.c checks it on hand-computed
 * cases) and the fuzz harnesses (fuzz/fuzz_common.h compares the parser
 * with it after every call). Keep it obviously right, not fast.
 *
 * The semantics. Bytes are numbered 0, 1, ... from init; floor = 0.
 *  - A candidate is a position s >= floor where bytes s..s+3 are h0 h1 L 0
 *    (the 16-bit little-endian length L at s+2) with 72 <= L <= max_len;
 *    its end is s + L. It becomes known when byte s+3 arrives.
 *  - h0 h1 at s >= floor with a length outside [72, max_len]: one
 *    length_error when byte s+3 arrives.
 *  - Byte q (e = q + 1 after it):
 *    1. the pending candidates that end at e, earliest start first: CRC of
 *       [s, e) zero: the frame [s, e) is returned, every pending candidate
 *       is dropped, floor = e, and nothing else about byte q is examined;
 *       else crc_errors++ and that candidate is removed;
 *    2. then a header pair completed by byte q at s = q - 3 >= floor: a bad
 *       length is a length error; a valid one becomes pending when fewer
 *       than K are (first come, first served), else given_up++ (a frame
 *       that begins there is lost).
 *  - Held bytes (pending) = e - head, head = the earliest pending start;
 *    with none pending, max(floor, e - 3): the last three bytes, which may
 *    begin a header, whatever they are.
 *  - bytes_skipped = bytes_in - bytes of returned frames - pending.
 *  - A flush (end of input) drops every held byte: pending 0, counted
 *    skipped; nothing else changes (no frame, no given_up).
 */
#ifndef XFGCU_PARSER_REF_H
#define XFGCU_PARSER_REF_H

#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "xfgcu/xf_protocol.h" /* header bytes, XF_PACKET_MIN_LEN, xf_direction */

/** Counters at one point of the stream (those of xf_parser_stats, and the held bytes). */
typedef struct pr_counts {
    uint32_t bytes_in;
    uint32_t frames;
    uint32_t crc_errors;
    uint32_t length_errors;
    uint32_t bytes_skipped;
    uint32_t given_up;
    uint32_t pending; /* xf_parser_pending() */
} pr_counts;

/** A frame (or a candidate): stream offset and length; it ends at start + len. */
typedef struct pr_frame {
    size_t start;
    size_t len;
} pr_frame;

typedef struct pr_model {
    pr_frame *frames; /* the frames returned, in order; frame i is returned by byte frames[i].start + len - 1 */
    size_t nframes;
    pr_counts *at; /* at[i]: the counters after the first i bytes, i = 0 .. n */
    size_t n;
    pr_counts final; /* at[n], or after the flush if one was asked for */
} pr_model;

/* CRC-16/XMODEM bit by bit: poly 0x1021, init 0, MSB first, no final XOR. */
static inline uint16_t pr_crc(const uint8_t *d, size_t n)
{
    unsigned c = 0; /* 16 bits kept */
    size_t i;
    int k;
    for (i = 0; i < n; i++) {
        c ^= (unsigned)d[i] << 8;
        for (k = 0; k < 8; k++) {
            c = ((c & 0x8000u) ? (c << 1) ^ 0x1021u : c << 1) & 0xFFFFu;
        }
    }
    return (uint16_t)c;
}

/* Held bytes after the first e bytes. */
static inline size_t pr_held(size_t e, size_t floor, const pr_frame *cand, size_t ncand)
{
    size_t head = (e > floor + 3u) ? e - 3u : floor, i;
    for (i = 0; i < ncand; i++) {
        head = (i == 0u || cand[i].start < head) ? cand[i].start : head;
    }
    return e - head;
}

static inline void pr_free(pr_model *m)
{
    free(m->frames);
    free(m->at);
    m->frames = NULL;
    m->at = NULL;
    m->nframes = 0;
}

/*
 * Run the model on s[0 .. n) for the packets of direction dir, with K
 * slots for pending candidates and the largest length max_len (72..255);
 * flush: the input ends after s (xf_parser_flush()), which only changes
 * m->final. Returns 0, or -1 (bad K or max_len, out of memory: *m empty).
 * Free with pr_free().
 */
static inline int pr_run(const uint8_t *s, size_t n, xf_direction dir, unsigned K, unsigned max_len, int flush,
                         pr_model *m)
{
    const uint8_t h0 = (uint8_t)((dir == XF_DIR_HOST) ? XF_HOST_HEADER0 : XF_GCU_HEADER0);
    const uint8_t h1 = (uint8_t)((dir == XF_DIR_HOST) ? XF_HOST_HEADER1 : XF_GCU_HEADER1);
    pr_frame *cand; /* the pending candidates, in order of start (a new one always starts last) */
    size_t ncand = 0, floor = 0, frame_bytes = 0, e, i;
    pr_counts c;

    memset(m, 0, sizeof(*m));
    memset(&c, 0, sizeof(c));
    if (K < 1u || max_len < XF_PACKET_MIN_LEN || max_len > 255u) {
        return -1;
    }
    cand = (pr_frame *)malloc(K * sizeof(*cand));
    m->frames = (pr_frame *)malloc((n / XF_PACKET_MIN_LEN + 1u) * sizeof(*m->frames));
    m->at = (pr_counts *)malloc((n + 1u) * sizeof(*m->at));
    if (cand == NULL || m->frames == NULL || m->at == NULL) {
        free(cand);
        pr_free(m);
        return -1;
    }
    m->n = n;
    m->at[0] = c;

    for (e = 1; e <= n; e++) {
        const size_t q = e - 1u;
        int framed = 0;
        c.bytes_in++;
        /* 1. the pending candidates that end here, earliest start first */
        for (i = 0; i < ncand && !framed;) {
            if (cand[i].start + cand[i].len != e) {
                i++;
            } else if (pr_crc(s + cand[i].start, cand[i].len) == 0u) {
                m->frames[m->nframes++] = cand[i];
                c.frames++;
                frame_bytes += cand[i].len;
                ncand = 0;
                floor = e;
                framed = 1;
            } else {
                c.crc_errors++;
                memmove(cand + i, cand + i + 1u, (ncand - i - 1u) * sizeof(*cand));
                ncand--;
            }
        }
        /* 2. a header pair completed by byte q, at q - 3 */
        if (!framed && q >= floor + 3u && s[q - 3u] == h0 && s[q - 2u] == h1) {
            pr_frame nc;
            nc.start = q - 3u;
            nc.len = (size_t)s[q - 1u] | ((size_t)s[q] << 8);
            if (nc.len < XF_PACKET_MIN_LEN || nc.len > max_len) {
                c.length_errors++;
            } else if (ncand < K) {
                cand[ncand++] = nc;
            } else {
                c.given_up++;
            }
        }
        c.pending = (uint32_t)pr_held(e, floor, cand, ncand);
        c.bytes_skipped = (uint32_t)(e - frame_bytes - c.pending);
        m->at[e] = c;
    }
    m->final = c;
    if (flush) {
        m->final.bytes_skipped += m->final.pending;
        m->final.pending = 0;
    }
    free(cand);
    return 0;
}

#endif /* XFGCU_PARSER_REF_H */
