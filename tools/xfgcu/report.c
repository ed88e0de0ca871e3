/*
 * report.c - the program's one-line messages on stderr (cli.h): its own, and those of the text
 * layer's error context (text_err.h), with the program's hint where the layer gives none.
 */
#include <stdarg.h>
#include <stdio.h>

#include "cli.h"

/* Text on stderr with its control characters escaped (\n, \t, \r, \xHH): a message that
 * echoes the user's input stays one line, whatever the input holds. */
static void put_escaped(const char *text)
{
    const unsigned char *p = (const unsigned char *)text;
    for (; *p != '\0'; p++) {
        if (*p >= 0x20u && *p != 0x7Fu) {
            fputc(*p, stderr);
        } else if (*p == '\n' || *p == '\t' || *p == '\r') {
            fprintf(stderr, "\\%c", *p == '\n' ? 'n' : *p == '\t' ? 't' : 'r');
        } else {
            fprintf(stderr, "\\x%02X", (unsigned)*p);
        }
    }
}

int cli_report(int code, const char *where, const char *fmt, ...)
{
    char text[2048];
    int n;
    va_list ap;
    fflush(stdout); /* what was printed before the failure comes first */
    va_start(ap, fmt);
    n = vsnprintf(text, sizeof(text), fmt, ap);
    va_end(ap);
    fputs("xfgcu: ", stderr);
    if (where != NULL) {
        put_escaped(where);
        fputs(": ", stderr);
    }
    put_escaped(n >= 0 ? text : fmt);
    if (n >= (int)sizeof(text)) {
        fputs("...", stderr); /* said so, not cut silently */
    }
    fputc('\n', stderr);
    return code;
}

void cli_text_notes(const text_err *e)
{
    const char *p = e->notes;
    while (*p != '\0') {
        int n = 0;
        while (p[n] != '\0' && p[n] != '\n') {
            n++;
        }
        cli_note("%.*s", n, p);
        p += n + (p[n] == '\n');
    }
}

int cli_text_fail(const text_err *e, const char *hint)
{
    cli_text_notes(e);
    if (hint != NULL) {
        return cli_fail("%s (see 'xfgcu %s --help')", e->message, hint);
    }
    return cli_fail("%s", e->message);
}
