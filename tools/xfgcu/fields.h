/*
 * fields.h - the named fields of the four frames, as data.
 *
 * One row per canonical field name (docs/protocol.md sections 3-6 and 10)
 * and per reserved block, in wire order. Where a row is and what it is
 * called are the codec's: its offset is XF_OFF_HOST_<NAME> / XF_OFF_GCU_<NAME>
 * (xf_protocol.h), its name that NAME in lower case, its size the distance
 * to the next row. What the command line adds: whether the wire integer is
 * signed, how a person reads it, and the version that brought it. JSON
 * output, JSON input and the readable table all walk these rows over the
 * packet's bytes, so a field cannot be printed under one name and parsed
 * under another.
 */
#ifndef XFGCU_FIELDS_H
#define XFGCU_FIELDS_H

#include <stddef.h>
#include <stdint.h>

#include "xfgcu/xfgcu.h"

/** How the readable table shows a raw value. */
typedef enum field_unit {
    FU_RAW,       /**< the number itself */
    FU_BYTE_HEX,  /**< a header byte: 0x01 */
    FU_CTRL,      /**< control quantity: angle or rate, per mode */
    FU_CDEG,      /**< 0.01 deg */
    FU_ACCEL,     /**< 0.01 m/s^2 */
    FU_VEL,       /**< 0.01 m/s */
    FU_DEG7,      /**< 1e-7 deg */
    FU_MM,        /**< mm */
    FU_DISTANCE,  /**< 0.1 m, <= 0: no measurement */
    FU_ZOOM,      /**< 0.1 x */
    FU_GCU_RATE,  /**< 0.01 deg/s (V0.1) or 0.1 deg/s (V0.2) */
    FU_GNSS_MS,   /**< ms of GNSS week */
    FU_GNSS_WEEK, /**< GNSS week (with gnss_ms: a UTC time) */
    FU_HOURS,     /**< hours from UTC */
    FU_MODE,      /**< gimbal_mode, named */
    FU_MODEL,     /**< gimbal_code, named */
    FU_HOST_STATUS,
    FU_POD_STATUS,
    FU_ERROR_CODE,
    FU_THERMAL,
    FU_CAMERA,
    FU_RESERVED /**< a reserved block, not a field: hex under "reserved_main" / "reserved_sub" */
} field_unit;

typedef struct field_desc {
    char name[24];     /**< canonical name: the JSON key */
    uint8_t offset;    /**< of its first byte in the packet */
    uint8_t size;      /**< bytes: 1, 2 or 4 (a reserved block: its length) */
    uint8_t is_signed; /**< the wire integer is signed */
    uint8_t unit;      /**< field_unit */
    uint8_t since;     /**< first protocol version that defines the bytes (GCU 63-66: 2) */
} field_desc;

/** The rows of direction @p dir, in wire order: fields and reserved blocks. */
const field_desc *fields_of(xf_direction dir, size_t *count);
/** The row named @p name (a field or a reserved block), or NULL. */
const field_desc *field_find(xf_direction dir, const char *name);
/** Does a packet of @p version carry @p f? (Version 0 counts as 1.) */
int field_present(const field_desc *f, uint8_t version);

/** Raw value of field @p f in the packet's bytes @p pkt. */
long long field_get(const uint8_t *pkt, const field_desc *f);
/** Store @p v, which must be within field_range(), into the packet's bytes. */
void field_set(uint8_t *pkt, const field_desc *f, long long v);
/** The wire type's range. */
void field_range(const field_desc *f, long long *lo, long long *hi);

/* ---- the pod status word's byte order (docs/protocol.md §11.7) ----------------
 * pod_status stays the raw little-endian wire integer everywhere; its flags
 * are read in the order the word itself points to (xf_pod_status_order()),
 * little-endian, the documented order, when it does not tell, or in the
 * order decode's --pod-order forces. */

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

/** A named bit of a status word. */
typedef struct flag_name {
    unsigned mask;
    const char *name;
} flag_name;

/** The canonical names of the XF_POD_* flags, in bit order, ended by {0, NULL}. */
extern const flag_name pod_flag_names[];

/* Reserved bytes are not fields, but decode -> encode must give back every
 * byte, so they travel as hex. A block also holds the bytes of the fields
 * just before it that the packet's version does not have: a GCU packet of
 * V0.1 has bytes 63-68 reserved, V0.2 only 67-68. */
#define RESERVED_MAX 8

/** Where reserved block @p f of direction @p dir is in a packet of @p version: its offset; *len its size. */
size_t reserved_span(xf_direction dir, const field_desc *f, uint8_t version, size_t *len);

#endif /* XFGCU_FIELDS_H */
