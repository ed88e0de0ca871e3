/**
 * @file
 * @brief The one error enum of xfgcu, xf_strerror() and xf_err_name().
 *
 * Zero is success, every error is negative, and a positive value is a
 * success with a warning. The values -1 and 1 are skipped, so that a stray
 * "-1", "1" or `true` from other code is never taken for ours (and no
 * ::xf_err equals ::XF_PARSE_FRAME, the parser's own result, xf_parser.h).
 *
 * Which fault each code means, by who is at fault:
 *
 * - **The caller.** ::XF_ERR_ARG: a bug in the call (NULL pointer, an enum
 *   value outside its type). ::XF_ERR_NO_SPACE: the output buffer is too
 *   small. ::XF_ERR_RANGE: a value is outside its field's range (the member
 *   at fault is named where there is one: `bad_field`, an ::xf_field).
 *   ::XF_ERR_UNSUPPORTED: a valid request this build, link or gimbal model
 *   cannot do.
 *   ::XF_ERR_CONFIG: the caller and the library were built with other layout
 *   options (xf_config.h).
 * - **The input.** ::XF_ERR_HEADER, ::XF_ERR_LENGTH, ::XF_ERR_CRC,
 *   ::XF_ERR_TRUNCATED: the four ways bytes are not a packet.
 *   ::XF_ERR_PARAMS: a known order's parameter bytes have the wrong length.
 *   ::XF_ERR_FORMAT: text or a file is not in the format expected (a
 *   malformed line; a file that is not what it should be).
 * - **Lookups.** ::XF_ERR_NOT_FOUND: what was named does not exist. The
 *   rule: an order the protocol does not define is "not found" whether it
 *   is given by value (xf_command_check() and the functions that call it)
 *   or by name (xf_order_from_name()); likewise a device, a port or a host
 *   name that is not there. (Unknown orders still go on the wire raw:
 *   xf_host_packet.order and params.)
 * - **The world.** ::XF_ERR_IO: the operating system reported an error.
 *   ::XF_ERR_TIMEOUT: no answer in time. ::XF_ERR_CLOSED: the link is closed
 *   or was lost. ::XF_ERR_PERMISSION, ::XF_ERR_BUSY (in use, or a queue is
 *   full), ::XF_ERR_AGAIN (nothing can be done now: try again later).
 *   ::XF_ERR_EOF: the input has ended (the end of a file: not a fault of the
 *   file, but no more data).
 *
 * The warnings: ::XF_WARN_RATE.
 */
#ifndef XF_ERROR_H
#define XF_ERROR_H

#include "xf_config.h"

XF_BEGIN_DECLS

/**
 * Result of every xfgcu function that can fail: ::XF_OK, a positive warning
 * (the call succeeded), or a negative error. Which codes a function returns
 * is listed in its documentation; which fault each code means, in
 * xf_error.h's description. The values never change between versions.
 */
typedef enum xf_err {
    XF_OK = 0, /**< success */
    /* success with a warning (positive; 1 is skipped) */
    XF_WARN_RATE = 2, /**< accepted, but outside the 30-50 Hz the vendor recommends */
    /* the caller */
    XF_ERR_ARG = -2,         /**< invalid argument (NULL pointer, bad enum): a bug in the caller */
    XF_ERR_NO_SPACE = -3,    /**< the output buffer is too small */
    XF_ERR_RANGE = -4,       /**< a value is outside its field's range; the field is named */
    XF_ERR_UNSUPPORTED = -5, /**< valid, but not supported by this build, link or gimbal model */
    XF_ERR_CONFIG = -6,      /**< the library was built with other layout options than the caller (xf_config.h) */
    /* the input */
    XF_ERR_HEADER = -10,    /**< the two header bytes are wrong for the direction */
    XF_ERR_LENGTH = -11,    /**< the length field is outside [72, XF_PACKET_MAX_LEN] or disagrees with the data */
    XF_ERR_CRC = -12,       /**< the CRC does not match */
    XF_ERR_TRUNCATED = -13, /**< fewer bytes than the length field says */
    XF_ERR_PARAMS = -14,    /**< the parameter bytes have the wrong length for the order */
    XF_ERR_FORMAT = -15,    /**< the input is not in the expected format (a malformed line, not a capture) */
    /* the world (transports and client), and lookups */
    XF_ERR_IO = -20,         /**< the operating system reported an error */
    XF_ERR_TIMEOUT = -21,    /**< no answer in time */
    XF_ERR_CLOSED = -22,     /**< the link is closed or was lost */
    XF_ERR_NOT_FOUND = -23,  /**< no such thing: an unknown order (by value or by name), device or host */
    XF_ERR_PERMISSION = -24, /**< permission denied */
    XF_ERR_BUSY = -25,       /**< in use (port taken, queue full) */
    XF_ERR_AGAIN = -26,      /**< nothing to do now; try again later */
    XF_ERR_EOF = -27         /**< the input has ended: no more data */
} xf_err;

