/*
 * test_parser_ref.c - the reference model of the parser (parser_ref.h)
 * checked on small cases computed by hand from the documented semantics,
 * with several slot counts K and largest lengths; and its counters'
 * identities on random streams. The fuzz harnesses compare the parser with
 * this model after every call, so the model must be right by itself.
 *
 * Packets are built with test_util.h's own bit-by-bit CRC, not the model's.
 */
#include <stdlib.h>
#include "test_util.h"
#include "parser_ref.h"

#define GH0 0x8Au /* GCU headers, as docs/protocol.md spells them */
#define GH1 0x5Eu

typedef struct stream {
    uint8_t d[4096];
    size_t n;
} stream;

static void put(stream *s, const uint8_t *b, size_t n)
{
    assert_true(s->n + n <= sizeof(s->d));
    memcpy(s->d + s->n, b, n);
    s->n += n;
}

static void put_hex(stream *s, const char *hex)
{
    unsigned v;
    int used;
    while (sscanf(hex, " %2x%n", &v, &used) == 1) {
        uint8_t b = (uint8_t)v;
        put(s, &b, 1);
        hex += used;
    }
}

static void put_fill(stream *s, uint8_t v, size_t n)
{
    assert_true(s->n + n <= sizeof(s->d));
    memset(s->d + s->n, v, n);
    s->n += n;
}

/* An intact GCU packet of len bytes, body filled with fill; returns its offset. */
static size_t put_packet(stream *s, size_t len, uint8_t fill)
{
    size_t at = s->n;
    put_fill(s, fill, len);
    ref_finish_packet(s->d + at, len, XF_DIR_GCU);
    return at;
}

static void run(const stream *s, unsigned K, unsigned max_len, int flush, pr_model *m)
{
    assert_int_equal(pr_run(s->d, s->n, XF_DIR_GCU, K, max_len, flush, m), 0);
}

/* The counters' own identities, at every byte: they only grow, bytes_in is
 * the position, the byte balance holds, frames match the frame list. */
static void check_identities(const stream *s, const pr_model *m, unsigned max_len)
{
    size_t i, f = 0, frame_bytes = 0;
    assert_int_equal(m->n, s->n);
    for (i = 0; i <= m->n; i++) {
        const pr_counts *c = &m->at[i];
        assert_int_equal(c->bytes_in, i);
        if (f < m->nframes && m->frames[f].start + m->frames[f].len == i) {
            frame_bytes += m->frames[f].len;
            f++;
            assert_int_equal(c->pending, 0); /* nothing is held after a frame */
        }
        assert_int_equal(c->frames, f);
        assert_int_equal(c->bytes_in, frame_bytes + c->bytes_skipped + c->pending);
        assert_true(c->pending < max_len);
        if (i > 0u) {
            const pr_counts *b = &m->at[i - 1u];
            assert_true(c->crc_errors >= b->crc_errors && c->length_errors >= b->length_errors);
            assert_true(c->given_up >= b->given_up && c->bytes_skipped >= b->bytes_skipped);
            assert_true(c->pending <= b->pending + 1u);
        }
    }
    assert_int_equal(f, m->nframes);
    for (i = 0; i < m->nframes; i++) {
        const uint8_t *p = s->d + m->frames[i].start;
        size_t len = m->frames[i].len;
        assert_true(len >= XF_PACKET_MIN_LEN && len <= max_len);
        assert_true(p[0] == GH0 && p[1] == GH1 && (size_t)p[2] + ((size_t)p[3] << 8) == len);
        assert_int_equal(ref_crc16(p, len - 2u), ((unsigned)p[len - 2u] << 8) | p[len - 1u]);
        if (i > 0u) {
            assert_true(m->frames[i].start >= m->frames[i - 1u].start + m->frames[i - 1u].len);
        }
    }
}

static const unsigned k_values[] = {1, 2, 4, 16};
static const unsigned max_values[] = {84, 255};

/* ---- hand-computed cases ------------------------------------------------- */

