/*
 * hexin.h - hex text to bytes, for packets given as arguments, on stdin,
 * and in JSON strings.
 *
 * Accepted: hex digits in groups separated by white space, ':' or ','; a
 * group may start with 0x. Each group must hold whole bytes (an even number
 * of digits): "A8E5 4800", "a8:e5:48:00", "0xA8, 0xE5" are the same bytes.
 * The reader is incremental so that stdin can be read in chunks, and it
 * remembers where each fault is (offset, line, column).
 */
#ifndef XFGCU_HEXIN_H
#define XFGCU_HEXIN_H

#include <stddef.h>
#include <stdint.h>

typedef enum hex_fault_kind {
    HEX_OK = 0,
    HEX_BAD_CHAR,    /**< a character that is neither a hex digit nor a separator */
    HEX_ODD_DIGITS,  /**< a group with an odd number of digits: half a byte */
    HEX_EMPTY_PREFIX /**< "0x" followed by no digit */
} hex_fault_kind;

/** Where and what went wrong. Offsets are 0-based, line and column 1-based. */
typedef struct hex_fault {
    hex_fault_kind kind;
    size_t offset;
    size_t line;
    size_t column;
    unsigned char ch; /**< HEX_BAD_CHAR: the character */
} hex_fault;

/** Incremental reader state; zero it with hex_reader_init(). */
typedef struct hex_reader {
    size_t offset, line, column;                   /* position of the next character */
    size_t group_offset, group_line, group_column; /* where the current group started */
    size_t digits;                                 /* digits of the current group, after any 0x */
    unsigned nibble;                               /* high nibble waiting for its partner (digits odd) */
    int in_group;
    int lone_zero;    /* the group so far is the single digit 0: "x" may follow */
    int after_prefix; /* the group so far is "0x" */
} hex_reader;

void hex_reader_init(hex_reader *r);

/**
 * Convert @p len characters. Bytes go to @p out while fewer than @p cap were
 * written; *produced counts every byte converted (even past @p cap).
 * @return 0, or -1 with *fault set (conversion stops there).
 */
int hex_reader_feed(hex_reader *r, const char *text, size_t len, uint8_t *out, size_t cap, size_t *produced,
                    hex_fault *fault);

/** End of text: the last group must be complete. @return 0 or -1 with *fault set. */
int hex_reader_finish(hex_reader *r, hex_fault *fault);

/** A short description of @p fault, e.g. "'g' is not a hex digit". */
void hex_fault_text(const hex_fault *fault, char *buf, size_t cap);

/**
 * Convert a whole string (an argument, a JSON value) into at most @p cap
 * bytes; *n gets the number of bytes the text holds (may exceed @p cap).
 */
int hex_parse_string(const char *text, uint8_t *out, size_t cap, size_t *n, hex_fault *fault);

/** Format bytes as upper-case hex; @p sep (0 for none) between bytes. @p buf needs 3 * n + 1 bytes. */
void hex_format(const uint8_t *bytes, size_t n, char sep, char *buf);

#endif /* XFGCU_HEXIN_H */
