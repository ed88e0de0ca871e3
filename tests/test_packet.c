/*
 * test_packet.c - xf_packet.h: every field at its spec offset, both
 * directions, both protocol versions, pack and unpack; the vendor's
 * appendix-1 packet; every error path of pack, unpack and check; the byte
 * order of the pod status word (xf_protocol.h).
 *
 * Expected bytes come from test_fields.h (the spec's layout) and
 * test_util.h (a bitwise CRC), never from the codec.
 */
#include "test_fields.h"

/* Two wire images per field: one with the top bit of the last (most
 * significant) byte set, so signed fields are negative, and one without.
 * Every byte is non-zero and different, so a byte landing at the wrong
 * offset or in the wrong order shows. */
static const uint8_t pattern_neg[8] = {0x81, 0x92, 0xA3, 0xB4, 0xC5, 0xD6, 0xE7, 0xF8};
static const uint8_t pattern_pos[8] = {0x1E, 0x2D, 0x3C, 0x4B, 0x5A, 0x69, 0x78, 0x07};

static const uint8_t versions[2] = {XF_PROTOCOL_V1, XF_PROTOCOL_V2};

/* ---- the tables themselves ---------------------------------------------- */

/* The spec's tables cover bytes 4..69 once each, and every struct member has
 * the C type the spec gives its field (signedness and width). */
static void check_table(const field_desc *fields, size_t n)
{
    int seen[72] = {0};
    size_t i, k;
    for (i = 0; i < n; i++) {
        const field_desc *f = &fields[i];
        for (k = 0; k < f->nbytes; k++) {
            seen[f->wire_off + k]++;
        }
        if (f->kind == FK_BYTES) {
            assert_int_equal(f->member_kind, FK_BYTES);
            assert_int_equal(f->member_size, f->nbytes);
        } else {
            if (f->member_kind != (int)f->kind || f->member_size != f->nbytes) {
                print_error("member %s has the wrong C type for the spec's field\n", f->name);
                fail();
            }
        }
    }
    for (k = 0; k < 72; k++) {
        int want = (k >= 4 && k <= 69) ? 1 : 0;
        if (seen[k] != want) {
            print_error("byte %zu covered %d times\n", k, seen[k]);
            fail();
        }
    }
}

static void test_struct_types_match_spec(void **state)
{
    (void)state;
    check_table(host_fields, ARRAY_LEN(host_fields));
    check_table(gcu_fields, ARRAY_LEN(gcu_fields));
}

/* ---- every field, pack ---------------------------------------------------- */

/* Zero packet of version v with one field set from a wire image; pack must
 * give a 72-byte packet that is zero except the header, the version, that
 * field's bytes and the CRC. */
static void pack_each_field(xf_direction dir)
{
    const field_desc *fields = (dir == XF_DIR_HOST) ? host_fields : gcu_fields;
    size_t nfields = (dir == XF_DIR_HOST) ? ARRAY_LEN(host_fields) : ARRAY_LEN(gcu_fields);
    size_t vi, fi, pi;
    for (vi = 0; vi < 2; vi++) {
        for (fi = 0; fi < nfields; fi++) {
            for (pi = 0; pi < 2; pi++) {
                const field_desc *f = &fields[fi];
                const uint8_t *pat = pi ? pattern_pos : pattern_neg;
                xf_host_packet hp;
                xf_gcu_packet gp;
                uint8_t buf[80], want[72];
                size_t out_len = 0;
                xf_err err;
                memset(buf, 0xEE, sizeof(buf));
                memset(want, 0, sizeof(want));
                want[4] = versions[vi];
                memcpy(want + f->wire_off, pat, f->nbytes); /* may overwrite the version: intended */
                ref_finish_packet(want, 72, dir);
                if (dir == XF_DIR_HOST) {
                    memset(&hp, 0, sizeof(hp));
                    hp.version = versions[vi];
                    field_store_wire(&hp, f, pat);
                    err = xf_host_pack(&hp, buf, sizeof(buf), &out_len);
                } else {
                    memset(&gp, 0, sizeof(gp));
                    gp.version = versions[vi];
                    field_store_wire(&gp, f, pat);
                    err = xf_gcu_pack(&gp, buf, sizeof(buf), &out_len);
                }
                if (err != XF_OK || out_len != 72u) {
                    print_error("field %s: err %d, len %zu\n", f->name, err, out_len);
                    fail();
                }
                if (memcmp(buf, want, 72) != 0) {
                    print_error("pack, field %s, version %u, pattern %zu\n", f->name, versions[vi], pi);
                }
                assert_bytes_equal(buf, want, 72);
                /* nothing written past the packet */
                assert_int_equal(buf[72], 0xEE);
            }
        }
    }
}

static void test_host_pack_each_field(void **state)
{
    (void)state;
    pack_each_field(XF_DIR_HOST);
}

static void test_gcu_pack_each_field(void **state)
{
    (void)state;
    pack_each_field(XF_DIR_GCU);
}

/* ---- every field, unpack -------------------------------------------------- */

/* A hand-built packet with one field set: unpack must put exactly that value
 * (with the spec's signedness) into that member and the baseline into all
 * others, overwriting whatever the struct held before. */
