/*
 * test_command.c - xf_command.h: the order table against the spec, a golden
 * parameter vector for every order (bytes written by hand from docs/protocol.md §7 and §10),
 * encode and decode, every range rule, version-aware ranges, feedback
 * decoding for every order, and the error paths.
 */
#include "test_orders.h"

typedef struct fv {
    xf_field f;
    int32_t v;
} fv;

/* A golden vector: the command (xf_command_init(order) plus `set`), the
 * protocol version to encode for, and the parameter bytes written by hand. */
typedef struct golden {
    uint8_t order;
    uint8_t version;
    size_t nset;
    fv set[6];
    size_t len;
    uint8_t bytes[12];
} golden;

#define S0()                                                                                                           \
    0,                                                                                                                 \
    {                                                                                                                  \
        {                                                                                                              \
            XF_F_CAMERAS, 0                                                                                            \
        }                                                                                                              \
    }
#define S1(a, b)                                                                                                       \
    1,                                                                                                                 \
    {                                                                                                                  \
        {                                                                                                              \
            a, b                                                                                                       \
        }                                                                                                              \
    }
#define S2(a, b, c, d)                                                                                                 \
    2,                                                                                                                 \
    {                                                                                                                  \
        {a, b}, { c, d }                                                                                               \
    }
#define S3(a, b, c, d, e, f)                                                                                           \
    3,                                                                                                                 \
    {                                                                                                                  \
        {a, b}, {c, d}, { e, f }                                                                                       \
    }
#define S5(a, b, c, d, e, f, g, h, i, j)                                                                               \
    5,                                                                                                                 \
    {                                                                                                                  \
        {a, b}, {c, d}, {e, f}, {g, h}, { i, j }                                                                       \
    }
#define B0()                                                                                                           \
    0, { 0 }

/* One per order of the table (the first 36 rows), then extra vectors. */
static const golden goldens[] = {
    {0x00, 1, S0(), B0()},                    /* null */
    {0x01, 1, S0(), B0()},                    /* calibration */
    {0x03, 1, S0(), B0()},                    /* neutral */
    {0x06, 2, S1(XF_F_VALUE, 1), 1, {0x01}},  /* osd_coordinate: target */
    {0x07, 2, S1(XF_F_VALUE, 1), 1, {0x01}},  /* auto_flip: off */
    {0x08, 2, S1(XF_F_HOURS, -2), 1, {0xFE}}, /* time_zone -2 = 0xFE (§10) */
    {0x10, 1, S0(), B0()},                    /* angle_control */
    {0x11, 1, S0(), B0()},                    /* head_lock */
    {0x12, 1, S0(), B0()},                    /* head_follow */
    {0x13, 1, S0(), B0()},                    /* orthoview */
    {0x14, 1, S0(), B0()},                    /* euler */
    /* gaze_geo: lon 170.9175332 (1709175332 = 0x65DFF224), lat -38.0300822
     * (-380300822 = 0xE95511EA), alt 41.123 m (41123 = 0x0000A0A3) */
    {0x15,
     1,
     S3(XF_F_LONGITUDE, 1709175332, XF_F_LATITUDE, -380300822, XF_F_ALTITUDE, 41123),
     12,
     {0x24, 0xF2, 0xDF, 0x65, 0xEA, 0x11, 0x55, 0xE9, 0xA3, 0xA0, 0x00, 0x00}},
    {0x16, 1, S0(), B0()}, /* gaze_lock */
    /* track start, box (100,100)-(105,105), camera 1 (vendor appendix 4) */
    {0x17,
     1,
     S5(XF_F_VALUE, 1, XF_F_X0, 100, XF_F_Y0, 100, XF_F_X1, 105, XF_F_Y1, 105),
     10,
     {0x01, 0x01, 0x64, 0x00, 0x64, 0x00, 0x69, 0x00, 0x69, 0x00}},
    /* click_to_aim x=10000 (0x2710) y=5000 (0x1388) (vendor appendix 4) */
    {0x1A, 1, S2(XF_F_X0, 10000, XF_F_Y0, 5000), 5, {0x01, 0x10, 0x27, 0x88, 0x13}},
    /* external_track start, dx -1024 (0xFC00), dy 512 (0x0200) */
    {0x1B, 1, S3(XF_F_DX, -1024, XF_F_DY, 512, XF_F_VALUE, 2), 6, {0x01, 0x00, 0xFC, 0x00, 0x02, 0x02}},
    {0x1C, 2, S0(), B0()},      /* fpv */
    {0x20, 1, S0(), 1, {0x01}}, /* shutter, KK default 0x01 */
    {0x21, 1, S0(), 1, {0x01}}, /* record */
    {0x22, 1, S0(), 1, {0x01}}, /* zoom_in */
    {0x23, 1, S0(), 1, {0x01}}, /* zoom_out */
    {0x24, 1, S0(), 1, {0x01}}, /* zoom_stop */
    /* all cameras to 5.5x: ZZ = -55 = 0xFFC9 (vendor appendix 4) */
    {0x25, 1, S2(XF_F_CAMERAS, 0xFF, XF_F_ZOOM, -55), 3, {0xFF, 0xC9, 0xFF}},
    {0x26, 1, S0(), 1, {0x01}},                    /* focus */
    {0x2A, 1, S0(), 2, {0x02, 0x00}},              /* palette: next, thermal camera */
    {0x2B, 1, S1(XF_F_VALUE, 1), 2, {0x01, 0x01}}, /* night vision on */
    /* area_temp on, box (1000,2000)-(3000,4000) */
    {0x30,
     2,
     S5(XF_F_VALUE, 1, XF_F_X0, 1000, XF_F_Y0, 2000, XF_F_X1, 3000, XF_F_Y1, 4000),
     10,
     {0x02, 0x01, 0xE8, 0x03, 0xD0, 0x07, 0xB8, 0x0B, 0xA0, 0x0F}},
    /* temp_alarm on, high 50.0 C (500 = 0x01F4), low -20.0 C (-200 = 0xFF38) */
    {0x31, 2, S3(XF_F_VALUE, 1, XF_F_TEMP_HIGH, 500, XF_F_TEMP_LOW, -200), 6, {0x02, 0x01, 0xF4, 0x01, 0x38, 0xFF}},
    /* isotherm on, 100.0 C .. 25.0 C */
    {0x32, 2, S3(XF_F_VALUE, 1, XF_F_TEMP_HIGH, 1000, XF_F_TEMP_LOW, 250), 6, {0x02, 0x01, 0xE8, 0x03, 0xFA, 0x00}},
    /* spot_temp on at (5000, 10000) */
    {0x33, 2, S3(XF_F_VALUE, 1, XF_F_X0, 5000, XF_F_Y0, 10000), 6, {0x02, 0x01, 0x88, 0x13, 0x10, 0x27}},
    {0x73, 1, S1(XF_F_VALUE, 1), 1, {0x01}},   /* osd hide */
    {0x74, 2, S1(XF_F_VALUE, 3), 1, {0x03}},   /* pip mode 3 (V0.2) */
    {0x75, 2, S1(XF_F_VALUE, 1), 1, {0x01}},   /* target_detection on */
    {0x76, 2, S1(XF_F_VALUE, 1), 1, {0x01}},   /* digital_zoom on */
    {0x80, 1, S1(XF_F_VALUE, 255), 1, {0xFF}}, /* lighting 255 (appendix 4) */
    {0x81, 1, S1(XF_F_VALUE, 2), 1, {0x02}},   /* ranging on (0x02) */
    /* ---- extra vectors ---- */
    {0x25, 1, S1(XF_F_ZOOM, 5000), 3, {0x01, 0x88, 0x13}},                    /* camera 1 to half range */
    {0x25, 1, S2(XF_F_CAMERAS, 0xFF, XF_F_ZOOM, -10), 3, {0xFF, 0xF6, 0xFF}}, /* all to 1.0x */
    {0x25, 2, S2(XF_F_CAMERAS, 0x03, XF_F_ZOOM, -32768), 3, {0x03, 0x00, 0x80}},
    {0x08, 2, S1(XF_F_HOURS, 14), 1, {0x0E}},
    {0x08, 2, S1(XF_F_HOURS, -12), 1, {0xF4}},
    {0x74, 1, S0(), 1, {0x00}}, /* pip next (V0.1) */
    {0x2A, 2, S1(XF_F_VALUE, 10), 2, {0x02, 0x0A}},
    {0x2A, 1, S2(XF_F_CAMERAS, 0x01, XF_F_VALUE, 100), 2, {0x01, 0x64}},
    {0x1B, 1, S3(XF_F_DX, 3071, XF_F_DY, 3071, XF_F_VALUE, 2), 6, {0x01, 0xFF, 0x0B, 0xFF, 0x0B, 0x02}}, /* lost */
    {0x1B, 1, S2(XF_F_DX, 1024, XF_F_DY, -1), 6, {0x01, 0x00, 0x04, 0xFF, 0xFF, 0x00}},                  /* exit */
    {0x17, 1, S0(), 10, {0x01, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00}},                   /* exit */
    {0x2B, 1, S1(XF_F_VALUE, 2), 2, {0x01, 0x02}}, /* night vision auto */
    {0x80, 1, S0(), 1, {0x00}},                    /* lighting off */
    {0x81, 1, S0(), 1, {0x00}},                    /* ranging off */
    {0x31, 2, S3(XF_F_VALUE, 0, XF_F_TEMP_HIGH, -300, XF_F_TEMP_LOW, 300), 6, {0x02, 0x00, 0xD4, 0xFE, 0x2C, 0x01}},
    {0x15,
     2,
     S3(XF_F_LONGITUDE, -1, XF_F_LATITUDE, 0x7FFFFFFF, XF_F_ALTITUDE, (int32_t)-2147483647 - 1),
     12,
     {0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0x7F, 0x00, 0x00, 0x00, 0x80}},
};

