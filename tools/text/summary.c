/*
 * summary.c - the last word on a stream (summary.h).
 */
#include "summary.h"

void summary_print(const text_summary *s, FILE *out)
{
    fprintf(out, "%zu packets: %zu host to GCU, %zu GCU to host; %llu bytes skipped, %llu CRC errors, %llu frames given up\n",
            s->host_packets + s->gcu_packets, s->host_packets, s->gcu_packets, (unsigned long long)s->bytes_skipped,
            (unsigned long long)s->crc_errors, (unsigned long long)s->given_up);
}

json_t *summary_json(const text_summary *s)
{
    json_t *in = json_pack("{s:I, s:I, s:I, s:I, s:I, s:I}", "packets", (json_int_t)(s->host_packets + s->gcu_packets),
                           "host_packets", (json_int_t)s->host_packets, "gcu_packets", (json_int_t)s->gcu_packets,
                           "bytes_skipped", (json_int_t)s->bytes_skipped, "crc_errors", (json_int_t)s->crc_errors,
                           "given_up", (json_int_t)s->given_up);
    return (in != NULL) ? json_pack("{s:o}", "summary", in) : NULL;
}

int summary_not_packet(const json_t *obj)
{
    return json_is_object(obj) && json_object_get(obj, "direction") == NULL &&
           (json_object_get(obj, "summary") != NULL || json_object_get(obj, "event") != NULL);
}
