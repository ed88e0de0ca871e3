/*
 * probe_ask.h - probe's open questions: the ones of docs/protocol.md section 12 that a real gimbal
 * can answer without moving or changing a setting, asked with packets sent outside the client (it
 * is paused meanwhile: each exchange is shorter than the link's stale time), and the others listed
 * with the reason they are not asked.
 *
 * Asked: does the GCU answer packets of the version it did not answer first (question 7); does
 * every reply to a repeated order carry its execution state (8: zoom stop, which stops a zoom that
 * is not running, three times in a row); is the null's reply 72 bytes or 73 (9, from the client's
 * nulls); how it reads a parameter of the wrong length (1: the same zoom stop with two bytes); the
 * byte order of the pod status word (13, as the client decided it).
 */
#ifndef XFGCU_PROBE_ASK_H
#define XFGCU_PROBE_ASK_H

#include <jansson.h>
#include <stdint.h>

#include "online.h"

#define ASK_QUESTIONS 14 /* the rows of docs/protocol.md section 12 */

/** One question: its row in docs/protocol.md section 12, and what the gimbal answered or why not asked. */
typedef struct ask_answer {
    uint8_t number;    /* the row */
    const char *title; /* a few words */
    int asked;         /* 1: asked (answer is the finding); 0: not asked (answer is why) */
    char answer[240];  /* one line */
    json_t *detail;    /* the figures behind the answer (an object), or NULL */
} ask_answer;

typedef struct ask_report {
    ask_answer q[ASK_QUESTIONS];
    unsigned null_replies[2]; /* replies to the client's nulls seen so far: [0] 72 bytes, [1] with a state */
} ask_report;

/** Every question not asked yet ("the probe stopped before it", or why it never is). */
void ask_init(ask_report *r);

/** Count a GCU packet the client received, for the null's reply (question 9). */
void ask_observe(ask_report *r, const uint8_t *data, size_t len);

/**
 * Ask the questions that can be asked on the link (the client settles first), in the version the GCU
 * answers in. Stops early, leaving the rest as ask_init() left them, when @p stop() says so.
 */
void ask_questions(online *o, ask_report *r, int (*stop)(void *user), void *user);

/** The answers as text lines, after a heading. */
void ask_print(const ask_report *r, FILE *out);
/** The answers as a JSON array (the details are taken: call once); NULL if out of memory. */
json_t *ask_json(ask_report *r);
/** Free what ask_questions() allocated (the details not taken by ask_json()). */
void ask_free(ask_report *r);

#endif /* XFGCU_PROBE_ASK_H */