static void golden_cmd(const golden *g, xf_command *c)
{
    size_t i;
    const order_spec *s = order_spec_find(g->order);
    memset(c, 0, sizeof(*c));
    c->order = g->order;
    c->cameras = s->default_cameras;
    for (i = 0; i < g->nset; i++) {
        cmd_put(c, g->set[i].f, g->set[i].v);
    }
}

static const golden *golden_for(uint8_t order)
{
    size_t i;
    for (i = 0; i < ARRAY_LEN(goldens); i++) {
        if (goldens[i].order == order) {
            return &goldens[i];
        }
    }
    return NULL;
}

/* ---- the order table ------------------------------------------------------ */

/* xf_order_at lists exactly the 36 orders of §7 and §10, each with its
 * spec name, version, default mask, feedback kind and layout. */
static void test_order_table_matches_spec(void **state)
{
    size_t i, k;
    (void)state;
    assert_int_equal(XF_ORDER_COUNT, 36);
    assert_int_equal(ARRAY_LEN(order_specs), 36);
    assert_null(xf_order_at(36));
    assert_null(xf_order_at(1000));
    for (i = 0; i < XF_ORDER_COUNT; i++) {
        const xf_order_info *info = xf_order_at(i);
        const order_spec *s;
        assert_non_null(info);
        s = order_spec_find(info->order);
        if (s == NULL) {
            print_error("order 0x%02X is not in the spec\n", info->order);
            fail();
        }
        assert_int_equal(info->since, s->since);
        assert_int_equal(info->default_cameras, s->default_cameras);
        assert_int_equal((info->flags & XF_ORDER_MASK_FAILURE) != 0, s->mask_failure);
        assert_int_equal((info->flags & XF_ORDER_OPERATING) != 0, s->operating);
        /* only external_track is streamed (§7) */
        assert_int_equal((info->flags & XF_ORDER_STREAMED) != 0, info->order == 0x1B);
        assert_int_equal((info->flags & XF_ORDER_V1_ONLY) != 0, info->order == 0x1B); /* dropped by V2.0.6 */
        assert_int_equal(info->nfields, s->nlayout);
        for (k = 0; k < s->nlayout; k++) {
            assert_int_equal(info->fields[k], s->layout[k]);
            assert_int_equal(xf_field_size((xf_field)info->fields[k]), spec_field_size(s->layout[k]));
        }
        assert_int_equal(xf_order_params_len(info->order), spec_params_len(s));
        assert_ptr_equal(xf_order_lookup(info->order), info);
        assert_string_equal(xf_order_name(info->order), s->name);
        for (k = 0; k < i; k++) {
            assert_int_not_equal(xf_order_at(k)->order, info->order);
        }
    }
    /* every spec order is listed (so the two sets are equal) */
    for (i = 0; i < ARRAY_LEN(order_specs); i++) {
        assert_non_null(xf_order_lookup(order_specs[i].order));
    }
    /* and nothing else is known */
    for (i = 0; i < 256; i++) {
        if (order_spec_find((uint8_t)i) == NULL) {
            assert_null(xf_order_lookup((uint8_t)i));
            assert_null(xf_order_name((uint8_t)i));
            assert_int_equal(xf_order_params_len((uint8_t)i), 0);
        }
    }
    /* the longest block is gaze_geo's 12 bytes (§2: largest packet 84) */
    assert_int_equal(XF_PARAMS_KNOWN_MAX, 12);
}

static void test_order_names(void **state)
{
    size_t i;
    uint8_t o;
    (void)state;
    for (i = 0; i < ARRAY_LEN(order_specs); i++) {
        char dashed[32];
        size_t k;
        o = 0xEE;
        assert_err(xf_order_from_name(order_specs[i].name, &o), XF_OK);
        assert_int_equal(o, order_specs[i].order);
        /* '-' and '_' are the same */
        for (k = 0; order_specs[i].name[k] != '\0' && k + 1 < sizeof(dashed); k++) {
            dashed[k] = (order_specs[i].name[k] == '_') ? '-' : order_specs[i].name[k];
        }
        dashed[k] = '\0';
        o = 0xEE;
        assert_err(xf_order_from_name(dashed, &o), XF_OK);
        assert_int_equal(o, order_specs[i].order);
    }
    o = 0xEE;
    /* an unknown name is "not found", as an unknown order byte is (test_command_errors) */
    assert_err(xf_order_from_name("zoom", &o), XF_ERR_NOT_FOUND);     /* prefix of zoom_in */
    assert_err(xf_order_from_name("zoom_inx", &o), XF_ERR_NOT_FOUND); /* longer */
    assert_err(xf_order_from_name("", &o), XF_ERR_NOT_FOUND);
    assert_err(xf_order_from_name("ZOOM_IN", &o), XF_ERR_NOT_FOUND);
    assert_int_equal(o, 0xEE);
    assert_err(xf_order_from_name(NULL, &o), XF_ERR_ARG);
    assert_err(xf_order_from_name("null", NULL), XF_ERR_ARG);
}

