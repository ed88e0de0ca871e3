/*
 * candidates.c - the parser's rules (docs/codec.md) on crafted candidates:
 * impossible and bogus lengths, false candidates nested and overlapping, a
 * frame right after a failed CRC, the ring's wrap, the longest frame, the
 * slots full (first come, first served) and storms of header bytes. Each case
 * says what the rules make of it; the storms are also compared with the
 * reference model after every call.
 */
#include "parser_test.h"

/* A header followed by an impossible length is dropped at once: the frame
 * right after it is not delayed. */
void test_bad_lengths_do_not_delay(void **state)
{
    static const struct {
        uint16_t len;
        uint32_t errors;
    } cases[] = {{0, 1},
                 {1, 1},
                 {71, 1},
                 {256, 1},
                 {0x0100, 1},
                 {0x1000, 1},
                 {0xFFFF, 1},
                 /* 8A 5E 8A 5E: the length bytes are the next header: two length errors */
                 {0x5E8A, 2}};
    test_rng r;
    uint8_t buf[300];
    size_t i, n;
    (void)state;
    rng_seed(&r, 99);
    for (i = 0; i < ARRAY_LEN(cases); i++) {
        harness h;
        buf[0] = 0x8A;
        buf[1] = 0x5E;
        le_put(buf + 2, cases[i].len, 2);
        n = 4u + make_frame(&r, XF_DIR_GCU, 1, buf + 4);
        harness_init(&h, XF_DIR_GCU);
        assert_int_equal(harness_feed(&h, buf, n), 1);
        assert_bytes_equal(h.out, buf + 4, n - 4u);
        assert_int_equal(h.p.stats.length_errors, cases[i].errors);
        assert_int_equal(h.p.stats.bytes_skipped, 4);
        assert_int_equal(h.p.stats.crc_errors, 0);
        harness_free(&h);
    }
}

/* Nested false candidates: 8A 5E 50 00 (80 bytes), inside it 8A 5E 4C 00
 * (76 bytes), inside that the real 72-byte frame. All three end on the same
 * byte and are checked in order of start: the two false ones fail
 * (crc_errors 2), then the frame comes out, from that byte's call. */
void test_nested_false_candidates(void **state)
{
    static const uint8_t pre[8] = {0x8A, 0x5E, 0x50, 0x00, 0x8A, 0x5E, 0x4C, 0x00};
    test_rng r;
    uint8_t buf[200];
    harness h;
    (void)state;
    NEED_SLOTS(3);
    rng_seed(&r, 1234);
    memcpy(buf, pre, 8);
    make_frame(&r, XF_DIR_GCU, 0, buf + 8);
    harness_init(&h, XF_DIR_GCU);
    assert_int_equal(harness_feed(&h, buf, 79), 0); /* one byte short of the outer candidate */
    assert_int_equal(harness_feed(&h, buf + 79, 1), 1);
    assert_bytes_equal(h.out, buf + 8, 72);
    assert_int_equal(h.p.stats.crc_errors, 2);
    assert_int_equal(h.p.stats.bytes_skipped, 8);
    assert_int_equal(xf_parser_pending(&h.p), 0);
    harness_free(&h);
}

/* A frame right after a candidate whose CRC fails is found in the bytes
 * already held, for a corrupted frame, a truncated one and a
 * header with a valid-looking length. */
