/**
 * @file
 * @brief A link that wraps another and reports every byte going through
 * it, both ways, with the time: for tracing and recording.
 *
 * Portable (no OS), header-only: the callback decides what to do with the
 * bytes (xf_capture_chunk() writes them to a capture file). The links have
 * no clock (xf_hal.h): the tap is given its own, xf_tap_clock_fn, to stamp
 * the chunks with (xf_posix_now_ms() on POSIX, a tick counter on an MCU:
 * best the clock that drives xf_client_step()). The tap adds no blocking
 * of its own: its functions take as long as the wrapped link's, the
 * clock's and the callback's.
 */
#ifndef XF_TAP_H
#define XF_TAP_H

#include <stddef.h>
#include <stdint.h>
#include "xfgcu/xf_config.h"
#include "xfgcu/xf_hal.h"
#include "xfgcu/xf_protocol.h"

XF_BEGIN_DECLS

/**
 * Called with each chunk written (::XF_DIR_HOST: host -> GCU) or read
 * (::XF_DIR_GCU), as the link moved it: after a successful write, and after
 * a read that returned bytes. It runs inside the link's write or read, so
 * inside xf_client_step() when a client uses the tap: it must not call back
 * into the client or the link.
 * @param user    the pointer given to xf_tap_init()
 * @param dir     ::XF_DIR_HOST for bytes written, ::XF_DIR_GCU for bytes read
 * @param data    the bytes, valid during the call only
 * @param len     number of bytes (> 0 for reads)
 * @param now_ms  the time, from the tap's clock (xf_tap_clock_fn)
 */
typedef void (*xf_tap_fn)(void *user, xf_direction dir, const uint8_t *data, size_t len, uint32_t now_ms);

/**
 * The tap's clock: asked once per chunk reported, just before xf_tap_fn.
 * @param user  the pointer given to xf_tap_init()
 * @return the time, ms, on a clock that wraps at 2^32
 */
typedef uint32_t (*xf_tap_clock_fn)(void *user);

/** A tap's state; fill it with xf_tap_init(). */
typedef struct xf_tap {
    xf_hal inner;           /**< the wrapped link (a copy) */
    xf_tap_fn fn;           /**< the callback; NULL reports nothing */
    xf_tap_clock_fn now_ms; /**< the clock the chunks are stamped with */
    void *user;             /**< passed to @c fn and @c now_ms */
} xf_tap;

/**
 * Wrap @p inner (copied); @p out becomes the tapped link: its functions call
 * the inner link's and report what moved. The tap must outlive @p out. No
 * argument is checked: @p tap, @p inner and @p out must not be NULL, and
 * @p now_ms must not be NULL when @p fn is not (every chunk is stamped).
 * @param tap     the tap's storage
 * @param inner   the link to wrap
 * @param fn      the callback (may be NULL)
 * @param now_ms  the clock the chunks are stamped with (may be NULL only
 *   when @p fn is)
 * @param user    passed to @p fn and @p now_ms
 * @param out     receives the tapped link
 */
static inline void xf_tap_init(xf_tap *tap, const xf_hal *inner, xf_tap_fn fn, xf_tap_clock_fn now_ms, void *user,
                               xf_hal *out);

static inline xf_err xf__tap_write(void *ctx, const uint8_t *data, size_t len)
{
    xf_tap *t = (xf_tap *)ctx;
    xf_err err = t->inner.write(t->inner.ctx, data, len);
    if (err == XF_OK && t->fn != NULL) {
        t->fn(t->user, XF_DIR_HOST, data, len, t->now_ms(t->user));
    }
    return err;
}

static inline xf_err xf__tap_read(void *ctx, uint8_t *buf, size_t cap, size_t *out_len)
{
    xf_tap *t = (xf_tap *)ctx;
    xf_err err = xf_hal_read(&t->inner, buf, cap, out_len);
    if (err == XF_OK && *out_len > 0u && t->fn != NULL) {
        t->fn(t->user, XF_DIR_GCU, buf, *out_len, t->now_ms(t->user));
    }
    return err;
}

static inline int xf__tap_fd(void *ctx)
{
    xf_tap *t = (xf_tap *)ctx;
    return xf_hal_fd(&t->inner);
}

static inline void xf_tap_init(xf_tap *tap, const xf_hal *inner, xf_tap_fn fn, xf_tap_clock_fn now_ms, void *user,
                               xf_hal *out)
{
    tap->inner = *inner;
    tap->fn = fn;
    tap->now_ms = now_ms;
    tap->user = user;
    out->ctx = tap;
    out->write = xf__tap_write;
    out->read = xf__tap_read;
    out->fd = xf__tap_fd;
}

XF_END_DECLS

#endif /* XF_TAP_H */
