/*
 * fields.h - the named fields of the four frames, as data.
 *
 * One row per canonical field name (docs/protocol.md sections 3-6 and 10):
 * where the member lives in xf_host_packet / xf_gcu_packet, its wire type,
 * and how a person reads it. JSON output, JSON input and the readable table
 * all walk these rows, so a field cannot be printed under one name and
 * parsed under another.
 */
#ifndef XFGCU_FIELDS_H
#define XFGCU_FIELDS_H

#include <stddef.h>
#include <stdint.h>

#include "xfgcu/xfgcu.h"

typedef enum field_type { FT_U8, FT_S8, FT_U16, FT_S16, FT_U32, FT_S32 } field_type;

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
    FU_CAMERA
} field_unit;

typedef struct field_desc {
    const char *name; /**< canonical name: the JSON key */
    size_t offset;    /**< of the member in xf_host_packet or xf_gcu_packet */
    uint8_t type;     /**< field_type */
    uint8_t unit;     /**< field_unit */
    uint8_t frame;    /**< 0 main frame, 1 sub frame */
    uint8_t since;    /**< first protocol version that defines the bytes (GCU 63-66: 2) */
} field_desc;

/** The rows of direction @p dir, in wire order. */
const field_desc *fields_of(xf_direction dir, size_t *count);
/** The row named @p name, or NULL. */
const field_desc *field_find(xf_direction dir, const char *name);
/** Does a packet of @p version carry @p f? (Version 0 counts as 1.) */
int field_present(const field_desc *f, uint8_t version);

/** Raw value of @p f in @p pkt (an xf_host_packet or xf_gcu_packet). */
long long field_get(const void *pkt, const field_desc *f);
/** Store @p v, which must be within field_range(). */
void field_set(void *pkt, const field_desc *f, long long v);
/** The wire type's range. */
void field_range(const field_desc *f, long long *lo, long long *hi);

/* ---- reserved bytes -------------------------------------------------------
 * Reserved bytes are not fields, but decode -> encode must give back every
 * byte, so they travel as hex under "reserved_main" / "reserved_sub". The
 * sub frame's reserved block depends on the version: a GCU packet of V0.1
 * has bytes 63-68 reserved, V0.2 only 67-68. */
#define RESERVED_MAIN 0
#define RESERVED_SUB  1
#define RESERVED_MAX  8

/** Name of a reserved block: "reserved_main" or "reserved_sub". */
const char *reserved_name(int block);
/** Number of reserved bytes in @p block for @p dir and @p version. */
size_t reserved_size(xf_direction dir, uint8_t version, int block);
/** Copy the reserved bytes out of @p pkt (at most RESERVED_MAX); returns the count. */
size_t reserved_get(const void *pkt, xf_direction dir, uint8_t version, int block, uint8_t *out);
/** Store reserved_size() bytes into @p pkt. */
void reserved_set(void *pkt, xf_direction dir, uint8_t version, int block, const uint8_t *in);

#endif /* XFGCU_FIELDS_H */
