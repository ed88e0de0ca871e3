/*
 * test_crc.c - xf_crc.h: CRC-16/XMODEM against a bitwise reference and the
 * vendor's own nibble routine, the check value, incremental updates, one
 * byte into the CRC kept in the top half of a word, and the CRC's big-endian
 * place in a packet.
 *
 * Built twice: with the default nibble table and with XF_CRC_TABLE_256=1
 * (test_crc_table256). Both must agree with the same two references, hence
 * with each other.
 */
#include "test_util.h"

static void test_report_config(void **state)
{
    (void)state;
#ifdef EXPECT_CRC_TABLE_256
    /* the CMake target says this binary is the 256-table build: make sure */
    assert_int_equal(XF_CRC_TABLE_256, EXPECT_CRC_TABLE_256);
#endif
    print_message("CRC implementation: %s table\n", XF_CRC_TABLE_256 ? "256-entry" : "16-entry nibble");
}

static void test_check_value(void **state)
{
    static const uint8_t check[9] = {'1', '2', '3', '4', '5', '6', '7', '8', '9'};
    (void)state;
    assert_int_equal(xf_crc16(check, 9), 0x31C3);
    assert_int_equal(ref_crc16(check, 9), 0x31C3);
    assert_int_equal(vendor_crc16(check, 9), 0x31C3);
    assert_int_equal(xf_crc16_update(0, check, 9), 0x31C3);
    /* one more known value of CRC-16/XMODEM: "A" -> 0x58E5 */
    assert_int_equal(xf_crc16((const uint8_t *)"A", 1), 0x58E5);
    /* init 0, no final XOR: the empty message and a zero byte give 0 */
    assert_int_equal(xf_crc16(check, 0), 0x0000);
    assert_int_equal(xf_crc16(NULL, 0), 0x0000);
    assert_int_equal(xf_crc16_update(0x1234, NULL, 0), 0x1234);
    {
        static const uint8_t zero[1] = {0};
        static const uint8_t one[1] = {1};
        assert_int_equal(xf_crc16(zero, 1), 0x0000);
        assert_int_equal(xf_crc16(one, 1), 0x1021); /* the polynomial itself */
    }
}

/* The appendix-1 packet's CRC is E9 D4 over bytes 0..69 (docs/protocol.md §9.1). */
static void test_appendix1_crc(void **state)
{
    (void)state;
    assert_int_equal(xf_crc16(appendix1_packet, 70), 0xE9D4);
    assert_int_equal(ref_crc16(appendix1_packet, 70), 0xE9D4);
    assert_int_equal(vendor_crc16(appendix1_packet, 70), 0xE9D4);
    /* the CRC over the whole packet, its own CRC included, is 0 (MSB-first, stored big-endian) */
    assert_int_equal(xf_crc16(appendix1_packet, 72), 0x0000);
}

static void test_random_buffers(void **state)
{
    test_rng r;
    uint8_t buf[600];
    int round;
    (void)state;
    rng_seed(&r, 0xC0FFEE1234ull);
    for (round = 0; round < 3000; round++) {
        size_t len = rng_below(&r, (round % 10 == 0) ? 600 : 80);
        uint16_t want;
        rng_fill(&r, buf, len);
        want = ref_crc16(buf, len);
        assert_int_equal(xf_crc16(buf, len), want);
        if (len < 256) {
            assert_int_equal(vendor_crc16(buf, (uint8_t)len), want);
        }
    }
    /* all 65536 two-byte messages */
    {
        unsigned v;
        for (v = 0; v < 65536u; v++) {
            buf[0] = (uint8_t)(v >> 8);
            buf[1] = (uint8_t)v;
            if (xf_crc16(buf, 2) != ref_crc16(buf, 2)) {
                print_error("message %02X %02X\n", buf[0], buf[1]);
                fail();
            }
        }
    }
}

