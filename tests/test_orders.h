/*
 * test_orders.h - the order tables of docs/protocol.md §7 and §10, restated
 * for the tests: each order's name, the version that introduced it, its
 * default camera mask, whether its failure feedback is a camera mask, and
 * its parameter layout. Plus a reference encoder and a reference range
 * check written from those tables, so that the codec's own table
 * (xf_order_info) is checked against the spec and not against itself.
 */
#ifndef XFGCU_TEST_ORDERS_H
#define XFGCU_TEST_ORDERS_H

#include "test_util.h"

typedef struct order_spec {
    uint8_t order;
    const char *name;
    uint8_t since;           /* 1: V0.1 (§7); 2: added by V0.2 (§10) */
    uint8_t default_cameras; /* KK default (§7 "KK (0x01)", §9.4; thermal orders 0x02), 0 = no mask */
    uint8_t mask_failure;    /* failure feedback is NN, the failed-camera mask */
    uint8_t operating;       /* may answer 0x02 "operating" (calibration) */
    uint8_t nlayout;
    xf_field layout[6]; /* parameters in wire order */
} order_spec;

#define L0()                                                                                                           \
    0, { XF_F_CAMERAS }
#define L1(a)                                                                                                          \
    1, { a }
#define L2(a, b)                                                                                                       \
    2, { a, b }
#define L3(a, b, c)                                                                                                    \
    3, { a, b, c }
#define L4(a, b, c, d)                                                                                                 \
    4, { a, b, c, d }
#define L6(a, b, c, d, e, f)                                                                                           \
    6, { a, b, c, d, e, f }

static const order_spec order_specs[] = {
    /* §7, protocol V0.1 */
    {0x00, "null", 1, 0, 0, 0, L0()},
    {0x01, "calibration", 1, 0, 0, 1, L0()},
    {0x03, "neutral", 1, 0, 0, 0, L0()},
    {0x10, "angle_control", 1, 0, 0, 0, L0()},
    {0x11, "head_lock", 1, 0, 0, 0, L0()},
    {0x12, "head_follow", 1, 0, 0, 0, L0()},
    {0x13, "orthoview", 1, 0, 0, 0, L0()},
    {0x14, "euler", 1, 0, 0, 0, L0()},
    {0x15, "gaze_geo", 1, 0, 0, 0, L3(XF_F_LONGITUDE, XF_F_LATITUDE, XF_F_ALTITUDE)},
    {0x16, "gaze_lock", 1, 0, 0, 0, L0()},
    {0x17, "track", 1, 0x01, 1, 0, L6(XF_F_CAMERAS, XF_F_VALUE, XF_F_X0, XF_F_Y0, XF_F_X1, XF_F_Y1)},
    {0x1A, "click_to_aim", 1, 0x01, 1, 0, L3(XF_F_CAMERAS, XF_F_X0, XF_F_Y0)},
    {0x1B, "external_track", 1, 0x01, 1, 0, L4(XF_F_CAMERAS, XF_F_DX, XF_F_DY, XF_F_VALUE)},
    {0x20, "shutter", 1, 0x01, 0, 0, L1(XF_F_CAMERAS)},
    {0x21, "record", 1, 0x01, 0, 0, L1(XF_F_CAMERAS)},
    {0x22, "zoom_in", 1, 0x01, 1, 0, L1(XF_F_CAMERAS)},
    {0x23, "zoom_out", 1, 0x01, 1, 0, L1(XF_F_CAMERAS)},
    {0x24, "zoom_stop", 1, 0x01, 1, 0, L1(XF_F_CAMERAS)},
    {0x25, "zoom_to", 1, 0x01, 1, 0, L2(XF_F_CAMERAS, XF_F_ZOOM)},
    {0x26, "focus", 1, 0x01, 0, 0, L1(XF_F_CAMERAS)},
    {0x2A, "palette", 1, 0x02, 1, 0, L2(XF_F_CAMERAS, XF_F_VALUE)},
    {0x2B, "night_vision", 1, 0x01, 0, 0, L2(XF_F_CAMERAS, XF_F_VALUE)},
    {0x73, "osd", 1, 0, 0, 0, L1(XF_F_VALUE)},
    {0x74, "pip", 1, 0, 0, 0, L1(XF_F_VALUE)},
    {0x80, "lighting", 1, 0, 0, 0, L1(XF_F_VALUE)},
    {0x81, "ranging", 1, 0, 0, 0, L1(XF_F_VALUE)},
    /* §10, protocol V0.2 */
    {0x06, "osd_coordinate", 2, 0, 0, 0, L1(XF_F_VALUE)},
    {0x07, "auto_flip", 2, 0, 0, 0, L1(XF_F_VALUE)},
    {0x08, "time_zone", 2, 0, 0, 0, L1(XF_F_HOURS)},
    {0x1C, "fpv", 2, 0, 0, 0, L0()},
    {0x30, "area_temp", 2, 0x02, 1, 0, L6(XF_F_CAMERAS, XF_F_VALUE, XF_F_X0, XF_F_Y0, XF_F_X1, XF_F_Y1)},
    {0x31, "temp_alarm", 2, 0x02, 1, 0, L4(XF_F_CAMERAS, XF_F_VALUE, XF_F_TEMP_HIGH, XF_F_TEMP_LOW)},
    {0x32, "isotherm", 2, 0x02, 1, 0, L4(XF_F_CAMERAS, XF_F_VALUE, XF_F_TEMP_HIGH, XF_F_TEMP_LOW)},
    {0x33, "spot_temp", 2, 0x02, 1, 0, L4(XF_F_CAMERAS, XF_F_VALUE, XF_F_X0, XF_F_Y0)},
    {0x75, "target_detection", 2, 0, 0, 0, L1(XF_F_VALUE)},
    {0x76, "digital_zoom", 2, 0, 0, 0, L1(XF_F_VALUE)},
};