/* xf_command_init: zero, the order, and the spec's default mask (0x01;
 * palette and the V0.2 thermal orders 0x02; none for orders without KK). */
static void test_command_init_defaults(void **state)
{
    size_t i, k;
    (void)state;
    for (i = 0; i < ARRAY_LEN(order_specs); i++) {
        const order_spec *s = &order_specs[i];
        xf_command c;
        memset(&c, 0x6B, sizeof(c));
        xf_command_init(&c, s->order);
        assert_int_equal(c.order, s->order);
        assert_int_equal(c.cameras, s->default_cameras);
        for (k = 0; k < ALL_FIELDS_COUNT; k++) {
            if (all_fields[k] != XF_F_CAMERAS) {
                assert_sint_equal(cmd_get(&c, all_fields[k]), 0);
            }
        }
    }
    {
        xf_command c;
        xf_command_init(&c, 0x55); /* unknown order: no default mask */
        assert_int_equal(c.order, 0x55);
        assert_int_equal(c.cameras, 0);
        xf_command_init(NULL, 0x20); /* must not crash */
    }
    /* a few by hand, straight from §7 / §10 */
    {
        xf_command c;
        xf_command_init(&c, XF_ORDER_PALETTE);
        assert_int_equal(c.cameras, 0x02);
        xf_command_init(&c, XF_ORDER_SPOT_TEMP);
        assert_int_equal(c.cameras, 0x02);
        xf_command_init(&c, XF_ORDER_SHUTTER);
        assert_int_equal(c.cameras, 0x01);
        xf_command_init(&c, XF_ORDER_NIGHT_VISION);
        assert_int_equal(c.cameras, 0x01);
        xf_command_init(&c, XF_ORDER_OSD);
        assert_int_equal(c.cameras, 0x00);
    }
}

/* ---- golden vectors ------------------------------------------------------- */

static void check_golden(const golden *g)
{
    const order_spec *s = order_spec_find(g->order);
    xf_command c, d;
    xf_host_packet pkt;
    uint8_t out[32], ref[32], pbuf[100], want[100];
    size_t n = 999;
    xf_field bad = XF_F_NONE;
    memset(&d, 0, sizeof(d)); /* a failed decode below leaves d as it was */
    assert_non_null(s);
    golden_cmd(g, &c);

    /* the hand-written bytes agree with the spec layout (a check of the test) */
    assert_int_equal(ref_encode(&c, s, ref), g->len);
    assert_bytes_equal(ref, g->bytes, g->len);

    /* encode */
    memset(out, 0xEE, sizeof(out));
    assert_err(xf_command_encode(&c, g->version, out, sizeof(out), &n, &bad), XF_OK);
    assert_int_equal(n, g->len);
    assert_bytes_equal(out, g->bytes, g->len);
    assert_int_equal(out[g->len], 0xEE); /* nothing past the parameters */
    /* exactly enough room is enough */
    assert_err(xf_command_encode(&c, g->version, out, g->len, &n, &bad), XF_OK);

    /* decode */
    memset(&d, 0x5C, sizeof(d));
    assert_err(xf_command_decode(g->order, g->bytes, g->len, g->version, &d, &bad), XF_OK);
    assert_cmd_equal(&d, &c);

    /* into a host packet: order at 69, parameters from 70, length 72 + n */
    xf_host_packet_init(&pkt, g->version);
    assert_err(xf_host_set_command(&pkt, &c, &bad), XF_OK);
    assert_int_equal(pkt.order, g->order);
    assert_int_equal(pkt.params_len, g->len);
    assert_err(xf_host_pack(&pkt, pbuf, sizeof(pbuf), &n), XF_OK);
    assert_int_equal(n, 72u + g->len);
    memset(want, 0, sizeof(want));
    want[4] = g->version;
    want[30] = 0x01;
    want[69] = g->order;
    memcpy(want + 70, g->bytes, g->len);
    ref_finish_packet(want, 72u + g->len, XF_DIR_HOST);
    assert_bytes_equal(pbuf, want, 72u + g->len);
}

static void test_golden_every_order(void **state)
{
    size_t i;
    (void)state;
    /* a vector for each of the codec's 36 orders */
    for (i = 0; i < XF_ORDER_COUNT; i++) {
        const golden *g = golden_for(xf_order_at(i)->order);
        if (g == NULL) {
            print_error("no golden vector for order 0x%02X\n", xf_order_at(i)->order);
            fail();
        }
    }
    for (i = 0; i < ARRAY_LEN(goldens); i++) {
        check_golden(&goldens[i]);
    }
}

/* Members an order does not use are ignored on encode and zero after decode. */
static void test_unused_members_ignored(void **state)
{
    size_t i, k;
    (void)state;
    for (i = 0; i < ARRAY_LEN(order_specs); i++) {
        const golden *g = golden_for(order_specs[i].order);
        xf_command c, noisy, d;
        uint8_t out[32];
        size_t n = 0;
        memset(&d, 0, sizeof(d)); /* a failed decode below leaves d as it was */
        golden_cmd(g, &c);
        noisy = c;
        for (k = 0; k < ALL_FIELDS_COUNT; k++) {
            size_t j;
            int used = 0;
            for (j = 0; j < order_specs[i].nlayout; j++) {
                used |= order_specs[i].layout[j] == all_fields[k];
            }
            if (!used) {
                cmd_put(&noisy, all_fields[k], 0x4321);
            }
        }
        assert_err(xf_command_encode(&noisy, g->version, out, sizeof(out), &n, NULL), XF_OK);
        assert_int_equal(n, g->len);
        assert_bytes_equal(out, g->bytes, g->len);
        assert_err(xf_command_decode(g->order, out, n, g->version, &d, NULL), XF_OK);
        assert_cmd_equal(&d, &c);
    }
}

/* ---- range rules ---------------------------------------------------------- */

typedef struct range_case {
    uint8_t order;
    uint8_t version;
    size_t nset;
    fv set[4];
    const char *bad; /* NULL: valid */
} range_case;

#define R1(a, b)                                                                                                       \
    1,                                                                                                                 \
    {                                                                                                                  \
        {                                                                                                              \
            a, b                                                                                                       \
        }                                                                                                              \
    }
#define R2(a, b, c, d)                                                                                                 \
    2,                                                                                                                 \
    {                                                                                                                  \
        {a, b}, { c, d }                                                                                               \
    }
#define R3(a, b, c, d, e, f)                                                                                           \
    3,                                                                                                                 \
    {                                                                                                                  \
        {a, b}, {c, d}, { e, f }                                                                                       \
    }
