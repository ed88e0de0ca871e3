/*
 * fieldtext.c - the fields of the codec's table as text (fieldtext.h).
 */
#include "fieldtext.h"

#include <stdio.h>
#include <string.h>

void fieldtext_version(uint8_t raw, char *buf, size_t cap)
{
    snprintf(buf, cap, "%u.%u", (unsigned)raw / 10u, (unsigned)raw % 10u);
}

int fieldtext_hex(const xf_wire_field *f)
{
    return f->kind == XF_WIRE_BYTE || f->kind == XF_WIRE_FLAGS ||
           (f->kind == XF_WIRE_ENUM && f->value_name != xf_gimbal_model); /* model codes are decimal */
}

void fieldtext_model(uint8_t code, char *buf, size_t cap)
{
    const char *name = xf_gimbal_model(code);
    snprintf(buf, cap, "%s (code %u)", name != NULL ? name : "unknown model", (unsigned)code);
}

/* The number with the decimals of its step and its unit: "-30.00 deg", "5.5x", "3.1". */
static void number_text(const xf_wire_field *f, int64_t raw, uint8_t version, char *buf, size_t cap)
{
    unsigned d = xf_wire_field_decimals(f, version);
    const char *sep = (f->unit[0] == '\0' || strcmp(f->unit, "x") == 0) ? "" : " ";
    snprintf(buf, cap, "%.*f%s%s", (int)d, xf_wire_field_value(f, raw, version), sep, f->unit);
}

void fieldtext_value(const xf_wire_field *f, int64_t raw, uint8_t version, text_view view, char *buf, size_t cap)
{
    if (view == TEXT_RAW || f->kind != XF_WIRE_NUMBER) {
        snprintf(buf, cap, "%lld", (long long)raw);
    } else if (strcmp(f->name, "target_distance") == 0 && raw <= 0) {
        snprintf(buf, cap, "no valid measurement"); /* -10 and 0: docs/protocol.md §9.8 */
    } else {
        number_text(f, raw, version, buf, cap);
    }
}

size_t reserved_span(const xf_wire_field *f, uint8_t version, size_t *len)
{
    size_t n;
    const xf_wire_field *first = xf_wire_fields((xf_wire_group)f->group, &n);
    const xf_wire_field *start = f;
    while (start > first && !xf_wire_field_present(start - 1, version)) {
        start--;
    }
    *len = (size_t)(f->offset + f->width - start->offset);
    return start->offset;
}

const xf_wire_field *pod_row(void) { return xf_wire_field_find(XF_WIRE_GCU, "pod_status"); }

xf_pod_order pod_order_for(uint16_t pod_status, pod_reading how)
{
    switch (how) {
    case POD_READ_LE: return XF_POD_ORDER_LE;
    case POD_READ_BE: return XF_POD_ORDER_BE;
    default:
        /* the word does not tell: the order both documents state */
        return (xf_pod_status_order(pod_status) == XF_POD_ORDER_BE) ? XF_POD_ORDER_BE : XF_POD_ORDER_LE;
    }
}

const char *pod_order_name(xf_pod_order order) { return (order == XF_POD_ORDER_BE) ? "be" : "le"; }
