/*
 * calls.c - the parser's calls on small, exact cases: a frame fed one byte at
 * a time, where `consumed` stops, flush and reset, the frame decoders' length
 * check, the direction filter, and the arguments refused.
 */
#include "parser_test.h"

void test_appendix_one_byte_at_a_time(void **state)
{
    xf_parser p;
    xf_frame f;
    size_t i, used;
    (void)state;
    assert_err(xf_parser_init(&p, XF_DIR_HOST), XF_OK);
    for (i = 0; i < 72; i++) {
        xf_parse_status rc = xf_parser_feed(&p, appendix1_packet + i, 1, &used, &f);
        assert_int_equal(used, 1);
        if (i < 71) {
            assert_int_equal(rc, XF_PARSE_MORE);
            assert_int_equal(xf_parser_pending(&p), i + 1u);
        } else {
            assert_int_equal(rc, XF_PARSE_FRAME);
            assert_int_equal(f.len, 72);
            assert_bytes_equal(f.data, appendix1_packet, 72);
        }
    }
    assert_int_equal(xf_parser_pending(&p), 0);
    assert_int_equal(p.stats.frames, 1);
    assert_int_equal(p.stats.bytes_in, 72);
    assert_int_equal(p.stats.bytes_skipped, 0);
    assert_int_equal(xf_parser_feed(&p, NULL, 0, &used, &f), XF_PARSE_MORE);
    assert_int_equal(used, 0);
}

/* Back-to-back frames in one buffer: each call stops right after a frame. */
void test_consumed_stops_at_frame(void **state)
{
    test_rng r;
    uint8_t buf[600];
    size_t a, b, c, used = 0;
    xf_parser p;
    xf_frame f;
    (void)state;
    rng_seed(&r, 42);
    a = make_frame(&r, XF_DIR_GCU, 1, buf);
    b = make_frame(&r, XF_DIR_GCU, 0, buf + a);
    c = make_frame(&r, XF_DIR_GCU, XF_PARAMS_MAX, buf + a + b);
    assert_err(xf_parser_init(&p, XF_DIR_GCU), XF_OK);
    assert_int_equal(xf_parser_feed(&p, buf, a + b + c, &used, &f), XF_PARSE_FRAME);
    assert_int_equal(used, a);
    assert_int_equal(f.len, a);
    assert_bytes_equal(f.data, buf, a);
    assert_int_equal(xf_parser_feed(&p, buf + a, b + c, &used, &f), XF_PARSE_FRAME);
    assert_int_equal(used, b);
    assert_bytes_equal(f.data, buf + a, b);
    assert_int_equal(xf_parser_feed(&p, buf + a + b, c, &used, &f), XF_PARSE_FRAME);
    assert_int_equal(used, c);
    assert_int_equal(f.len, XF_PACKET_MAX_LEN);
    assert_bytes_equal(f.data, buf + a + b, c);
    assert_int_equal(xf_parser_feed(&p, buf, 0, &used, &f), XF_PARSE_MORE);
    assert_int_equal(p.stats.crc_errors, 0);
    assert_int_equal(p.stats.length_errors, 0);
    assert_int_equal(p.stats.bytes_skipped, 0);
}

/* consumed stops right after a frame's last byte however the frame got
 * there: whole in the chunk (no copy), behind a false candidate (from the
 * parser's ring), and split across chunks; the rest of the chunk is left
 * to the caller, untouched. */
void test_consumed_after_false_candidate(void **state)
{
    static const uint8_t false_cand[4] = {0x8A, 0x5E, 0x50, 0x00}; /* claims 80 bytes: ends after the frame */
    test_rng r;
    uint8_t buf[600];
    size_t a, used = 0, i;
    xf_parser p;
    xf_frame f;
    (void)state;
    NEED_SLOTS(2);
    rng_seed(&r, 43);
    memcpy(buf, false_cand, 4);
    a = make_frame(&r, XF_DIR_GCU, 1, buf + 4);
    memset(buf + 4 + a, 0x8A, 100); /* header bytes after it, which must not be taken */
    assert_err(xf_parser_init(&p, XF_DIR_GCU), XF_OK);
    assert_int_equal(xf_parser_feed(&p, buf, 4 + a + 100, &used, &f), XF_PARSE_FRAME);
    assert_int_equal(used, 4 + a);
    assert_int_equal(f.len, a);
    assert_bytes_equal(f.data, buf + 4, a);
    assert_true(f.data >= p.buf && f.data + f.len <= p.buf + sizeof(p.buf)); /* it came from the parser */
    assert_int_equal(xf_parser_pending(&p), 0);
    assert_int_equal(p.stats.bytes_skipped, 4);
    assert_int_equal(p.stats.bytes_in, 4 + a);
    /* the same in chunks of 5: the chunk with the last byte stops there */
    assert_err(xf_parser_init(&p, XF_DIR_GCU), XF_OK);
    for (i = 0; i < 4 + a; i += 5) {
        size_t n = 5, end = 4 + a;
        xf_parse_status st = xf_parser_feed(&p, buf + i, n, &used, &f);
        if (i + n >= end) {
            assert_int_equal(st, XF_PARSE_FRAME);
            assert_int_equal(used, end - i);
            break;
        }
        assert_int_equal(st, XF_PARSE_MORE);
        assert_int_equal(used, n);
    }
}