/**
 * A short English description of a result code.
 * @param err  an ::xf_err value (any int is accepted)
 * @return a static string, never NULL and never allocated: "ok", a
 *   description such as "bad CRC", or "unknown error" for a value that is not
 *   an ::xf_err. Never blocks.
 */
XF_API const char *xf_strerror(int err);

/**
 * The name of a result code's constant, for logs and test reports.
 * @param err  the code
 * @return a static string, never NULL: the constant's name as spelled in
 *   this header ("XF_OK", "XF_ERR_CRC", ...), or "unknown" for a value that
 *   is not an ::xf_err. Never blocks.
 */
XF_API const char *xf_err_name(xf_err err);

#if XF_EMIT_DEFINITIONS
XF_API const char *xf_strerror(int err)
{
    switch (err) {
    case XF_OK: return "ok";
    case XF_WARN_RATE: return "rate outside the recommended 30-50 Hz";
    case XF_ERR_ARG: return "invalid argument";
    case XF_ERR_NO_SPACE: return "output buffer too small";
    case XF_ERR_RANGE: return "value out of range";
    case XF_ERR_UNSUPPORTED: return "not supported";
    case XF_ERR_CONFIG:
        return "library built with other options (XF_PACKET_MAX_LEN, XF_PARSER_SLOTS, XF_CLIENT_QUEUE, "
               "XF_CLIENT_RESULTS)";
    case XF_ERR_HEADER: return "bad header";
    case XF_ERR_LENGTH: return "bad length";
    case XF_ERR_CRC: return "bad CRC";
    case XF_ERR_TRUNCATED: return "truncated packet";
    case XF_ERR_PARAMS: return "wrong parameter length for the order";
    case XF_ERR_FORMAT: return "not in the expected format";
    case XF_ERR_IO: return "I/O error";
    case XF_ERR_TIMEOUT: return "timed out";
    case XF_ERR_CLOSED: return "link closed";
    case XF_ERR_NOT_FOUND: return "not found";
    case XF_ERR_PERMISSION: return "permission denied";
    case XF_ERR_BUSY: return "busy";
    case XF_ERR_AGAIN: return "try again";
    case XF_ERR_EOF: return "end of input";
    default: return "unknown error";
    }
}

XF_API const char *xf_err_name(xf_err err)
{
    switch (err) {
    case XF_OK: return "XF_OK";
    case XF_WARN_RATE: return "XF_WARN_RATE";
    case XF_ERR_ARG: return "XF_ERR_ARG";
    case XF_ERR_NO_SPACE: return "XF_ERR_NO_SPACE";
    case XF_ERR_RANGE: return "XF_ERR_RANGE";
    case XF_ERR_UNSUPPORTED: return "XF_ERR_UNSUPPORTED";
    case XF_ERR_CONFIG: return "XF_ERR_CONFIG";
    case XF_ERR_HEADER: return "XF_ERR_HEADER";
    case XF_ERR_LENGTH: return "XF_ERR_LENGTH";
    case XF_ERR_CRC: return "XF_ERR_CRC";
    case XF_ERR_TRUNCATED: return "XF_ERR_TRUNCATED";
    case XF_ERR_PARAMS: return "XF_ERR_PARAMS";
    case XF_ERR_FORMAT: return "XF_ERR_FORMAT";
    case XF_ERR_IO: return "XF_ERR_IO";
    case XF_ERR_TIMEOUT: return "XF_ERR_TIMEOUT";
    case XF_ERR_CLOSED: return "XF_ERR_CLOSED";
    case XF_ERR_NOT_FOUND: return "XF_ERR_NOT_FOUND";
    case XF_ERR_PERMISSION: return "XF_ERR_PERMISSION";
    case XF_ERR_BUSY: return "XF_ERR_BUSY";
    case XF_ERR_AGAIN: return "XF_ERR_AGAIN";
    case XF_ERR_EOF: return "XF_ERR_EOF";
    default: return "unknown";
    }
}
#endif

XF_END_DECLS

#endif /* XF_ERROR_H */
