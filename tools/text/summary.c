/*
 * summary.c - the last word on a stream (summary.h).
 */
#define _POSIX_C_SOURCE 200809L /* jsonpkt.h's struct timespec */

#include "summary.h"

#include <stdlib.h>

#include "jsonpkt.h"
#include "text_err.h"

static json_t *summary_json(const text_summary *s)
{
    json_t *in = json_pack(
        "{s:I, s:I, s:I, s:I, s:I, s:I}", "packets", (json_int_t)s->host_packets + (json_int_t)s->gcu_packets,
        "host_packets", (json_int_t)s->host_packets, "gcu_packets", (json_int_t)s->gcu_packets, "bytes_skipped",
        (json_int_t)s->bytes_skipped, "crc_errors", (json_int_t)s->crc_errors, "given_up", (json_int_t)s->given_up);
    return (in != NULL) ? json_pack("{s:o}", "summary", in) : NULL;
}

int summary_print(const text_summary *s, int json, FILE *out)
{
    json_t *obj;
    char *text;
    if (!json) {
        fprintf(out,
                "%zu packets: %zu host to GCU, %zu GCU to host; %llu bytes skipped, %llu CRC errors, %llu frames "
                "given up\n",
                s->host_packets + s->gcu_packets, s->host_packets, s->gcu_packets, (unsigned long long)s->bytes_skipped,
                (unsigned long long)s->crc_errors, (unsigned long long)s->given_up);
        return TEXT_OK;
    }
    obj = summary_json(s);
    text = jsonpkt_dumps(obj);
    json_decref(obj);
    if (text == NULL) {
        return TEXT_BAD;
    }
    fprintf(out, "%s\n", text);
    free(text);
    return TEXT_OK;
}

int summary_not_packet(const json_t *obj)
{
    return json_is_object(obj) && json_object_get(obj, "direction") == NULL &&
           (json_object_get(obj, "summary") != NULL || json_object_get(obj, "event") != NULL);
}
