/*
 * probe_ask.c - probe's open questions (probe_ask.h).
 *
 * An exchange is a few packets written on the client's link while the client is paused: a quiet
 * moment first, so that the replies to the client's last packets are read and dropped, then the
 * question's packets one packet period apart, then a null (the once-rule: the GCU's next packet of
 * the order is a new command), then a quiet moment again, whose replies still count. Nothing of
 * it is a command of the client's, so no result of the client's can be taken from it, and the
 * client resumes where it was, with nulls.
 */
#include "probe_ask.h"

#include <stdarg.h>
#include <string.h>

#define REPEATS 3u /* packets of a question's order in a row */

/* The questions of docs/protocol.md section 12, by row; why each one that is never asked is not. */
static const struct {
    const char *title;
    const char *not_asked;
} open_rows[ASK_QUESTIONS] = {
    {"a parameter of the wrong length", NULL},
    {"a parameter outside the range of the GCU's version",
     "needs palette or pip beyond a version's range: they change a setting the GCU does not report"},
    {"record with a parameter other than 0x01", "record starts or stops a video"},
    {"palette or thermometry with another camera mask than 0x02",
     "palette changes the thermal palette, which the GCU does not report: it could not be set back"},
    {"an order no document defines", "an order no document defines may do anything on an unknown firmware"},
    {"a command read in the GCU's version or the host's",
     "needs an order whose meaning differs by version (pip, palette, osd): each changes a setting"},
    {"does it answer both version bytes", NULL},
    {"the execution state in every reply to a repeated order", NULL},
    {"the null's reply: 72 bytes or 73", NULL},
    {"desired angles held while ctrl_valid is clear", "moves the gimbal"},
    {"a mode order's control quantities: read in the old mode or the new",
     "a reply does not tell which mode read the packet's control quantities"},
    {"the main screen's camera in each picture-in-picture mode", "needs rates at known zooms: moves the gimbal"},
    {"the byte order of the pod status word", NULL},
    {"the unit of V2.0.6's rate example", "needs a yaw rate in head lock: moves the gimbal"},
};

void ask_observe(ask_report *r, const uint8_t *data, size_t len)
{
    if (data[XF_OFF_ORDER] == XF_ORDER_NULL) {
        r->null_replies[len > XF_PACKET_MIN_LEN]++;
    }
}

/* ---- exchanges ---------------------------------------------------------------------------- */

/* What came back in an exchange. */
typedef struct heard {
    uint8_t order;       /* the question's order */
    unsigned replies;    /* every GCU packet after the first quiet moment */
    unsigned of_order;   /* replies of the question's order */
    unsigned with_state; /* of which with an execution state */
    int state;           /* the first state, -1 before one */
} heard;

static void hear(void *user, const uint8_t *data, size_t len)
{
    heard *h = (heard *)user;
    h->replies++;
    if (data[XF_OFF_ORDER] == h->order) {
        h->of_order++;
        if (len > XF_PACKET_MIN_LEN && h->with_state++ == 0u) {
            h->state = data[XF_OFF_PARAMS];
        }
    }
}

static void drop(void *user, const uint8_t *data, size_t len)
{
    (void)user;
    (void)data;
    (void)len;
}

static uint32_t period_ms(const online *o) { return 1000u / (uint32_t)o->opt->rate_hz; }

/* Long enough for the replies on the way: two packet periods and the reorder bound. */
static uint32_t quiet_ms(const online *o)
{
    return 2u * period_ms(o) + (uint32_t)xf_client_health(&o->client)->reorder_ms;
}

static xf_err send_packet(online *o, uint8_t version, uint8_t order, const uint8_t *params, uint8_t n)
{
    uint8_t buf[XF_PACKET_MAX_LEN];
    size_t len = 0;
    xf_host_packet p;
    xf_host_packet_init(&p, version);
    p.order = order;
    p.params_len = n;
    if (n > 0u) {
        memcpy(p.params, params, n);
    }
    return xf_host_pack(&p, buf, sizeof(buf), &len) == XF_OK ? online_raw_send(o, buf, len) : XF_ERR_ARG;
}

