/**
 * @file
 * @brief The whole codec of xfgcu, the C driver library for XFRobot
 * (Xianfei) gimbals speaking the GCU private protocol (V0.1 and V0.2).
 *
 * Includes every codec header. Layers, each usable alone:
 *
 * @code{.unparsed}
 *   xf_config.h   compile-time options (#ifndef defaults, #error checks)
 *   xf_error.h    the one error enum and xf_strerror()
 *   xf_bytes.h    little-endian put/get helpers
 *   xf_crc.h      CRC-16/XMODEM
 *   xf_protocol.h constants: headers, sizes, orders, modes, status bits
 *   xf_packet.h   typed frames; pack and unpack for both directions
 *   xf_command.h  typed parameters of every order; feedback
 *   xf_parser.h   streaming parser that resynchronises after noise
 *   xf_units.h    physical units, GNSS time, camera axes
 *   xf_fields.h   every field described as data: offsets, scales, units, names
 * @endcode
 *
 * No allocation, no static state, no OS. The functions and tables are
 * defined once, where XF_IMPLEMENTATION is defined (the compiled xfgcu::codec
 * library, src/xf_codec.c; or one file of yours, for header-only use):
 * @code
 *   #define XF_IMPLEMENTATION
 *   #include "xfgcu/xfgcu.h"
 * @endcode
 */
#ifndef XFGCU_H
#define XFGCU_H

#include "xf_config.h"
#include "xf_version.h"
#include "xf_error.h"
#include "xf_bytes.h"
#include "xf_crc.h"
#include "xf_protocol.h"
#include "xf_packet.h"
#include "xf_command.h"
#include "xf_parser.h"
#include "xf_units.h"
#include "xf_fields.h"

#endif /* XFGCU_H */
