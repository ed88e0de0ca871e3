/*
 * xf_hal.h - the transport interface the client runs on.
 *
 * A link is a struct of function pointers plus a context pointer, so the
 * same client code runs over a POSIX serial port, a socket, or an MCU's
 * UART driver written by the user. No OS type appears here.
 *
 * Semantics every backend keeps:
 *
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
 *  now_ms(ctx)
 *      A monotonic millisecond clock. It wraps at 2^32: compare times with
 *      xf_ms_since(), never with < or >.
 *
 *  fd(ctx)      (optional, POSIX only; NULL on an MCU)
 *      The descriptor to wait on for readability, or -1 while there is none
 *      (closed, reconnecting). It may change after XF_ERR_CLOSED, so ask
 *      again each time round the poll loop.
 */
#ifndef XF_HAL_H
#define XF_HAL_H

#include <stddef.h>
#include <stdint.h>
#include "xf_config.h"
#include "xf_error.h"

XF_BEGIN_DECLS

typedef struct xf_hal {
    void *ctx;
    xf_err (*write)(void *ctx, const uint8_t *data, size_t len);
    xf_err (*read)(void *ctx, uint8_t *buf, size_t cap, size_t *out_len);
    uint32_t (*now_ms)(void *ctx);
    int (*fd)(void *ctx);
} xf_hal;

/** Milliseconds from @p then to @p now on a wrapping 32-bit clock (correct across the wrap). */
static inline uint32_t xf_ms_since(uint32_t now, uint32_t then) { return (uint32_t)(now - then); }

/** XF_OK if @p hal has the three required functions, else XF_ERR_ARG. */
static inline xf_err xf_hal_check(const xf_hal *hal)
{
    return (hal != NULL && hal->write != NULL && hal->read != NULL && hal->now_ms != NULL) ? XF_OK : XF_ERR_ARG;
}

/** The descriptor to poll, or -1 (no fd function, or none now). */
static inline int xf_hal_fd(const xf_hal *hal) { return (hal != NULL && hal->fd != NULL) ? hal->fd(hal->ctx) : -1; }

XF_END_DECLS

#endif /* XF_HAL_H */