void test_frame_after_crc_failure(void **state)
{
    test_rng r;
    uint8_t bad[256], good[256], buf[600];
    size_t bl, gl, cut;
    harness h;
    (void)state;
    NEED_SLOTS(2);
    rng_seed(&r, 555);
    gl = make_frame(&r, XF_DIR_GCU, 1, good);

    /* a whole frame with a flipped bit, then the good one */
    bl = make_frame(&r, XF_DIR_GCU, 1, bad);
    bad[30] ^= 0x04;
    memcpy(buf, bad, bl);
    memcpy(buf + bl, good, gl);
    harness_init(&h, XF_DIR_GCU);
    assert_int_equal(harness_feed(&h, buf, bl + gl), 1);
    assert_bytes_equal(h.out, good, gl);
    assert_int_equal(h.p.stats.crc_errors, 1);
    harness_free(&h);

    /* truncated frames (false starts) of every length, then the good one */
    for (cut = 1; cut < 72; cut++) {
        make_frame(&r, XF_DIR_GCU, 0, bad);
        memcpy(buf, bad, cut);
        memcpy(buf + cut, good, gl);
        memcpy(buf + cut + gl, good, gl); /* and a second copy right after */
        harness_init(&h, XF_DIR_GCU);
        harness_feed(&h, buf, cut + 2u * gl);
        if (h.nframes != 2) {
            print_error("false start of %zu bytes: %zu frames\n", cut, h.nframes);
            fail();
        }
        assert_bytes_equal(h.out, good, gl);
        assert_bytes_equal(h.out + gl, good, gl);
        harness_free(&h);
    }

    /* 8A 5E 50 00 then two frames: the first lies inside the false
     * candidate's 80 bytes, the second starts inside it and ends later */
    buf[0] = 0x8A;
    buf[1] = 0x5E;
    buf[2] = 0x50;
    buf[3] = 0x00;
    memcpy(buf + 4, good, gl);
    bl = make_frame(&r, XF_DIR_GCU, 0, buf + 4 + gl);
    harness_init(&h, XF_DIR_GCU);
    assert_int_equal(harness_feed(&h, buf, 4u + gl + bl), 2);
    assert_bytes_equal(h.out, good, gl);
    assert_bytes_equal(h.out + gl, buf + 4 + gl, bl);
    assert_int_equal(h.p.stats.bytes_skipped, 4);
    harness_free(&h);
}

/* A header whose length was corrupted (0x00FF, 0x0050, 0x00C8) does not
 * hold back the intact frames behind it (xf_parser.h: the frame that ends
 * sooner is checked as soon as it is complete): each frame comes out on
 * its own last byte. */
void test_bogus_length_does_not_delay(void **state)
{
    static const uint16_t lens[] = {0x00FF, 0x0050, 0x00C8, 0x0049};
    test_rng r;
    uint8_t buf[1024];
    size_t li, i, k, n, off[4];
    (void)state;
    NEED_SLOTS(2);
    rng_seed(&r, 0xB0B);
    for (li = 0; li < ARRAY_LEN(lens); li++) {
        harness h;
        buf[0] = 0x8A;
        buf[1] = 0x5E;
        le_put(buf + 2, lens[li], 2);
        n = 4;
        for (i = 0; i < 4; i++) {
            off[i] = n;
            n += make_frame(&r, XF_DIR_GCU, 0, buf + n);
        }
        harness_init(&h, XF_DIR_GCU);
        for (k = 0, i = 0; k < n; k++) {
            size_t got = harness_feed(&h, buf + k, 1);
            int frame_ends_here = (i < 4 && k + 1u == off[i] + 72u);
            if ((size_t)frame_ends_here != got) {
                print_error("length 0x%04X: byte %zu gave %zu frame(s)\n", lens[li], k, got);
                fail();
            }
            i += got;
        }
        assert_int_equal(h.nframes, 4);
        for (i = 0; i < 4; i++) {
            assert_bytes_equal(h.out + 72u * i, buf + off[i], 72);
        }
        assert_int_equal(h.p.stats.bytes_skipped, 4);
        assert_int_equal(xf_parser_pending(&h.p), 0);
        harness_free(&h);
    }
}

/* Two overlapping bogus lengths (8A 5E FF 00 8A 5E FF 00 by default: the
 * largest valid length, XF_PACKET_MAX_LEN): the frames
 * behind them come out, whole and in order, once the false candidates are
 * complete; with these offsets one of them straddles the end of the
 * parser's 256-byte ring (white-box check that the wrap path ran). */
