/*
 * xf_tap.h - a link that wraps another and reports every byte going
 * through it, both ways, with the time: for tracing and recording.
 * Portable (no OS): the callback decides what to do with the bytes.
 */
#ifndef XF_TAP_H
#define XF_TAP_H

#include <stddef.h>
#include <stdint.h>
#include "xf_config.h"
#include "xf_hal.h"
#include "xf_protocol.h"

XF_BEGIN_DECLS

/** Called with each chunk written (XF_DIR_HOST: host -> GCU) or read (XF_DIR_GCU), as the link moved it. */
typedef void (*xf_tap_fn)(void *user, xf_direction dir, const uint8_t *data, size_t len, uint32_t now_ms);

typedef struct xf_tap {
    xf_hal inner;
    xf_tap_fn fn;
    void *user;
} xf_tap;

/** Wrap @p inner (copied); @p out becomes the tapped link. The tap must outlive @p out. */
static inline void xf_tap_init(xf_tap *tap, const xf_hal *inner, xf_tap_fn fn, void *user, xf_hal *out);

static inline xf_err xf__tap_write(void *ctx, const uint8_t *data, size_t len)
{
    xf_tap *t = (xf_tap *)ctx;
    xf_err err = t->inner.write(t->inner.ctx, data, len);
    if (err == XF_OK && t->fn != NULL) {
        t->fn(t->user, XF_DIR_HOST, data, len, t->inner.now_ms(t->inner.ctx));
    }
    return err;
}

static inline xf_err xf__tap_read(void *ctx, uint8_t *buf, size_t cap, size_t *out_len)
{
    xf_tap *t = (xf_tap *)ctx;
    xf_err err = t->inner.read(t->inner.ctx, buf, cap, out_len);
    if (err == XF_OK && *out_len > 0u && t->fn != NULL) {
        t->fn(t->user, XF_DIR_GCU, buf, *out_len, t->inner.now_ms(t->inner.ctx));
    }
    return err;
}

static inline uint32_t xf__tap_now(void *ctx)
{
    xf_tap *t = (xf_tap *)ctx;
    return t->inner.now_ms(t->inner.ctx);
}

static inline int xf__tap_fd(void *ctx)
{
    xf_tap *t = (xf_tap *)ctx;
    return xf_hal_fd(&t->inner);
}

static inline void xf_tap_init(xf_tap *tap, const xf_hal *inner, xf_tap_fn fn, void *user, xf_hal *out)
{
    tap->inner = *inner;
    tap->fn = fn;
    tap->user = user;
    out->ctx = tap;
    out->write = xf__tap_write;
    out->read = xf__tap_read;
    out->now_ms = xf__tap_now;
    out->fd = xf__tap_fd;
}

XF_END_DECLS

#endif /* XF_TAP_H */