#define R4(a, b, c, d, e, f, g, h)                                                                                     \
    4,                                                                                                                 \
    {                                                                                                                  \
        {a, b}, {c, d}, {e, f}, { g, h }                                                                               \
    }

/* Each on top of the order's first golden vector (a valid command). */
static const range_case range_cases[] = {
    /* track: TT 0/1, corners on [0, 10000], top-left then bottom-right */
    {0x17, 1, R1(XF_F_VALUE, 2), "value"},
    {0x17, 1, R1(XF_F_VALUE, 0), NULL},
    {0x17, 1, R2(XF_F_X0, 10001, XF_F_X1, 10001), "x0"},
    {0x17, 1, R2(XF_F_Y0, 10001, XF_F_Y1, 10001), "y0"},
    {0x17, 1, R1(XF_F_X1, 10001), "x1"},
    {0x17, 1, R1(XF_F_Y1, 10001), "y1"},
    {0x17, 1, R1(XF_F_X1, 99), "x1"},
    {0x17, 1, R1(XF_F_Y1, 99), "y1"},
    {0x17, 1, R1(XF_F_X1, 100), NULL},
    {0x17, 1, R4(XF_F_X0, 10000, XF_F_Y0, 10000, XF_F_X1, 10000, XF_F_Y1, 10000), NULL},
    {0x17, 1, R4(XF_F_X0, 0, XF_F_Y0, 0, XF_F_X1, 0, XF_F_Y1, 0), NULL},
    {0x17, 1, R1(XF_F_CAMERAS, 0), "cameras"},
    /* area_temp: same rules */
    {0x30, 2, R1(XF_F_VALUE, 2), "value"},
    {0x30, 2, R2(XF_F_X0, 10001, XF_F_X1, 10001), "x0"},
    {0x30, 2, R2(XF_F_Y0, 10001, XF_F_Y1, 10001), "y0"},
    {0x30, 2, R1(XF_F_X1, 10001), "x1"},
    {0x30, 2, R1(XF_F_Y1, 10001), "y1"},
    {0x30, 2, R1(XF_F_X1, 999), "x1"},
    {0x30, 2, R1(XF_F_Y1, 1999), "y1"},
    {0x30, 2, R1(XF_F_CAMERAS, 0), "cameras"},
    {0x30, 2, R4(XF_F_X0, 0, XF_F_Y0, 0, XF_F_X1, 10000, XF_F_Y1, 10000), NULL},
    /* click_to_aim: a point on the grid */
    {0x1A, 1, R1(XF_F_X0, 10001), "x0"},
    {0x1A, 1, R1(XF_F_Y0, 10001), "y0"},
    {0x1A, 1, R1(XF_F_Y0, 65535), "y0"},
    {0x1A, 1, R2(XF_F_X0, 10000, XF_F_Y0, 10000), NULL},
    {0x1A, 1, R2(XF_F_X0, 0, XF_F_Y0, 0), NULL},
    {0x1A, 1, R1(XF_F_CAMERAS, 0), "cameras"},
    /* spot_temp */
    {0x33, 2, R1(XF_F_VALUE, 2), "value"},
    {0x33, 2, R1(XF_F_X0, 10001), "x0"},
    {0x33, 2, R1(XF_F_Y0, 10001), "y0"},
    {0x33, 2, R1(XF_F_VALUE, 0), NULL},
    {0x33, 2, R1(XF_F_CAMERAS, 0), "cameras"},
    /* external_track: TT 0/2, offsets [-1024, 1024] unless both >= 3071 */
    {0x1B, 1, R1(XF_F_VALUE, 1), "value"},
    {0x1B, 1, R1(XF_F_VALUE, 3), "value"},
    {0x1B, 1, R1(XF_F_VALUE, 0), NULL},
    {0x1B, 1, R1(XF_F_DX, -1025), "dx"},
    {0x1B, 1, R1(XF_F_DX, 1025), "dx"},
    {0x1B, 1, R1(XF_F_DY, -1025), "dy"},
    {0x1B, 1, R1(XF_F_DY, 1025), "dy"},
    {0x1B, 1, R2(XF_F_DX, 1024, XF_F_DY, -1024), NULL},
    {0x1B, 1, R2(XF_F_DX, 3071, XF_F_DY, 3071), NULL},
    {0x1B, 1, R2(XF_F_DX, 32767, XF_F_DY, 5000), NULL},
    {0x1B, 1, R2(XF_F_DX, 3071, XF_F_DY, 0), "dx"},
    {0x1B, 1, R2(XF_F_DX, 0, XF_F_DY, 3071), "dy"},
    {0x1B, 1, R2(XF_F_DX, 3070, XF_F_DY, 3071), "dx"},
    {0x1B, 1, R1(XF_F_CAMERAS, 0), "cameras"},
    /* zoom_to: ZZ in [-32768, -10] or [1, 10000] */
    {0x25, 1, R1(XF_F_ZOOM, -9), "zoom"},
    {0x25, 1, R1(XF_F_ZOOM, 0), "zoom"},
    {0x25, 1, R1(XF_F_ZOOM, 10001), "zoom"},
    {0x25, 1, R1(XF_F_ZOOM, 32767), "zoom"},
    {0x25, 1, R1(XF_F_ZOOM, -10), NULL},
    {0x25, 1, R1(XF_F_ZOOM, 1), NULL},
    {0x25, 1, R1(XF_F_ZOOM, 10000), NULL},
    {0x25, 1, R1(XF_F_ZOOM, -32768), NULL},
    {0x25, 1, R1(XF_F_CAMERAS, 0), "cameras"},
    /* palette: [0, 100] in V0.1, [0, 10] in V0.2 */
    {0x2A, 1, R1(XF_F_VALUE, 100), NULL},
    {0x2A, 1, R1(XF_F_VALUE, 101), "value"},
    {0x2A, 1, R1(XF_F_VALUE, 11), NULL},
    {0x2A, 2, R1(XF_F_VALUE, 10), NULL},
    {0x2A, 2, R1(XF_F_VALUE, 11), "value"},
    {0x2A, 2, R1(XF_F_VALUE, 100), "value"},
    {0x2A, 1, R1(XF_F_CAMERAS, 0), "cameras"},
    /* pip: only 0 in V0.1, [0, 4] in V0.2 */
    {0x74, 1, R1(XF_F_VALUE, 0), NULL},
    {0x74, 1, R1(XF_F_VALUE, 1), "value"},
    {0x74, 2, R1(XF_F_VALUE, 4), NULL},
    {0x74, 2, R1(XF_F_VALUE, 5), "value"},
    /* night_vision: 0, 1, 2 */
    {0x2B, 1, R1(XF_F_VALUE, 2), NULL},
    {0x2B, 1, R1(XF_F_VALUE, 3), "value"},
    {0x2B, 1, R1(XF_F_CAMERAS, 0), "cameras"},
    /* ranging: 0 off, 2 on */
    {0x81, 1, R1(XF_F_VALUE, 0), NULL},
    {0x81, 1, R1(XF_F_VALUE, 1), "value"},
    {0x81, 1, R1(XF_F_VALUE, 3), "value"},
    /* on/off orders */
    {0x73, 1, R1(XF_F_VALUE, 0), NULL},
    {0x73, 1, R1(XF_F_VALUE, 2), "value"},
    {0x06, 2, R1(XF_F_VALUE, 2), "value"},
    {0x07, 2, R1(XF_F_VALUE, 2), "value"},
    {0x75, 2, R1(XF_F_VALUE, 2), "value"},
    {0x76, 2, R1(XF_F_VALUE, 2), "value"},
    {0x76, 2, R1(XF_F_VALUE, 0), NULL},
    /* time_zone: [-12, 14] hours */
    {0x08, 2, R1(XF_F_HOURS, -12), NULL},
    {0x08, 2, R1(XF_F_HOURS, 14), NULL},
    {0x08, 2, R1(XF_F_HOURS, -13), "hours"},
    {0x08, 2, R1(XF_F_HOURS, 15), "hours"},
    {0x08, 2, R1(XF_F_HOURS, -128), "hours"},
    /* temp_alarm / isotherm: TT 0/1; when on, high >= low */
    {0x31, 2, R1(XF_F_VALUE, 2), "value"},
    {0x31, 2, R2(XF_F_TEMP_HIGH, -201, XF_F_TEMP_LOW, -200), "temp_low"},
    {0x31, 2, R2(XF_F_TEMP_HIGH, -200, XF_F_TEMP_LOW, -200), NULL},
    {0x31, 2, R3(XF_F_VALUE, 0, XF_F_TEMP_HIGH, -201, XF_F_TEMP_LOW, -200), NULL},
    {0x31, 2, R1(XF_F_CAMERAS, 0), "cameras"},
    {0x32, 2, R1(XF_F_VALUE, 2), "value"},
    {0x32, 2, R2(XF_F_TEMP_HIGH, 0, XF_F_TEMP_LOW, 1), "temp_low"},
    {0x32, 2, R1(XF_F_CAMERAS, 0), "cameras"},
    /* lighting: any level */
    {0x80, 1, R1(XF_F_VALUE, 0), NULL},
    {0x80, 1, R1(XF_F_VALUE, 128), NULL},
    /* several members out of range: the one-byte ones (cameras, then value) are named first */
    {0x1B, 1, R2(XF_F_VALUE, 1, XF_F_DX, 2000), "value"},
    {0x17, 1, R2(XF_F_VALUE, 2, XF_F_X1, 10001), "value"},
    {0x17, 1, R2(XF_F_CAMERAS, 0, XF_F_VALUE, 2), "cameras"},
    {0x33, 2, R2(XF_F_X0, 10001, XF_F_CAMERAS, 0), "cameras"},
    /* a mask of no camera, for every masked order */
    {0x20, 1, R1(XF_F_CAMERAS, 0), "cameras"},
    {0x21, 1, R1(XF_F_CAMERAS, 0), "cameras"},
    {0x22, 1, R1(XF_F_CAMERAS, 0), "cameras"},
    {0x23, 1, R1(XF_F_CAMERAS, 0), "cameras"},
    {0x24, 1, R1(XF_F_CAMERAS, 0), "cameras"},
    {0x26, 1, R1(XF_F_CAMERAS, 0), "cameras"},
    {0x20, 1, R1(XF_F_CAMERAS, 0xFF), NULL},
    {0x22, 2, R1(XF_F_CAMERAS, 0x80), NULL},
};

