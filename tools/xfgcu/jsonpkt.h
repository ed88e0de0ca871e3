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

#endif /* XFGCU_JSONPKT_H */
