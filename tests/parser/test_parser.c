/*
 * test_parser.c - xf_parser.h, the streaming parser: the program.
 *
 * The central property: fed a stream in any chunking, the parser returns
 * every intact frame, byte-identical and in order, whatever noise, false
 * starts, stray header bytes and bogus lengths lie between them; its
 * counters only grow and always satisfy
 *     bytes_in == bytes of returned frames + bytes_skipped + pending.
 *
 * The tests live by concern in this folder (parser_test.h lists them):
 * calls.c (the calls on exact cases), candidates.c (the rules on crafted
 * candidates), streams.c (random streams against the reference model), on
 * the rig of harness.c. This file runs them all; it is the program's one
 * translation unit that defines XF_IMPLEMENTATION, so the parser is compiled
 * here under the build's options (XF_PARSER_SLOTS, XF_PACKET_MAX_LEN, ...),
 * which tests/CMakeLists.txt gives every file of the program alike.
 */
#define XF_IMPLEMENTATION
#include "parser_test.h"

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_appendix_one_byte_at_a_time),
        cmocka_unit_test(test_consumed_stops_at_frame),
        cmocka_unit_test(test_consumed_after_false_candidate),
        cmocka_unit_test(test_flush),
        cmocka_unit_test(test_frame_length_field),
        cmocka_unit_test(test_direction_filter),
        cmocka_unit_test(test_bad_lengths_do_not_delay),
        cmocka_unit_test(test_nested_false_candidates),
        cmocka_unit_test(test_frame_after_crc_failure),
        cmocka_unit_test(test_bogus_length_does_not_delay),
        cmocka_unit_test(test_bogus_lengths_and_ring_wrap),
        cmocka_unit_test(test_max_length_frame),
        cmocka_unit_test(test_reset),
        cmocka_unit_test(test_adversarial_lengths),
        cmocka_unit_test(test_crafted_storms),
        cmocka_unit_test(test_slots_edges),
        cmocka_unit_test(test_parser_args),
        cmocka_unit_test(test_random_stream_whole),
        cmocka_unit_test(test_random_stream_byte_at_a_time),
        cmocka_unit_test(test_random_stream_random_chunks),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