static void unpack_each_field(xf_direction dir)
{
    const field_desc *fields = (dir == XF_DIR_HOST) ? host_fields : gcu_fields;
    size_t nfields = (dir == XF_DIR_HOST) ? ARRAY_LEN(host_fields) : ARRAY_LEN(gcu_fields);
    size_t vi, fi, pi, gi;
    for (vi = 0; vi < 2; vi++) {
        for (fi = 0; fi < nfields; fi++) {
            for (pi = 0; pi < 2; pi++) {
                const field_desc *f = &fields[fi];
                const uint8_t *pat = pi ? pattern_pos : pattern_neg;
                xf_host_packet hp;
                xf_gcu_packet gp;
                const void *pkt;
                uint8_t buf[72];
                uint8_t plen;
                memset(buf, 0, sizeof(buf));
                buf[4] = versions[vi];
                memcpy(buf + f->wire_off, pat, f->nbytes);
                ref_finish_packet(buf, 72, dir);
                /* garbage first: every member must be written by unpack */
                memset(&hp, 0xC3, sizeof(hp));
                memset(&gp, 0xC3, sizeof(gp));
                if (dir == XF_DIR_HOST) {
                    assert_err(xf_host_unpack(buf, 72, &hp), XF_OK);
                    pkt = &hp;
                    plen = hp.params_len;
                } else {
                    assert_err(xf_gcu_unpack(buf, 72, &gp), XF_OK);
                    pkt = &gp;
                    plen = gp.params_len;
                }
                assert_int_equal(plen, 0);
                for (gi = 0; gi < nfields; gi++) {
                    const field_desc *g = &fields[gi];
                    uint8_t got[8];
                    field_load_wire(pkt, g, got);
                    if (memcmp(got, buf + g->wire_off, g->nbytes) != 0) {
                        print_error("unpack: member %s (setting %s, version %u)\n", g->name, f->name, versions[vi]);
                        assert_bytes_equal(got, buf + g->wire_off, g->nbytes);
                    }
                    if (gi == fi && f->kind != FK_BYTES) {
                        /* the numeric value, signedness from the spec */
                        int64_t want =
                            kind_is_signed(f->kind) ? le_get_signed(pat, f->nbytes) : (int64_t)le_get(pat, f->nbytes);
                        assert_sint_equal(field_value(pkt, f), want);
                    }
                }
            }
        }
    }
}

static void test_host_unpack_each_field(void **state)
{
    (void)state;
    unpack_each_field(XF_DIR_HOST);
}

static void test_gcu_unpack_each_field(void **state)
{
    (void)state;
    unpack_each_field(XF_DIR_GCU);
}

/* A few fields by name with values whose bytes are worked out by hand, so
 * that the table-driven tests above are not the only evidence. */
static void test_named_fields_by_hand(void **state)
{
    xf_gcu_packet g;
    xf_host_packet h;
    uint8_t buf[72];
    size_t n;
    (void)state;

    memset(&g, 0, sizeof(g));
    g.version = 2;
    g.sub.thermal_status = 0xC1;  /* byte 63 */
    g.sub.camera_status = 0xA012; /* bytes 64-65: 12 A0 */
    g.sub.time_zone = -2;         /* byte 66: FE */
    g.sub.error_code = 0xC080;    /* bytes 41-42: 80 C0 */
    g.main.cam_yaw = 35999;       /* bytes 22-23: 9F 8C (U16, not negative) */
    g.main.rate_z = -1;           /* bytes 28-29: FF FF */
    g.sub.target_distance = -10;  /* bytes 43-46: F6 FF FF FF */
    assert_err(xf_gcu_pack(&g, buf, sizeof(buf), &n), XF_OK);
    assert_int_equal(n, 72);
    assert_int_equal(buf[0], 0x8A);
    assert_int_equal(buf[1], 0x5E);
    assert_int_equal(buf[2], 0x48);
    assert_int_equal(buf[3], 0x00);
    assert_int_equal(buf[4], 0x02);
    assert_int_equal(buf[63], 0xC1);
    assert_int_equal(buf[64], 0x12);
    assert_int_equal(buf[65], 0xA0);
    assert_int_equal(buf[66], 0xFE);
    assert_int_equal(buf[41], 0x80);
    assert_int_equal(buf[42], 0xC0);
    assert_int_equal(buf[22], 0x9F);
    assert_int_equal(buf[23], 0x8C);
    assert_int_equal(buf[28], 0xFF);
    assert_int_equal(buf[29], 0xFF);
    assert_int_equal(buf[43], 0xF6);
    assert_int_equal(buf[44], 0xFF);
    assert_int_equal(buf[45], 0xFF);
    assert_int_equal(buf[46], 0xFF);

    memset(&g, 0x77, sizeof(g));
    assert_err(xf_gcu_unpack(buf, 72, &g), XF_OK);
    assert_int_equal(g.version, 2);
    assert_int_equal(g.sub.thermal_status, 0xC1);
    assert_int_equal(g.sub.camera_status, 0xA012);
    assert_sint_equal(g.sub.time_zone, -2);
    assert_int_equal(g.sub.error_code, 0xC080);
    assert_int_equal(g.main.cam_yaw, 35999);
    assert_sint_equal(g.main.rate_z, -1);
    assert_sint_equal(g.sub.target_distance, -10);

    /* Host: gnss_week 2278 at 55-56 (E6 08), relative_height -1 at 57-60. */
    memset(&h, 0, sizeof(h));
    h.version = 1;
    h.sub.gnss_week = 2278;
    h.sub.relative_height = -1;
    h.main.carrier_yaw = 0xFFFF;
    assert_err(xf_host_pack(&h, buf, sizeof(buf), &n), XF_OK);
    assert_int_equal(buf[0], 0xA8);
    assert_int_equal(buf[1], 0xE5);
    assert_int_equal(buf[55], 0xE6);
    assert_int_equal(buf[56], 0x08);
    assert_int_equal(buf[57], 0xFF);
    assert_int_equal(buf[60], 0xFF);
    assert_int_equal(buf[16], 0xFF);
    memset(&h, 0, sizeof(h));
    assert_err(xf_host_unpack(buf, 72, &h), XF_OK);
    assert_int_equal(h.main.carrier_yaw, 65535);
    assert_sint_equal(h.sub.relative_height, -1);
}

/* ---- parameters ----------------------------------------------------------- */

