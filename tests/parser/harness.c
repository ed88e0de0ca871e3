/*
 * harness.c - the parser tests' rig (parser_test.h): the harness that feeds
 * the parser and checks its counters after every call, the stream builder,
 * and the comparisons with the reference model (parser_ref.h).
 */
#include <stdlib.h>
#include "parser_test.h"

#define MAX_FRAMES 40000      /* frames a harness or a stream holds */
#define MAX_OUT    (4u << 20) /* bytes of the frames a harness returned */
#define MAX_STREAM (2u << 20) /* bytes of a stream */

/* ---- harness: feed, collect, check the counters after every call -------- */

void harness_init(harness *h, xf_direction dir)
{
    memset(h, 0, sizeof(*h));
    h->dir = dir;
    assert_err(xf_parser_init(&h->p, dir), XF_OK);
    h->out = (uint8_t *)malloc(MAX_OUT);
    h->lens = (size_t *)malloc(MAX_FRAMES * sizeof(size_t));
    assert_non_null(h->out);
    assert_non_null(h->lens);
}

void harness_free(harness *h)
{
    free(h->out);
    free(h->lens);
    h->out = NULL;
    h->lens = NULL;
}

void check_counters(harness *h)
{
    const xf_parser_stats *s = &h->p.stats;
    /* never decrease */
    assert_true(s->bytes_in >= h->last.bytes_in);
    assert_true(s->frames >= h->last.frames);
    assert_true(s->crc_errors >= h->last.crc_errors);
    assert_true(s->length_errors >= h->last.length_errors);
    assert_true(s->bytes_skipped >= h->last.bytes_skipped);
    /* every byte in is in a frame, skipped, or still held */
    if ((uint64_t)s->bytes_in != h->frame_bytes + s->bytes_skipped + xf_parser_pending(&h->p)) {
        print_error("bytes_in %u != frames %llu + skipped %u + pending %zu\n", s->bytes_in,
                    (unsigned long long)h->frame_bytes, s->bytes_skipped, xf_parser_pending(&h->p));
        fail();
    }
    assert_int_equal(s->frames, h->nframes);
    assert_true(xf_parser_pending(&h->p) <= XF_PACKET_MAX_LEN);
    if (h->model != NULL) {
        const pr_counts *m = &h->model->at[s->bytes_in];
        if (s->frames != m->frames || s->crc_errors != m->crc_errors || s->length_errors != m->length_errors ||
            s->given_up != m->given_up || s->bytes_skipped != m->bytes_skipped ||
            xf_parser_pending(&h->p) != m->pending) {
            print_error(
                "after %u bytes: parser frames %u crc %u len %u given_up %u skipped %u pending %zu; model %u %u %u "
                "%u %u %u\n",
                s->bytes_in, s->frames, s->crc_errors, s->length_errors, s->given_up, s->bytes_skipped,
                xf_parser_pending(&h->p), m->frames, m->crc_errors, m->length_errors, m->given_up, m->bytes_skipped,
                m->pending);
            fail();
        }
    }
    h->last = *s;
}

/* Feed one chunk, draining every frame it completes. Returns the number of
 * frames it produced. */
size_t harness_feed(harness *h, const uint8_t *data, size_t len)
{
    size_t produced = 0;
    for (;;) {
        xf_frame f;
        size_t used = (size_t)-1;
        xf_parse_status rc;
        memset(&f, 0, sizeof(f));
        rc = xf_parser_feed(&h->p, data, len, &used, &f);
        if (rc != XF_PARSE_FRAME && rc != XF_PARSE_MORE) {
            print_error("xf_parser_feed returned %d\n", (int)rc);
            fail();
        }
        assert_true(used <= len);
        if (rc == XF_PARSE_MORE) {
            assert_int_equal(used, len); /* MORE means every byte was taken */
        } else {
            assert_non_null(f.data);
            assert_true(f.len >= 72u && f.len <= XF_PACKET_MAX_LEN);
            assert_err(xf_packet_check(f.data, f.len, h->dir), XF_OK);
            assert_true(h->nframes < MAX_FRAMES && h->out_len + f.len <= MAX_OUT);
            memcpy(h->out + h->out_len, f.data, f.len);
            h->out_len += f.len;
            if (h->model != NULL) {
                /* no added latency: the frame is the model's next one and ends with the call's last byte taken */
                const pr_frame *mf = &h->model->frames[h->nframes];
                assert_true(h->nframes < h->model->nframes);
                assert_int_equal(mf->start + mf->len, (size_t)(data - h->base) + used);
                assert_int_equal(f.len, mf->len);
                assert_memory_equal(f.data, h->base + mf->start, f.len);
            }
            h->lens[h->nframes++] = f.len;
            h->frame_bytes += f.len;
            produced++;
        }
        check_counters(h);
        if (used > 0u) {
            data += used;
            len -= used;
        }
        if (rc == XF_PARSE_MORE) {
            return produced;
        }
    }
}

