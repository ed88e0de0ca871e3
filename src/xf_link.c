/*
 * xf_link.c - any link from one spec string ("tcp:HOST[:PORT]", "udp:HOST[:PORT][,local=PORT]",
 * "serial:PATH[,baud=N]"): the parser, and an xf_link that holds whichever link it names.
 */
#define _POSIX_C_SOURCE 200809L
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "xf_posix_internal.h"
#include "xfgcu/posix/xf_link.h"

#define XF__SPEC_QUOTED 64u /* bytes of a spec quoted in an error */
#define XF__TEXT_QUOTED 32  /* bytes of a part of it (a port, an option) quoted in an error */

static const char xf__kinds_hint[] = "give tcp:HOST[:PORT], udp:HOST[:PORT][,local=PORT] or serial:PATH[,baud=N]";

/* A piece of the spec: not NUL-terminated. */
typedef struct xf__span {
    const char *p;
    size_t n;
} xf__span;

static int xf__span_is(xf__span s, const char *word) { return strlen(word) == s.n && memcmp(s.p, word, s.n) == 0; }

static int xf__span_quoted_len(xf__span s) { return (int)(s.n < (size_t)XF__TEXT_QUOTED ? s.n : XF__TEXT_QUOTED); }

/* ---- errors ----------------------------------------------------------------------------- */

/* "SPEC: reason", the spec cut to XF__SPEC_QUOTED bytes and its control characters shown as '?'. */
#if defined(__GNUC__)
__attribute__((format(printf, 4, 5)))
#endif
static xf_err
xf__spec_fail(xf_link_spec *out, const char *spec, xf_err code, const char *fmt, ...)
{
    char quoted[XF__SPEC_QUOTED + 4u], reason[160];
    size_t i = 0;
    va_list ap;
    va_start(ap, fmt);
    (void)vsnprintf(reason, sizeof(reason), fmt, ap);
    va_end(ap);
    for (; spec != NULL && spec[i] != '\0' && i < XF__SPEC_QUOTED; i++) {
        unsigned char c = (unsigned char)spec[i];
        quoted[i] = (c < 0x20u || c == 0x7Fu) ? '?' : (char)c;
    }
    if (spec != NULL && spec[i] != '\0') {
        memcpy(quoted + i, "...", 3u);
        i += 3u;
    }
    quoted[i] = '\0';
    out->kind = XF_LINK_KIND_NONE;
    if (spec == NULL || i == 0u) {
        return xf__fail(&out->error, code, "%s", reason);
    }
    return xf__fail(&out->error, code, "%s: %s", quoted, reason);
}

/* ---- numbers and names ------------------------------------------------------------------ */

/* Decimal digits only, saturating at 0xFFFFFFFF: 0, or -1 when @p s is empty or not all digits. */
static int xf__parse_u32(xf__span s, uint32_t *out)
{
    uint32_t v = 0;
    size_t i;
    if (s.n == 0u) {
        return -1;
    }
    for (i = 0; i < s.n; i++) {
        uint32_t d = (uint32_t)(unsigned char)s.p[i] - (uint32_t)'0';
        if (d > 9u) {
            return -1;
        }
        v = (v > (0xFFFFFFFFu - d) / 10u) ? 0xFFFFFFFFu : v * 10u + d;
    }
    *out = v;
    return 0;
}

/* A port (@p what names it in the messages) in [lo, 65535]. */
static xf_err xf__parse_port(xf_link_spec *out, const char *spec, const char *what, xf__span s, uint32_t lo,
                             uint16_t *port)
{
    uint32_t v = 0;
    if (s.n == 0u) {
        return xf__spec_fail(out, spec, XF_ERR_ARG, "%s is empty", what);
    }
    if (xf__parse_u32(s, &v) != 0) {
        return xf__spec_fail(out, spec, XF_ERR_ARG, "%s '%.*s' is not a decimal number", what, xf__span_quoted_len(s),
                             s.p);
    }
    if (v < lo || v > 65535u) {
        return xf__spec_fail(out, spec, XF_ERR_RANGE, "%s %.*s is out of range %u..65535", what, xf__span_quoted_len(s),
                             s.p, (unsigned)lo);
    }
    *port = (uint16_t)v;
    return XF_OK;
}