static void test_params_placement(void **state)
{
    /* click_to_aim x=10000 y=5000 (vendor appendix 4): 01 10 27 88 13 */
    static const uint8_t params[5] = {0x01, 0x10, 0x27, 0x88, 0x13};
    xf_host_packet h, back;
    uint8_t buf[100], want[77];
    size_t n = 0;
    (void)state;
    memset(&h, 0, sizeof(h));
    h.version = 1;
    h.order = 0x1A;
    h.params_len = 5;
    memcpy(h.params, params, 5);
    assert_int_equal(xf_host_packet_size(&h), 77);
    assert_err(xf_host_pack(&h, buf, sizeof(buf), &n), XF_OK);
    assert_int_equal(n, 77);
    memset(want, 0, sizeof(want));
    want[4] = 1;
    want[69] = 0x1A;
    memcpy(want + 70, params, 5);
    ref_finish_packet(want, 77, XF_DIR_HOST);
    assert_int_equal(want[2], 77); /* the length field counts the whole packet */
    assert_bytes_equal(buf, want, 77);

    memset(&back, 0xA5, sizeof(back));
    assert_err(xf_host_unpack(buf, 77, &back), XF_OK);
    assert_int_equal(back.order, 0x1A);
    assert_int_equal(back.params_len, 5);
    assert_memory_equal(back.params, params, 5);
}

/* The largest packet: 255 bytes, 183 parameter bytes. */
static void test_max_length_packet(void **state)
{
    xf_gcu_packet g, back;
    uint8_t buf[255], want[255];
    size_t i, n = 0;
    (void)state;
    assert_int_equal(XF_PARAMS_MAX, 183);
    memset(&g, 0, sizeof(g));
    g.version = 2;
    g.order = 0x99;
    g.params_len = 183;
    for (i = 0; i < 183; i++) {
        g.params[i] = (uint8_t)(i * 7u + 1u);
    }
    assert_err(xf_gcu_pack(&g, buf, sizeof(buf), &n), XF_OK);
    assert_int_equal(n, 255);
    memset(want, 0, sizeof(want));
    want[4] = 2;
    want[69] = 0x99;
    memcpy(want + 70, g.params, 183);
    ref_finish_packet(want, 255, XF_DIR_GCU);
    assert_int_equal(want[2], 0xFF);
    assert_int_equal(want[3], 0x00);
    assert_bytes_equal(buf, want, 255);
    assert_err(xf_gcu_unpack(buf, 255, &back), XF_OK);
    assert_int_equal(back.params_len, 183);
    assert_memory_equal(back.params, g.params, 183);
}

/* ---- the vendor's appendix-1 packet (docs/protocol.md §9.1) ------------------------- */

static void test_appendix1_unpack(void **state)
{
    xf_host_packet p;
    size_t i;
    (void)state;
    memset(&p, 0x5A, sizeof(p));
    assert_err(xf_packet_check(appendix1_packet, 72, XF_DIR_HOST), XF_OK);
    assert_err(xf_host_unpack(appendix1_packet, 72, &p), XF_OK);
    assert_int_equal(p.version, 1);
    assert_sint_equal(p.main.roll_ctrl, 0);
    assert_sint_equal(p.main.pitch_ctrl, 100);
    assert_sint_equal(p.main.yaw_ctrl, -100);
    assert_int_equal(p.main.status, XF_STATUS_INS_VALID | XF_STATUS_CTRL_VALID);
    assert_int_equal(p.main.status, 0x05);
    assert_sint_equal(p.main.carrier_roll, -1132);
    assert_sint_equal(p.main.carrier_pitch, 101);
    assert_int_equal(p.main.carrier_yaw, 24000);
    assert_sint_equal(p.main.accel_north, 112);
    assert_sint_equal(p.main.accel_east, -112);
    assert_sint_equal(p.main.accel_up, 112);
    /* printed 40 80 = 0x8040, taken literally (docs/protocol.md §9.1) */
    assert_sint_equal(p.main.vel_north, -32704);
    assert_sint_equal(p.main.vel_east, -2112);
    assert_sint_equal(p.main.vel_up, -32704);
    assert_int_equal(p.main.sub_request, 1);
    for (i = 0; i < sizeof(p.main.reserved_main); i++) {
        assert_int_equal(p.main.reserved_main[i], 0);
    }
    assert_int_equal(p.sub.sub_header, 1);
    assert_sint_equal(p.sub.longitude, 1709175332);
    assert_sint_equal(p.sub.latitude, 380300822);
    assert_sint_equal(p.sub.altitude, 41123);
    assert_int_equal(p.sub.satellites, 19);
    assert_int_equal(p.sub.gnss_ms, 352718000u);
    assert_sint_equal(p.sub.gnss_week, 2278);
    assert_sint_equal(p.sub.relative_height, 12120);
    for (i = 0; i < sizeof(p.sub.reserved_sub); i++) {
        assert_int_equal(p.sub.reserved_sub[i], 0);
    }
    assert_int_equal(p.order, XF_ORDER_NULL);
    assert_int_equal(p.params_len, 0);
}

/* The same packet built from values (not from unpack) packs to the exact
 * 72 bytes, CRC E9 D4 included. */
static void test_appendix1_pack(void **state)
{
    xf_host_packet p;
    uint8_t buf[72];
    size_t n = 0;
    (void)state;
    xf_host_packet_init(&p, XF_PROTOCOL_V1);
    p.main.roll_ctrl = 0;
    p.main.pitch_ctrl = 100;
    p.main.yaw_ctrl = -100;
    p.main.status = XF_STATUS_INS_VALID | XF_STATUS_CTRL_VALID;
    p.main.carrier_roll = -1132;
    p.main.carrier_pitch = 101;
    p.main.carrier_yaw = 24000;
    p.main.accel_north = 112;
    p.main.accel_east = -112;
    p.main.accel_up = 112;
    p.main.vel_north = -32704;
    p.main.vel_east = -2112;
    p.main.vel_up = -32704;
    p.sub.sub_header = XF_SUB_HEADER;
    p.sub.longitude = 1709175332;
    p.sub.latitude = 380300822;
    p.sub.altitude = 41123;
    p.sub.satellites = 19;
    p.sub.gnss_ms = 352718000u;
    p.sub.gnss_week = 2278;
    p.sub.relative_height = 12120;
    assert_err(xf_host_pack(&p, buf, sizeof(buf), &n), XF_OK);
    assert_int_equal(n, 72);
    assert_bytes_equal(buf, appendix1_packet, 72);
    assert_int_equal(buf[70], 0xE9);
    assert_int_equal(buf[71], 0xD4);
}