static void test_range_rules(void **state)
{
    size_t i, k;
    (void)state;
    for (i = 0; i < ARRAY_LEN(range_cases); i++) {
        const range_case *rc = &range_cases[i];
        const order_spec *s = order_spec_find(rc->order);
        xf_command c, d;
        uint8_t out[32], bytes[32];
        size_t n = 0, len;
        xf_field bad = XF_F_ALTITUDE; /* overwritten: the member at fault, or XF_F_NONE */
        xf_err want = (rc->bad == NULL) ? XF_OK : XF_ERR_RANGE;
        memset(&d, 0, sizeof(d));
        golden_cmd(golden_for(rc->order), &c);
        for (k = 0; k < rc->nset; k++) {
            cmd_put(&c, rc->set[k].f, rc->set[k].v);
        }
        /* the case itself agrees with the reference rules */
        assert_int_equal(ref_bad_fields(&c, rc->version) == 0u, rc->bad == NULL);

        if (xf_command_check(&c, rc->version, &bad) != want) {
            print_error("case %zu (order 0x%02X, V%u)\n", i, rc->order, rc->version);
        }
        assert_err(xf_command_check(&c, rc->version, &bad), want);
        assert_string_equal(xf_field_name(bad), (rc->bad != NULL) ? rc->bad : "none");
        /* encode checks first */
        bad = XF_F_ALTITUDE;
        assert_err(xf_command_encode(&c, rc->version, out, sizeof(out), &n, &bad), want);
        assert_string_equal(xf_field_name(bad), (rc->bad != NULL) ? rc->bad : "none");
        /* decode of the same bytes checks too */
        len = ref_encode(&c, s, bytes);
        bad = XF_F_ALTITUDE;
        assert_err(xf_command_decode(rc->order, bytes, len, rc->version, &d, &bad), want);
        assert_string_equal(xf_field_name(bad), (rc->bad != NULL) ? rc->bad : "none");
        if (rc->bad == NULL) {
            assert_int_equal(bad, XF_F_NONE);
            assert_cmd_equal(&d, &c);
        }
        /* a NULL bad_field is allowed */
        assert_err(xf_command_check(&c, rc->version, NULL), want);
    }
}

/* The same bytes are valid or not depending on the packet's version. */
static void test_version_aware_decode(void **state)
{
    static const uint8_t palette50[2] = {0x02, 50};
    static const uint8_t pip3[1] = {0x03};
    xf_command c;
    xf_host_packet pkt;
    xf_field bad = XF_F_NONE;
    (void)state;
    assert_err(xf_command_decode(XF_ORDER_PALETTE, palette50, 2, 1, &c, &bad), XF_OK);
    assert_int_equal(c.value, 50);
    assert_err(xf_command_decode(XF_ORDER_PALETTE, palette50, 2, 2, &c, &bad), XF_ERR_RANGE);
    assert_int_equal(bad, XF_F_VALUE);
    assert_err(xf_command_decode(XF_ORDER_PIP, pip3, 1, 2, &c, &bad), XF_OK);
    assert_int_equal(c.value, 3);
    bad = XF_F_NONE;
    assert_err(xf_command_decode(XF_ORDER_PIP, pip3, 1, 1, &c, &bad), XF_ERR_RANGE);
    assert_int_equal(bad, XF_F_VALUE);
    /* xf_host_set_command uses the packet's version */
    xf_command_init(&c, XF_ORDER_PIP);
    c.value = 3;
    xf_host_packet_init(&pkt, 1);
    assert_err(xf_host_set_command(&pkt, &c, &bad), XF_ERR_RANGE);
    assert_int_equal(bad, XF_F_VALUE);
    assert_int_equal(pkt.order, XF_ORDER_NULL); /* untouched */
    assert_int_equal(pkt.params_len, 0);
    xf_host_packet_init(&pkt, 2);
    assert_err(xf_host_set_command(&pkt, &c, &bad), XF_OK);
    assert_int_equal(bad, XF_F_NONE);
    assert_int_equal(pkt.order, XF_ORDER_PIP);
    assert_int_equal(pkt.params_len, 1);
    assert_int_equal(pkt.params[0], 3);
}