/* Letters, digits and . - _ name a host; an IPv6 address adds : and a zone's %. */
static int xf__host_char(char c)
{
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '.' || c == '-' ||
           c == '_' || c == ':' || c == '%';
}

/* Copy a host (or, with @p is_path, a device path) into its member, checked. */
static xf_err xf__take_where(xf_link_spec *out, const char *spec, xf__span s, int is_path)
{
    char *dst = is_path ? out->path : out->host;
    size_t cap = is_path ? sizeof(out->path) : sizeof(out->host);
    const char *what = is_path ? "device path" : "host";
    size_t i;
    if (s.n == 0u) {
        return xf__spec_fail(out, spec, XF_ERR_ARG, "no %s", what);
    }
    if (s.n >= cap) {
        return xf__spec_fail(out, spec, XF_ERR_RANGE, "%s longer than %u bytes", what, (unsigned)(cap - 1u));
    }
    for (i = 0; !is_path && i < s.n; i++) {
        if (!xf__host_char(s.p[i])) {
            unsigned char c = (unsigned char)s.p[i];
            return xf__spec_fail(out, spec, XF_ERR_ARG, "'%c' has no place in a host name",
                                 (c < 0x20u || c >= 0x7Fu) ? '?' : (char)c);
        }
    }
    memcpy(dst, s.p, s.n);
    dst[s.n] = '\0';
    return XF_OK;
}

/* HOST, HOST:PORT, [V6], [V6]:PORT, or a bare V6 (two colons or more, no port). */
static xf_err xf__parse_host_port(xf_link_spec *out, const char *spec, xf__span s)
{
    xf__span host = s, port = {NULL, 0};
    const char *colon = (s.n > 0u) ? memchr(s.p, ':', s.n) : NULL;
    int has_port = 0;
    xf_err err;
    if (s.n > 0u && s.p[0] == '[') {
        const char *end = memchr(s.p, ']', s.n);
        size_t after;
        if (end == NULL) {
            return xf__spec_fail(out, spec, XF_ERR_ARG, "'[' without ']'");
        }
        host.p = s.p + 1;
        host.n = (size_t)(end - host.p);
        after = s.n - (size_t)(end + 1 - s.p);
        if (host.n == 0u) {
            return xf__spec_fail(out, spec, XF_ERR_ARG, "no host between '[' and ']'");
        }
        if (after > 0u && end[1] != ':') {
            return xf__spec_fail(out, spec, XF_ERR_ARG, "after ']' comes ':PORT' or nothing");
        }
        if (after > 0u) {
            has_port = 1;
            port.p = end + 2;
            port.n = after - 1u;
        }
    } else if (colon != NULL && memchr(colon + 1, ':', s.n - (size_t)(colon + 1 - s.p)) == NULL) {
        has_port = 1; /* one colon: HOST:PORT */
        host.n = (size_t)(colon - s.p);
        port.p = colon + 1;
        port.n = s.n - host.n - 1u;
    }
    err = xf__take_where(out, spec, host, 0);
    if (err == XF_OK && has_port) {
        out->port_given = 1;
        err = xf__parse_port(out, spec, "port", port, 1u, &out->port);
    }
    return err;
}