/* xf_host_packet_init: all zero but the version and sub_request = 0x01. */
static void test_host_packet_init(void **state)
{
    xf_host_packet p;
    uint8_t buf[72], want[72];
    (void)state;
    memset(&p, 0xAB, sizeof(p));
    xf_host_packet_init(&p, 2);
    assert_int_equal(p.version, 2);
    assert_int_equal(p.main.sub_request, XF_SUB_HEADER);
    assert_int_equal(p.order, XF_ORDER_NULL);
    assert_int_equal(p.params_len, 0);
    assert_err(xf_host_pack(&p, buf, sizeof(buf), NULL), XF_OK);
    memset(want, 0, sizeof(want));
    want[4] = 2;
    want[30] = 0x01;
    ref_finish_packet(want, 72, XF_DIR_HOST);
    assert_bytes_equal(buf, want, 72);
    xf_host_packet_init(NULL, 1); /* must not crash */
}

/* ---- errors: pack --------------------------------------------------------- */

static void test_pack_errors(void **state)
{
    xf_host_packet h;
    xf_gcu_packet g;
    uint8_t buf[300];
    size_t i, n = 12345;
    size_t plen;
    (void)state;
    xf_host_packet_init(&h, 1);
    memset(&g, 0, sizeof(g));

    assert_err(xf_host_pack(NULL, buf, sizeof(buf), &n), XF_ERR_ARG);
    assert_err(xf_host_pack(&h, NULL, sizeof(buf), &n), XF_ERR_ARG);
    assert_err(xf_gcu_pack(NULL, buf, sizeof(buf), &n), XF_ERR_ARG);
    assert_err(xf_gcu_pack(&g, NULL, sizeof(buf), &n), XF_ERR_ARG);
    assert_int_equal(n, 12345); /* out_len untouched on error */

    /* params_len above XF_PARAMS_MAX (183) */
    h.params_len = 184;
    g.params_len = 184;
    assert_err(xf_host_pack(&h, buf, sizeof(buf), &n), XF_ERR_RANGE);
    assert_err(xf_gcu_pack(&g, buf, sizeof(buf), &n), XF_ERR_RANGE);
    h.params_len = 255;
    g.params_len = 255;
    assert_err(xf_host_pack(&h, buf, sizeof(buf), &n), XF_ERR_RANGE);
    assert_err(xf_gcu_pack(&g, buf, sizeof(buf), &n), XF_ERR_RANGE);

    /* a buffer one byte short, for several sizes: NO_SPACE, nothing written */
    for (plen = 0; plen <= 183; plen += 61) {
        size_t need = 72u + plen;
        h.params_len = (uint8_t)plen;
        g.params_len = (uint8_t)plen;
        memset(buf, 0xCD, sizeof(buf));
        assert_err(xf_host_pack(&h, buf, need - 1u, &n), XF_ERR_NO_SPACE);
        assert_err(xf_gcu_pack(&g, buf, need - 1u, &n), XF_ERR_NO_SPACE);
        assert_err(xf_host_pack(&h, buf, 0, &n), XF_ERR_NO_SPACE);
        for (i = 0; i < sizeof(buf); i++) {
            if (buf[i] != 0xCD) {
                print_error("byte %zu written by a failed pack\n", i);
                fail();
            }
        }
        assert_int_equal(n, 12345);
        /* exactly enough is enough */
        assert_err(xf_host_pack(&h, buf, need, &n), XF_OK);
        assert_int_equal(n, need);
        assert_int_equal(buf[need], 0xCD);
        assert_err(xf_gcu_pack(&g, buf, need, NULL), XF_OK);
        n = 12345;
    }
    assert_int_equal(xf_host_packet_size(NULL), 0);
    assert_int_equal(xf_gcu_packet_size(NULL), 0);
}

/* ---- errors: unpack and check -------------------------------------------- */

/* A valid GCU packet with parameters to mutate. */
static size_t make_gcu_packet(uint8_t *buf, size_t params_len)
{
    size_t i, len = 72u + params_len;
    memset(buf, 0, len);
    buf[4] = 1;
    for (i = 5; i < len - 2u; i++) {
        buf[i] = (uint8_t)(i * 13u);
    }
    ref_finish_packet(buf, len, XF_DIR_GCU);
    return len;
}

static void expect_unpack_error(const uint8_t *buf, size_t len, xf_direction dir, xf_err want)
{
    xf_host_packet h, h0;
    xf_gcu_packet g, g0;
    memset(&h, 0x3C, sizeof(h));
    memset(&g, 0x3C, sizeof(g));
    memcpy(&h0, &h, sizeof(h));
    memcpy(&g0, &g, sizeof(g));
    assert_err(xf_packet_check(buf, len, dir), want);
    if (dir == XF_DIR_HOST) {
        assert_err(xf_host_unpack(buf, len, &h), want);
        if (want != XF_OK) {
            assert_memory_equal(&h, &h0, sizeof(h)); /* written only on success */
        }
    } else {
        assert_err(xf_gcu_unpack(buf, len, &g), want);
        if (want != XF_OK) {
            assert_memory_equal(&g, &g0, sizeof(g));
        }
    }
}

