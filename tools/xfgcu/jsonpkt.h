/*
 * jsonpkt.h - packets as JSON objects (libjansson), both ways.
 *
 * Output keys, in this order: direction, version, length, order,
 * [order_name], params, then for a host packet [command] or
 * [command_error], for a GCU packet [feedback]; then every field of the
 * direction's two frames under its canonical name as the raw wire integer
 * ([mode_name] after gimbal_mode, [pod_status_order] and [pod_flags] after
 * pod_status, [gimbal_model] after gimbal_code), with [reserved_main] /
 * [reserved_sub] as hex when a reserved byte is not 0.
 * Keys in brackets are extras: encode accepts them and never needs them.
 *
 * Input is the same object; missing fields are 0, "direction" defaults to
 * "host", "version" to --protocol. Anything else is refused by name.
 */
#ifndef XFGCU_JSONPKT_H
#define XFGCU_JSONPKT_H

#include <jansson.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <time.h>

#include "fields.h"
#include "xfgcu/xfgcu.h"

/**
 * The object for a packet already checked with xf_packet_check(), with the flags of
 * pod_status read as @p pod says; NULL if out of memory.
 */
json_t *jsonpkt_from_wire(const uint8_t *buf, size_t len, xf_direction dir, pod_reading pod);

/** Print the object of a checked packet as one compact line. @return an exit code. */
int jsonpkt_print(const uint8_t *buf, size_t len, xf_direction dir, pod_reading pod, FILE *out);

/**
 * Build the packet an object describes into @p out (capacity @p cap, at
 * least XF_PACKET_MAX_LEN). @p where names the object's origin in messages
 * ("--json", "stdin line 3"). Prints any error. @return an exit code.
 */
int jsonpkt_to_wire(const json_t *obj, uint8_t default_version, const char *where, uint8_t *out, size_t cap,
                    size_t *len);

/* ---- times ------------------------------------------------------------------------ */

/** @p ms since 1970 as "2026-11-26T10:00:00.123Z" (UTC, ISO 8601) into @p buf (24 bytes or more);
 *  "?" for a time gmtime() cannot read. The one format of every time the program writes. */
void jsonpkt_utc_text(int64_t ms, char *buf, size_t cap);

/** Milliseconds since 1970 of a CLOCK_REALTIME reading. */
int64_t jsonpkt_ms(const struct timespec *wall);

/**
 * Add "time_mono" (seconds on CLOCK_MONOTONIC: for intervals) and "time_utc" (@p wall as
 * jsonpkt_utc_text() writes it) to @p obj, the times every --json object carries, from readings
 * taken by the caller (now, or when a reply came). @return @p obj (NULL stays NULL)
 */
json_t *jsonpkt_times(json_t *obj, const struct timespec *mono, const struct timespec *wall);

#endif /* XFGCU_JSONPKT_H */