static void test_clean_three(void **state)
{
    stream s = {{0}, 0};
    size_t k, x;
    (void)state;
    put_packet(&s, 72, 0x11);
    put_packet(&s, 73, 0x22);
    put_packet(&s, 80, 0x33);
    for (k = 0; k < ARRAY_LEN(k_values); k++) {
        for (x = 0; x < ARRAY_LEN(max_values); x++) {
            pr_model m;
            size_t i;
            run(&s, k_values[k], max_values[x], 1, &m);
            check_identities(&s, &m, max_values[x]);
            assert_int_equal(m.nframes, 3);
            assert_int_equal(m.frames[0].start, 0);
            assert_int_equal(m.frames[1].start, 72);
            assert_int_equal(m.frames[2].start, 145);
            assert_int_equal(m.frames[2].len, 80);
            /* each frame at its own last byte, not one byte later */
            assert_int_equal(m.at[71].frames, 0);
            assert_int_equal(m.at[72].frames, 1);
            assert_int_equal(m.at[144].frames, 1);
            assert_int_equal(m.at[145].frames, 2);
            assert_int_equal(m.at[224].frames, 2);
            assert_int_equal(m.at[225].frames, 3);
            /* held while incomplete: h0, h0 h1, h0 h1 L, then the candidate */
            assert_int_equal(m.at[1].pending, 1);
            assert_int_equal(m.at[2].pending, 2);
            assert_int_equal(m.at[3].pending, 3);
            assert_int_equal(m.at[71].pending, 71);
            assert_int_equal(m.at[73].pending, 1);
            for (i = 0; i <= s.n; i++) {
                assert_int_equal(m.at[i].bytes_skipped, 0);
                assert_int_equal(m.at[i].crc_errors + m.at[i].length_errors, 0);
            }
            /* a frame alone never finds every slot taken, even with one slot */
            assert_int_equal(m.final.given_up, 0);
            assert_int_equal(m.final.pending, 0);
            pr_free(&m);
        }
    }
}

static void test_flipped_bit(void **state)
{
    stream s = {{0}, 0};
    pr_model m;
    (void)state;
    put_packet(&s, 72, 0x11);
    s.d[40] ^= 0x04;
    put_packet(&s, 72, 0x22);
    run(&s, 4, 255, 0, &m);
    check_identities(&s, &m, 255);
    assert_int_equal(m.at[71].crc_errors, 0);
    assert_int_equal(m.at[72].crc_errors, 1); /* when the broken one ends */
    assert_int_equal(m.nframes, 1);
    assert_int_equal(m.frames[0].start, 72);
    assert_int_equal(m.final.crc_errors, 1);
    assert_int_equal(m.final.bytes_skipped, 72);
    assert_int_equal(m.final.pending, 0);
    pr_free(&m);
}

/* h0 h1 200 0, then a frame: it comes out at its own end; the false
 * candidate, which started before it, is dropped with it (no CRC error). */
static void test_frame_inside_false_candidate(void **state)
{
    stream s = {{0}, 0};
    pr_model m;
    (void)state;
    put_hex(&s, "8A 5E C8 00");
    put_packet(&s, 72, 0x11);
    put_fill(&s, 0x00, 200);
    run(&s, 4, 255, 1, &m);
    check_identities(&s, &m, 255);
    assert_int_equal(m.at[75].frames, 0);
    assert_int_equal(m.at[75].pending, 75); /* held from the false candidate's start */
    assert_int_equal(m.at[76].frames, 1);
    assert_int_equal(m.frames[0].start, 4);
    assert_int_equal(m.at[76].pending, 0);
    assert_int_equal(m.at[76].bytes_skipped, 4);
    assert_int_equal(m.final.crc_errors, 0);
    assert_int_equal(m.final.given_up, 0);
    assert_int_equal(m.final.length_errors, 0);
    assert_int_equal(m.final.bytes_skipped, 204);
    pr_free(&m);

    /* A false candidate that ends inside the frame fails first. */
    s.n = 0;
    put_hex(&s, "8A 5E 4A 00"); /* 74: ends at 74 */
    put_packet(&s, 72, 0x11);   /* ends at 76 */
    run(&s, 4, 255, 0, &m);
    check_identities(&s, &m, 255);
    assert_int_equal(m.at[73].crc_errors, 0);
    assert_int_equal(m.at[74].crc_errors, 1);
    assert_int_equal(m.at[74].pending, 74 - 4); /* the frame's candidate is the earliest left */
    assert_int_equal(m.at[74].bytes_skipped, 4);
    assert_int_equal(m.at[76].frames, 1);
    pr_free(&m);
}