/* flush: the input ended. It returns no frame (each intact frame was
 * returned by the feed that completed it), drops what is held, counts it
 * as skipped, and the parser then starts afresh: a candidate cut by the
 * end of one input never joins bytes of the next. */
void test_flush(void **state)
{
    test_rng r;
    uint8_t f1[256], f2[256];
    size_t l1, l2, used;
    xf_parser p;
    xf_frame f;
    (void)state;
    rng_seed(&r, 7);
    l1 = make_frame(&r, XF_DIR_GCU, 0, f1);
    l2 = make_frame(&r, XF_DIR_GCU, 2, f2);
    assert_err(xf_parser_init(&p, XF_DIR_GCU), XF_OK);
    assert_int_equal(xf_parser_flush(&p, &f), XF_PARSE_MORE); /* nothing held: nothing to do */
    assert_int_equal(xf_parser_feed(&p, f1, 50, &used, &f), XF_PARSE_MORE);
    assert_int_equal(xf_parser_pending(&p), 50);
    f.data = NULL;
    assert_int_equal(xf_parser_flush(&p, &f), XF_PARSE_MORE);
    assert_null(f.data); /* never written */
    assert_int_equal(xf_parser_pending(&p), 0);
    assert_int_equal(p.stats.bytes_skipped, 50);
    assert_int_equal(p.stats.bytes_in, 50);
    /* the rest of f1 after the flush is no frame; f2 then is */
    assert_int_equal(xf_parser_feed(&p, f1 + 50, l1 - 50u, &used, &f), XF_PARSE_MORE);
    assert_int_equal(xf_parser_feed(&p, f2, l2, &used, &f), XF_PARSE_FRAME);
    assert_bytes_equal(f.data, f2, l2);
    assert_int_equal(p.stats.frames, 1);
    /* a partial header at the end is dropped too */
    assert_int_equal(xf_parser_feed(&p, f1, 3, &used, &f), XF_PARSE_MORE);
    assert_int_equal(xf_parser_pending(&p), 3);
    assert_int_equal(xf_parser_flush(&p, &f), XF_PARSE_MORE);
    assert_int_equal(xf_parser_pending(&p), 0);
    assert_int_equal(p.stats.bytes_in, p.stats.bytes_skipped + l2);
    assert_int_equal(xf_parser_flush(NULL, &f), XF_PARSE_ERR_ARG);
    assert_int_equal(xf_parser_flush(&p, NULL), XF_PARSE_ERR_ARG);
}

/* xf_frame_gcu/xf_frame_host trust the parser's CRC but check the header
 * and that the length field agrees with the frame's length. */
void test_frame_length_field(void **state)
{
    test_rng r;
    uint8_t buf[256];
    xf_gcu_packet g;
    xf_host_packet hp;
    xf_frame f;
    size_t n;
    (void)state;
    rng_seed(&r, 8);
    n = make_frame(&r, XF_DIR_GCU, 1, buf);
    f.data = buf;
    f.len = n;
    assert_err(xf_frame_gcu(&f, &g), XF_OK);
    assert_err(xf_frame_host(&f, &hp), XF_ERR_HEADER);
    f.len = n - 1u; /* disagrees with the length field */
    assert_err(xf_frame_gcu(&f, &g), XF_ERR_LENGTH);
    f.len = n;
    buf[2] ^= 1u; /* the field disagrees with the length */
    assert_err(xf_frame_gcu(&f, &g), XF_ERR_LENGTH);
    buf[2] ^= 1u;
    buf[3] = 1; /* a length above 255 */
    assert_err(xf_frame_gcu(&f, &g), XF_ERR_LENGTH);
    buf[3] = 0;
    f.len = 71;
    assert_err(xf_frame_gcu(&f, &g), XF_ERR_LENGTH);
    f.data = NULL;
    assert_err(xf_frame_gcu(&f, &g), XF_ERR_ARG);
    assert_err(xf_frame_gcu(NULL, &g), XF_ERR_ARG);
}

/* Host parser ignores GCU frames and the reverse. */
void test_direction_filter(void **state)
{
    test_rng r;
    uint8_t gcu[3][256], host[256];
    size_t gl[3], hl, i;
    harness h;
    (void)state;
    rng_seed(&r, 7);
    for (i = 0; i < 3; i++) {
        gl[i] = random_frame(&r, XF_DIR_GCU, gcu[i]);
    }
    hl = make_frame(&r, XF_DIR_HOST, 5, host);

    harness_init(&h, XF_DIR_HOST);
    for (i = 0; i < 3; i++) {
        assert_int_equal(harness_feed(&h, gcu[i], gl[i]), 0);
    }
    assert_int_equal(harness_feed(&h, host, hl), 1);
    assert_bytes_equal(h.out, host, hl);
    assert_int_equal(h.p.stats.bytes_skipped, gl[0] + gl[1] + gl[2]);
    harness_free(&h);

    harness_init(&h, XF_DIR_GCU);
    assert_int_equal(harness_feed(&h, host, hl), 0);
    assert_int_equal(harness_feed(&h, appendix1_packet, 72), 0);
    assert_int_equal(harness_feed(&h, gcu[1], gl[1]), 1);
    assert_bytes_equal(h.out, gcu[1], gl[1]);
    harness_free(&h);
}

