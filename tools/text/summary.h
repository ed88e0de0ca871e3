/*
 * summary.h - the last word on a stream that decode or replay read: its packets, the bytes in none,
 * the CRC errors and the frames the parsers gave up (xf_parser_stats.given_up), as the text line and
 * as the JSON summary line ({"summary": {...}}: a line without "direction", which encode skips).
 */
#ifndef XFGCU_SUMMARY_H
#define XFGCU_SUMMARY_H

#include <jansson.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

/** What a stream held. */
typedef struct text_summary {
    size_t host_packets;    /**< valid host packets */
    size_t gcu_packets;     /**< valid GCU packets */
    uint64_t bytes_skipped; /**< bytes in no valid packet */
    uint64_t crc_errors;    /**< candidates whose CRC failed */
    uint64_t given_up;      /**< times a parser gave up looking at headers (xf_parser_stats.given_up) */
} text_summary;

/**
 * Print the summary on @p out: as the text line "12 packets: 6 host to GCU, 6 GCU to host; 3 bytes
 * skipped, 0 CRC errors, 0 frames given up", or with @p json as the line {"summary": {"packets",
 * "host_packets", "gcu_packets", "bytes_skipped", "crc_errors", "given_up"}}.
 * @return TEXT_OK, or TEXT_BAD when out of memory (nothing printed)
 */
int summary_print(const text_summary *s, int json, FILE *out);

/** Is @p obj a line of the program's JSON that is no packet: a summary, or an event (monitor, sim)? */
int summary_not_packet(const json_t *obj);

#endif /* XFGCU_SUMMARY_H */