static void test_length_errors(void **state)
{
    stream s = {{0}, 0};
    pr_model m;
    (void)state;
    put_hex(&s, "8A 5E 0A 00"); /* length 10 */
    put_packet(&s, 72, 0x11);
    put_hex(&s, "8A 5E 00 01"); /* 256 */
    put_hex(&s, "8A 5E 47 00"); /* 71 */
    run(&s, 4, 255, 0, &m);
    check_identities(&s, &m, 255);
    assert_int_equal(m.at[2].pending, 2);
    assert_int_equal(m.at[3].pending, 3); /* with no candidate, the last three bytes */
    assert_int_equal(m.at[3].length_errors, 0);
    assert_int_equal(m.at[4].length_errors, 1); /* counted when the length's high byte arrives */
    assert_int_equal(m.at[4].bytes_skipped, 1);
    assert_int_equal(m.at[4].pending, 3);
    assert_int_equal(m.at[76].frames, 1);
    assert_int_equal(m.at[78].pending, 2);
    assert_int_equal(m.at[79].pending, 3);
    assert_int_equal(m.at[80].length_errors, 2);
    assert_int_equal(m.at[80].pending, 3);
    assert_int_equal(m.at[83].pending, 3);
    assert_int_equal(m.at[84].pending, 3);
    assert_int_equal(m.final.length_errors, 3);
    assert_int_equal(m.final.crc_errors, 0);
    pr_free(&m);

    /* 85: a candidate with max 255, a length error with max 84 */
    s.n = 0;
    put_hex(&s, "8A 5E 55 00");
    put_packet(&s, 72, 0x11);
    run(&s, 4, 255, 0, &m);
    assert_int_equal(m.at[3].pending, 3);
    assert_int_equal(m.at[4].pending, 4);
    assert_int_equal(m.final.length_errors, 0);
    assert_int_equal(m.nframes, 1);
    assert_int_equal(m.at[76].frames, 1);
    pr_free(&m);
    run(&s, 4, 84, 0, &m);
    check_identities(&s, &m, 84);
    assert_int_equal(m.at[3].pending, 3);
    assert_int_equal(m.at[4].length_errors, 1);
    assert_int_equal(m.at[4].pending, 3);
    assert_int_equal(m.nframes, 1);
    pr_free(&m);
}

/* First come, first served: K false candidates that end after a frame take
 * every slot, so the headers after them (one more false one, then the
 * frame's) are given up, each counted, and the frame is lost. With K + 2
 * slots both are admitted, and the frame comes out. */
static void test_first_come_first_served(void **state)
{
    size_t k;
    (void)state;
    for (k = 0; k < ARRAY_LEN(k_values); k++) {
        const unsigned K = k_values[k];
        stream s = {{0}, 0};
        size_t i, f;
        pr_model m;
        for (i = 0; i <= K; i++) {
            put_hex(&s, "8A 5E FF 00");
        }
        f = put_packet(&s, 72, 0x11);
        run(&s, K, 255, 1, &m);
        check_identities(&s, &m, 255);
        assert_int_equal(m.at[4u * K + 3u].given_up, 0);
        assert_int_equal(m.at[4u * K + 4u].given_up, 1); /* the claim after the K-th */
        assert_int_equal(m.at[f + 3u].given_up, 1);
        assert_int_equal(m.at[f + 4u].given_up, 2); /* the frame's */
        assert_int_equal(m.final.given_up, 2);
        assert_int_equal(m.nframes, 0);
        assert_int_equal(m.final.crc_errors + m.final.length_errors, 0); /* none ends in the stream */
        assert_int_equal(m.at[s.n].pending, s.n);                        /* held from the first */
        assert_int_equal(m.final.bytes_skipped, s.n);
        pr_free(&m);

        run(&s, K + 2u, 255, 1, &m);
        check_identities(&s, &m, 255);
        assert_int_equal(m.nframes, 1);
        assert_int_equal(m.frames[0].start, f);
        assert_int_equal(m.at[f + 71u].frames, 0);
        assert_int_equal(m.at[f + 72u].frames, 1);
        assert_int_equal(m.final.given_up, 0);
        assert_int_equal(m.final.bytes_skipped, 4u * (K + 1u));
        pr_free(&m);
    }
}