/* The options after the first comma: "key=value,key=value". */
static xf_err xf__parse_options(xf_link_spec *out, const char *spec, xf__span s)
{
    int have_local = 0, have_baud = 0;
    const char *end = s.p + s.n;
    const char *p = s.p;
    const char *takes = (out->kind == XF_LINK_KIND_UDP)      ? "udp takes local=PORT"
                        : (out->kind == XF_LINK_KIND_SERIAL) ? "serial takes baud=N"
                                                             : "tcp takes none";
    while (p != NULL) {
        const char *comma = memchr(p, ',', (size_t)(end - p));
        xf__span opt, key, value;
        const char *eq;
        xf_err err;
        opt.p = p;
        opt.n = (size_t)((comma != NULL ? comma : end) - p);
        p = (comma != NULL) ? comma + 1 : NULL;
        eq = (opt.n > 0u) ? memchr(opt.p, '=', opt.n) : NULL;
        if (opt.n == 0u) {
            return xf__spec_fail(out, spec, XF_ERR_ARG, "empty option (%s)", takes);
        }
        if (eq == NULL) {
            return xf__spec_fail(out, spec, XF_ERR_ARG, "option '%.*s' has no '=' and value (%s)",
                                 xf__span_quoted_len(opt), opt.p, takes);
        }
        key.p = opt.p;
        key.n = (size_t)(eq - opt.p);
        value.p = eq + 1;
        value.n = opt.n - key.n - 1u;
        if (out->kind == XF_LINK_KIND_UDP && xf__span_is(key, "local")) {
            if (have_local++) {
                return xf__spec_fail(out, spec, XF_ERR_ARG, "local given twice");
            }
            err = xf__parse_port(out, spec, "local", value, 0u, &out->local_port);
        } else if (out->kind == XF_LINK_KIND_SERIAL && xf__span_is(key, "baud")) {
            if (have_baud++) {
                return xf__spec_fail(out, spec, XF_ERR_ARG, "baud given twice");
            }
            if (xf__parse_u32(value, &out->baud) != 0) {
                return xf__spec_fail(out, spec, XF_ERR_ARG, "baud '%.*s' is not a decimal number",
                                     xf__span_quoted_len(value), value.p);
            }
            err = xf_serial_baud_ok(out->baud)
                      ? XF_OK
                      : xf__spec_fail(out, spec, XF_ERR_RANGE, "baud must be 115200, 250000, 500000 or 1000000");
        } else {
            err = xf__spec_fail(out, spec, XF_ERR_ARG, "unknown option '%.*s' (%s)", xf__span_quoted_len(key), key.p,
                                takes);
        }
        if (err != XF_OK) {
            return err;
        }
    }
    return XF_OK;
}

static void xf__spec_defaults(xf_link_spec *out, xf_link_kind kind)
{
    memset(out, 0, sizeof(*out));
    out->kind = kind;
    out->port = (uint16_t)((kind == XF_LINK_KIND_TCP) ? XF_GCU_TCP_PORT : XF_GCU_UDP_PORT);
    out->local_port = (uint16_t)XF_HOST_UDP_PORT;
    out->baud = 115200u;
}

xf_err xf_link_spec_parse(const char *spec, xf_link_spec *out)
{
    static const char *const names[] = {"serial", "udp", "tcp"};
    static const xf_link_kind kinds[] = {XF_LINK_KIND_SERIAL, XF_LINK_KIND_UDP, XF_LINK_KIND_TCP};
    xf__span kind, body, opts = {NULL, 0};
    const char *colon, *comma;
    size_t len = 0, i;
    xf_err err;
    if (out == NULL) {
        return XF_ERR_ARG;
    }
    memset(out, 0, sizeof(*out));
    if (spec == NULL || spec[0] == '\0') {
        return xf__spec_fail(out, spec, XF_ERR_ARG, "no link spec: %s", xf__kinds_hint);
    }
    while (len <= XF_LINK_SPEC_MAX && spec[len] != '\0') {
        unsigned char c = (unsigned char)spec[len];
        if (c < 0x20u || c == 0x7Fu) {
            return xf__spec_fail(out, spec, XF_ERR_ARG, "control character at byte %u", (unsigned)len);
        }
        len++;
    }
    if (len > XF_LINK_SPEC_MAX) {
        return xf__spec_fail(out, spec, XF_ERR_RANGE, "longer than %u bytes", (unsigned)XF_LINK_SPEC_MAX);
    }
    colon = memchr(spec, ':', len);
    if (colon == NULL) {
        return xf__spec_fail(out, spec, XF_ERR_ARG, "no link kind: %s", xf__kinds_hint);
    }
    kind.p = spec;
    kind.n = (size_t)(colon - spec);
    for (i = 0; i < sizeof(names) / sizeof(names[0]); i++) {
        if (xf__span_is(kind, names[i])) {
            break;
        }
    }
    if (i == sizeof(names) / sizeof(names[0])) {
        return xf__spec_fail(out, spec, XF_ERR_ARG, "unknown link kind '%.*s': %s", xf__span_quoted_len(kind), kind.p,
                             xf__kinds_hint);
    }
    xf__spec_defaults(out, kinds[i]);
    body.p = colon + 1;
    body.n = len - kind.n - 1u;
    comma = memchr(body.p, ',', body.n);
    if (comma != NULL) {
        opts.p = comma + 1;
        opts.n = body.n - (size_t)(opts.p - body.p);
        body.n = (size_t)(comma - body.p);
    }
    err =
        (out->kind == XF_LINK_KIND_SERIAL) ? xf__take_where(out, spec, body, 1) : xf__parse_host_port(out, spec, body);
    if (err == XF_OK && comma != NULL) {
        err = xf__parse_options(out, spec, opts);
    }
    return err;
}

