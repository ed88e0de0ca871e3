/*
 * text_err.c - the error context (text_err.h) and number parsing.
 */
#include "text_err.h"

#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void text_err_init(text_err *e) { memset(e, 0, sizeof(*e)); }

/* @p text into @p out (capacity @p cap) with its control characters escaped; "..." when it does
 * not fit, so that nothing is cut silently. */
static void escape_into(char *out, size_t cap, const char *text)
{
    const unsigned char *p = (const unsigned char *)text;
    size_t n = strlen(out);
    for (; *p != '\0' && n + 8u < cap; p++) {
        if (*p >= 0x20u && *p != 0x7Fu) {
            out[n++] = (char)*p;
        } else if (*p == '\n' || *p == '\t' || *p == '\r') {
            out[n++] = '\\';
            out[n++] = (*p == '\n') ? 'n' : (*p == '\t') ? 't' : 'r';
        } else {
            n += (size_t)snprintf(out + n, cap - n, "\\x%02X", (unsigned)*p);
        }
    }
    out[n] = '\0';
    if (*p != '\0') {
        snprintf(out + (n < cap - 4u ? n : cap - 4u), 4u, "...");
    }
}

int text_fail(text_err *e, const char *where, const char *fmt, ...)
{
    char text[2048];
    va_list ap;
    if (e == NULL || e->failed) {
        return TEXT_BAD;
    }
    va_start(ap, fmt);
    if (vsnprintf(text, sizeof(text), fmt, ap) >= (int)sizeof(text)) {
        memcpy(text + sizeof(text) - 4u, "...", 4u); /* said so, not cut silently */
    }
    va_end(ap);
    e->failed = 1;
    e->message[0] = '\0';
    if (where != NULL) {
        escape_into(e->message, sizeof(e->message), where);
        escape_into(e->message, sizeof(e->message), ": ");
    }
    escape_into(e->message, sizeof(e->message), text);
    return TEXT_BAD;
}

void text_note(text_err *e, const char *fmt, ...)
{
    char text[512];
    size_t used;
    va_list ap;
    if (e == NULL) {
        return;
    }
    va_start(ap, fmt);
    (void)vsnprintf(text, sizeof(text), fmt, ap);
    va_end(ap);
    used = strlen(e->notes);
    if (used + strlen(text) + 2u > sizeof(e->notes)) {
        if (used + 5u <= sizeof(e->notes) && (used < 4u || strcmp(e->notes + used - 4u, "...\n") != 0)) {
            memcpy(e->notes + used, "...\n", 5u); /* the list goes on: said so */
        }
        return;
    }
    escape_into(e->notes, sizeof(e->notes) - 1u, text);
    used = strlen(e->notes);
    e->notes[used] = '\n';
    e->notes[used + 1u] = '\0';
}

int text_parse_int(const char *s, long long *out)
{
    const char *p = s;
    int neg = 0, base = 10;
    char *end = NULL;
    unsigned long long u;
    if (*p == '+' || *p == '-') {
        neg = (*p == '-');
        p++;
    }
    if (p[0] == '0' && (p[1] == 'x' || p[1] == 'X')) {
        base = 16;
        p += 2;
    }
    /* strtoull would also take spaces and a second sign: only digits may follow */
    if (!((*p >= '0' && *p <= '9') || (base == 16 && ((*p >= 'a' && *p <= 'f') || (*p >= 'A' && *p <= 'F'))))) {
        return -1;
    }
    errno = 0;
    u = strtoull(p, &end, base);
    if (errno != 0 || *end != '\0') {
        return -1;
    }
    if (neg) {
        if (u > (unsigned long long)LLONG_MAX + 1u) {
            return -1;
        }
        *out = (u == (unsigned long long)LLONG_MAX + 1u) ? LLONG_MIN : -(long long)u;
    } else {
        if (u > (unsigned long long)LLONG_MAX) {
            return -1;
        }
        *out = (long long)u;
    }
    return 0;
}

int text_parse_real(const char *s, double *out)
{
    char *end = NULL;
    double v;
    if (!((*s >= '0' && *s <= '9') || *s == '-' || *s == '+' || *s == '.')) {
        return -1; /* no leading space, no "nan" or "inf" */
    }
    errno = 0;
    v = strtod(s, &end);
    if (errno != 0 || end == s || *end != '\0' || !isfinite(v)) {
        return -1;
    }
    *out = v;
    return 0;
}
