/**
 * @file
 * @brief The transport interface the client runs on.
 *
 * A link is a struct of function pointers plus a context pointer, so the
 * same client code runs over a POSIX serial port, a socket, or an MCU's
 * UART driver written by the user. No OS type appears here.
 *
 * Semantics every backend keeps (also given at each member of ::xf_hal):
 *
 * @code{.unparsed}
 *  write(ctx, data, len)
 *      Hands one whole packet to the link in one go: a UART must see no idle
 *      gap inside a packet, a datagram link sends one datagram. Never blocks
 *      longer than it takes the driver to accept the bytes (bounded; each
 *      backend documents its bound). Returns XF_OK (all bytes accepted),
 *      XF_ERR_AGAIN (not accepted now, nothing was sent: try next cycle),
 *      XF_ERR_CLOSED (the link is down; the backend may be restoring it),
 *      or XF_ERR_IO.
 *
 *  read(ctx, buf, cap, &n)
 *      Never blocks. Copies what has arrived, up to cap bytes, and sets n
 *      (0 = nothing now). Returns XF_OK, XF_ERR_CLOSED (the link is down:
 *      n = 0; keep calling, a backend that reconnects does so here), or
 *      XF_ERR_IO.
 *
 *  fd(ctx)      (optional, POSIX only; NULL on an MCU)
 *      The descriptor to wait on for readability, or -1 while there is none
 *      (closed, reconnecting). It may change after XF_ERR_CLOSED, so ask
 *      again each time round the poll loop.
 * @endcode
 *
 * A backend's functions are called from one thread only (the one that
 * steps the client or simulator using it), never concurrently. The helpers
 * below are header-only and never block.
 *
 * No clock: the client takes time only from its callers
 * (xf_client_step(c, now_ms) and the setters), so that one clock drives it,
 * tests can run it on a virtual clock, and an MCU passes its tick counter;
 * the HAL has no clock. The simulator takes time from its step calls too
 * (xf_sim_step()). Times
 * are milliseconds on a clock that wraps at 2^32: compare them with
 * xf_ms_since(), never with < or >.
 */
#ifndef XF_HAL_H
#define XF_HAL_H

#include <stddef.h>
#include <stdint.h>
#include "xf_config.h"
#include "xf_error.h"

XF_BEGIN_DECLS

/**
 * A link: a context pointer and the functions that move bytes over it.
 * write and read are required (xf_hal_check()); fd is optional. The
 * client and simulator copy the struct; the context it points to must
 * outlive them. Implementations: posix/xf_posix.h (serial, UDP, TCP),
 * posix/xf_simlink.h (the simulator's ends), or your own.
 */
typedef struct xf_hal {
    void *ctx; /**< the backend's state, passed to every function below */
    /**
     * Hand one whole packet to the link in one go: a UART must see no idle
     * gap inside a packet, a datagram link sends one datagram. Never blocks
     * longer than it takes the driver to accept the bytes (bounded; each
     * backend documents its bound).
     * @param ctx   xf_hal.ctx
     * @param data  the packet
     * @param len   its length in bytes
     * @return ::XF_OK (all bytes accepted), ::XF_ERR_AGAIN (not accepted now,
     *   nothing was sent: try next cycle), ::XF_ERR_CLOSED (the link is
     *   down; the backend may be restoring it), or ::XF_ERR_IO
     */
    xf_err (*write)(void *ctx, const uint8_t *data, size_t len);
    /**
     * Copy what has arrived, up to @p cap bytes. Never blocks.
     * @param ctx      xf_hal.ctx
     * @param buf      where the bytes go
     * @param cap      capacity of @p buf
     * @param out_len  receives the number of bytes copied (0 = nothing now), at
     *   most @p cap (more is ::XF_ERR_IO to xf_hal_read(), which every reader uses)
     * @return ::XF_OK, ::XF_ERR_CLOSED (the link is down, *out_len = 0; keep
     *   calling: a backend that reconnects does so here), or ::XF_ERR_IO
     */
    xf_err (*read)(void *ctx, uint8_t *buf, size_t cap, size_t *out_len);
    /**
     * Optional (POSIX only; NULL on an MCU): the descriptor to wait on for
     * readability. It may change after ::XF_ERR_CLOSED, so ask again each
     * time round the poll loop (xf_hal_fd()).
     * @param ctx  xf_hal.ctx
     * @return the descriptor, or -1 while there is none (closed, reconnecting)
     */
    int (*fd)(void *ctx);
} xf_hal;

/**
 * Milliseconds from @p then to @p now on a wrapping 32-bit clock (correct
 * across the wrap, as long as less than 2^32 ms lie between them).
 * @param now   the later time, ms
 * @param then  the earlier time, ms
 * @return now - then, modulo 2^32
 */
static inline uint32_t xf_ms_since(uint32_t now, uint32_t then) { return (uint32_t)(now - then); }

/**
 * Whether a link has the two required functions (write and read).
 * @param hal  the link
 * @return ::XF_OK, or ::XF_ERR_ARG (NULL @p hal, or a required function missing)
 */
static inline xf_err xf_hal_check(const xf_hal *hal)
{
    return (hal != NULL && hal->write != NULL && hal->read != NULL) ? XF_OK : XF_ERR_ARG;
}

/**
 * The descriptor to poll for the link's input.
 * @param hal  the link (may be NULL)
 * @return the descriptor, or -1 (NULL @p hal, no fd function, or none now)
 */
static inline int xf_hal_fd(const xf_hal *hal) { return (hal != NULL && hal->fd != NULL) ? hal->fd(hal->ctx) : -1; }

/**
 * Read the link (xf_hal.read), holding it to its contract: a read that says it copied more
 * than @p cap bytes is ::XF_ERR_IO with *out_len = 0 (a broken backend: none of its bytes can
 * be trusted, and those past @p buf are not there). How the client, the simulator and the
 * program read a link.
 * @param hal      the link (checked by xf_hal_check())
 * @param buf      where the bytes go
 * @param cap      capacity of @p buf
 * @param out_len  receives the number of bytes copied (0 on any error)
 * @return what xf_hal.read returned, or ::XF_ERR_IO for an over-long read
 */
static inline xf_err xf_hal_read(const xf_hal *hal, uint8_t *buf, size_t cap, size_t *out_len)
{
    xf_err err;
    *out_len = 0;
    err = hal->read(hal->ctx, buf, cap, out_len);
    if (err != XF_OK || *out_len > cap) {
        *out_len = 0;
        return (err != XF_OK) ? err : XF_ERR_IO;
    }
    return XF_OK;
}

XF_END_DECLS

#endif /* XF_HAL_H */
