/*
 * test_wire_fields.c - the field table (xf_fields.h) against the codec: every row of both
 * directions, in both protocol versions, at the offset, width and signedness of the spec's
 * layout (test_fields.h), read back from what the packers write and written where the
 * unpackers read; every parameter member against xf_command_encode() and _decode(); the scales
 * against the conversions of xf_units.h; engineering values that round-trip exactly through
 * their decimal text.
 */
#include <math.h>
#include <stdlib.h>

#include "test_fields.h"

static const uint8_t versions[2] = {XF_PROTOCOL_V1, XF_PROTOCOL_V2};
/* Wire images with every byte different and non-zero: negative and positive when signed. */
static const uint8_t pattern_neg[4] = {0x81, 0x92, 0xA3, 0xB4};
static const uint8_t pattern_pos[4] = {0x1E, 0x2D, 0x3C, 0x4B};

/* The entry of test_fields.h for a row ("main.cam_pitch" for "cam_pitch"). */
static const field_desc *spec_of(const field_desc *spec, size_t n, const char *name)
{
    size_t i;
    for (i = 0; i < n; i++) {
        const char *dot = strchr(spec[i].name, '.');
        if (strcmp(dot != NULL ? dot + 1 : spec[i].name, name) == 0) {
            return &spec[i];
        }
    }
    return NULL;
}

static const field_desc *spec_table(xf_direction dir, size_t *n)
{
    *n = (dir == XF_DIR_HOST) ? ARRAY_LEN(host_fields) : ARRAY_LEN(gcu_fields);
    return (dir == XF_DIR_HOST) ? host_fields : gcu_fields;
}

/* The rows of each direction cover bytes 5..68 once, in wire order, each where the spec's
 * layout has the member of its name, as wide and as signed. */
static void check_frame_rows(xf_direction dir)
{
    size_t i, n, nspec;
    const xf_wire_field *rows = xf_wire_fields(xf_wire_frames(dir), &n);
    const field_desc *spec = spec_table(dir, &nspec);
    unsigned next = XF_OFF_MAIN;
    assert_non_null(rows);
    for (i = 0; i < n; i++) {
        const field_desc *s = spec_of(spec, nspec, rows[i].name);
        if (s == NULL) {
            print_error("row %s has no member of that name\n", rows[i].name);
            fail();
        }
        assert_int_equal(rows[i].offset, next);
        assert_int_equal(rows[i].offset, s->wire_off);
        assert_int_equal(rows[i].width, s->nbytes);
        assert_int_equal(rows[i].group, xf_wire_frames(dir));
        assert_int_equal(rows[i].kind == XF_WIRE_RESERVED, s->kind == FK_BYTES);
        assert_int_equal(rows[i].is_signed, kind_is_signed(s->kind));
        assert_ptr_equal(xf_wire_field_find(xf_wire_frames(dir), rows[i].name), &rows[i]);
        assert_true(rows[i].meaning[0] != '\0');
        next += rows[i].width;
    }
    assert_int_equal(next, XF_OFF_ORDER);
    /* and every member of the frames has its row */
    for (i = 0; i < nspec; i++) {
        const char *dot = strchr(spec[i].name, '.');
        if (dot != NULL) {
            assert_non_null(xf_wire_field_find(xf_wire_frames(dir), dot + 1));
        }
    }
}

static void test_frame_rows(void **state)
{
    (void)state;
    check_frame_rows(XF_DIR_HOST);
    check_frame_rows(XF_DIR_GCU);
}

static xf_err pack_any(xf_direction dir, const void *pkt, uint8_t *buf, size_t *len)
{
    return (dir == XF_DIR_HOST) ? xf_host_pack((const xf_host_packet *)pkt, buf, XF_PACKET_MAX_LEN, len)
                                : xf_gcu_pack((const xf_gcu_packet *)pkt, buf, XF_PACKET_MAX_LEN, len);
}

static xf_err unpack_any(xf_direction dir, const uint8_t *buf, size_t len, void *pkt)
{
    xf_frame f;
    f.data = buf;
    f.len = len; /* the frame decoders skip the CRC, which a field written in place leaves stale */
    return (dir == XF_DIR_HOST) ? xf_frame_host(&f, (xf_host_packet *)pkt) : xf_frame_gcu(&f, (xf_gcu_packet *)pkt);
}