void test_bogus_lengths_and_ring_wrap(void **state)
{
    static const uint8_t pre[8] = {0x8A, 0x5E, XF_PACKET_MAX_LEN, 0x00, 0x8A, 0x5E, XF_PACKET_MAX_LEN, 0x00};
    test_rng r;
    uint8_t buf[1024];
    size_t off[6], i, n = 8, chunk;
    (void)state;
    NEED_SLOTS(3);
    rng_seed(&r, 0xFF);
    memcpy(buf, pre, 8);
    for (i = 0; i < 6; i++) {
        off[i] = n;
        n += make_frame(&r, XF_DIR_GCU, 0, buf + n);
    }
    for (chunk = 1; chunk <= 500; chunk = chunk * 3u + 1u) {
        harness h;
        size_t k;
        harness_init(&h, XF_DIR_GCU);
        for (k = 0; k < n; k += chunk) {
            harness_feed(&h, buf + k, (k + chunk <= n) ? chunk : n - k);
        }
        assert_int_equal(h.nframes, 6);
        for (i = 0; i < 6; i++) {
            assert_bytes_equal(h.out + 72u * i, buf + off[i], 72);
        }
        /* dropped unchecked when the first frame came out: they overlap it */
        assert_int_equal(h.p.stats.crc_errors, 0);
        assert_int_equal(h.p.stats.bytes_skipped, 8);
        assert_int_equal(xf_parser_pending(&h.p), 0);
        harness_free(&h);
    }
}

/* The longest frame (255 bytes, 183 parameter bytes by default), clean and
 * after a false candidate (so that it comes from the ring and spans the
 * ring's end). */
void test_max_length_frame(void **state)
{
    enum { MAXLEN = XF_PACKET_MAX_LEN, TOTAL = 4 + XF_PACKET_MAX_LEN + 72 };
    xf_gcu_packet g;
    uint8_t frame[MAXLEN], buf[TOTAL];
    size_t n = 0, i;
    harness h;
    (void)state;
    NEED_SLOTS(2);
    memset(&g, 0, sizeof(g));
    g.version = 2;
    g.order = 0x42;
    g.params_len = (uint8_t)XF_PARAMS_MAX;
    for (i = 0; i < XF_PARAMS_MAX; i++) {
        g.params[i] = (uint8_t)(0x8A ^ i); /* includes 8A 5E-looking bytes */
    }
    assert_err(xf_gcu_pack(&g, frame, sizeof(frame), &n), XF_OK);
    assert_int_equal(n, MAXLEN);

    harness_init(&h, XF_DIR_GCU);
    assert_int_equal(harness_feed(&h, frame, MAXLEN), 1);
    assert_bytes_equal(h.out, frame, MAXLEN);
    harness_free(&h);

    /* 8A 5E 48 00 (72) + the longest frame + a 72-byte frame */
    buf[0] = 0x8A;
    buf[1] = 0x5E;
    buf[2] = 0x48;
    buf[3] = 0x00;
    memcpy(buf + 4, frame, MAXLEN);
    {
        test_rng r;
        rng_seed(&r, 3);
        make_frame(&r, XF_DIR_GCU, 0, buf + 4 + MAXLEN);
    }
    for (i = 1; i <= 7; i += 3) {
        size_t k;
        harness_init(&h, XF_DIR_GCU);
        for (k = 0; k < TOTAL; k += i) {
            harness_feed(&h, buf + k, (k + i <= TOTAL) ? i : TOTAL - k);
        }
        assert_int_equal(h.nframes, 2);
        assert_bytes_equal(h.out, frame, MAXLEN);
        assert_bytes_equal(h.out + MAXLEN, buf + 4 + MAXLEN, 72);
        assert_int_equal(h.p.stats.crc_errors, 1); /* the false candidate ended inside the frame, and failed */
        harness_free(&h);
    }
}