static void test_unpack_errors(void **state)
{
    uint8_t buf[400], bad[400];
    xf_gcu_packet g;
    xf_host_packet h;
    xf_direction d = XF_DIR_HOST;
    size_t len, i;
    (void)state;
    len = make_gcu_packet(buf, 1);
    assert_int_equal(len, 73);
    expect_unpack_error(buf, len, XF_DIR_GCU, XF_OK);

    /* NULL arguments */
    assert_err(xf_gcu_unpack(NULL, len, &g), XF_ERR_ARG);
    assert_err(xf_gcu_unpack(buf, len, NULL), XF_ERR_ARG);
    assert_err(xf_host_unpack(NULL, len, &h), XF_ERR_ARG);
    assert_err(xf_host_unpack(appendix1_packet, 72, NULL), XF_ERR_ARG);
    assert_err(xf_packet_check(NULL, len, XF_DIR_GCU), XF_ERR_ARG);
    assert_err(xf_packet_check(buf, len, (xf_direction)7), XF_ERR_ARG);
    assert_err(xf_packet_direction(NULL, len, &d), XF_ERR_ARG);
    assert_err(xf_packet_direction(buf, len, NULL), XF_ERR_ARG);

    /* direction detection */
    assert_err(xf_packet_direction(buf, len, &d), XF_OK);
    assert_int_equal(d, XF_DIR_GCU);
    assert_err(xf_packet_direction(appendix1_packet, 72, &d), XF_OK);
    assert_int_equal(d, XF_DIR_HOST);
    assert_err(xf_packet_direction(buf, 1, &d), XF_ERR_TRUNCATED);
    memcpy(bad, buf, len);
    bad[1] = 0xE5; /* 8A E5: neither */
    assert_err(xf_packet_direction(bad, len, &d), XF_ERR_HEADER);

    /* bad header bytes */
    memcpy(bad, buf, len);
    bad[0] = 0x8B;
    expect_unpack_error(bad, len, XF_DIR_GCU, XF_ERR_HEADER);
    memcpy(bad, buf, len);
    bad[1] = 0x5F;
    expect_unpack_error(bad, len, XF_DIR_GCU, XF_ERR_HEADER);
    /* the other direction's header, even with a right CRC for it */
    memcpy(bad, buf, len);
    ref_finish_packet(bad, len, XF_DIR_HOST);
    expect_unpack_error(bad, len, XF_DIR_GCU, XF_ERR_HEADER);
    expect_unpack_error(buf, len, XF_DIR_HOST, XF_ERR_HEADER);
    expect_unpack_error(appendix1_packet, 72, XF_DIR_GCU, XF_ERR_HEADER);

    /* length field out of [72, 255]: 71, 0, 256, 0xFFFF (CRC recomputed so
     * only the length is wrong) */
    {
        static const uint16_t bad_lengths[] = {71, 0, 1, 256, 0x0100, 0xFFFF};
        for (i = 0; i < ARRAY_LEN(bad_lengths); i++) {
            uint16_t crc;
            memcpy(bad, buf, len);
            le_put(bad + 2, bad_lengths[i], 2);
            crc = ref_crc16(bad, len - 2u);
            bad[len - 2u] = (uint8_t)(crc >> 8);
            bad[len - 1u] = (uint8_t)crc;
            expect_unpack_error(bad, len, XF_DIR_GCU, XF_ERR_LENGTH);
        }
        /* 71 bytes with length field 71, as if a real 71-byte packet */
        memcpy(bad, buf, 71);
        le_put(bad + 2, 71, 2);
        expect_unpack_error(bad, 71, XF_DIR_GCU, XF_ERR_LENGTH);
    }

    /* fewer bytes than the length says */
    expect_unpack_error(buf, len - 1u, XF_DIR_GCU, XF_ERR_TRUNCATED);
    expect_unpack_error(buf, 72, XF_DIR_GCU, XF_ERR_TRUNCATED);
    expect_unpack_error(buf, 4, XF_DIR_GCU, XF_ERR_TRUNCATED);
    expect_unpack_error(buf, 3, XF_DIR_GCU, XF_ERR_TRUNCATED);
    expect_unpack_error(buf, 1, XF_DIR_GCU, XF_ERR_TRUNCATED);
    expect_unpack_error(buf, 0, XF_DIR_GCU, XF_ERR_TRUNCATED);

    /* more bytes than the length says */
    memcpy(bad, buf, len);
    bad[len] = 0x00;
    expect_unpack_error(bad, len + 1u, XF_DIR_GCU, XF_ERR_LENGTH);
    memset(bad + len, 0, 200);
    expect_unpack_error(bad, len + 200u, XF_DIR_GCU, XF_ERR_LENGTH);

    /* any single flipped bit after the header and length is a CRC error
     * (CRC-16 detects every 1-bit error) */
    for (i = 4 * 8; i < len * 8u; i++) {
        memcpy(bad, buf, len);
        bad[i / 8u] ^= (uint8_t)(1u << (i % 8u));
        expect_unpack_error(bad, len, XF_DIR_GCU, XF_ERR_CRC);
    }
    /* the CRC stored little-endian instead of big-endian */
    memcpy(bad, buf, len);
    bad[len - 2u] = buf[len - 1u];
    bad[len - 1u] = buf[len - 2u];
    if (bad[len - 2u] != buf[len - 2u]) {
        expect_unpack_error(bad, len, XF_DIR_GCU, XF_ERR_CRC);
    }
    /* host side too: the appendix packet with a flipped bit */
    memcpy(bad, appendix1_packet, 72);
    bad[40] ^= 0x10;
    expect_unpack_error(bad, 72, XF_DIR_HOST, XF_ERR_CRC);
}

/* ---- names: xf_strerror, gimbal models, modes ----------------------------- */

/* Every xf_err, with the name of its constant (xf_err_name() must give it back). */
#define ERR_CODE(e)                                                                                                    \
    {                                                                                                                  \
        e, #e                                                                                                          \
    }
static const struct {
    xf_err code;
    const char *name;
} all_codes[] = {
    ERR_CODE(XF_OK),           ERR_CODE(XF_WARN_RATE),     ERR_CODE(XF_ERR_ARG),
    ERR_CODE(XF_ERR_NO_SPACE), ERR_CODE(XF_ERR_RANGE),     ERR_CODE(XF_ERR_UNSUPPORTED),
    ERR_CODE(XF_ERR_CONFIG),   ERR_CODE(XF_ERR_HEADER),    ERR_CODE(XF_ERR_LENGTH),
    ERR_CODE(XF_ERR_CRC),      ERR_CODE(XF_ERR_TRUNCATED), ERR_CODE(XF_ERR_PARAMS),
    ERR_CODE(XF_ERR_FORMAT),   ERR_CODE(XF_ERR_IO),        ERR_CODE(XF_ERR_TIMEOUT),
    ERR_CODE(XF_ERR_CLOSED),   ERR_CODE(XF_ERR_NOT_FOUND), ERR_CODE(XF_ERR_PERMISSION),
    ERR_CODE(XF_ERR_BUSY),     ERR_CODE(XF_ERR_AGAIN),     ERR_CODE(XF_ERR_EOF),
};
#undef ERR_CODE