/* One row in one version, with one pattern: the packer's bytes read through the row, and the
 * row's write read back by the unpacker. */
static void check_row_both_ways(xf_direction dir, const xf_wire_field *row, const field_desc *s, uint8_t version,
                                const uint8_t *pattern)
{
    union {
        xf_host_packet host;
        xf_gcu_packet gcu;
    } pkt, back;
    uint8_t buf[XF_PACKET_MAX_LEN];
    size_t len = 0;
    int64_t value;
    memset(&pkt, 0, sizeof(pkt));
    pkt.host.version = version; /* the first member of both */
    field_store_wire(&pkt, s, pattern);
    value = field_value(&pkt, s);
    assert_err(pack_any(dir, &pkt, buf, &len), XF_OK);
    assert_sint_equal(xf_wire_field_get(row, buf), value); /* packer -> row */

    memset(&pkt, 0, sizeof(pkt));
    pkt.host.version = version;
    assert_err(pack_any(dir, &pkt, buf, &len), XF_OK);
    xf_wire_field_put(row, buf, value);
    assert_err(unpack_any(dir, buf, len, &back), XF_OK);
    assert_sint_equal(field_value(&back, s), value); /* row -> unpacker */
}

static void check_rows_against_codec(xf_direction dir)
{
    size_t i, v, n, nspec;
    const xf_wire_field *rows = xf_wire_fields(xf_wire_frames(dir), &n);
    const field_desc *spec = spec_table(dir, &nspec);
    for (v = 0; v < ARRAY_LEN(versions); v++) {
        for (i = 0; i < n; i++) {
            const field_desc *s = spec_of(spec, nspec, rows[i].name);
            if (rows[i].kind == XF_WIRE_RESERVED) {
                continue;
            }
            check_row_both_ways(dir, &rows[i], s, versions[v], pattern_neg);
            check_row_both_ways(dir, &rows[i], s, versions[v], pattern_pos);
            /* present from its version on; the packers write its bytes in every version */
            assert_int_equal(xf_wire_field_present(&rows[i], versions[v]), versions[v] >= rows[i].since);
        }
    }
}

static void test_rows_against_packers(void **state)
{
    (void)state;
    check_rows_against_codec(XF_DIR_HOST);
    check_rows_against_codec(XF_DIR_GCU);
    assert_false(xf_wire_field_present(xf_wire_field_find(XF_WIRE_GCU, "time_zone"), XF_PROTOCOL_V1));
    assert_true(xf_wire_field_present(xf_wire_field_find(XF_WIRE_GCU, "time_zone"), XF_PROTOCOL_V2));
}

/* The packet's own rows: length, version and order where the codec puts them. */
static void test_packet_rows(void **state)
{
    xf_host_packet pkt;
    uint8_t buf[XF_PACKET_MAX_LEN];
    size_t len = 0;
    (void)state;
    xf_host_packet_init(&pkt, XF_PROTOCOL_V2);
    pkt.order = XF_ORDER_ZOOM_TO;
    pkt.params_len = 3;
    assert_err(xf_host_pack(&pkt, buf, sizeof(buf), &len), XF_OK);
    assert_sint_equal(xf_wire_field_get(xf_wire_field_find(XF_WIRE_PACKET, "length"), buf), 75);
    assert_sint_equal(xf_wire_field_get(xf_wire_field_find(XF_WIRE_PACKET, "version"), buf), 2);
    assert_sint_equal(xf_wire_field_get(xf_wire_field_find(XF_WIRE_PACKET, "order"), buf), XF_ORDER_ZOOM_TO);
    assert_ptr_equal(xf_wire_field_find(XF_WIRE_PACKET, "order")->value_name, xf_order_name);
}

