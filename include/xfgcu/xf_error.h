/**
 * @file
 * @brief The one error enum of xfgcu, and xf_strerror().
 *
 * Zero is success, every error is negative, and a positive value is a
 * success with a warning. The code says who is at fault:
 * the caller (ARG, NO_SPACE, RANGE), the bytes received (HEADER, LENGTH, CRC,
 * TRUNCATED), or the outside world (IO, TIMEOUT, CLOSED, ...). The value -1
 * is skipped so that a stray "-1" from other code is never taken for ours.
 */
#ifndef XF_ERROR_H
#define XF_ERROR_H

#include "xf_config.h"

XF_BEGIN_DECLS

/**
 * Result of every xfgcu function that can fail: ::XF_OK, a positive warning
 * (the call succeeded), or a negative error. Which codes a function returns
 * is listed in its documentation.
 */
typedef enum xf_err {
    XF_OK = 0, /**< success */
    /* success with a warning (positive) */
    XF_WARN_RATE = 1, /**< accepted, but outside the 30-50 Hz the vendor recommends */
    /* the caller */
    XF_ERR_ARG = -2,         /**< invalid argument (NULL pointer, bad enum): a bug in the caller */
    XF_ERR_NO_SPACE = -3,    /**< the output buffer is too small */
    XF_ERR_RANGE = -4,       /**< a value is outside its field's range; the field is named */
    XF_ERR_UNSUPPORTED = -5, /**< valid, but not supported by this build or link */
    XF_ERR_CONFIG = -6,      /**< the library was built with other layout options than the caller (xf_config.h) */
    /* the bytes */
    XF_ERR_HEADER = -10,    /**< the two header bytes are wrong for the direction */
    XF_ERR_LENGTH = -11,    /**< the length field is outside [72, XF_PACKET_MAX_LEN] or disagrees with the data */
    XF_ERR_CRC = -12,       /**< the CRC does not match */
    XF_ERR_TRUNCATED = -13, /**< fewer bytes than the length field says */
    XF_ERR_PARAMS = -14,    /**< the parameter bytes have the wrong length for the order */
    /* the world (transports and client) */
    XF_ERR_IO = -20,         /**< the operating system reported an error */
    XF_ERR_TIMEOUT = -21,    /**< no answer in time */
    XF_ERR_CLOSED = -22,     /**< the link is closed or was lost */
    XF_ERR_NOT_FOUND = -23,  /**< no such device or host */
    XF_ERR_PERMISSION = -24, /**< permission denied */
    XF_ERR_BUSY = -25,       /**< in use (port taken, queue full) */
    XF_ERR_AGAIN = -26       /**< nothing to do now; try again later */
} xf_err;

/**
 * A short English description of a result code.
 * @param err  an ::xf_err value (any int is accepted)
 * @return a static string, never NULL and never allocated: "ok", a
 *   description such as "bad CRC", or "unknown error" for a value that is not
 *   an ::xf_err. Never blocks.
 */
XF_API const char *xf_strerror(int err);

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
        return "library built with other options (XF_PACKET_MAX_LEN, XF_PARSER_MEMO, XF_CLIENT_QUEUE, "
               "XF_CLIENT_RESULTS)";
    case XF_ERR_HEADER: return "bad header";
    case XF_ERR_LENGTH: return "bad length";
    case XF_ERR_CRC: return "bad CRC";
    case XF_ERR_TRUNCATED: return "truncated packet";
    case XF_ERR_PARAMS: return "wrong parameter length for the order";
    case XF_ERR_IO: return "I/O error";
    case XF_ERR_TIMEOUT: return "timed out";
    case XF_ERR_CLOSED: return "link closed";
    case XF_ERR_NOT_FOUND: return "not found";
    case XF_ERR_PERMISSION: return "permission denied";
    case XF_ERR_BUSY: return "busy";
    case XF_ERR_AGAIN: return "try again";
    default: return "unknown error";
    }
}
#endif

XF_END_DECLS

#endif /* XF_ERROR_H */