/* xf_parser_reset drops what is held (counted as skipped), keeps the
 * direction and the counters. */
void test_reset(void **state)
{
    test_rng r;
    uint8_t f1[256], f2[256];
    size_t l1, l2;
    uint32_t skipped;
    harness h;
    (void)state;
    rng_seed(&r, 2024);
    l1 = make_frame(&r, XF_DIR_HOST, 0, f1);
    l2 = make_frame(&r, XF_DIR_HOST, 3, f2);
    harness_init(&h, XF_DIR_HOST);
    assert_int_equal(harness_feed(&h, f1, l1), 1);
    assert_int_equal(harness_feed(&h, f2, 40), 0);
    assert_int_equal(xf_parser_pending(&h.p), 40);
    skipped = h.p.stats.bytes_skipped;
    xf_parser_reset(&h.p);
    assert_int_equal(xf_parser_pending(&h.p), 0);
    assert_int_equal(h.p.stats.bytes_skipped, skipped + 40u);
    assert_int_equal(h.p.stats.frames, 1);
    assert_int_equal(h.p.stats.bytes_in, l1 + 40u);
    check_counters(&h);
    /* the rest of the cut frame is not a frame; the next whole one is */
    harness_feed(&h, f2 + 40, l2 - 40u);
    assert_int_equal(h.nframes, 1);
    assert_int_equal(harness_feed(&h, f1, l1), 1);
    assert_int_equal(harness_feed(&h, f2, l2), 1);
    assert_bytes_equal(h.out + l1, f1, l1);
    assert_bytes_equal(h.out + 2u * l1, f2, l2);
    /* reset after a CRC failure too */
    f1[10] ^= 1;
    harness_feed(&h, f1, l1);
    harness_feed(&h, f2, 30);
    xf_parser_reset(&h.p);
    check_counters(&h);
    f1[10] ^= 1;
    assert_int_equal(harness_feed(&h, f1, l1), 1);
    /* still a host parser */
    {
        uint8_t g[256];
        size_t gl = make_frame(&r, XF_DIR_GCU, 0, g);
        assert_int_equal(harness_feed(&h, g, gl), 0);
    }
    xf_parser_reset(NULL); /* must not crash */
    assert_int_equal(xf_parser_pending(NULL), 0);
    harness_free(&h);
}

void test_parser_args(void **state)
{
    xf_parser p;
    xf_frame f;
    size_t used = 77;
    uint8_t b[4] = {0};
    (void)state;
    assert_err(xf_parser_init(NULL, XF_DIR_GCU), XF_ERR_ARG);
    assert_err(xf_parser_init(&p, (xf_direction)2), XF_ERR_ARG);
    assert_err(xf_parser_init(&p, XF_DIR_GCU), XF_OK);
    assert_int_equal(xf_parser_feed(NULL, b, 4, &used, &f), XF_PARSE_ERR_ARG);
    assert_int_equal(xf_parser_feed(&p, b, 4, &used, NULL), XF_PARSE_ERR_ARG);
    assert_int_equal(xf_parser_feed(&p, NULL, 4, &used, &f), XF_PARSE_ERR_ARG);
    assert_int_equal(xf_parser_flush(NULL, &f), XF_PARSE_ERR_ARG);
    assert_int_equal(xf_parser_flush(&p, NULL), XF_PARSE_ERR_ARG);
    /* the parser's error is the xf_err of the same value, and no xf_err is a frame */
    assert_int_equal((int)XF_PARSE_ERR_ARG, (int)XF_ERR_ARG);
    assert_string_equal(xf_err_name((xf_err)XF_PARSE_ERR_ARG), "XF_ERR_ARG");
    assert_string_equal(xf_err_name((xf_err)XF_PARSE_FRAME), "unknown");
    assert_int_equal(p.stats.bytes_in, 0);
    /* allowed: no data, no consumed pointer */
    assert_int_equal(xf_parser_feed(&p, NULL, 0, &used, &f), XF_PARSE_MORE);
    assert_int_equal(used, 0);
    assert_int_equal(xf_parser_feed(&p, b, 4, NULL, &f), XF_PARSE_MORE);
    assert_int_equal(p.stats.bytes_in, 4);
    assert_int_equal(p.stats.bytes_skipped, 1); /* the last three may begin a header */
    assert_int_equal(xf_parser_pending(&p), 3);
}