/* K false candidates that end sooner than a frame starting after them: the
 * frame finds every slot taken and is lost (the documented loss); with
 * K + 1 slots it takes the last. */
static void test_k_false_ending_sooner(void **state)
{
    size_t k, x;
    (void)state;
    for (k = 0; k < ARRAY_LEN(k_values); k++) {
        for (x = 0; x < ARRAY_LEN(max_values); x++) {
            const unsigned K = k_values[k], max = max_values[x];
            stream s = {{0}, 0};
            size_t i, f;
            pr_model m;
            for (i = 0; i < K; i++) {
                put_hex(&s, "8A 5E 54 00"); /* 84: ends at 84 + 4i */
            }
            f = put_packet(&s, 84, 0x11); /* at 4K, ends at 4K + 84: after all of them */
            put_fill(&s, 0x00, 100);
            run(&s, K, max, 1, &m);
            check_identities(&s, &m, max);
            assert_int_equal(m.at[f + 3u].given_up, 0);
            assert_int_equal(m.at[f + 4u].given_up, 1); /* when the frame's header completes */
            assert_int_equal(m.nframes, 0);
            assert_int_equal(m.final.crc_errors, K);
            assert_int_equal(m.at[84].crc_errors, 1); /* the first false one, at its end */
            assert_int_equal(m.final.given_up, 1);
            assert_int_equal(m.final.bytes_skipped, s.n);
            pr_free(&m);

            run(&s, K + 1u, max, 1, &m);
            check_identities(&s, &m, max);
            assert_int_equal(m.final.given_up, 0);
            assert_int_equal(m.final.crc_errors, K); /* they all end before the frame */
            assert_int_equal(m.nframes, 1);
            assert_int_equal(m.frames[0].start, f);
            assert_int_equal(m.at[f + 84u].frames, 1);
            pr_free(&m);
        }
    }
}

/* A check frees a slot. Eight false 72-byte claims back to back: min(K, 8)
 * are admitted, each of the others given up when its header completes. The
 * first one's check, at byte 72, frees its slot: a frame whose header
 * completes after it is admitted, and found, whatever K. */
static void test_slot_freed_by_check(void **state)
{
    size_t k;
    (void)state;
    for (k = 0; k < ARRAY_LEN(k_values); k++) {
        const unsigned K = k_values[k], B = (K < 8u) ? K : 8u;
        stream s = {{0}, 0};
        size_t i, f;
        pr_model m;
        for (i = 0; i < 8u; i++) {
            put_hex(&s, "8A 5E 48 00"); /* ends at 72 + 4i */
        }
        put_fill(&s, 0x00, 72u - s.n);
        f = put_packet(&s, 72, 0x11); /* at 72 */
        put_fill(&s, 0x00, 100);
        run(&s, K, 255, 1, &m);
        check_identities(&s, &m, 255);
        assert_int_equal(m.at[4u * B].given_up, 0);
        assert_int_equal(m.at[32].given_up, 8u - B); /* the claims after the B-th */
        assert_int_equal(m.at[71].crc_errors, 0);
        assert_int_equal(m.at[72].crc_errors, 1);
        assert_int_equal(m.at[72u + 4u * (B - 1u)].crc_errors, B); /* B admitted, B checked */
        assert_int_equal(m.final.crc_errors, B);
        assert_int_equal(m.final.given_up, 8u - B);
        assert_int_equal(m.final.length_errors, 0);
        assert_int_equal(m.nframes, 1);
        assert_int_equal(m.frames[0].start, f);
        assert_int_equal(m.at[f + 72u].frames, 1);
        pr_free(&m);
    }
}

/* A false candidate and a frame that end on the same byte: the earlier start
 * is examined first; with one slot the frame's header finds it taken. */
