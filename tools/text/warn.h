/*
 * warn.h - what the vendor's text does not allow in a packet that decodes: the one place of these
 * rules, for decode and replay (the "warnings" of their JSON, a line each in the table), monitor
 * and the Python package. A warning never stops a packet from decoding: the packet is what was
 * sent, and the warning says why a GCU (or a host) may read it otherwise than its sender meant.
 *
 * The rules (docs/protocol.md, "Host behaviours from the field", says where each comes from):
 *  - a field outside the range the vendor gives it: the yaws in [0, 360) (a host that writes its
 *    heading as -180..180 into the U16 field), the carrier's roll and pitch, the angles the GCU
 *    reports, the target offsets, latitudes, longitudes, the GNSS time of week;
 *  - valid control quantities beyond the range of an angle (±180°; a rate's is narrower, but the
 *    packet does not say which the mode reads);
 *  - ins_valid set with an all-zero carrier attitude (invented INS data spoils the gimbal's own);
 *  - a host packet whose parameters its order does not take (length, range; record's 0x00) or an
 *    order no version defines;
 *  - a reply to the null order that carries an execution state (V2.0.6: a null has none);
 *  - a version byte other than 1 and 2.
 * Velocities sent in dm/s (a host in the field does) cannot be told from slow motion within one
 * packet: no rule.
 */
#ifndef XFGCU_WARN_H
#define XFGCU_WARN_H

#include <stddef.h>
#include <stdint.h>

#include "xfgcu/xfgcu.h"

#define WARN_MAX  8u   /**< warnings kept per packet; more are counted in warn_list.more */
#define WARN_TEXT 256u /**< the longest warning, NUL included */

/** The warnings of one packet, each one line without a newline. */
typedef struct warn_list {
    size_t n;                       /**< warnings in text[] */
    size_t more;                    /**< warnings beyond WARN_MAX, not kept */
    char text[WARN_MAX][WARN_TEXT]; /**< "carrier_yaw 54537 (545.37 deg) is outside ..." */
} warn_list;

/**
 * The warnings of a packet already checked with xf_packet_check() (@p dir its direction), in the
 * order of its bytes. @return the number of warnings (w->n + w->more)
 */
size_t warn_packet(const uint8_t *buf, size_t len, xf_direction dir, warn_list *w);

/**
 * Why a host packet's parameters do not fit its order in @p version ("track takes 10 parameter
 * bytes, not 9", "cameras out of range"), as decode's command_error says it. @return 1 with
 * @p buf set, or 0 when they fit (or the order is unknown: warn_packet() says so)
 */
int warn_params(uint8_t order, const uint8_t *params, size_t n, uint8_t version, char *buf, size_t cap);

#endif /* XFGCU_WARN_H */