/* Worst case input: the largest valid length every four bytes, then a
 * real frame, zeros, and another frame. First come, first served: the
 * false candidates hold every slot while the first frame's header arrives,
 * so it is lost (the documented condition); once they have ended, the
 * second is found. Every candidate admitted is checked, exactly as the
 * model says. With XF_PACKET_MAX_LEN=84 the claims are length errors and
 * both frames come out. */
void test_adversarial_lengths(void **state)
{
    stream s;
    harness h;
    pr_model m;
    test_rng r;
    uint8_t f[256], g[256];
    size_t i, fl, gl;
    (void)state;
    stream_init(&s);
    rng_seed(&r, 0xAD);
    for (i = 0; i < 16384; i++) {
        static const uint8_t cand[4] = {0x8A, 0x5E, 0xFF, 0x00};
        put(&s, cand, 4);
    }
    fl = make_frame(&r, XF_DIR_GCU, 1, f);
    put(&s, f, fl);
    for (i = 0; i < 300; i++) {
        put1(&s, 0);
    }
    gl = make_frame(&r, XF_DIR_GCU, 0, g);
    put(&s, g, gl);
    feed_checked(&h, &m, &s, 1000);
    if (XF_PACKET_MAX_LEN == 255) {
        /* the second frame always comes out, last; the first only if its header found a slot
         * free, which with few slots it does not */
        assert_true(h.nframes >= 1u && h.out_len >= gl);
        assert_bytes_equal(h.out + h.out_len - gl, g, gl);
        if (XF_PARSER_SLOTS <= 4) {
            assert_int_equal(h.nframes, 1);
        }
        assert_true(h.p.stats.given_up >= 1u);
        assert_true(h.p.stats.crc_errors >= 16384u * 4u / 255u); /* at least one claim at a time */
    } else {
        assert_int_equal(h.nframes, 2);
        assert_true(h.p.stats.length_errors >= 16384u);
    }
    harness_free(&h);
    pr_free(&m);
    stream_free(&s);
}

/* Rule 3 at its edges, with K = XF_PARSER_SLOTS: K - 1 false 255-byte claims
 * back to back, then a frame: it takes the last slot and comes out. K claims,
 * a pair with a bad length, then a frame: the pair is still counted, but every
 * slot is taken when the frame's header completes, so it is given up
 * (given_up 1) and lost. A 72-byte claim that ends on the very byte that
 * completes a frame's header, with K - 1 claims behind it: its check frees
 * its slot first, and the frame is admitted and comes out. Each at several
 * chunk sizes, compared with the model after every call. */
void test_slots_edges(void **state)
{
    static const uint8_t claim72[4] = {0x8A, 0x5E, 72, 0x00}, claim255[4] = {0x8A, 0x5E, XF_PACKET_MAX_LEN, 0x00};
    static const uint8_t bad_pair[4] = {0x8A, 0x5E, 0x10, 0x00};
    static const size_t chunks[] = {1, 5, 16, 4096};
    uint8_t f[256];
    size_t i, c, kase, fl;
    test_rng r;
    (void)state;
    rng_seed(&r, 77);
    fl = make_frame(&r, XF_DIR_GCU, 0, f);
    for (kase = 0; kase < 3u; kase++) {
        stream s;
        stream_init(&s);
        if (kase == 2u) {
            put(&s, claim72, 4);
        }
        for (i = 0; i < XF_PARSER_SLOTS - (kase != 1u); i++) {
            put(&s, claim255, 4);
        }
        if (kase == 1u) {
            put(&s, bad_pair, 4);
        }
        while (kase == 2u && s.len < 72u - 4u) {
            put1(&s, 0x00); /* the frame's header completes on the claim's last byte */
        }
        put(&s, f, fl);
        for (i = 0; i < 300u; i++) {
            put1(&s, 0x00);
        }
        for (c = 0; c < sizeof(chunks) / sizeof(chunks[0]); c++) {
            harness h;
            pr_model m;
            feed_checked(&h, &m, &s, chunks[c]);
            assert_int_equal(h.nframes, (kase == 1u) ? 0u : 1u);
            assert_int_equal(h.p.stats.given_up, (kase == 1u) ? 1u : 0u);
            assert_int_equal(h.p.stats.length_errors, (kase == 1u) ? 1u : 0u);
            if (kase == 2u && XF_PACKET_MAX_LEN == 255) {
                assert_int_equal(h.p.stats.crc_errors, 1u); /* the 72-byte claim; the others went with the frame */
            }
            harness_free(&h);
            pr_free(&m);
        }
        stream_free(&s);
    }
}