static void test_same_end(void **state)
{
    stream s = {{0}, 0};
    pr_model m;
    (void)state;
    put_hex(&s, "8A 5E 54 00"); /* 84 */
    put_fill(&s, 0x00, 8);
    put_packet(&s, 72, 0x11); /* at 12, ends at 84 */
    run(&s, 1, 255, 0, &m);
    check_identities(&s, &m, 255);
    assert_int_equal(m.at[15].given_up, 0);
    assert_int_equal(m.at[16].given_up, 1); /* the frame's header */
    assert_int_equal(m.nframes, 0);
    assert_int_equal(m.final.crc_errors, 1);
    pr_free(&m);
    run(&s, 2, 255, 0, &m);
    check_identities(&s, &m, 255);
    assert_int_equal(m.final.given_up, 0);
    assert_int_equal(m.at[84].crc_errors, 1);
    assert_int_equal(m.at[84].frames, 1);
    assert_int_equal(m.frames[0].start, 12);
    pr_free(&m);
}

/* A truncated packet, then an intact one: the truncated one's candidate
 * fails inside the intact one (CRC error), or is dropped with it when it
 * would end later. */
static void test_truncated_then_intact(void **state)
{
    stream s = {{0}, 0};
    pr_model m;
    size_t f;
    (void)state;
    put_packet(&s, 84, 0x11);
    s.n = 40;
    f = put_packet(&s, 72, 0x22); /* ends at 112; the truncated one at 84 */
    run(&s, 4, 255, 1, &m);
    check_identities(&s, &m, 255);
    assert_int_equal(m.at[84].crc_errors, 1);
    assert_int_equal(m.at[84].pending, 84 - f);
    assert_int_equal(m.at[112].frames, 1);
    assert_int_equal(m.frames[0].start, f);
    assert_int_equal(m.final.bytes_skipped, 40);
    pr_free(&m);

    s.n = 0;
    put_packet(&s, 255, 0x11);
    s.n = 40;
    f = put_packet(&s, 72, 0x22);
    run(&s, 4, 255, 1, &m);
    check_identities(&s, &m, 255);
    assert_int_equal(m.at[112].frames, 1);
    assert_int_equal(m.final.crc_errors, 0);
    pr_free(&m);
}

/* What is held at the end of the input: a candidate from its first byte;
 * with none, the last three bytes, whatever they are (they may begin a
 * header; a length error comes with the fourth byte). */
static void test_held_prefixes(void **state)
{
    static const struct {
        const char *tail;
        unsigned max;
        uint32_t pending;
    } cases[] = {
        {"8A", 255, 3},         {"8A 5E", 255, 3},       {"8A 5E 48", 255, 3},
        {"8A 5E 55", 84, 3},    {"8A 5E 48 00", 255, 4}, {"8A 5E 48 01", 255, 3},
        {"8A 5E 55 00", 84, 3}, {"8A 5E FF 00", 255, 4}, {"8A 5E FF 00 11", 255, 5},
        {"5E 48 00", 255, 3},   {"8A 5E 8A 5E", 255, 3}, {"11 8A 5E", 84, 3},
        {"", 255, 3},
    };
    size_t i;
    (void)state;
    for (i = 0; i < ARRAY_LEN(cases); i++) {
        stream s = {{0}, 0};
        pr_model m;
        put_hex(&s, "00 11 22");
        put_hex(&s, cases[i].tail);
        run(&s, 4, cases[i].max, 0, &m);
        if (m.final.pending != cases[i].pending) {
            print_error("tail \"%s\" max %u: pending %u, expected %u\n", cases[i].tail, cases[i].max,
                        (unsigned)m.final.pending, (unsigned)cases[i].pending);
            fail();
        }
        check_identities(&s, &m, cases[i].max);
        pr_free(&m);
        /* the flush drops them, as skipped bytes */
        run(&s, 4, cases[i].max, 1, &m);
        assert_int_equal(m.final.pending, 0);
        assert_int_equal(m.final.bytes_skipped, s.n);
        assert_int_equal(m.at[s.n].pending, cases[i].pending);
        pr_free(&m);
    }
}

/* Nothing before floor: a frame whose last byte is h0, followed by h1 72 0,
 * makes no candidate (it would start inside the frame). */