/* REPEATS packets of @p order with its @p n parameter bytes, in @p version, then a null. */
static void exchange(online *o, uint8_t version, uint8_t order, const uint8_t *params, uint8_t n, heard *h)
{
    unsigned i;
    memset(h, 0, sizeof(*h));
    h->order = order;
    h->state = -1;
    (void)online_raw_read(o, quiet_ms(o), drop, NULL);
    for (i = 0; i < REPEATS; i++) {
        (void)send_packet(o, version, order, params, n);
        (void)online_raw_read(o, period_ms(o), hear, h);
    }
    if (order != XF_ORDER_NULL) {
        (void)send_packet(o, version, XF_ORDER_NULL, NULL, 0u);
    }
    (void)online_raw_read(o, quiet_ms(o), hear, h);
    online_linger(o, 3u); /* the client again, for a few packets: its link stays up */
}

/* ---- the questions ------------------------------------------------------------------------- */

static ask_answer *answer(ask_report *r, unsigned number, int asked, const char *fmt, ...)
#if defined(__GNUC__) || defined(__clang__)
    __attribute__((format(printf, 4, 5)))
#endif
    ;

static ask_answer *answer(ask_report *r, unsigned number, int asked, const char *fmt, ...)
{
    ask_answer *a = &r->q[number - 1u];
    va_list ap;
    a->asked = asked;
    va_start(ap, fmt);
    vsnprintf(a->answer, sizeof(a->answer), fmt, ap);
    va_end(ap);
    return a;
}

/* 7: nulls in the version the GCU did not answer first. */
static void ask_versions(online *o, ask_report *r)
{
    uint8_t answered = xf_client_health(&o->client)->version_answered;
    uint8_t other = (answered == XF_PROTOCOL_V2) ? XF_PROTOCOL_V1 : XF_PROTOCOL_V2;
    heard h;
    ask_answer *a;
    exchange(o, other, XF_ORDER_NULL, NULL, 0u, &h);
    if (h.replies > 0u) {
        a = answer(r, 7, 1, "yes: it answers version 1 and version 2 (%u replies to %u nulls of version %u)", h.replies,
                   REPEATS, other);
    } else {
        a = answer(r, 7, 1, "no: it answers version %u only (%u nulls of version %u got no reply)", answered, REPEATS,
                   other);
    }
    a->detail = json_pack("{s:b, s:b}", "answers_version_1", answered == XF_PROTOCOL_V1 || h.replies > 0u,
                          "answers_version_2", answered == XF_PROTOCOL_V2 || h.replies > 0u);
}

/* 8: zoom stop three times in a row (it stops a zoom that is not running: nothing changes). */
static void ask_repeats(online *o, ask_report *r, uint8_t version)
{
    uint8_t camera1 = XF_CAM1;
    heard h;
    ask_answer *a;
    exchange(o, version, XF_ORDER_ZOOM_STOP, &camera1, 1u, &h);
    if (h.of_order == 0u) {
        a = answer(r, 8, 1, "no reply to zoom_stop sent %u times in a row", REPEATS);
    } else if (h.with_state == h.of_order) {
        a = answer(r, 8, 1, "yes: all %u replies to zoom_stop sent %u times in a row carried it", h.of_order, REPEATS);
    } else {
        a = answer(r, 8, 1,
                   "no: %u of %u replies to zoom_stop sent %u times in a row carried it, the others were 72 "
                   "bytes",
                   h.with_state, h.of_order, REPEATS);
    }
    a->detail =
        json_pack("{s:i, s:i, s:i}", "sent", (int)REPEATS, "replies", (int)h.of_order, "with_state", (int)h.with_state);
}

/* 1: zoom stop with two parameter bytes (01 00) instead of one: whatever a GCU reads, it stops a
 * zoom that is not running. */
static void ask_length(online *o, ask_report *r, uint8_t version)
{
    static const uint8_t two[2] = {XF_CAM1, 0x00u};
    heard h;
    ask_answer *a;
    exchange(o, version, XF_ORDER_ZOOM_STOP, two, 2u, &h);
    if (h.state == 0) {
        a = answer(r, 1, 1, "it took zoom_stop with 2 parameter bytes (01 00): state 0x00");
    } else if (h.state > 0) {
        a = answer(r, 1, 1, "it answered zoom_stop with 2 parameter bytes (01 00) with failure: state 0x%02X", h.state);
    } else if (h.of_order > 0u) {
        a = answer(r, 1, 1, "its %u replies to zoom_stop with 2 parameter bytes carried no execution state",
                   h.of_order);
    } else {
        a = answer(r, 1, 1, "no reply to zoom_stop with 2 parameter bytes (01 00): it ignores such a packet");
    }
    a->detail = json_pack("{s:o, s:i}", "state", h.state >= 0 ? json_integer(h.state) : json_null(), "replies",
                          (int)h.of_order);
}