#define ALL_FIELDS_COUNT 15
static const xf_field all_fields[ALL_FIELDS_COUNT] = {
    XF_F_CAMERAS, XF_F_VALUE, XF_F_HOURS,     XF_F_X0,       XF_F_Y0,        XF_F_X1,       XF_F_Y1,       XF_F_DX,
    XF_F_DY,      XF_F_ZOOM,  XF_F_TEMP_HIGH, XF_F_TEMP_LOW, XF_F_LONGITUDE, XF_F_LATITUDE, XF_F_ALTITUDE,
};

static inline const order_spec *order_spec_find(uint8_t order)
{
    size_t i;
    for (i = 0; i < ARRAY_LEN(order_specs); i++) {
        if (order_specs[i].order == order) {
            return &order_specs[i];
        }
    }
    return NULL;
}

/* Wire size and signedness of each parameter, from the spec's tables:
 * KK and TT are U8, the time zone S8, grid coordinates U16, offsets, zoom
 * and temperatures S16, geo-coordinates S32. */
static inline size_t spec_field_size(xf_field f)
{
    switch (f) {
    case XF_F_CAMERAS:
    case XF_F_VALUE:
    case XF_F_HOURS: return 1;
    case XF_F_LONGITUDE:
    case XF_F_LATITUDE:
    case XF_F_ALTITUDE: return 4;
    default: return 2;
    }
}

static inline size_t spec_params_len(const order_spec *s)
{
    size_t i, n = 0;
    for (i = 0; i < s->nlayout; i++) {
        n += spec_field_size(s->layout[i]);
    }
    return n;
}