/* In-range values of every member, each different, for the orders' parameters. */
static void set_distinct(xf_command *cmd, uint8_t version)
{
    static const uint8_t tries[] = {1, 2, 0};
    size_t k;
    cmd->cameras = XF_CAM1; /* V0.2's track and click_to_aim take only 0x01 */
    cmd->hours = -7;
    cmd->x0 = 1234, cmd->y0 = 2345, cmd->x1 = 3456, cmd->y1 = 4567;
    cmd->dx = -1000, cmd->dy = 1001;
    cmd->zoom = -1234;
    cmd->temp_high = 1500, cmd->temp_low = -300;
    cmd->longitude = -1234567890, cmd->latitude = 876543210, cmd->altitude = -123456;
    for (k = 0; k < ARRAY_LEN(tries); k++) {
        cmd->value = tries[k];
        if (xf_command_check(cmd, version, NULL) == XF_OK) {
            return;
        }
    }
    fail_msg("no value of order 0x%02X passes", cmd->order);
}

/* One order's parameters: the encoder's bytes read through the rows, at offsets that the rows'
 * widths give along the order's layout, and the rows' bytes decoded. */
static void check_order_params(const xf_order_info *info, uint8_t version)
{
    uint8_t bytes[XF_PARAMS_KNOWN_MAX], written[XF_PARAMS_KNOWN_MAX];
    xf_command cmd, back;
    size_t i, n = 0, off = 0;
    xf_command_init(&cmd, info->order);
    set_distinct(&cmd, version);
    assert_err(xf_command_encode(&cmd, version, bytes, sizeof(bytes), &n, NULL), XF_OK);
    memset(written, 0, sizeof(written));
    for (i = 0; i < info->nfields; i++) {
        xf_wire_field at = *xf_wire_param((xf_field)info->fields[i]);
        at.offset = (uint8_t)off;
        assert_sint_equal(xf_wire_field_get(&at, bytes), xf_command_get(&cmd, (xf_field)info->fields[i]));
        xf_wire_field_put(&at, written, xf_command_get(&cmd, (xf_field)info->fields[i]));
        off += at.width;
    }
    assert_int_equal(off, n);
    assert_err(xf_command_decode(info->order, written, n, version, &back, NULL), XF_OK);
    for (i = 0; i < info->nfields; i++) {
        assert_sint_equal(xf_command_get(&back, (xf_field)info->fields[i]),
                          xf_command_get(&cmd, (xf_field)info->fields[i]));
    }
}

static void test_params_against_encoder(void **state)
{
    size_t i, v;
    (void)state;
    for (i = 0; i < XF_ORDER_COUNT; i++) {
        for (v = 0; v < ARRAY_LEN(versions); v++) {
            check_order_params(xf_order_at(i), versions[v]);
        }
    }
    for (i = 0; i <= (size_t)XF_F_ALTITUDE; i++) {
        const xf_wire_field *p = xf_wire_param((xf_field)i);
        xf_command c;
        memset(&c, 0, sizeof(c));
        xf_command_set(&c, (xf_field)i, -1); /* only a signed member keeps -1 */
        assert_string_equal(p->name, xf_field_name((xf_field)i));
        assert_int_equal(p->width, xf_field_size((xf_field)i));
        assert_int_equal(p->is_signed, xf_command_get(&c, (xf_field)i) < 0);
        assert_int_equal(p->group, XF_WIRE_PARAMS);
    }
    assert_null(xf_wire_param(XF_F_NONE));
}

#define ROW(group, name) xf_wire_field_find((group), (name))

/* What xf_units.h makes of a raw value of a row, by the row's unit; 1 when it has a conversion. */
static int units_value(const xf_wire_field *f, int32_t r, uint8_t version, double *out)
{
    float m = 0.0f;
    if (strcmp(f->unit, "deg/s") == 0) {
        *out = (double)xf_gcu_rate_dps((int16_t)r, version);
    } else if (strcmp(f->unit, "deg") == 0) {
        *out = (f->width == 4u) ? xf_deg7(r) : (double)xf_cdeg(r);
    } else if (strcmp(f->unit, "x") == 0) {
        *out = (double)xf_zoom_x((uint16_t)r);
    } else if (strcmp(f->name, "target_distance") == 0) {
        *out = xf_distance_m(r, &m) ? (double)m : r / 10.0; /* the library's no-measurement: the table's number */
    } else if (strcmp(f->unit, "m") == 0) {
        *out = r / 1000.0; /* xf_mm_raw's inverse */
    } else if (strcmp(f->unit, "m/s^2") == 0 || strcmp(f->unit, "m/s") == 0) {
        *out = r / 100.0; /* xf_accel_raw's and xf_velocity_raw's */
    } else {
        return 0;
    }
    return 1;
}