/* ---- stream builder ------------------------------------------------------- */

void stream_init(stream *s)
{
    memset(s, 0, sizeof(*s));
    s->buf = (uint8_t *)malloc(MAX_STREAM);
    s->foff = (size_t *)malloc(MAX_FRAMES * sizeof(size_t));
    s->flen = (size_t *)malloc(MAX_FRAMES * sizeof(size_t));
    assert_non_null(s->buf);
    assert_non_null(s->foff);
    assert_non_null(s->flen);
}

void stream_free(stream *s)
{
    free(s->buf);
    free(s->foff);
    free(s->flen);
}

void put(stream *s, const uint8_t *p, size_t n)
{
    assert_true(s->len + n <= MAX_STREAM);
    memcpy(s->buf + s->len, p, n);
    s->len += n;
}

void put1(stream *s, uint8_t b) { put(s, &b, 1); }

/* A valid frame: random content, spec header, length and CRC. */
size_t make_frame(test_rng *r, xf_direction dir, size_t params_len, uint8_t *out)
{
    size_t len = 72u + params_len;
    rng_fill(r, out, len);
    ref_finish_packet(out, len, dir);
    return len;
}

size_t random_frame(test_rng *r, xf_direction dir, uint8_t *out)
{
    uint32_t k = rng_below(r, 10);
    size_t plen = (k < 4) ? 0 : (k < 7) ? 1 : (k < 9) ? rng_below(r, 13) : rng_below(r, XF_PARAMS_MAX + 1u);
    return make_frame(r, dir, plen, out);
}

static void put_frame(stream *s, const uint8_t *f, size_t n)
{
    assert_true(s->nframes < MAX_FRAMES);
    s->foff[s->nframes] = s->len;
    s->flen[s->nframes] = n;
    s->nframes++;
    put(s, f, n);
}

/* One piece of junk between frames. */
static void put_junk(stream *s, test_rng *r, xf_direction dir)
{
    uint8_t h0 = (dir == XF_DIR_HOST) ? 0xA8 : 0x8A;
    uint8_t h1 = (dir == XF_DIR_HOST) ? 0xE5 : 0x5E;
    uint8_t tmp[256];
    size_t n, i;
    switch (rng_below(r, 9)) {
    case 0: /* noise, rich in first header bytes */
        n = 1u + rng_below(r, 40);
        for (i = 0; i < n; i++) {
            put1(s, (rng_below(r, 6) == 0) ? h0 : rng_u8(r));
        }
        break;
    case 1: /* stray header bytes */
        switch (rng_below(r, 4)) {
        case 0: put1(s, h0); break;
        case 1:
            put1(s, h0);
            put1(s, h1);
            break;
        case 2:
            put1(s, h0);
            put1(s, h0);
            put1(s, h1);
            put1(s, 0x48);
            break;
        default:
            put1(s, h1);
            put1(s, h0);
            break;
        }
        break;
    case 2: /* a header with a length below 72 */
        put1(s, h0);
        put1(s, h1);
        le_put(tmp, rng_below(r, 72), 2);
        put(s, tmp, 2);
        break;
    case 3: /* a header with a length above 255 */
        put1(s, h0);
        put1(s, h1);
        le_put(tmp, 256u + rng_below(r, 65536u - 256u), 2);
        put(s, tmp, 2);
        break;
    case 4: /* a valid-looking length (0x00FF, 0x0050 or any in [72, 255]) and a few bytes */
        put1(s, h0);
        put1(s, h1);
        i = rng_below(r, 3);
        le_put(tmp, (i == 0) ? 0xFFu : (i == 1) ? 0x50u : 72u + rng_below(r, 184), 2);
        put(s, tmp, 2);
        n = rng_below(r, 12);
        rng_fill(r, tmp, n);
        put(s, tmp, n);
        break;
    case 5: /* a false start: a frame cut short, before its CRC (cut after
             * the CRC's first byte, it is intact whenever the next byte
             * equals the CRC's second: 1 in 256) */
        n = random_frame(r, dir, tmp);
        put(s, tmp, 1u + rng_below(r, (uint32_t)n - 2u));
        break;
    case 6: /* a whole frame with one bit flipped */
        n = random_frame(r, dir, tmp);
        i = rng_below(r, (uint32_t)n * 8u);
        tmp[i / 8u] ^= (uint8_t)(1u << (i % 8u));
        put(s, tmp, n);
        break;
    case 7: /* a frame of the other direction */
        n = random_frame(r, (dir == XF_DIR_HOST) ? XF_DIR_GCU : XF_DIR_HOST, tmp);
        put(s, tmp, n);
        break;
    default: /* a frame hidden behind a nested pair of false candidates */
        put1(s, h0);
        put1(s, h1);
        put1(s, 0x50);
        put1(s, 0x00);
        put1(s, h0);
        put1(s, h1);
        put1(s, 0x4C);
        put1(s, 0x00);
        break;
    }
}