/* Crafted storms, each followed by a real frame, fed in several chunk sizes
 * and compared with the model after every call: a run of h0 bytes (every
 * byte the fourth after an h0), header pairs with bad lengths, h0 h1 h0 00
 * (a candidate and an h0 look every four bytes), nested lengths (each
 * candidate ends before the last one pending), the largest length every
 * four bytes, a 79-byte claim every 40 bytes with h0 bytes between, and
 * 72-byte claims every 24 bytes with a real frame among them every eighth.
 * They drive the paths a clean stream never takes. */
void test_crafted_storms(void **state)
{
    static const size_t chunks[] = {1, 2, 3, 5, 16, 64, 4096};
    stream s;
    test_rng r;
    uint8_t f[256];
    size_t i, c, k, fl, inserted = 0;
    (void)state;
    stream_init(&s);
    rng_seed(&r, 0x5708);
    for (k = 0; k < 7; k++) {
        for (i = 0; i < 600; i++) {
            static const uint8_t pair8a[4] = {0x8A, 0x5E, 0x8A, 0x00};
            static const uint8_t dense[4] = {0x8A, 0x5E, XF_PACKET_MAX_LEN, 0x00};
            static const uint8_t claim72[4] = {0x8A, 0x5E, 72, 0x00};
            uint8_t nested[4] = {0x8A, 0x5E, 0, 0x00}, claim79[4] = {0x8A, 0x5E, 79, 0x00};
            nested[2] = (uint8_t)(XF_PACKET_MAX_LEN - 5u * (i % ((XF_PACKET_MAX_LEN - 72u) / 5u + 1u)));
            switch (k) {
            case 0: put1(&s, 0x8A); break;
            case 1: put(&s, pair8a, 2); break;
            case 2: put(&s, pair8a, 4); break;
            case 3: put(&s, nested, 4); break;
            case 4: put(&s, dense, 4); break;
            case 5:
                claim79[2] = (uint8_t)((XF_PACKET_MAX_LEN < 79) ? XF_PACKET_MAX_LEN : 79);
                put(&s, claim79, 4);
                for (fl = 0; fl < 36u; fl++) {
                    put1(&s, 0x8A);
                }
                break;
            default:
                if (i % 8u == 7u) {
                    fl = make_frame(&r, XF_DIR_GCU, 0, f);
                    put(&s, f, fl);
                    inserted++;
                    break;
                }
                put(&s, claim72, 4);
                for (fl = 0; fl < 10u; fl++) {
                    put(&s, pair8a, 2);
                }
                break;
            }
        }
        fl = make_frame(&r, XF_DIR_GCU, k & 1u, f);
        put(&s, f, fl);
    }
    for (c = 0; c < sizeof(chunks) / sizeof(chunks[0]); c++) {
        harness h;
        pr_model m;
        feed_checked(&h, &m, &s, chunks[c]);
        assert_true(h.p.stats.length_errors > 0u && h.p.stats.crc_errors > 0u);
        if (XF_PACKET_MAX_LEN == 255) {
            assert_true(h.nframes >= 2u); /* the frames after the h0 run and the pairs */
        }
        if (XF_PARSER_SLOTS >= 4) { /* three claims at once among the claims every 24 bytes: a slot for each frame */
            assert_true(h.nframes >= inserted && h.nframes <= 7u + inserted);
        }
        harness_free(&h);
        pr_free(&m);
    }
    stream_free(&s);
}