/* 9: the replies to the client's nulls. */
static void ask_null(ask_report *r)
{
    unsigned plain = r->null_replies[0], stated = r->null_replies[1];
    ask_answer *a;
    if (plain + stated == 0u) {
        a = answer(r, 9, 1, "no reply to a null seen");
    } else if (stated == 0u) {
        a = answer(r, 9, 1, "72 bytes, no execution state, as V2.0.6 says (%u replies)", plain);
    } else {
        a = answer(r, 9, 1, "%u of %u replies to nulls were 73 bytes, with an execution state", stated, plain + stated);
    }
    a->detail = json_pack("{s:i, s:i}", "bytes_72", (int)plain, "bytes_73", (int)stated);
}

/* 13: the order the client decided from the words the GCU sent (docs/protocol.md §11.7). */
static void ask_pod_order(online *o, ask_report *r)
{
    xf_pod_order order = xf_client_pod_order(&o->client);
    ask_answer *a = answer(r, 13, 1, "%s",
                           order == XF_POD_ORDER_LE   ? "little-endian: the words it sent tell"
                           : order == XF_POD_ORDER_BE ? "big-endian: the words it sent tell"
                                                      : "undecided: every word it sent reads the same both ways");
    a->detail = json_pack("{s:s}", "pod_status_order",
                          order == XF_POD_ORDER_LE   ? "le"
                          : order == XF_POD_ORDER_BE ? "be"
                                                     : "undecided");
}

/* The client settles (no reply to a command of its own still on the link) before the link is used
 * outside it, for at most --timeout. */
static void settle(online *o)
{
    uint32_t start = xf_posix_now_ms();
    while (!xf_client_settled(&o->client) && xf_client_link(&o->client) == XF_LINK_UP &&
           xf_ms_since(xf_posix_now_ms(), start) < (uint32_t)o->opt->timeout_ms) {
        online_poll(o, 10);
    }
}

void ask_init(ask_report *r)
{
    unsigned i;
    memset(r, 0, sizeof(*r));
    for (i = 0; i < ASK_QUESTIONS; i++) {
        r->q[i].number = (uint8_t)(i + 1u);
        r->q[i].title = open_rows[i].title;
        (void)answer(r, i + 1u, 0, "%s",
                     open_rows[i].not_asked != NULL ? open_rows[i].not_asked : "the probe stopped before it");
    }
}

void ask_questions(online *o, ask_report *r, int (*stop)(void *user), void *user)
{
    uint8_t version = xf_client_gcu_version(&o->client);
    settle(o);
    if (!stop(user)) {
        ask_versions(o, r);
    }
    if (!stop(user)) {
        ask_repeats(o, r, version);
    }
    if (!stop(user)) {
        ask_length(o, r, version);
    }
    ask_null(r);
    ask_pod_order(o, r);
}

/* ---- the report ------------------------------------------------------------------------------ */

void ask_print(const ask_report *r, FILE *out)
{
    unsigned i;
    fprintf(out, "\nopen questions (docs/protocol.md section 12):\n");
    for (i = 0; i < ASK_QUESTIONS; i++) {
        const ask_answer *a = &r->q[i];
        fprintf(out, "  %2u %-60s %s%s\n", (unsigned)a->number, a->title, a->asked ? "" : "not asked: ", a->answer);
    }
}

json_t *ask_json(ask_report *r)
{
    json_t *list = json_array();
    unsigned i;
    for (i = 0; list != NULL && i < ASK_QUESTIONS; i++) {
        ask_answer *a = &r->q[i];
        json_t *detail = (a->detail != NULL) ? a->detail : json_null();
        json_t *o = json_pack("{s:i, s:s, s:b, s:s, s:o}", "question", (int)a->number, "title", a->title, "asked",
                              a->asked, a->asked ? "answer" : "why", a->answer, "detail", detail);
        a->detail = NULL; /* taken by o, or freed with it (json_pack's "o" steals it either way) */
        if (o == NULL || json_array_append_new(list, o) != 0) {
            json_decref(list);
            list = NULL;
        }
    }
    return list;
}

void ask_free(ask_report *r)
{
    unsigned i;
    for (i = 0; i < ASK_QUESTIONS; i++) {
        json_decref(r->q[i].detail);
        r->q[i].detail = NULL;
    }
}
