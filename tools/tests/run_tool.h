/*
 * run_tool.h - run the built xfgcu binary (path: XFGCU_EXE) with given
 * arguments and stdin, and collect its exit status, stdout and stderr.
 */
#ifndef XFGCU_RUN_TOOL_H
#define XFGCU_RUN_TOOL_H

#include <jansson.h>
#include <stddef.h>
#include <stdint.h>

typedef struct tool_result {
    int status; /* exit code, or 128 + signal */
    char *out;  /* NUL-terminated */
    size_t out_len;
    char *err; /* NUL-terminated */
    size_t err_len;
} tool_result;

/** Run xfgcu with @p argc arguments (argv[0] not included) and @p input on stdin (NULL: empty). */
tool_result run_tool_argv(int argc, const char *const *args, const char *input);
/** The same with @p input_len bytes of @p input on stdin, NUL bytes included. */
tool_result run_tool_bytes(int argc, const char *const *args, const char *input, size_t input_len);
/** Same with the arguments listed, NULL-terminated. */
tool_result run_tool(const char *input, ...);
void tool_result_free(tool_result *r);

/**
 * The argv that posix_spawn() takes (char *const[], NULL-terminated): XFGCU_EXE then the @p argc
 * strings of @p args, copied into one allocation with the pointers, so that no const is cast
 * away. The caller free()s it.
 */
char **spawn_argv(int argc, const char *const *args);

/**
 * A local port bound on 127.0.0.1 (any free one; @p type SOCK_DGRAM or SOCK_STREAM), its number
 * written as text into @p port. The socket is returned, bound and not listening: held open, it
 * refuses connections or swallows datagrams; closed, the port is free for a program to take.
 */
int hold_port(int type, char *port, size_t cap);

/** Number of lines (newline-terminated) in @p text. */
size_t count_lines(const char *text);
/**
 * Assert the usual failure: @p status, nothing on stdout, and one stderr
 * line starting "xfgcu: " that contains every needle (NULL-terminated list).
 */
void assert_failure(const tool_result *r, int status, ...);

/**
 * The summary line that ends the JSON of decode (of a stream) and replay: checked to be one
 * ({"summary": {...}}, no "direction"), cut from r->out, and its inner object returned (the
 * caller frees it).
 */
json_t *cut_summary(tool_result *r);
/** The lines of @p text (JSON Lines) that are packets (have "direction"), not events or summaries. */
size_t count_packet_lines(const char *text);

/** The JSON object on the first line of @p text (fails the test if it is not JSON). */
json_t *parse_line(const char *text);
/** The integer under @p key (fails the test if there is none). */
json_int_t int_key(const json_t *obj, const char *key);
/** The number (integer or not) under @p key (fails the test if there is none). */
double num_key(const json_t *obj, const char *key);
/** The string under @p key (fails the test if there is none). */
const char *str_key(const json_t *obj, const char *key);

/** Uppercase hex with single spaces and a newline, as `encode` prints. */
void hex_line(const uint8_t *bytes, size_t n, char *buf);
/** Fix the length field and CRC of a packet of @p len bytes. */
void seal_packet(uint8_t *bytes, size_t len);

/** The appendix-1 packet of the vendor document (docs/protocol.md section 9.1). */
extern const uint8_t appendix1[72];
#define APPENDIX1_HEX                                                                                                  \
    "A8 E5 48 00 01 00 00 64 00 9C FF 05 94 FB 65 00 C0 5D 70 00 90 FF 70 00 40 80 C0 F7 40 80 01 00 00 00 00 00 00 "  \
    "01 24 F2 DF 65 16 EE AA 16 A3 A0 00 00 13 B0 0C 06 15 E6 08 58 2F 00 00 00 00 00 00 00 00 00 00 00 E9 D4"

#endif /* XFGCU_RUN_TOOL_H */