/* The scales are the conversions of xf_units.h, for every row that has one. */
static void test_scales_are_the_units(void **state)
{
    static const int32_t raws[] = {-32768, -3000, -1, 0, 1, 4500, 32767};
    size_t g, i, k, v, n, checked = 0;
    double want;
    (void)state;
    for (g = XF_WIRE_HOST; g <= XF_WIRE_GCU; g++) {
        const xf_wire_field *rows = xf_wire_fields((xf_wire_group)g, &n);
        for (i = 0; i < n; i++) {
            for (v = 0; v < ARRAY_LEN(versions); v++) {
                for (k = 0; k < ARRAY_LEN(raws); k++) {
                    int32_t r = (rows[i].is_signed || raws[k] >= 0) ? raws[k] : -raws[k];
                    if (units_value(&rows[i], r, versions[v], &want)) {
                        assert_near(xf_wire_field_value(&rows[i], r, versions[v]), want, 1e-3);
                        checked++;
                    }
                }
            }
        }
    }
    assert_true(checked >= 2u * 7u * 25u); /* 25 rows have a unit the library converts */
    /* the raw conversions of the host's fields agree too */
    assert_sint_equal(xf_carrier_pitch_raw(-12.34f), -1234);
    assert_near(xf_wire_field_value(ROW(XF_WIRE_HOST, "carrier_pitch"), -1234, 1), -12.34, 1e-12);
    assert_sint_equal(xf_mm_raw(12.345), 12345);
    assert_near(xf_wire_field_value(ROW(XF_WIRE_HOST, "altitude"), 12345, 1), 12.345, 1e-12);
    /* the fields whose unit the packet does not say stay integers */
    assert_int_equal(xf_wire_field_decimals(ROW(XF_WIRE_HOST, "roll_ctrl"), 1), 0);
    assert_int_equal(xf_wire_field_decimals(xf_wire_param(XF_F_ZOOM), 2), 0);
    assert_near(xf_wire_field_value(xf_wire_param(XF_F_TEMP_HIGH), -25, 2), -2.5, 1e-12);
}

/* Every raw value of a row as its engineering value, printed as the program prints JSON
 * numbers (15 significant digits) and read back: the same integer. */
static void check_text_round_trip(const xf_wire_field *f, int64_t raw, uint8_t version)
{
    char text[64];
    int64_t back = 0;
    snprintf(text, sizeof(text), "%.15g", xf_wire_field_value(f, raw, version));
    assert_err(xf_wire_field_raw(f, strtod(text, NULL), version, &back), XF_OK);
    assert_sint_equal(back, raw);
}

static void check_group_round_trip(xf_wire_group g, test_rng *rng)
{
    size_t i, k, v, n;
    const xf_wire_field *rows = xf_wire_fields(g, &n);
    for (i = 0; i < n; i++) {
        int64_t lo, hi, r = 0;
        if (rows[i].kind == XF_WIRE_RESERVED) {
            continue;
        }
        xf_wire_field_range(&rows[i], &lo, &hi);
        for (v = 0; v < ARRAY_LEN(versions); v++) {
            double step = 1.0; /* 10^-decimals */
            unsigned d = xf_wire_field_decimals(&rows[i], versions[v]);
            for (k = 0; k < d; k++) {
                step /= 10.0;
            }
            check_text_round_trip(&rows[i], lo, versions[v]);
            check_text_round_trip(&rows[i], hi, versions[v]);
            check_text_round_trip(&rows[i], 0, versions[v]);
            for (k = 0; k < 200u; k++) {
                check_text_round_trip(&rows[i], lo + (int64_t)(rng_next(rng) % (uint64_t)(hi - lo + 1)), versions[v]);
            }
            /* out of range, and between two steps: refused, never rounded */
            assert_err(
                xf_wire_field_raw(&rows[i], xf_wire_field_value(&rows[i], hi, versions[v]) + step, versions[v], &r),
                XF_ERR_RANGE);
            if (d > 0u) {
                assert_err(xf_wire_field_raw(&rows[i], step / 2.0, versions[v], &r), XF_ERR_ARG);
            } else {
                assert_err(xf_wire_field_raw(&rows[i], 0.5, versions[v], &r), XF_ERR_ARG);
            }
        }
    }
}

