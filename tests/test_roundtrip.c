/*
 * test_roundtrip.c - seeded random round trips.
 *
 * Packets: random field values, random params_len 0..183, random version;
 * pack must equal an independent encoding from the spec's layout
 * (test_fields.h), unpack must give the struct back, and packing that
 * again must give the same bytes.
 *
 * Commands: random members for every order; xf_command_check must agree
 * with the reference rules of test_orders.h, and every command that passes
 * must encode to the reference bytes and decode back equal.
 *
 * This file is also built without XF_IMPLEMENTATION, against the compiled
 * codec library (test_roundtrip_library).
 */
#include "test_fields.h"
#include "test_orders.h"

#define PACKET_ROUNDS            3000
#define COMMAND_ROUNDS_PER_ORDER 1500

/* Random member values: random wire bytes stored through the spec's type,
 * so every value of every member is reachable. */
static void random_fields(test_rng *r, void *pkt, const field_desc *fields, size_t n)
{
    size_t i;
    for (i = 0; i < n; i++) {
        uint8_t wire[8];
        rng_fill(r, wire, sizeof(wire));
        field_store_wire(pkt, &fields[i], wire);
    }
}

static uint8_t random_params_len(test_rng *r)
{
    switch (rng_below(r, 4)) {
    case 0: return 0;
    case 1: return 1;
    case 2: return (uint8_t)rng_below(r, 13);
    default: return (uint8_t)rng_below(r, XF_PARAMS_MAX + 1u);
    }
}

static uint8_t random_version(test_rng *r)
{
    /* mostly the two real versions; any byte is accepted on receipt (docs/protocol.md §9.3) */
    uint32_t k = rng_below(r, 8);
    return (k < 3) ? 1 : (k < 6) ? 2 : rng_u8(r);
}

static void test_random_host_packets(void **state)
{
    test_rng r;
    int round;
    (void)state;
    rng_seed(&r, 0x486F737450616B31ull);
    for (round = 0; round < PACKET_ROUNDS; round++) {
        xf_host_packet p, back;
        uint8_t buf[256], want[256], again[256];
        size_t n = 0, n2 = 0, wn;
        memset(&p, 0, sizeof(p));
        random_fields(&r, &p, host_fields, ARRAY_LEN(host_fields));
        p.version = random_version(&r);
        p.params_len = random_params_len(&r);
        rng_fill(&r, p.params, p.params_len);

        assert_err(xf_host_pack(&p, buf, sizeof(buf), &n), XF_OK);
        wn = ref_pack(&p, host_fields, ARRAY_LEN(host_fields), p.params_len, p.params, XF_DIR_HOST, want);
        assert_int_equal(n, wn);
        assert_bytes_equal(buf, want, n);

        memset(&back, 0x99, sizeof(back));
        assert_err(xf_host_unpack(buf, n, &back), XF_OK);
        assert_host_pkt_equal(&back, &p);

        assert_err(xf_host_pack(&back, again, sizeof(again), &n2), XF_OK);
        assert_int_equal(n2, n);
        assert_bytes_equal(again, buf, n);
    }
}

static void test_random_gcu_packets(void **state)
{
    test_rng r;
    int round;
    (void)state;
    rng_seed(&r, 0x476375506B743232ull);
    for (round = 0; round < PACKET_ROUNDS; round++) {
        xf_gcu_packet p, back;
        uint8_t buf[256], want[256], again[256];
        size_t n = 0, n2 = 0, wn;
        memset(&p, 0, sizeof(p));
        random_fields(&r, &p, gcu_fields, ARRAY_LEN(gcu_fields));
        p.version = random_version(&r);
        p.params_len = random_params_len(&r);
        rng_fill(&r, p.params, p.params_len);

        assert_err(xf_gcu_pack(&p, buf, sizeof(buf), &n), XF_OK);
        wn = ref_pack(&p, gcu_fields, ARRAY_LEN(gcu_fields), p.params_len, p.params, XF_DIR_GCU, want);
        assert_int_equal(n, wn);
        assert_bytes_equal(buf, want, n);

        memset(&back, 0x99, sizeof(back));
        assert_err(xf_gcu_unpack(buf, n, &back), XF_OK);
        assert_gcu_pkt_equal(&back, &p);

        assert_err(xf_gcu_pack(&back, again, sizeof(again), &n2), XF_OK);
        assert_int_equal(n2, n);
        assert_bytes_equal(again, buf, n);

        /* and the packet is found by a parser too, whole */
        {
            xf_parser ps;
            xf_frame f = {NULL, 0};
            size_t used = 0;
            assert_err(xf_parser_init(&ps, XF_DIR_GCU), XF_OK);
            assert_int_equal(xf_parser_feed(&ps, buf, n, &used, &f), XF_PARSE_FRAME);
            assert_int_equal(used, n);
            assert_int_equal(f.len, n);
            assert_bytes_equal(f.data, buf, n);
        }
    }
}

/* A random value for a command member, biased towards the interesting
 * edges of its range so that both valid and invalid commands come up. */
