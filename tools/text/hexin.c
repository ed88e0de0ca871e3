/*
 * hexin.c - hex text to bytes (see hexin.h for the accepted layout).
 *
 * A character-at-a-time state machine, so that a group split across two
 * reads of stdin is handled like any other and every fault keeps its exact
 * position.
 */
#include "hexin.h"

#include <stdio.h>
#include <string.h>

static int hex_value(unsigned char c)
{
    if (c >= '0' && c <= '9') {
        return c - '0';
    }
    if (c >= 'a' && c <= 'f') {
        return c - 'a' + 10;
    }
    if (c >= 'A' && c <= 'F') {
        return c - 'A' + 10;
    }
    return -1;
}

static int is_separator(unsigned char c)
{
    return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f' || c == ':' || c == ',';
}

void hex_reader_init(hex_reader *r)
{
    memset(r, 0, sizeof(*r));
    r->line = 1;
    r->column = 1;
}

static int fault_at_group(const hex_reader *r, hex_fault_kind kind, hex_fault *fault)
{
    fault->kind = kind;
    fault->offset = r->group_offset;
    fault->line = r->group_line;
    fault->column = r->group_column;
    fault->ch = 0;
    return -1;
}

/* A separator or the end of the text closes the current group. */
static int close_group(hex_reader *r, hex_fault *fault)
{
    if (!r->in_group) {
        return 0;
    }
    if (r->after_prefix) {
        return fault_at_group(r, HEX_EMPTY_PREFIX, fault);
    }
    if ((r->digits & 1u) != 0u) {
        return fault_at_group(r, HEX_ODD_DIGITS, fault);
    }
    r->in_group = 0;
    return 0;
}

static void open_group(hex_reader *r)
{
    r->in_group = 1;
    r->digits = 0;
    r->lone_zero = 0;
    r->after_prefix = 0;
    r->group_offset = r->offset;
    r->group_line = r->line;
    r->group_column = r->column;
}

/* One character; returns 1 and sets *byte when it completes a byte, 0 when not, -1 on a fault. */
static int step(hex_reader *r, unsigned char c, uint8_t *byte, hex_fault *fault)
{
    int v = hex_value(c);
    if (is_separator(c)) {
        return close_group(r, fault);
    }
    if ((c == 'x' || c == 'X') && r->in_group && r->lone_zero) {
        r->digits = 0; /* "0x": the 0 was a prefix, not half a byte */
        r->lone_zero = 0;
        r->after_prefix = 1;
        return 0;
    }
    if (v < 0) {
        fault->kind = HEX_BAD_CHAR;
        fault->offset = r->offset;
        fault->line = r->line;
        fault->column = r->column;
        fault->ch = c;
        return -1;
    }
    if (!r->in_group) {
        open_group(r);
        r->lone_zero = (c == '0');
    } else {
        r->lone_zero = 0;
    }
    r->after_prefix = 0;
    r->digits++;
    if ((r->digits & 1u) != 0u) {
        r->nibble = (unsigned)v;
        return 0;
    }
    *byte = (uint8_t)((r->nibble << 4) | (unsigned)v);
    return 1;
}

static void advance(hex_reader *r, unsigned char c)
{
    r->offset++;
    if (c == '\n') {
        r->line++;
        r->column = 1;
    } else {
        r->column++;
    }
}

int hex_reader_feed(hex_reader *r, const char *text, size_t len, uint8_t *out, size_t cap, size_t *produced,
                    hex_fault *fault)
{
    size_t i;
    for (i = 0; i < len; i++) {
        unsigned char c = (unsigned char)text[i];
        uint8_t byte = 0;
        int got = step(r, c, &byte, fault);
        if (got < 0) {
            return -1;
        }
        if (got > 0) {
            if (*produced < cap) {
                out[*produced] = byte;
            }
            (*produced)++;
        }
        advance(r, c);
    }
    return 0;
}

int hex_reader_finish(hex_reader *r, hex_fault *fault) { return close_group(r, fault); }

void hex_fault_text(const hex_fault *fault, char *buf, size_t cap)
{
    switch (fault->kind) {
    case HEX_BAD_CHAR:
        if (fault->ch >= 0x21u && fault->ch < 0x7Fu) {
            snprintf(buf, cap, "'%c' is not a hex digit", (char)fault->ch);
        } else {
            snprintf(buf, cap, "byte 0x%02X is not a hex digit", (unsigned)fault->ch);
        }
        break;
    case HEX_ODD_DIGITS: snprintf(buf, cap, "odd number of hex digits in the group starting here"); break;
    case HEX_EMPTY_PREFIX: snprintf(buf, cap, "'0x' without hex digits"); break;
    default: snprintf(buf, cap, "no fault"); break;
    }
}

int hex_parse_string(const char *text, uint8_t *out, size_t cap, size_t *n, hex_fault *fault)
{
    hex_reader r;
    hex_reader_init(&r);
    *n = 0;
    if (hex_reader_feed(&r, text, strlen(text), out, cap, n, fault) != 0) {
        return -1;
    }
    return hex_reader_finish(&r, fault);
}

void hex_format(const uint8_t *bytes, size_t n, char sep, char *buf)
{
    static const char digits[] = "0123456789ABCDEF";
    size_t i;
    char *p = buf;
    for (i = 0; i < n; i++) {
        if (i > 0u && sep != '\0') {
            *p++ = sep;
        }
        *p++ = digits[bytes[i] >> 4];
        *p++ = digits[bytes[i] & 0x0Fu];
    }
    *p = '\0';
}