static void test_floor(void **state)
{
    stream s = {{0}, 0};
    pr_model m;
    unsigned v;
    (void)state;
    put_packet(&s, 72, 0x11);
    for (v = 0; v < 65536u && s.d[71] != GH0; v++) {
        s.d[10] = (uint8_t)(v >> 8);
        s.d[11] = (uint8_t)v;
        ref_finish_packet(s.d, 72, XF_DIR_GCU);
    }
    assert_int_equal(s.d[71], GH0);
    put_hex(&s, "5E 48 00");
    put_fill(&s, 0x00, 80);
    run(&s, 4, 255, 0, &m);
    check_identities(&s, &m, 255);
    assert_int_equal(m.at[72].frames, 1);
    assert_int_equal(m.at[72].pending, 0);
    assert_int_equal(m.at[75].pending, 3); /* 5E 48 00: held, as any last three bytes */
    assert_int_equal(m.final.crc_errors + m.final.length_errors + m.final.given_up, 0);
    assert_int_equal(m.final.bytes_skipped, 80);
    pr_free(&m);
}

/* ---- random streams: the identities hold, whatever K and max ------------- */

static void test_random_identities(void **state)
{
    test_rng r;
    int round;
    (void)state;
    rng_seed(&r, 20240611u);
    for (round = 0; round < 200; round++) {
        stream s = {{0}, 0};
        size_t k, x;
        while (s.n < 2000u) {
            uint32_t what = rng_below(&r, 6);
            if (what == 0u) {
                uint8_t b[4] = {GH0, GH1, (uint8_t)rng_range(&r, 60, 255), (uint8_t)(rng_below(&r, 8) == 0u)};
                put(&s, b, 4);
            } else if (what <= 2u) {
                size_t at = put_packet(&s, (size_t)rng_range(&r, 72, 84), rng_u8(&r));
                if (rng_below(&r, 4) == 0u) {
                    s.d[at + rng_below(&r, 72)] ^= (uint8_t)(1u << rng_below(&r, 8));
                } else if (rng_below(&r, 4) == 0u) {
                    s.n -= rng_below(&r, 72);
                }
            } else {
                size_t n = rng_below(&r, 12), i;
                for (i = 0; i < n; i++) {
                    static const uint8_t pick[] = {GH0, GH1, 0x48, 0x00, 0x11};
                    uint8_t b = (rng_below(&r, 2) != 0u) ? pick[rng_below(&r, 5)] : rng_u8(&r);
                    put(&s, &b, 1);
                }
            }
        }
        for (k = 0; k < ARRAY_LEN(k_values); k++) {
            for (x = 0; x < ARRAY_LEN(max_values); x++) {
                pr_model m, mf;
                run(&s, k_values[k], max_values[x], 0, &m);
                check_identities(&s, &m, max_values[x]);
                run(&s, k_values[k], max_values[x], 1, &mf);
                assert_int_equal(mf.final.pending, 0);
                assert_int_equal(mf.final.bytes_skipped, m.final.bytes_skipped + m.final.pending);
                assert_int_equal(mf.final.given_up, m.final.given_up);
                pr_free(&m);
                pr_free(&mf);
            }
        }
    }
}

static void test_bad_arguments(void **state)
{
    static const uint8_t b[1] = {0};
    pr_model m;
    (void)state;
    assert_int_equal(pr_run(b, 1, XF_DIR_GCU, 0, 255, 0, &m), -1);
    assert_int_equal(pr_run(b, 1, XF_DIR_GCU, 4, 71, 0, &m), -1);
    assert_int_equal(pr_run(b, 1, XF_DIR_GCU, 4, 256, 0, &m), -1);
    assert_int_equal(pr_run(b, 0, XF_DIR_HOST, 4, 255, 1, &m), 0);
    assert_int_equal(m.n, 0);
    assert_int_equal(m.final.bytes_in, 0);
    pr_free(&m);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_clean_three),
        cmocka_unit_test(test_flipped_bit),
        cmocka_unit_test(test_frame_inside_false_candidate),
        cmocka_unit_test(test_length_errors),
        cmocka_unit_test(test_first_come_first_served),
        cmocka_unit_test(test_k_false_ending_sooner),
        cmocka_unit_test(test_slot_freed_by_check),
        cmocka_unit_test(test_same_end),
        cmocka_unit_test(test_truncated_then_intact),
        cmocka_unit_test(test_held_prefixes),
        cmocka_unit_test(test_floor),
        cmocka_unit_test(test_random_identities),
        cmocka_unit_test(test_bad_arguments),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