/* xf_strerror() and xf_err_name() give every xf_err its own string, and nothing else one: iterating
 * over every int near the codes finds exactly the values listed above. */
static void test_strerror_distinct(void **state)
{
    const char *unknown = xf_strerror(-999);
    size_t i, k;
    int v;
    (void)state;
    assert_non_null(unknown);
    assert_string_equal(xf_err_name((xf_err)-999), "unknown");
    for (i = 0; i < ARRAY_LEN(all_codes); i++) {
        const char *s = xf_strerror(all_codes[i].code);
        assert_non_null(s);
        assert_true(s[0] != '\0');
        assert_string_not_equal(s, unknown);
        assert_string_equal(xf_err_name(all_codes[i].code), all_codes[i].name);
        for (k = 0; k < i; k++) {
            assert_true(all_codes[i].code != all_codes[k].code);
            assert_string_not_equal(s, xf_strerror(all_codes[k].code));
            assert_string_not_equal(xf_err_name(all_codes[i].code), xf_err_name(all_codes[k].code));
        }
    }
    for (v = -300; v <= 300; v++) {
        int listed = 0;
        for (i = 0; i < ARRAY_LEN(all_codes); i++) {
            listed |= (int)all_codes[i].code == v;
        }
        if (listed != (strcmp(xf_err_name((xf_err)v), "unknown") != 0) ||
            listed != (strcmp(xf_strerror(v), unknown) != 0)) {
            print_error("value %d: listed %d, name %s, text %s\n", v, listed, xf_err_name((xf_err)v), xf_strerror(v));
            fail();
        }
    }
    /* -1 and 1 are deliberately not ours; 1 is XF_PARSE_FRAME, no xf_err */
    assert_string_equal(xf_strerror(-1), unknown);
    assert_string_equal(xf_strerror(1), unknown);
    assert_string_equal(xf_strerror(XF_PARSE_FRAME), unknown);
    /* zero is success, errors negative, warnings positive */
    assert_true(XF_OK == 0 && XF_WARN_RATE > 0 && XF_ERR_ARG < 0 && XF_ERR_EOF < 0 && XF_ERR_FORMAT < 0);
}

static void test_gimbal_model_names(void **state)
{
    /* docs/protocol.md §6 and §10 */
    static const struct {
        uint8_t code;
        const char *name;
    } models[] = {
        {0, "Z-6A"},        {2, "Z-6C"},        {3, "M-2400G2"},     {21, "Z-8TA"},       {22, "Z-8TB"},
        {24, "Z-8RA"},      {25, "Z-8RB"},      {26, "Z-8RC"},       {27, "Z-8LA"},       {30, "Z-9A"},
        {40, "D-80AI"},     {41, "D-90AI"},     {44, "D-80Pro"},     {45, "D-90Pro(TA)"}, {49, "Z-1Pro"},
        {50, "Z-1Mini"},    {52, "Z-2Mini"},    {53, "D-125AI(T)"},  {55, "D-90DE"},      {57, "D-125AI(V)"},
        {58, "Z-9B_V4(T)"}, {59, "Z-9B_V4(V)"}, {60, "D-90Pro(VA)"}, {61, "D-90Pro(T)"},  {62, "D-90Pro(V)"},
    };
    unsigned c;
    size_t i;
    (void)state;
    for (c = 0; c < 256; c++) {
        const char *want = NULL;
        const char *got = xf_gimbal_model((uint8_t)c);
        for (i = 0; i < ARRAY_LEN(models); i++) {
            if (models[i].code == c) {
                want = models[i].name;
            }
        }
        if (c == 31) {
            /* "Z-9B" in V2.0.4, "Z-9B_V3" in V0.2: either */
            assert_non_null(got);
            assert_true(strncmp(got, "Z-9B", 4) == 0);
        } else if (want == NULL) {
            if (got != NULL) {
                print_error("code %u has a name: %s\n", c, got);
                fail();
            }
        } else {
            assert_non_null(got);
            assert_string_equal(got, want);
        }
    }
}

static void test_mode_names(void **state)
{
    (void)state;
    assert_string_equal(xf_mode_name(0x10), "angle_control");
    assert_string_equal(xf_mode_name(0x11), "head_lock");
    assert_string_equal(xf_mode_name(0x12), "head_follow");
    assert_string_equal(xf_mode_name(0x13), "orthoview");
    assert_string_equal(xf_mode_name(0x14), "euler");
    assert_string_equal(xf_mode_name(0x16), "gaze");
    assert_string_equal(xf_mode_name(0x17), "track");
    assert_string_equal(xf_mode_name(0x1C), "fpv");
    assert_null(xf_mode_name(0x15));
    assert_null(xf_mode_name(0x00));
    assert_null(xf_mode_name(0xFF));
}

/* ---- the byte order of the pod status word (docs/protocol.md §11.7) ------------------------- */

/* The flags the documents name, from the XF_POD_* constants, not from the mask. */
static const uint16_t pod_named[] = {XF_POD_TRACKING_OK,     XF_POD_TARGET_VALID, XF_POD_RANGING_ON,
                                     XF_POD_NIGHT_VISION_ON, XF_POD_LIGHTING_ON,  XF_POD_UPWARD_MOUNT};

static int pod_word_defined(unsigned w)
{
    size_t i;
    for (i = 0; i < ARRAY_LEN(pod_named); i++) {
        w &= ~(unsigned)pod_named[i];
    }
    return w == 0u;
}

