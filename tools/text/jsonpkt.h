/*
 * jsonpkt.h - packets as JSON objects (libjansson), both ways, in either view of the fields.
 *
 * Output keys, in this order: direction, version, length, order, [order_name], params, then for a
 * host packet [command] or [command_error], for a GCU packet [feedback]; then every field of the
 * direction's two frames under its canonical name ([mode_name] after gimbal_mode,
 * [pod_status_order] and [pod_flags] after pod_status, [gimbal_model] after gimbal_code), with
 * [reserved_main] / [reserved_sub] as hex when a reserved byte is not 0, and last [warnings], the
 * lines of warn.h, when the packet has any. Keys in brackets are extras: encode accepts them and
 * never needs them.
 *
 * The view (fieldtext.h, docs/protocol.md "Units"): TEXT_ENGINEERING gives a field with a scale
 * as its engineering value (a JSON number with the digits of its step: "cam_pitch": -30.0),
 * TEXT_RAW the wire integer ("cam_pitch": -3000); fields without a scale are integers in both.
 * The parameters of "command" follow the same rule.
 *
 * Input is the same object, in the view the caller names; missing fields are 0, "direction"
 * defaults to "host", "version" to the caller's. Anything else is refused by name; a value
 * between two steps of its field, or outside it, is refused, never rounded. So what
 * jsonpkt_from_wire() gives, jsonpkt_to_wire() turns back into the very same bytes, in either
 * view, whatever the packet holds (reserved bytes and unknown orders included).
 */
#ifndef XFGCU_JSONPKT_H
#define XFGCU_JSONPKT_H

#include <jansson.h>
#include <stddef.h>
#include <stdint.h>
#include <time.h>

#include "fieldtext.h"
#include "text_err.h"
#include "xfgcu/xfgcu.h"

/**
 * The object for a packet already checked with xf_packet_check(), with the flags of pod_status
 * read as @p pod says and the fields in @p view; NULL if out of memory.
 */
json_t *jsonpkt_from_wire(const uint8_t *buf, size_t len, xf_direction dir, pod_reading pod, text_view view);

/**
 * Build the packet an object describes, its fields in @p view, into @p out (capacity @p cap, at
 * least XF_PACKET_MAX_LEN). @p where names the object's origin in messages ("encode --json",
 * "stdin line 3"). @p obj is not changed (it is not const because jansson's key iteration takes
 * a non-const object). @return TEXT_OK, or TEXT_BAD with @p e saying why.
 */
int jsonpkt_to_wire(json_t *obj, uint8_t default_version, text_view view, const char *where, uint8_t *out, size_t cap,
                    size_t *len, text_err *e);

/**
 * Parse @p len bytes of JSON text holding one value and nothing else: a NUL byte, a truncated
 * value or anything after it is an error naming the column. @return the value, or NULL with
 * @p e saying why (prefixed by @p where).
 */
json_t *jsonpkt_parse(const char *text, size_t len, const char *where, text_err *e);

/**
 * A field's value as a JSON value in @p view: a number of its unit when it has a scale and the
 * view is TEXT_ENGINEERING, else the integer. NULL if out of memory.
 */
json_t *jsonpkt_value(const xf_wire_field *f, int64_t raw, uint8_t version, text_view view);

/**
 * @p obj as one compact line of text (keys in their order; numbers with at most 15 significant
 * digits, which writes every engineering value with the digits of its step and reads back to
 * the same wire integer), malloc'd; NULL if out of memory. The one way the layer writes JSON.
 */
char *jsonpkt_dumps(const json_t *obj);

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