/* Updating in pieces, split anywhere, equals the CRC of the whole. */
static void test_incremental(void **state)
{
    test_rng r;
    uint8_t buf[300];
    size_t split, split2;
    uint16_t whole;
    (void)state;
    rng_seed(&r, 77);
    rng_fill(&r, buf, sizeof(buf));
    whole = xf_crc16(buf, sizeof(buf));
    for (split = 0; split <= sizeof(buf); split++) {
        uint16_t c = xf_crc16_update(0, buf, split);
        c = xf_crc16_update(c, buf + split, sizeof(buf) - split);
        assert_int_equal(c, whole);
    }
    for (split = 0; split < 40; split++) {
        for (split2 = split; split2 < 40; split2++) {
            uint16_t c = xf_crc16_update(0, buf, split);
            c = xf_crc16_update(c, buf + split, split2 - split);
            c = xf_crc16_update(c, buf + split2, 40 - split2);
            assert_int_equal(c, ref_crc16(buf, 40));
        }
    }
}

/* One byte into the CRC (xf__crc_step, the CRC in the top half of a
 * word) agrees with the bitwise reference from every state,
 * and its low half stays zero. */
static void test_crc_byte_step(void **state)
{
    test_rng r;
    unsigned b;
    int i;
    (void)state;
    rng_seed(&r, 0x5117);
    for (i = 0; i < 300; i++) {
        uint16_t c = (i == 0) ? 0u : (i == 1) ? 0xFFFFu : (uint16_t)rng_u32(&r);
        for (b = 0; b < 256u; b++) {
            uint8_t byte = (uint8_t)b;
            uint32_t w = xf__crc_step((uint32_t)c << 16, byte);
            assert_int_equal(w & 0xFFFFu, 0);
            assert_int_equal(w >> 16, xf_crc16_update(c, &byte, 1));
        }
    }
    for (b = 0; b < 256u; b++) {
        uint8_t byte = (uint8_t)b;
        assert_int_equal(xf__crc_step(0, byte) >> 16, ref_crc16(&byte, 1));
    }
}

/* The CRC sits big-endian in the last two bytes of a packet (docs/protocol.md §2). */
static void test_crc_big_endian_in_packet(void **state)
{
    test_rng r;
    int round;
    (void)state;
    rng_seed(&r, 0xB16E);
    for (round = 0; round < 200; round++) {
        xf_host_packet h;
        xf_gcu_packet g;
        uint8_t buf[256];
        size_t n = 0;
        uint16_t crc;
        xf_host_packet_init(&h, 1);
        h.main.pitch_ctrl = (int16_t)rng_u32(&r);
        h.sub.gnss_ms = rng_u32(&r);
        h.params_len = (uint8_t)rng_below(&r, 20);
        rng_fill(&r, h.params, h.params_len);
        assert_err(xf_host_pack(&h, buf, sizeof(buf), &n), XF_OK);
        crc = ref_crc16(buf, n - 2u);
        assert_int_equal(buf[n - 2u], crc >> 8);
        assert_int_equal(buf[n - 1u], crc & 0xFFu);

        memset(&g, 0, sizeof(g));
        g.main.cam_yaw = (uint16_t)rng_u32(&r);
        g.sub.target_distance = (int32_t)rng_u32(&r);
        g.params_len = (uint8_t)rng_below(&r, 2);
        g.params[0] = rng_u8(&r);
        assert_err(xf_gcu_pack(&g, buf, sizeof(buf), &n), XF_OK);
        crc = ref_crc16(buf, n - 2u);
        assert_int_equal(buf[n - 2u], crc >> 8);
        assert_int_equal(buf[n - 1u], crc & 0xFFu);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_report_config),
        cmocka_unit_test(test_check_value),
        cmocka_unit_test(test_appendix1_crc),
        cmocka_unit_test(test_random_buffers),
        cmocka_unit_test(test_incremental),
        cmocka_unit_test(test_crc_byte_step),
        cmocka_unit_test(test_crc_big_endian_in_packet),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