/* The pod status word of a GCU packet whose bytes 6 and 7 are @p b6 @p b7, as the codec unpacks it. */
static uint16_t pod_word(uint8_t b6, uint8_t b7)
{
    xf_gcu_packet p;
    uint8_t buf[XF_PACKET_MIN_LEN];
    size_t n = 0;
    uint16_t crc;
    memset(&p, 0, sizeof(p));
    p.version = XF_PROTOCOL_V2;
    assert_err(xf_gcu_pack(&p, buf, sizeof(buf), &n), XF_OK);
    buf[XF_OFF_GCU_POD_STATUS] = b6;
    buf[XF_OFF_GCU_POD_STATUS + 1u] = b7;
    crc = ref_crc16(buf, n - 2u);
    buf[n - 2u] = (uint8_t)(crc >> 8); /* the CRC is big-endian */
    buf[n - 1u] = (uint8_t)(crc & 0xFFu);
    assert_err(xf_gcu_unpack(buf, n, &p), XF_OK);
    return p.main.pod_status;
}

static void test_pod_reserved_mask(void **state)
{
    unsigned bit;
    (void)state;
    assert_int_equal(XF_POD_RESERVED_MASK, 0xE87E); /* bits 15-13, 11, 6-1 */
    for (bit = 0; bit < 16u; bit++) {
        int reserved = (XF_POD_RESERVED_MASK & (1u << bit)) != 0u;
        if (reserved == pod_word_defined(1u << bit)) {
            print_error("bit %u: reserved %d, but the XF_POD_* flags say otherwise\n", bit, reserved);
            fail();
        }
    }
}

/* V2.0.6's decoded reply (docs/protocol.md §2.4): bytes 6-7 are 01 80 in head follow, explained as
 * "ranging on, range and target coordinates valid": the big-endian reading. */
static void test_pod_order_vendor_example(void **state)
{
    static const uint8_t reply[73] = {0x8A, 0x5E, 0x49, 0x00, 0x02, 0x12, 0x01, 0x80, 0x0C, 0xFE, 0xF4, 0x01, 0xDD,
                                      0xFC, 0x20, 0x00, 0x4A, 0x18, 0xFF, 0xFF, 0xA5, 0x03, 0x47, 0x18, 0xFF, 0xFF,
                                      0x01, 0x00, 0xFE, 0xFF, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x01, 0x1F,
                                      0x32, 0x29, 0x00, 0x00, 0x06, 0x17, 0x00, 0x00, 0x24, 0xF2, 0xDF, 0x65, 0x16,
                                      0xEE, 0xAA, 0x16, 0xA3, 0xA0, 0x00, 0x00, 0x2B, 0x01, 0x14, 0x00, 0x00, 0x00,
                                      0x00, 0x08, 0x00, 0x00, 0x20, 0x00, 0xEC, 0x85};
    xf_gcu_packet p;
    (void)state;
    assert_err(xf_packet_check(reply, sizeof(reply), XF_DIR_GCU), XF_OK);
    assert_err(xf_gcu_unpack(reply, sizeof(reply), &p), XF_OK);
    assert_int_equal(p.main.gimbal_mode, XF_MODE_HEAD_FOLLOW);
    assert_int_equal(p.main.pod_status, 0x8001); /* the codec keeps the little-endian wire integer */
    assert_int_equal(xf_pod_status_order(p.main.pod_status), XF_POD_ORDER_BE);
    assert_int_equal(xf_pod_flags(p.main.pod_status, XF_POD_ORDER_BE), XF_POD_RANGING_ON | XF_POD_TARGET_VALID);
    assert_int_equal(xf_pod_flags(p.main.pod_status, XF_POD_ORDER_LE), 0x8001); /* bit 15: reserved */
}

/* A word only the documented order makes sense of: 01 10 = tracking succeeded, mounted upside down. */
static void test_pod_order_plain_le(void **state)
{
    uint16_t w = pod_word(0x01, 0x10);
    (void)state;
    assert_int_equal(w, 0x1001);
    assert_int_equal(xf_pod_status_order(w), XF_POD_ORDER_LE);
    assert_int_equal(xf_pod_flags(w, XF_POD_ORDER_LE), XF_POD_TRACKING_OK | XF_POD_UPWARD_MOUNT);
    assert_int_equal(xf_pod_flags(w, XF_POD_ORDER_BE), 0x0110); /* bit 4: reserved */
    /* every flag alone, in either order */
    assert_int_equal(xf_pod_status_order(pod_word(0x80, 0x00)), XF_POD_ORDER_LE);
    assert_int_equal(xf_pod_status_order(pod_word(0x00, 0x80)), XF_POD_ORDER_BE);
    assert_int_equal(xf_pod_status_order(pod_word(0x00, 0x06)), XF_POD_ORDER_LE); /* night vision, light */
    assert_int_equal(xf_pod_status_order(pod_word(0x06, 0x00)), XF_POD_ORDER_BE);
    assert_int_equal(xf_pod_flags(pod_word(0x06, 0x00), XF_POD_ORDER_BE), XF_POD_NIGHT_VISION_ON | XF_POD_LIGHTING_ON);
}

/* Each reserved bit alone, in the little-endian reading (word 1 << bit) and in the big-endian one
 * (its bytes swapped): the other reading decides when it lands on a named flag, nothing does when
 * it lands on a reserved bit too. */
