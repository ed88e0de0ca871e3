/*
 * text_err.h - the error context of the text layer (xfgcu::text): what went wrong, in one line,
 * and the notes (warnings) met on the way, kept in the caller's struct. The layer has no
 * process-wide state: two threads with two contexts never meet.
 *
 * Messages say what is wrong and where ("encode zoom-to: --factor 0.5 is out of range: ..."),
 * and never how to ask for help: a program adds its own hint ("see 'xfgcu encode --help'"), a
 * binding its own wording. Every function of the layer that can fail returns TEXT_OK or
 * TEXT_BAD, and on TEXT_BAD the context holds the message.
 */
#ifndef XFGCU_TEXT_ERR_H
#define XFGCU_TEXT_ERR_H

#include <stddef.h>

#if defined(__GNUC__) || defined(__clang__)
#define TEXT_PRINTF(fmt, args) __attribute__((format(printf, fmt, args)))
#else
#define TEXT_PRINTF(fmt, args)
#endif

#define TEXT_OK  0    /**< success */
#define TEXT_BAD (-1) /**< bad input: the context says why */

/** What went wrong, and the notes: zero it with text_err_init(). */
typedef struct text_err {
    int failed;         /**< 1 once a failure is recorded (the first one is kept: it is the cause) */
    char message[1024]; /**< the failure: "[WHERE: ]what", one line, no newline */
    char notes[1024];   /**< the notes, each ended by '\n'; a note that does not fit ends the list with "..." */
} text_err;

/** An empty context. */
void text_err_init(text_err *e);

/**
 * Record a failure (the first one only: a later one is a consequence). Control characters of the
 * text are escaped (\n, \t, \xHH), so the message stays one line whatever input it quotes.
 * @param e      the context (may be NULL: nothing is recorded)
 * @param where  the prefix ("encode zoom-to", "stdin line 3"), or NULL
 * @return TEXT_BAD, so that a caller can `return text_fail(...)`
 */
int text_fail(text_err *e, const char *where, const char *fmt, ...) TEXT_PRINTF(3, 4);

/** Record a note: a warning that does not stop anything. */
void text_note(text_err *e, const char *fmt, ...) TEXT_PRINTF(2, 3);

/**
 * Parse a whole string as an integer: decimal, or hex with a 0x prefix, optional sign. Leading
 * zeros are decimal (never octal); no space, no second sign.
 * @return 0, or -1 if @p s is not an integer or overflows
 */
int text_parse_int(const char *s, long long *out);
/** Parse a whole string as a finite decimal number (no "nan", no "inf", no space). @return 0 or -1. */
int text_parse_real(const char *s, double *out);

#endif /* XFGCU_TEXT_ERR_H */
