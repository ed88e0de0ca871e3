/*
 * parser_test.h - the rig shared by the parser's tests (tests/parser/), and
 * the list of their test functions.
 *
 * The harness (harness.c) feeds the parser, collects every frame it returns
 * and checks its counters after every call: they only grow and always satisfy
 *     bytes_in == bytes of returned frames + bytes_skipped + pending;
 * given a reference model (parser_ref.h, the documented rules written
 * naively), it also checks that the counters and pending bytes are the
 * model's after every call and that each frame is the model's next one,
 * returned by the call that feeds its last byte (no added latency). The
 * stream builder writes intact frames and junk between them (noise, false
 * starts, stray header bytes, bogus lengths).
 *
 * One program per build option (tests/CMakeLists.txt) is built from every
 * file of this folder; test_parser.c holds main() and is the program's one
 * translation unit that defines XF_IMPLEMENTATION.
 */
#ifndef XFGCU_PARSER_TEST_H
#define XFGCU_PARSER_TEST_H

#include "../test_util.h"
#include "../parser_ref.h"

/* ---- the harness ------------------------------------------------------------ */

typedef struct harness {
    xf_parser p;
    xf_direction dir;
    xf_parser_stats last;
    uint64_t frame_bytes;
    size_t nframes;
    const pr_model *model; /* when set: the counters after every call and each frame's end are the model's */
    const uint8_t *base;   /* the stream the model ran on (fed in order from base) */
    uint8_t *out;          /* the frames returned, concatenated */
    size_t out_len;
    size_t *lens;
} harness;

void harness_init(harness *h, xf_direction dir);
void harness_free(harness *h);
/* The counters' identities, and the model's counters when h->model is set. */
void check_counters(harness *h);
/* Feed one chunk, draining every frame it completes; returns the number of frames. */
size_t harness_feed(harness *h, const uint8_t *data, size_t len);

/* ---- the stream builder ------------------------------------------------------- */

typedef struct stream {
    uint8_t *buf;
    size_t len;
    size_t nframes; /* frames the generator meant to send */
    size_t *foff;
    size_t *flen;
} stream;

void stream_init(stream *s);
void stream_free(stream *s);
void put(stream *s, const uint8_t *p, size_t n);
void put1(stream *s, uint8_t b);
/* A valid frame of 72 + params_len bytes in out: random content, the header, length and CRC. */
size_t make_frame(test_rng *r, xf_direction dir, size_t params_len, uint8_t *out);
/* A valid frame of a random length, short ones most often. */
size_t random_frame(test_rng *r, xf_direction dir, uint8_t *out);

/* ---- against the reference model (parser_ref.h) ---------------------------------- */

/* Every frame the harness collected is the model's, in order. */
void check_output(const harness *h, const stream *s, const pr_model *m);
/* Feed s's bytes [from, to) in chunks of c. */
void feed_chunks(harness *h, const stream *s, size_t from, size_t to, size_t c);
/* A GCU harness on s, fed in chunks of c, compared with the model after every call and at the end. */
void feed_checked(harness *h, pr_model *m, const stream *s, size_t c);
/* A random stream of frames and junk from seed whose meant frames the model returns (see harness.c). */
void build_clean_stream(stream *s, pr_model *m, test_rng *r, uint64_t seed, xf_direction dir, size_t frames);

/* A case whose frame overlaps n - 1 false candidates needs n slots; builds
 * with fewer (XF_PARSER_SLOTS=1) give it up by design, and say so: their
 * behaviour is checked against the model by the random streams. */
#define NEED_SLOTS(n)                                                                                                  \
    do {                                                                                                               \
        if (XF_PARSER_SLOTS < (n)) {                                                                                   \
            print_message("needs %d slots, this build has %d: skipped (the model tests cover it)\n", (n),              \
                          XF_PARSER_SLOTS);                                                                            \
            skip();                                                                                                    \
        }                                                                                                              \
    } while (0)

/* ---- the tests, by file (test_parser.c's main runs them all) ---------------------- */

/* calls.c: the calls' contract on small, exact cases */
void test_appendix_one_byte_at_a_time(void **state);
void test_consumed_stops_at_frame(void **state);
void test_consumed_after_false_candidate(void **state);
void test_flush(void **state);
void test_frame_length_field(void **state);
void test_direction_filter(void **state);
void test_reset(void **state);
void test_parser_args(void **state);

/* candidates.c: the rules on crafted candidates (bad and bogus lengths, nesting, slots) */
void test_bad_lengths_do_not_delay(void **state);
void test_nested_false_candidates(void **state);
void test_frame_after_crc_failure(void **state);
void test_bogus_length_does_not_delay(void **state);
void test_bogus_lengths_and_ring_wrap(void **state);
void test_max_length_frame(void **state);
void test_adversarial_lengths(void **state);
void test_crafted_storms(void **state);
void test_slots_edges(void **state);

/* streams.c: random streams, compared with the model after every call */
void test_random_stream_whole(void **state);
void test_random_stream_byte_at_a_time(void **state);
void test_random_stream_random_chunks(void **state);

#endif