/* ---- error paths ---------------------------------------------------------- */

static void test_command_errors(void **state)
{
    static const uint8_t unknown_orders[] = {0x02, 0x04, 0x09, 0x18, 0x50, 0x82, 0xFF};
    xf_command c;
    xf_host_packet pkt;
    uint8_t out[32];
    size_t i, n = 0;
    xf_field bad = XF_F_NONE;
    (void)state;

    /* NULL; every result but XF_ERR_RANGE leaves XF_F_NONE in bad_field */
#define EXPECT_NO_FIELD(call, want)                                                                                    \
    do {                                                                                                               \
        bad = XF_F_ALTITUDE;                                                                                           \
        assert_err(call, want);                                                                                        \
        assert_int_equal(bad, XF_F_NONE);                                                                              \
    } while (0)
    xf_command_init(&c, XF_ORDER_CLICK_TO_AIM);
    EXPECT_NO_FIELD(xf_command_check(NULL, 1, &bad), XF_ERR_ARG);
    EXPECT_NO_FIELD(xf_command_encode(NULL, 1, out, sizeof(out), &n, &bad), XF_ERR_ARG);
    EXPECT_NO_FIELD(xf_command_encode(&c, 1, NULL, sizeof(out), &n, &bad), XF_ERR_ARG);
    EXPECT_NO_FIELD(xf_command_decode(XF_ORDER_CLICK_TO_AIM, out, 5, 1, NULL, &bad), XF_ERR_ARG);
    EXPECT_NO_FIELD(xf_command_decode(XF_ORDER_CLICK_TO_AIM, NULL, 5, 1, &c, &bad), XF_ERR_ARG);
    EXPECT_NO_FIELD(xf_host_set_command(NULL, &c, &bad), XF_ERR_ARG);
    xf_host_packet_init(&pkt, 1);
    EXPECT_NO_FIELD(xf_host_set_command(&pkt, NULL, &bad), XF_ERR_ARG);
    /* no parameters: a NULL buffer is fine */
    xf_command_init(&c, XF_ORDER_NEUTRAL);
    assert_err(xf_command_encode(&c, 1, NULL, 0, &n, &bad), XF_OK);
    assert_int_equal(n, 0);
    assert_err(xf_command_decode(XF_ORDER_NEUTRAL, NULL, 0, 1, &c, &bad), XF_OK);

    /* no room */
    for (i = 0; i < ARRAY_LEN(order_specs); i++) {
        size_t len = spec_params_len(&order_specs[i]);
        const golden *g = golden_for(order_specs[i].order);
        golden_cmd(g, &c);
        if (len > 0) {
            EXPECT_NO_FIELD(xf_command_encode(&c, g->version, out, len - 1u, &n, &bad), XF_ERR_NO_SPACE);
            assert_err(xf_command_encode(&c, g->version, out, 0, &n, &bad), XF_ERR_NO_SPACE);
        }
        /* wrong parameter length for the order, both ways */
        memset(out, 0, sizeof(out));
        memcpy(out, g->bytes, len);
        EXPECT_NO_FIELD(xf_command_decode(g->order, out, len + 1u, g->version, &c, &bad), XF_ERR_PARAMS);
        assert_err(xf_command_decode(g->order, out, 30, g->version, &c, &bad), XF_ERR_PARAMS);
        if (len > 0) {
            assert_err(xf_command_decode(g->order, out, len - 1u, g->version, &c, &bad), XF_ERR_PARAMS);
            assert_err(xf_command_decode(g->order, out, 0, g->version, &c, &bad), XF_ERR_PARAMS);
        }
    }

    /* unknown orders */
    for (i = 0; i < ARRAY_LEN(unknown_orders); i++) {
        memset(&c, 0, sizeof(c));
        c.order = unknown_orders[i];
        c.cameras = 1;
        EXPECT_NO_FIELD(xf_command_check(&c, 1, &bad), XF_ERR_NOT_FOUND);
        EXPECT_NO_FIELD(xf_command_encode(&c, 1, out, sizeof(out), &n, &bad), XF_ERR_NOT_FOUND);
        EXPECT_NO_FIELD(xf_command_decode(unknown_orders[i], out, 0, 1, &c, &bad), XF_ERR_NOT_FOUND);
        EXPECT_NO_FIELD(xf_command_decode(unknown_orders[i], out, 3, 2, &c, &bad), XF_ERR_NOT_FOUND);
        EXPECT_NO_FIELD(xf_host_set_command(&pkt, &c, &bad), XF_ERR_NOT_FOUND);
    }
#undef EXPECT_NO_FIELD
}

/* xf_command_get / xf_command_set, xf_field_name, xf_field_size. */
static void test_field_accessors(void **state)
{
    xf_command c;
    size_t i;
    (void)state;
    for (i = 0; i < ALL_FIELDS_COUNT; i++) {
        assert_string_equal(xf_field_name(all_fields[i]), spec_field_name(all_fields[i]));
        assert_int_equal(xf_field_size(all_fields[i]), spec_field_size(all_fields[i]));
    }
    assert_string_equal(xf_field_name((xf_field)(XF_F_ALTITUDE + 1)), "?"); /* past the packed names */
    assert_string_equal(xf_field_name((xf_field)200), "?");
    /* no member: what bad_field holds when none is at fault */
    assert_string_equal(xf_field_name(XF_F_NONE), "none");
    assert_int_equal(xf_field_size(XF_F_NONE), 0);
    memset(&c, 0x5A, sizeof(c));
    xf_command_set(&c, XF_F_NONE, 1); /* does nothing */
    assert_int_equal(c.value, 0x5A);
    assert_sint_equal(xf_command_get(&c, XF_F_NONE), 0);
    memset(&c, 0, sizeof(c));
    /* in range: stored as is */
    xf_command_set(&c, XF_F_HOURS, -5);
    assert_sint_equal(c.hours, -5);
    xf_command_set(&c, XF_F_DX, -1024);
    assert_sint_equal(c.dx, -1024);
    xf_command_set(&c, XF_F_LATITUDE, -380300822);
    assert_sint_equal(c.latitude, -380300822);
    xf_command_set(&c, XF_F_Y1, 10000);
    assert_int_equal(c.y1, 10000);
    /* out of the member's type: saturated, never wrapped */
    xf_command_set(&c, XF_F_CAMERAS, 300);
    assert_int_equal(c.cameras, 255);
    xf_command_set(&c, XF_F_CAMERAS, -1);
    assert_int_equal(c.cameras, 0);
    xf_command_set(&c, XF_F_VALUE, 256);
    assert_int_equal(c.value, 255);
    xf_command_set(&c, XF_F_HOURS, 200);
    assert_sint_equal(c.hours, 127);
    xf_command_set(&c, XF_F_HOURS, -200);
    assert_sint_equal(c.hours, -128);
    xf_command_set(&c, XF_F_X0, 70000);
    assert_int_equal(c.x0, 65535);
    xf_command_set(&c, XF_F_X1, -1);
    assert_int_equal(c.x1, 0);
    xf_command_set(&c, XF_F_ZOOM, -40000);
    assert_sint_equal(c.zoom, -32768);
    xf_command_set(&c, XF_F_TEMP_HIGH, 40000);
    assert_sint_equal(c.temp_high, 32767);
    for (i = 0; i < ALL_FIELDS_COUNT; i++) {
        assert_sint_equal(xf_command_get(&c, all_fields[i]), cmd_get(&c, all_fields[i]));
    }
    assert_sint_equal(xf_command_get(NULL, XF_F_VALUE), 0);
    xf_command_set(NULL, XF_F_VALUE, 1); /* must not crash */
}