static void test_pod_order_each_reserved_bit(void **state)
{
    static const struct {
        unsigned bit;
        xf_pod_order other; /* where the other reading puts it */
    } cases[] = {
        {1, XF_POD_ORDER_BE},         /* other reading: bit 9, night vision */
        {2, XF_POD_ORDER_BE},         /* bit 10, lighting */
        {3, XF_POD_ORDER_UNDECIDED},  /* bit 11, reserved */
        {4, XF_POD_ORDER_BE},         /* bit 12, upward mount */
        {5, XF_POD_ORDER_UNDECIDED},  /* bit 13 */
        {6, XF_POD_ORDER_UNDECIDED},  /* bit 14 */
        {11, XF_POD_ORDER_UNDECIDED}, /* bit 3 */
        {13, XF_POD_ORDER_UNDECIDED}, /* bit 5 */
        {14, XF_POD_ORDER_UNDECIDED}, /* bit 6 */
        {15, XF_POD_ORDER_BE},        /* bit 7, target valid */
    };
    size_t i;
    (void)state;
    for (i = 0; i < ARRAY_LEN(cases); i++) {
        unsigned b = cases[i].bit;
        uint8_t lo = (uint8_t)((1u << b) & 0xFFu), hi = (uint8_t)((1u << b) >> 8);
        xf_pod_order mirrored = (cases[i].other == XF_POD_ORDER_BE) ? XF_POD_ORDER_LE : XF_POD_ORDER_UNDECIDED;
        /* reserved bit b in the little-endian reading */
        if (xf_pod_status_order(pod_word(lo, hi)) != cases[i].other) {
            print_error("reserved bit %u, little-endian reading: order %d, expected %d\n", b,
                        (int)xf_pod_status_order(pod_word(lo, hi)), (int)cases[i].other);
            fail();
        }
        /* the same bit in the big-endian reading */
        if (xf_pod_status_order(pod_word(hi, lo)) != mirrored) {
            print_error("reserved bit %u, big-endian reading: order %d, expected %d\n", b,
                        (int)xf_pod_status_order(pod_word(hi, lo)), (int)mirrored);
            fail();
        }
        /* read the way it decides, the word is the named flag */
        if (cases[i].other == XF_POD_ORDER_BE) {
            assert_int_equal(xf_pod_flags(pod_word(lo, hi), XF_POD_ORDER_BE), 1u << (b ^ 8u));
            assert_true(pod_word_defined(1u << (b ^ 8u)));
        }
    }
}

/* Undecided: both readings are words the documents define (each byte 00 or 01), or neither is. */
static void test_pod_order_undecided(void **state)
{
    static const uint8_t both[][2] = {{0x00, 0x00}, {0x01, 0x00}, {0x00, 0x01}, {0x01, 0x01}};
    static const uint8_t neither[][2] = {{0xFF, 0xFF}, {0x02, 0x02}, {0x08, 0x08}, {0x81, 0x81}, {0x7E, 0xE8}};
    size_t i;
    (void)state;
    for (i = 0; i < ARRAY_LEN(both); i++) {
        assert_int_equal(xf_pod_status_order(pod_word(both[i][0], both[i][1])), XF_POD_ORDER_UNDECIDED);
    }
    for (i = 0; i < ARRAY_LEN(neither); i++) {
        assert_int_equal(xf_pod_status_order(pod_word(neither[i][0], neither[i][1])), XF_POD_ORDER_UNDECIDED);
    }
    /* 01 00 means tracking in one order and ranging in the other: the caller's default decides */
    assert_int_equal(xf_pod_flags(pod_word(0x01, 0x00), XF_POD_ORDER_UNDECIDED), XF_POD_TRACKING_OK);
    assert_int_equal(xf_pod_flags(pod_word(0x01, 0x00), XF_POD_ORDER_LE), XF_POD_TRACKING_OK);
    assert_int_equal(xf_pod_flags(pod_word(0x01, 0x00), XF_POD_ORDER_BE), XF_POD_RANGING_ON);
}

/* Every word against the definition, written here from bytes and the named flags. */
static void test_pod_order_every_word(void **state)
{
    unsigned w, clean_both = 0;
    (void)state;
    for (w = 0; w < 0x10000u; w++) {
        unsigned b6 = w & 0xFFu, b7 = w >> 8;
        unsigned be = (b6 << 8) | b7; /* byte 6 the high byte */
        int le_ok = pod_word_defined(w), be_ok = pod_word_defined(be);
        xf_pod_order want = (le_ok && !be_ok)   ? XF_POD_ORDER_LE
                            : (be_ok && !le_ok) ? XF_POD_ORDER_BE
                                                : XF_POD_ORDER_UNDECIDED;
        xf_pod_order got = xf_pod_status_order((uint16_t)w);
        clean_both += (unsigned)(le_ok && be_ok);
        if (got != want || xf_pod_flags((uint16_t)w, XF_POD_ORDER_LE) != w ||
            xf_pod_flags((uint16_t)w, XF_POD_ORDER_UNDECIDED) != w ||
            xf_pod_flags((uint16_t)w, XF_POD_ORDER_BE) != be) {
            print_error("word 0x%04X: order %d (expected %d), flags LE 0x%04X BE 0x%04X\n", w, (int)got, (int)want,
                        xf_pod_flags((uint16_t)w, XF_POD_ORDER_LE), xf_pod_flags((uint16_t)w, XF_POD_ORDER_BE));
            fail();
        }
    }
    assert_int_equal(clean_both, 4); /* 00 00, 01 00, 00 01, 01 01 */
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_struct_types_match_spec), cmocka_unit_test(test_host_pack_each_field),
        cmocka_unit_test(test_gcu_pack_each_field),     cmocka_unit_test(test_host_unpack_each_field),
        cmocka_unit_test(test_gcu_unpack_each_field),   cmocka_unit_test(test_named_fields_by_hand),
        cmocka_unit_test(test_params_placement),        cmocka_unit_test(test_max_length_packet),
        cmocka_unit_test(test_appendix1_unpack),        cmocka_unit_test(test_appendix1_pack),
        cmocka_unit_test(test_host_packet_init),        cmocka_unit_test(test_pack_errors),
        cmocka_unit_test(test_unpack_errors),           cmocka_unit_test(test_strerror_distinct),
        cmocka_unit_test(test_gimbal_model_names),      cmocka_unit_test(test_mode_names),
        cmocka_unit_test(test_pod_reserved_mask),       cmocka_unit_test(test_pod_order_vendor_example),
        cmocka_unit_test(test_pod_order_plain_le),      cmocka_unit_test(test_pod_order_each_reserved_bit),
        cmocka_unit_test(test_pod_order_undecided),     cmocka_unit_test(test_pod_order_every_word),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
