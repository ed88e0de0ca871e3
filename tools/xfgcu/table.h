/*
 * table.h - a packet as a table for a person: field, raw value, physical
 * value with its unit (decode without --json).
 */
#ifndef XFGCU_TABLE_H
#define XFGCU_TABLE_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "fields.h"
#include "xfgcu/xfgcu.h"

/**
 * Print a packet already checked with xf_packet_check(); @p where says where it came from,
 * @p pod how to read the flags of pod_status.
 */
void table_print(const uint8_t *buf, size_t len, xf_direction dir, const char *where, pod_reading pod, FILE *out);

#endif /* XFGCU_TABLE_H */
