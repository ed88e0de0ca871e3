/*
 * fieldtext.h - the fields of the codec's table (xfgcu/xf_fields.h) as a person and a script read
 * them: the two views (engineering units, or the wire integers), each value as text, the
 * reserved blocks, the byte order of the pod status word, and the one way versions and models
 * are shown.
 *
 * The unit rule is docs/protocol.md's ("Units"): a field's engineering value is its wire integer
 * times its step, in its unit, under its canonical name; --raw (TEXT_RAW) gives the wire integer
 * under the same name.
 */
#ifndef XFGCU_FIELDTEXT_H
#define XFGCU_FIELDTEXT_H

#include <stddef.h>
#include <stdint.h>

#include "xfgcu/xfgcu.h"

/** Which number a field shows. */
typedef enum text_view {
    TEXT_ENGINEERING = 0, /**< the engineering value (the default): -30.0 (deg) for a cam_pitch of -3000 */
    TEXT_RAW = 1          /**< the wire integer (--raw) */
} text_view;

/** The field's value as text in @p view: "-30.00 deg", "5.5x", "3.1", "no valid measurement";
 *  "-3000" in TEXT_RAW. Names, flags and hex are for the caller (table.c) to add. */
void fieldtext_value(const xf_wire_field *f, int64_t raw, uint8_t version, text_view view, char *buf, size_t cap);

/** Whether a field's integer is shown in hex: marker bytes, flag words and codes, except model
 *  codes, which are decimal (gimbal_code 58). */
int fieldtext_hex(const xf_wire_field *f);

/** A version byte in tenths as "3.1" (hw_version, fw_version: docs/protocol.md §11.9). */
void fieldtext_version(uint8_t raw, char *buf, size_t cap);

/** A model code as "Z-9B_V4(T) (code 58)", or "unknown model (code 7)": the one way models are shown. */
void fieldtext_model(uint8_t code, char *buf, size_t cap);

/* Reserved bytes are not fields, but decode -> encode must give back every byte, so they travel
 * as hex. A block also holds the bytes of the fields just before it that the packet's version
 * does not have: a GCU packet of V0.1 has bytes 63-68 reserved, V0.2 only 67-68. */
#define RESERVED_MAX 8

/** Where reserved block @p f is in a packet of @p version: its offset; *len its size. */
size_t reserved_span(const xf_wire_field *f, uint8_t version, size_t *len);

/* ---- the pod status word's byte order (docs/protocol.md §11.7) ----------------
 * pod_status stays the little-endian wire integer everywhere; its flags are read in the order
 * the word itself points to (xf_pod_status_order()), little-endian, the documented order, when it
 * does not tell, or in the order decode's --pod-order forces. */

/** How to read the flags of pod_status: decided per packet (decode --pod-order auto), or forced. */
typedef enum pod_reading {
    POD_READ_AUTO, /**< xf_pod_status_order(); undecided: little-endian */
    POD_READ_LE,   /**< --pod-order le */
    POD_READ_BE    /**< --pod-order be */
} pod_reading;

/** The order @p pod_status is read in under @p how: ::XF_POD_ORDER_LE or ::XF_POD_ORDER_BE, never undecided. */
xf_pod_order pod_order_for(uint16_t pod_status, pod_reading how);
/** "le" or "be", as the JSON key pod_status_order says it. */
const char *pod_order_name(xf_pod_order order);
/** The pod_status row of the table: its bits name the flags. */
const xf_wire_field *pod_row(void);

#endif /* XFGCU_FIELDTEXT_H */
