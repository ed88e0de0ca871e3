/*
 * table.h - a packet as a table for a person: field, raw value, engineering value with its unit
 * (decode and replay without --json).
 */
#ifndef XFGCU_TABLE_H
#define XFGCU_TABLE_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "fieldtext.h"
#include "xfgcu/xfgcu.h"

/**
 * Print a packet already checked with xf_packet_check(); @p where says where it came from,
 * @p pod how to read the flags of pod_status, @p view whether the value column gives engineering
 * units (and the names of codes and flags) or, TEXT_RAW, the names only. What the vendor's text
 * does not allow follows the rows, one "warning: ..." line each (warn.h).
 */
void table_print(const uint8_t *buf, size_t len, xf_direction dir, const char *where, pod_reading pod, text_view view,
                 FILE *out);

/**
 * One parameter of a command as "name=value", the way the table shows it: "cameras=0x03",
 * "latitude=22.5000000 deg", "zoom=-55 (5.5x)"; "latitude=225000000" in TEXT_RAW.
 */
void table_member_text(xf_field f, int32_t v, uint8_t version, text_view view, char *buf, size_t cap);

#endif /* XFGCU_TABLE_H */