/* ---- feedback ------------------------------------------------------------- */

static void expect_feedback(uint8_t order, const uint8_t *fb, size_t len, uint8_t has_state, uint8_t result,
                            uint8_t failed)
{
    xf_feedback f;
    memset(&f, 0xA7, sizeof(f));
    assert_err(xf_feedback_decode(order, fb, len, &f), XF_OK);
    if (f.order != order || f.has_state != has_state || (has_state && (f.result != result || f.state != fb[0])) ||
        f.failed_cameras != failed) {
        print_error("order 0x%02X, %zu byte(s) %02X: got has_state %u state %02X result %u failed %02X; "
                    "expected has_state %u result %u failed %02X\n",
                    order, len, len ? fb[0] : 0, f.has_state, f.state, f.result, f.failed_cameras, has_state, result,
                    failed);
        fail();
    }
}

static void test_feedback_every_order(void **state)
{
    static const uint8_t b00[1] = {0x00}, b01[1] = {0x01}, b02[1] = {0x02}, b03[1] = {0x03}, bFF[1] = {0xFF};
    static const uint8_t two[2] = {0x00, 0x01};
    size_t i;
    (void)state;
    for (i = 0; i < ARRAY_LEN(order_specs); i++) {
        const order_spec *s = &order_specs[i];
        uint8_t o = s->order;
        /* success */
        expect_feedback(o, b00, 1, 1, XF_RESULT_OK, 0);
        /* failure 0x01: for mask orders that is "camera 1 failed" */
        expect_feedback(o, b01, 1, 1, XF_RESULT_FAILED, s->mask_failure ? 0x01 : 0);
        /* 0x02: operating for calibration; camera 2 failed for mask orders */
        if (s->operating) {
            expect_feedback(o, b02, 1, 1, XF_RESULT_OPERATING, 0);
        } else {
            expect_feedback(o, b02, 1, 1, XF_RESULT_FAILED, s->mask_failure ? 0x02 : 0);
        }
        /* NN with several cameras */
        expect_feedback(o, b03, 1, 1, XF_RESULT_FAILED, s->mask_failure ? 0x03 : 0);
        expect_feedback(o, bFF, 1, 1, XF_RESULT_FAILED, s->mask_failure ? 0xFF : 0);
        /* no execution state in this reply */
        expect_feedback(o, NULL, 0, 0, 0, 0);
        expect_feedback(o, b01, 0, 0, 0, 0);
        /* bytes after the first are ignored */
        expect_feedback(o, two, 2, 1, XF_RESULT_OK, 0);
    }
    /* the null order's reply has no state (§7, §10: a 72-byte reply) */
    expect_feedback(XF_ORDER_NULL, NULL, 0, 0, 0, 0);
    /* an order the protocol does not define: plain success / failure, no mask */
    expect_feedback(0x55, b00, 1, 1, XF_RESULT_OK, 0);
    expect_feedback(0x55, b01, 1, 1, XF_RESULT_FAILED, 0);
    expect_feedback(0x55, b02, 1, 1, XF_RESULT_FAILED, 0);
    expect_feedback(0x55, b03, 1, 1, XF_RESULT_FAILED, 0);
    expect_feedback(0xFF, NULL, 0, 0, 0, 0);
    /* errors */
    {
        xf_feedback f;
        assert_err(xf_feedback_decode(0x17, b00, 1, NULL), XF_ERR_ARG);
        assert_err(xf_feedback_decode(0x17, NULL, 1, &f), XF_ERR_ARG);
    }
}

/* The feedback of a whole GCU packet, as a host reads it. */
static void test_feedback_from_packet(void **state)
{
    uint8_t buf[73];
    xf_gcu_packet g;
    xf_feedback f;
    (void)state;
    memset(buf, 0, sizeof(buf));
    buf[4] = 1;
    buf[69] = 0x25; /* zoom_to */
    buf[70] = 0x02; /* camera 2 failed */
    ref_finish_packet(buf, 73, XF_DIR_GCU);
    assert_err(xf_gcu_unpack(buf, 73, &g), XF_OK);
    assert_err(xf_feedback_decode(g.order, g.params, g.params_len, &f), XF_OK);
    assert_int_equal(f.order, 0x25);
    assert_int_equal(f.has_state, 1);
    assert_int_equal(f.result, XF_RESULT_FAILED);
    assert_int_equal(f.failed_cameras, 0x02);
}

/* xf_feedback_state is the inverse of xf_feedback_decode for what a GCU
 * can send: success, failure (NN for mask orders), operating (calibration). */
static void test_feedback_state_inverse(void **state)
{
    static const uint8_t masks[] = {0x01, 0x02, 0x03, 0x80, 0xFF};
    size_t i, k;
    (void)state;
    for (i = 0; i < ARRAY_LEN(order_specs); i++) {
        const order_spec *s = &order_specs[i];
        uint8_t o = s->order, st;
        xf_feedback f;
        st = xf_feedback_state(o, XF_RESULT_OK, 0);
        assert_int_equal(st, 0x00);
        assert_err(xf_feedback_decode(o, &st, 1, &f), XF_OK);
        assert_int_equal(f.result, XF_RESULT_OK);

        for (k = 0; k < ARRAY_LEN(masks); k++) {
            st = xf_feedback_state(o, XF_RESULT_FAILED, masks[k]);
            /* NN for mask orders; plain 0x01 otherwise */
            assert_int_equal(st, s->mask_failure ? masks[k] : 0x01);
            assert_err(xf_feedback_decode(o, &st, 1, &f), XF_OK);
            assert_int_equal(f.result, XF_RESULT_FAILED);
            assert_int_equal(f.failed_cameras, s->mask_failure ? masks[k] : 0);
        }
        /* failure with no mask given: 0x01 */
        st = xf_feedback_state(o, XF_RESULT_FAILED, 0);
        assert_int_equal(st, 0x01);
        assert_err(xf_feedback_decode(o, &st, 1, &f), XF_OK);
        assert_int_equal(f.result, XF_RESULT_FAILED);

        if (s->operating) {
            st = xf_feedback_state(o, XF_RESULT_OPERATING, 0);
            assert_int_equal(st, 0x02);
            assert_err(xf_feedback_decode(o, &st, 1, &f), XF_OK);
            assert_int_equal(f.result, XF_RESULT_OPERATING);
        }
    }
}