static int32_t random_member(test_rng *r, xf_field f)
{
    uint32_t k = rng_below(r, 8);
    switch (f) {
    case XF_F_CAMERAS: return (k == 0) ? 0 : rng_range(r, 1, 255);
    case XF_F_VALUE: return (k < 5) ? rng_range(r, 0, 5) : (k < 7) ? rng_range(r, 0, 110) : rng_range(r, 0, 255);
    case XF_F_HOURS: return (k < 6) ? rng_range(r, -14, 16) : rng_range(r, -128, 127);
    case XF_F_X0:
    case XF_F_Y0:
    case XF_F_X1:
    case XF_F_Y1:
        return (k < 6) ? rng_range(r, 0, 10000) : (k < 7) ? rng_range(r, 9995, 10005) : rng_range(r, 0, 65535);
    case XF_F_DX:
    case XF_F_DY:
        return (k < 4) ? rng_range(r, -1030, 1030) : (k < 6) ? rng_range(r, 3065, 32767) : rng_range(r, -32768, 32767);
    case XF_F_ZOOM:
        return (k < 3) ? rng_range(r, -15, 5) : (k < 4) ? rng_range(r, 9995, 10005) : rng_range(r, -32768, 32767);
    case XF_F_TEMP_HIGH:
    case XF_F_TEMP_LOW: return (k < 4) ? rng_range(r, -50, 50) : rng_range(r, -32768, 32767);
    default: return (int32_t)rng_u32(r); /* geo-coordinates: any S32 */
    }
}

static void test_random_commands(void **state)
{
    test_rng r;
    size_t i;
    (void)state;
    rng_seed(&r, 0x436D6452616E6433ull);
    for (i = 0; i < XF_ORDER_COUNT; i++) {
        const xf_order_info *info = xf_order_at(i);
        const order_spec *s = order_spec_find(info->order);
        int round, valid = 0, invalid = 0;
        assert_non_null(s);
        for (round = 0; round < COMMAND_ROUNDS_PER_ORDER; round++) {
            xf_command c, d, want;
            uint8_t out[32], ref[32];
            size_t k, n = 0, rn;
            uint8_t version = (uint8_t)(1u + rng_below(&r, 2));
            xf_field bad = XF_F_NONE;
            unsigned ref_bad;
            xf_err err;
            xf_command_init(&c, info->order);
            /* every member random (unused ones must be ignored) ... */
            for (k = 0; k < ALL_FIELDS_COUNT; k++) {
                cmd_put(&c, all_fields[k], random_member(&r, all_fields[k]));
            }
            /* ... what decode gives back: the used ones, the rest zero */
            memset(&want, 0, sizeof(want));
            want.order = c.order;
            for (k = 0; k < s->nlayout; k++) {
                cmd_put(&want, s->layout[k], cmd_get(&c, s->layout[k]));
            }
            ref_bad = ref_bad_fields(&c, version);
            err = xf_command_check(&c, version, &bad);
            if (ref_bad == 0u) {
                if (err != XF_OK) {
                    print_error("order %s V%u rejected a valid command (%s)\n", s->name, version, xf_field_name(bad));
                    fail();
                }
            } else {
                size_t j;
                int named = 0;
                if (err != XF_ERR_RANGE) {
                    print_error("order %s V%u accepted an invalid command (ref mask 0x%X)\n", s->name, version,
                                ref_bad);
                    fail();
                }
                for (j = 0; j < ALL_FIELDS_COUNT; j++) {
                    if ((ref_bad & BAD(all_fields[j])) && bad == all_fields[j] &&
                        strcmp(xf_field_name(bad), spec_field_name(all_fields[j])) == 0) {
                        named = 1;
                    }
                }
                if (!named) {
                    print_error("order %s: bad_field \"%s\" is not one of the bad members (0x%X)\n", s->name,
                                xf_field_name(bad), ref_bad);
                    fail();
                }
                assert_err(xf_command_encode(&c, version, out, sizeof(out), &n, &bad), XF_ERR_RANGE);
                invalid++;
                continue;
            }
            valid++;
            assert_err(xf_command_encode(&c, version, out, sizeof(out), &n, &bad), XF_OK);
            rn = ref_encode(&c, s, ref);
            assert_int_equal(n, rn);
            assert_bytes_equal(out, ref, n);
            memset(&d, 0x3E, sizeof(d));
            assert_err(xf_command_decode(c.order, out, n, version, &d, &bad), XF_OK);
            assert_cmd_equal(&d, &want);
            /* and re-encoding the decoded command gives the same bytes */
            assert_err(xf_command_encode(&d, version, ref, sizeof(ref), &rn, &bad), XF_OK);
            assert_int_equal(rn, n);
            assert_bytes_equal(ref, out, n);
        }
        /* the generator reaches both sides of the rules for every order */
        if (valid < 10) {
            print_error("order %s: only %d valid random commands\n", s->name, valid);
            fail();
        }
        if (s->nlayout > 0 && invalid == 0 && info->order != XF_ORDER_LIGHTING && info->order != XF_ORDER_GAZE_GEO) {
            print_error("order %s: no invalid random command\n", s->name);
            fail();
        }
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_random_host_packets),
        cmocka_unit_test(test_random_gcu_packets),
        cmocka_unit_test(test_random_commands),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