xf_err xf_link_spec_init(xf_link_spec *out, xf_link_kind kind, const char *where)
{
    xf__span s;
    if (out == NULL) {
        return XF_ERR_ARG;
    }
    memset(out, 0, sizeof(*out));
    if (kind != XF_LINK_KIND_SERIAL && kind != XF_LINK_KIND_UDP && kind != XF_LINK_KIND_TCP) {
        return xf__spec_fail(out, NULL, XF_ERR_ARG, "link kind %d: not serial, udp or tcp", (int)kind);
    }
    xf__spec_defaults(out, kind);
    s.p = (where != NULL) ? where : "";
    s.n = strnlen(s.p, sizeof(out->path)); /* enough to tell "too long" for either member */
    return xf__take_where(out, where, s, kind == XF_LINK_KIND_SERIAL);
}

/* ---- the link --------------------------------------------------------------------------- */

/* A spec filled by hand is checked again before it is opened. */
static xf_err xf__spec_check(xf_link_spec *s)
{
    int serial = (s->kind == XF_LINK_KIND_SERIAL);
    const char *where = serial ? s->path : s->host;
    size_t cap = serial ? sizeof(s->path) : sizeof(s->host);
    if (s->kind != XF_LINK_KIND_SERIAL && s->kind != XF_LINK_KIND_UDP && s->kind != XF_LINK_KIND_TCP) {
        return xf__fail(&s->error, XF_ERR_ARG, "link kind %d: not serial, udp or tcp", (int)s->kind);
    }
    if (memchr(where, '\0', cap) == NULL || where[0] == '\0') {
        return xf__fail(&s->error, XF_ERR_ARG, "no %s (or one of %u bytes or more)", serial ? "device path" : "host",
                        (unsigned)cap);
    }
    if (serial && !xf_serial_baud_ok(s->baud)) {
        return xf__fail(&s->error, XF_ERR_RANGE, "serial %s: baud %u: must be 115200, 250000, 500000 or 1000000",
                        s->path, (unsigned)s->baud);
    }
    if (!serial && s->port == 0u) {
        return xf__fail(&s->error, XF_ERR_RANGE, "%s %s: port 0: must be 1..65535",
                        s->kind == XF_LINK_KIND_TCP ? "tcp" : "udp", s->host);
    }
    return XF_OK;
}

static xf_err xf__link_open_kind(xf_link *l)
{
    const xf_link_spec *s = &l->spec;
    if (s->kind == XF_LINK_KIND_SERIAL) {
        return xf_serial_open(&l->as.serial, s->path, s->baud);
    }
    if (s->kind == XF_LINK_KIND_UDP) {
        xf_udp_config uc;
        xf_udp_config_init(&uc);
        uc.gcu_host = s->host;
        uc.gcu_port = s->port;
        uc.local_port = s->local_port;
        return xf_udp_open(&l->as.udp, &uc);
    }
    {
        xf_tcp_config tc;
        xf_tcp_config_init(&tc);
        tc.host = s->host;
        tc.port = s->port;
        if (s->connect_timeout_ms != 0u) {
            tc.connect_timeout_ms = s->connect_timeout_ms;
        }
        return xf_tcp_open(&l->as.tcp, &tc);
    }
}

/* The error of the link l->as holds (as l->spec.kind says). */
static const xf_os_error *xf__held_error(const xf_link *l)
{
    switch (l->spec.kind) {
    case XF_LINK_KIND_SERIAL: return &l->as.serial.error;
    case XF_LINK_KIND_UDP: return &l->as.udp.error;
    case XF_LINK_KIND_TCP: return &l->as.tcp.error;
    default: return &l->error;
    }
}

/* Close the link l->as holds; only after it was opened, or tried (the links set their descriptors to -1 first). */
static void xf__close_held(xf_link *l)
{
    switch (l->spec.kind) {
    case XF_LINK_KIND_SERIAL: xf_serial_close(&l->as.serial); break;
    case XF_LINK_KIND_UDP: xf_udp_close(&l->as.udp); break;
    case XF_LINK_KIND_TCP: xf_tcp_close(&l->as.tcp); break;
    default: break;
    }
}