static void build_stream(stream *s, test_rng *r, xf_direction dir, size_t frames)
{
    size_t i, k;
    uint8_t f[256];
    for (i = 0; i < frames; i++) {
        size_t junk = (rng_below(r, 3) == 0) ? 0 : rng_below(r, 4);
        for (k = 0; k < junk; k++) {
            put_junk(s, r, dir);
        }
        put_frame(s, f, random_frame(r, dir, f));
    }
    /* Enough trailing bytes (with no header byte) for any pending bogus
     * length to complete and fail, so everything is decided at the end. */
    for (k = 0; k < 300; k++) {
        put1(s, 0x00);
    }
}

/* ---- against the reference model (parser_ref.h) ---------------------------- */

static void model_run(const stream *s, xf_direction dir, pr_model *m)
{
    assert_int_equal(pr_run(s->buf, s->len, dir, XF_PARSER_SLOTS, XF_PACKET_MAX_LEN, 0, m), 0);
}

/* Every frame the harness collected is the model's, in order. */
void check_output(const harness *h, const stream *s, const pr_model *m)
{
    size_t i, at = 0;
    assert_int_equal(h->nframes, m->nframes);
    for (i = 0; i < h->nframes; i++) {
        assert_int_equal(h->lens[i], m->frames[i].len);
        assert_memory_equal(h->out + at, s->buf + m->frames[i].start, m->frames[i].len);
        at += h->lens[i];
    }
}

/* A GCU harness that compares with the model of s after every call. */
static void harness_model(harness *h, pr_model *m, const stream *s)
{
    model_run(s, XF_DIR_GCU, m);
    harness_init(h, XF_DIR_GCU);
    h->model = m;
    h->base = s->buf;
}

/* Feed s's bytes [from, to) in chunks of c. */
void feed_chunks(harness *h, const stream *s, size_t from, size_t to, size_t c)
{
    size_t i;
    for (i = from; i < to; i += c) {
        harness_feed(h, s->buf + i, (i + c <= to) ? c : to - i);
    }
}

/* A GCU harness on s, fed in chunks of c, compared with the model after
 * every call and at the end. */
void feed_checked(harness *h, pr_model *m, const stream *s, size_t c)
{
    harness_model(h, m, s);
    feed_chunks(h, s, 0, s->len, c);
    check_output(h, s, m);
}

/* Build a stream from @p seed; the model must return every frame the
 * generator meant to send, except at most one per candidate given up (with
 * few slots, junk headers can crowd a meant frame out: the documented
 * loss). Junk can also, by chance, form an intact frame that swallows a
 * meant one (about 1 in 65536): the stream is then rebuilt from the next
 * seed. */
void build_clean_stream(stream *s, pr_model *m, test_rng *r, uint64_t seed, xf_direction dir, size_t frames)
{
    int attempt;
    for (attempt = 0; attempt < 20; attempt++, seed += 0x9E3779B9ull) {
        size_t i, k, lost = 0;
        s->len = 0;
        s->nframes = 0;
        rng_seed(r, seed);
        build_stream(s, r, dir, frames);
        model_run(s, dir, m);
        for (i = 0, k = 0; i < s->nframes; i++) {
            while (k < m->nframes && m->frames[k].start < s->foff[i]) {
                k++;
            }
            lost += !(k < m->nframes && m->frames[k].start == s->foff[i] && m->frames[k].len == s->flen[i]);
        }
        if (lost <= m->final.given_up) {
            return;
        }
        print_message("seed %llu: %zu meant frames lost, %u candidates given up: next seed\n", (unsigned long long)seed,
                      lost, m->final.given_up);
        pr_free(m);
    }
    fail_msg("no clean stream in 20 seeds: the generator is broken");
}