/* Track and click-to-aim: the first byte is a camera mask in V0.1, fixed at 0x01 in V0.2. */
static void test_track_first_byte(void **state)
{
    static const uint8_t orders[] = {XF_ORDER_TRACK, XF_ORDER_CLICK_TO_AIM};
    size_t i;
    (void)state;
    for (i = 0; i < 2u; i++) {
        xf_command c;
        xf_field bad = XF_F_NONE;
        xf_command_init(&c, orders[i]);
        c.x1 = 100;
        c.y1 = 100;
        assert_int_equal(c.cameras, XF_CAM1); /* the default agrees with both */
        assert_int_equal(xf_command_check(&c, XF_PROTOCOL_V2, &bad), XF_OK);
        c.cameras = XF_CAM1 | XF_CAM2;
        assert_int_equal(xf_command_check(&c, XF_PROTOCOL_V1, &bad), XF_OK);
        assert_int_equal(xf_command_check(&c, XF_PROTOCOL_V2, &bad), XF_ERR_RANGE);
        assert_int_equal(bad, XF_F_CAMERAS);
    }
}

/* OSD 0x73: V0.1 (V2.0.4) 0 = shown, 1 = hidden; V0.2 (V2.0.6) 0 = off, 1 = on. */
static void test_osd_value(void **state)
{
    (void)state;
    assert_int_equal(xf_osd_value(1, XF_PROTOCOL_V1), 0);
    assert_int_equal(xf_osd_value(0, XF_PROTOCOL_V1), 1);
    assert_int_equal(xf_osd_value(1, XF_PROTOCOL_V2), 1);
    assert_int_equal(xf_osd_value(0, XF_PROTOCOL_V2), 0);
    assert_int_equal(xf_osd_value(7, 3), 1); /* any nonzero shows; a later version as V0.2 */
}

/* V2.0.6's support list (appendix 8) as the vendor lays it out: one row per order, one column
 * per model, 'Y' where the order is marked supported; typed from the vendor's table apart from
 * the header's per-model masks, so that each checks the other. */
static void test_gimbal_supports(void **state)
{
    static const uint8_t codes[20] = {0, 2, 25, 26, 31, 40, 41, 44, 45, 49, 50, 52, 53, 55, 57, 58, 59, 60, 61, 62};
    static const struct {
        uint8_t order;
        const char *marks; /* one per code above */
    } rows[] = {
        {XF_ORDER_TRACK, "Y-Y-YYYYYYYYYYYYYY--"},
        {XF_ORDER_OSD_COORDINATE, "--------YYYYY-YYYYYY"},
        {XF_ORDER_AUTO_FLIP, "--------YYYYY-YYYYYY"},
        {XF_ORDER_TIME_ZONE, "--------YYYYY-YYYYYY"},
        {XF_ORDER_ZOOM_TO, "-----YYYYYYYYYYYYYYY"},
        {XF_ORDER_FOCUS, "YYYYYYYYY---YYYYYYYY"},
        {XF_ORDER_PALETTE, "----Y-Y-Y--YY-YYYYYY"},
        {XF_ORDER_NIGHT_VISION, "YYYYYYYYY---YYYYYYYY"},
        {XF_ORDER_AREA_TEMP, "--------Y---Y--Y--Y-"},
        {XF_ORDER_TEMP_ALARM, "--------Y---Y--Y--Y-"},
        {XF_ORDER_ISOTHERM, "--------Y---Y--Y--Y-"},
        {XF_ORDER_SPOT_TEMP, "--------Y---Y--Y--Y-"},
        {XF_ORDER_OSD, "-----YY-YYYYYYYYYYYY"},
        {XF_ORDER_PIP, "----YYY-Y--YYYYYYYYY"},
        {XF_ORDER_TARGET_DETECTION, "--------YYYYY-YYYY--"},
        {XF_ORDER_DIGITAL_ZOOM, "--------Y---Y-YYYYYY"},
        {XF_ORDER_LIGHTING, "----YY-Y-------YY---"},
        {XF_ORDER_RANGING, "--YYY-Y-Y---YYYYYYYY"},
    };
    static const uint8_t older[] = {3, 21, 22, 24, 27, 30}; /* only in V2.0.4's list: no claim */
    size_t m, k, i;
    (void)state;
    for (k = 0; k < ARRAY_LEN(rows); k++) {
        assert_int_equal(strlen(rows[k].marks), ARRAY_LEN(codes));
        for (m = 0; m < ARRAY_LEN(codes); m++) {
            xf_support want = (rows[k].marks[m] == 'Y') ? XF_SUPPORT_YES : XF_SUPPORT_NO;
            if (xf_gimbal_supports(codes[m], rows[k].order) != want) {
                print_error("model %u, order 0x%02X: expected %d\n", codes[m], rows[k].order, (int)want);
                fail();
            }
        }
    }
    /* every other order of V2.0.6 is supported by every model; external_track is not in V2.0.6 */
    for (i = 0; i < XF_ORDER_COUNT; i++) {
        uint8_t order = xf_order_at(i)->order;
        int listed = 0;
        for (k = 0; k < ARRAY_LEN(rows); k++) {
            listed |= (rows[k].order == order);
        }
        for (m = 0; m < ARRAY_LEN(codes) && !listed; m++) {
            assert_int_equal(xf_gimbal_supports(codes[m], order),
                             (order == XF_ORDER_EXTERNAL_TRACK) ? XF_SUPPORT_UNKNOWN : XF_SUPPORT_YES);
        }
        for (m = 0; m < ARRAY_LEN(older); m++) {
            assert_int_equal(xf_gimbal_supports(older[m], order), XF_SUPPORT_UNKNOWN);
            assert_non_null(xf_gimbal_model(older[m])); /* still named */
        }
    }
    assert_int_equal(xf_gimbal_supports(99, XF_ORDER_TRACK), XF_SUPPORT_UNKNOWN); /* no such model */
    assert_int_equal(xf_gimbal_supports(58, 0x02), XF_SUPPORT_UNKNOWN);           /* no such order */
    assert_int_equal(xf_gimbal_supports(0, XF_ORDER_PALETTE), XF_SUPPORT_NO);
    assert_string_equal(xf_gimbal_model(31), "Z-9B_V3"); /* V2.0.6's name */
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_order_table_matches_spec), cmocka_unit_test(test_order_names),
        cmocka_unit_test(test_command_init_defaults),    cmocka_unit_test(test_golden_every_order),
        cmocka_unit_test(test_unused_members_ignored),   cmocka_unit_test(test_range_rules),
        cmocka_unit_test(test_version_aware_decode),     cmocka_unit_test(test_command_errors),
        cmocka_unit_test(test_field_accessors),          cmocka_unit_test(test_feedback_every_order),
        cmocka_unit_test(test_feedback_from_packet),     cmocka_unit_test(test_feedback_state_inverse),
        cmocka_unit_test(test_gimbal_supports),          cmocka_unit_test(test_osd_value),
        cmocka_unit_test(test_track_first_byte),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