xf_err xf_link_open_spec(xf_link *l, const xf_link_spec *spec)
{
    xf_link_spec copy;
    xf_err err;
    if (l == NULL) {
        return XF_ERR_ARG;
    }
    if (spec == NULL) {
        memset(l, 0, sizeof(*l));
        return xf__fail(&l->error, XF_ERR_ARG, "no link spec given");
    }
    copy = *spec; /* spec may be &l->spec */
    memset(l, 0, sizeof(*l));
    l->spec = copy;
    memset(&l->spec.error, 0, sizeof(l->spec.error));
    err = xf__spec_check(&l->spec);
    if (err != XF_OK) {
        l->error = l->spec.error;
        l->spec.kind = XF_LINK_KIND_NONE;
        return err;
    }
    err = xf__link_open_kind(l);
    if (err != XF_OK) {
        l->error = *xf__held_error(l);
        if (l->error.text[0] == '\0') {
            (void)xf__fail(&l->error, err, "cannot open it: %s", xf_strerror(err));
        }
        xf__close_held(l); /* what the failed open left, if anything */
        return err;
    }
    l->is_open = 1;
    return XF_OK;
}

xf_err xf_link_open(xf_link *l, const char *spec)
{
    xf_err err;
    if (l == NULL) {
        return XF_ERR_ARG;
    }
    err = xf_link_spec_parse(spec, &l->spec);
    if (err != XF_OK) {
        xf_link_spec failed = l->spec;
        memset(l, 0, sizeof(*l));
        l->spec = failed;
        l->error = failed.error;
        return err;
    }
    return xf_link_open_spec(l, &l->spec);
}

xf_err xf_link_wait(xf_link *l, uint32_t timeout_ms)
{
    if (l == NULL) {
        return XF_ERR_ARG;
    }
    if (!l->is_open) {
        return XF_ERR_CLOSED;
    }
    return (l->spec.kind == XF_LINK_KIND_TCP) ? xf_tcp_wait(&l->as.tcp, timeout_ms) : XF_OK;
}

xf_err xf_link_hal(xf_link *l, xf_hal *hal)
{
    if (l == NULL || hal == NULL) {
        return XF_ERR_ARG;
    }
    if (!l->is_open) {
        return XF_ERR_CLOSED;
    }
    switch (l->spec.kind) {
    case XF_LINK_KIND_SERIAL: xf_serial_hal(&l->as.serial, hal); break;
    case XF_LINK_KIND_UDP: xf_udp_hal(&l->as.udp, hal); break;
    case XF_LINK_KIND_TCP: xf_tcp_hal(&l->as.tcp, hal); break;
    default: return XF_ERR_CLOSED;
    }
    return XF_OK;
}

int xf_link_keeps_order(const xf_link_spec *spec)
{
    return spec != NULL && (spec->kind == XF_LINK_KIND_SERIAL || spec->kind == XF_LINK_KIND_TCP);
}

void xf_link_close(xf_link *l)
{
    if (l != NULL && l->is_open) { /* a zeroed link holds descriptor 0: never closed */
        xf__close_held(l);
        l->is_open = 0;
    }
}

const xf_os_error *xf_link_error(const xf_link *l)
{
    if (l == NULL) {
        return NULL;
    }
    return l->is_open ? xf__held_error(l) : &l->error;
}

size_t xf_link_describe(const xf_link *l, char *buf, size_t cap)
{
    const xf_link_spec *s = (l != NULL) ? &l->spec : NULL;
    if (buf == NULL) {
        cap = 0;
    }
    if (s == NULL || (s->kind != XF_LINK_KIND_SERIAL && s->kind != XF_LINK_KIND_UDP && s->kind != XF_LINK_KIND_TCP) ||
        memchr(s->host, '\0', sizeof(s->host)) == NULL || memchr(s->path, '\0', sizeof(s->path)) == NULL) {
        return xf__print(buf, cap, "none");
    }
    if (s->kind == XF_LINK_KIND_SERIAL) {
        return xf__print(buf, cap, "serial %s at %u baud", s->path, (unsigned)s->baud);
    }
    return xf__print(buf, cap, strchr(s->host, ':') != NULL ? "%s [%s]:%u" : "%s %s:%u",
                     s->kind == XF_LINK_KIND_TCP ? "tcp" : "udp", s->host, (unsigned)s->port);
}