static void test_engineering_values_round_trip(void **state)
{
    test_rng rng;
    int64_t r = 7;
    (void)state;
    rng_seed(&rng, 28);
    check_group_round_trip(XF_WIRE_HOST, &rng);
    check_group_round_trip(XF_WIRE_GCU, &rng);
    check_group_round_trip(XF_WIRE_PARAMS, &rng);
    check_group_round_trip(XF_WIRE_PACKET, &rng);
    /* a computed value a hair off its step is the step: a double's error, not a new value */
    assert_err(xf_wire_field_raw(ROW(XF_WIRE_GCU, "cam_pitch"), 0.1 + 0.2, 1, &r), XF_OK);
    assert_sint_equal(r, 30);
    assert_err(xf_wire_field_raw(ROW(XF_WIRE_GCU, "cam_pitch"), (double)NAN, 1, &r), XF_ERR_ARG);
    assert_err(xf_wire_field_raw(NULL, 1.0, 1, &r), XF_ERR_ARG);
}

/* Value names are the codec's functions; bits lie inside their word, named once. */
static void test_names_and_bits(void **state)
{
    size_t g, i, k, n;
    (void)state;
    assert_ptr_equal(ROW(XF_WIRE_GCU, "gimbal_mode")->value_name, xf_mode_name);
    assert_ptr_equal(ROW(XF_WIRE_GCU, "gimbal_code")->value_name, xf_gimbal_model);
    assert_int_equal(ROW(XF_WIRE_GCU, "pod_status")->nbits, 6);
    assert_int_equal(ROW(XF_WIRE_HOST, "status")->bits[1].mask, XF_STATUS_CTRL_VALID);
    assert_string_equal(ROW(XF_WIRE_GCU, "camera_status")->bits[0].name, "pip_mode");
    assert_string_equal(ROW(XF_WIRE_GCU, "camera_status")->bits[0].constant, "XF_CAMERA_PIP_MASK");
    assert_string_equal(ROW(XF_WIRE_GCU, "cam_pitch")->constant, "XF_OFF_GCU_CAM_PITCH");
    assert_string_equal(xf_wire_param(XF_F_ZOOM)->constant, "XF_F_ZOOM");
    for (g = XF_WIRE_PACKET; g <= XF_WIRE_PARAMS; g++) {
        const xf_wire_field *rows = xf_wire_fields((xf_wire_group)g, &n);
        for (i = 0; i < n; i++) {
            unsigned seen = 0;
            assert_int_equal(rows[i].kind == XF_WIRE_ENUM, rows[i].value_name != NULL);
            assert_true(
                strncmp(rows[i].constant, g == XF_WIRE_PARAMS ? "XF_F_" : "XF_OFF_", g == XF_WIRE_PARAMS ? 5 : 7) == 0);
            assert_int_equal(rows[i].kind == XF_WIRE_FLAGS, rows[i].bits != NULL && rows[i].nbits > 0);
            for (k = 0; k < rows[i].nbits; k++) {
                assert_int_equal(rows[i].bits[k].mask & seen, 0);
                assert_int_equal(rows[i].bits[k].mask >> (8u * rows[i].width), 0);
                assert_true(rows[i].bits[k].name[0] != '\0' && rows[i].bits[k].meaning[0] != '\0');
                assert_true(strncmp(rows[i].bits[k].constant, "XF_", 3) == 0);
                seen |= rows[i].bits[k].mask;
            }
        }
    }
    assert_null(xf_wire_fields((xf_wire_group)9, &n));
    assert_int_equal(n, 0);
    assert_null(xf_wire_field_find(XF_WIRE_GCU, "cam_pitc"));
    assert_null(xf_wire_field_find(XF_WIRE_GCU, NULL));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_frame_rows),           cmocka_unit_test(test_rows_against_packers),
        cmocka_unit_test(test_packet_rows),          cmocka_unit_test(test_params_against_encoder),
        cmocka_unit_test(test_scales_are_the_units), cmocka_unit_test(test_engineering_values_round_trip),
        cmocka_unit_test(test_names_and_bits),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