/* Direct member access (not xf_command_get/set, which are under test). */
static inline int32_t cmd_get(const xf_command *c, xf_field f)
{
    switch (f) {
    case XF_F_CAMERAS: return c->cameras;
    case XF_F_VALUE: return c->value;
    case XF_F_HOURS: return c->hours;
    case XF_F_X0: return c->x0;
    case XF_F_Y0: return c->y0;
    case XF_F_X1: return c->x1;
    case XF_F_Y1: return c->y1;
    case XF_F_DX: return c->dx;
    case XF_F_DY: return c->dy;
    case XF_F_ZOOM: return c->zoom;
    case XF_F_TEMP_HIGH: return c->temp_high;
    case XF_F_TEMP_LOW: return c->temp_low;
    case XF_F_LONGITUDE: return c->longitude;
    case XF_F_LATITUDE: return c->latitude;
    case XF_F_ALTITUDE: return c->altitude;
    default: return 0;
    }
}

/* The caller passes a value that fits the member. */
static inline void cmd_put(xf_command *c, xf_field f, int32_t v)
{
    switch (f) {
    case XF_F_CAMERAS: c->cameras = (uint8_t)v; break;
    case XF_F_VALUE: c->value = (uint8_t)v; break;
    case XF_F_HOURS: c->hours = (int8_t)v; break;
    case XF_F_X0: c->x0 = (uint16_t)v; break;
    case XF_F_Y0: c->y0 = (uint16_t)v; break;
    case XF_F_X1: c->x1 = (uint16_t)v; break;
    case XF_F_Y1: c->y1 = (uint16_t)v; break;
    case XF_F_DX: c->dx = (int16_t)v; break;
    case XF_F_DY: c->dy = (int16_t)v; break;
    case XF_F_ZOOM: c->zoom = (int16_t)v; break;
    case XF_F_TEMP_HIGH: c->temp_high = (int16_t)v; break;
    case XF_F_TEMP_LOW: c->temp_low = (int16_t)v; break;
    case XF_F_LONGITUDE: c->longitude = v; break;
    case XF_F_LATITUDE: c->latitude = v; break;
    case XF_F_ALTITUDE: c->altitude = v; break;
    default: break;
    }
}

static inline const char *spec_field_name(xf_field f)
{
    static const char *const names[ALL_FIELDS_COUNT] = {
        "cameras", "value", "hours",     "x0",       "y0",        "x1",       "y1",       "dx",
        "dy",      "zoom",  "temp_high", "temp_low", "longitude", "latitude", "altitude",
    };
    return ((unsigned)f < ALL_FIELDS_COUNT) ? names[f] : "?";
}

/* Reference encoder: the layout's members, little-endian. */
static inline size_t ref_encode(const xf_command *c, const order_spec *s, uint8_t *out)
{
    size_t i, off = 0;
    for (i = 0; i < s->nlayout; i++) {
        size_t n = spec_field_size(s->layout[i]);
        le_put(out + off, (uint64_t)(int64_t)cmd_get(c, s->layout[i]), n);
        off += n;
    }
    return off;
}

#define BAD(f) (1u << (unsigned)(f))

/* Reference range check (docs/protocol.md §7, §10, plus the library's
 * documented conventions: a camera mask is never 0, boxes go top-left to
 * bottom-right, an alarm's high is not below its low, time zones are
 * [-12, 14]). Returns the set of members that break a rule. */
static inline unsigned ref_bad_fields(const xf_command *c, uint8_t version)
{
    const order_spec *s = order_spec_find(c->order);
    unsigned bad = 0;
    size_t i;
    int v2 = version >= 2;
    if (s == NULL) {
        return 0;
    }
    for (i = 0; i < s->nlayout; i++) {
        if (s->layout[i] == XF_F_CAMERAS && c->cameras == 0) {
            bad |= BAD(XF_F_CAMERAS);
        }
    }
    if (v2 && (c->order == 0x17 || c->order == 0x1A) && c->cameras != 1) {
        bad |= BAD(XF_F_CAMERAS); /* track, click_to_aim: V2.0.6 fixes the first byte at 0x01 */
    }
    switch (c->order) {
    case 0x17: /* track */
    case 0x30: /* area_temp */
        if (c->value > 1)
            bad |= BAD(XF_F_VALUE);
        if (c->x0 > 10000)
            bad |= BAD(XF_F_X0);
        if (c->y0 > 10000)
            bad |= BAD(XF_F_Y0);
        if (c->x1 > 10000 || c->x1 < c->x0)
            bad |= BAD(XF_F_X1);
        if (c->y1 > 10000 || c->y1 < c->y0)
            bad |= BAD(XF_F_Y1);
        break;
    case 0x33: /* spot_temp */
        if (c->value > 1)
            bad |= BAD(XF_F_VALUE);
        /* fall through */
    case 0x1A: /* click_to_aim */
        if (c->x0 > 10000)
            bad |= BAD(XF_F_X0);
        if (c->y0 > 10000)
            bad |= BAD(XF_F_Y0);
        break;
    case 0x1B: /* external_track: [-1024, 1024], or both >= 3071 = lost */
        if (c->value != 0 && c->value != 2)
            bad |= BAD(XF_F_VALUE);
        if (!(c->dx >= 3071 && c->dy >= 3071)) {
            if (c->dx < -1024 || c->dx > 1024)
                bad |= BAD(XF_F_DX);
            if (c->dy < -1024 || c->dy > 1024)
                bad |= BAD(XF_F_DY);
        }
        break;
    case 0x25: /* zoom_to: [-32768, -10] or [1, 10000] */
        if (!(c->zoom <= -10 || (c->zoom >= 1 && c->zoom <= 10000)))
            bad |= BAD(XF_F_ZOOM);
        break;
    case 0x2A: /* palette: [0, 100] in V0.1, [0, 10] in V0.2 */
        if (c->value > (v2 ? 10 : 100))
            bad |= BAD(XF_F_VALUE);
        break;
    case 0x74: /* pip: 0 in V0.1, [0, 4] in V0.2 */
        if (c->value > (v2 ? 4 : 0))
            bad |= BAD(XF_F_VALUE);
        break;
    case 0x2B: /* night_vision: 0 off, 1 on, 2 auto */
        if (c->value > 2)
            bad |= BAD(XF_F_VALUE);
        break;
    case 0x81: /* ranging: 0 off, 2 on */
        if (c->value != 0 && c->value != 2)
            bad |= BAD(XF_F_VALUE);
        break;
    case 0x73:
    case 0x06:
    case 0x07:
    case 0x75:
    case 0x76: /* on/off, show/hide */
        if (c->value > 1)
            bad |= BAD(XF_F_VALUE);
        break;
    case 0x08: /* time_zone */
        if (c->hours < -12 || c->hours > 14)
            bad |= BAD(XF_F_HOURS);
        break;
    case 0x31: /* temp_alarm */
    case 0x32: /* isotherm */
        if (c->value > 1)
            bad |= BAD(XF_F_VALUE);
        else if (c->value == 1 && c->temp_high < c->temp_low)
            bad |= BAD(XF_F_TEMP_HIGH) | BAD(XF_F_TEMP_LOW);
        break;
    default: break; /* lighting: any level; the rest take no checked value */
    }
    return bad;
}

/* Two commands equal in every member (order included). */
static inline void test_cmd_equal(const xf_command *got, const xf_command *want, const char *file, int line)
{
    size_t i;
    if (got->order != want->order) {
        print_error("order: got 0x%02X, expected 0x%02X\n", got->order, want->order);
        _fail(file, line);
    }
    for (i = 0; i < ALL_FIELDS_COUNT; i++) {
        xf_field f = all_fields[i];
        if (cmd_get(got, f) != cmd_get(want, f)) {
            print_error("order 0x%02X member %s: got %ld, expected %ld\n", want->order, spec_field_name(f),
                        (long)cmd_get(got, f), (long)cmd_get(want, f));
            _fail(file, line);
        }
    }
}
#define assert_cmd_equal(got, want) test_cmd_equal((got), (want), __FILE__, __LINE__)

#endif /* XFGCU_TEST_ORDERS_H */
