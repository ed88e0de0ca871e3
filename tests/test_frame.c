/*
 * test_frame.c - xf_frame_gcu / xf_frame_host: a frame the parser returned
 * decodes exactly as the checked unpack would decode the same bytes, and
 * what is not such a frame is refused.
 */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <string.h>
#include <cmocka.h>

#include "xfgcu/xfgcu.h"

static size_t gcu_packet(uint8_t *buf, size_t cap, uint8_t seed)
{
    xf_gcu_packet g;
    size_t n = 0;
    memset(&g, 0, sizeof(g));
    g.version = 2;
    g.main.gimbal_mode = XF_MODE_EULER;
    g.main.cam_pitch = (int16_t)(-100 * seed);
    g.sub.sub_header = XF_SUB_HEADER;
    g.sub.zoom_cam1 = (uint16_t)(10u + seed);
    g.sub.time_zone = -3;
    g.order = XF_ORDER_ZOOM_IN;
    g.params_len = 1;
    g.params[0] = 0x02;
    assert_int_equal(xf_gcu_pack(&g, buf, cap, &n), XF_OK);
    return n;
}

/* Equal decodes: every field (and no struct padding) compared by packing both. */
static void assert_packs_equal_gcu(const xf_gcu_packet *a, const xf_gcu_packet *b)
{
    uint8_t x[XF_PACKET_MAX_LEN], y[XF_PACKET_MAX_LEN];
    size_t nx = 0, ny = 0;
    assert_int_equal(xf_gcu_pack(a, x, sizeof(x), &nx), XF_OK);
    assert_int_equal(xf_gcu_pack(b, y, sizeof(y), &ny), XF_OK);
    assert_int_equal(nx, ny);
    assert_memory_equal(x, y, nx);
}

static void assert_packs_equal_host(const xf_host_packet *a, const xf_host_packet *b)
{
    uint8_t x[XF_PACKET_MAX_LEN], y[XF_PACKET_MAX_LEN];
    size_t nx = 0, ny = 0;
    assert_int_equal(xf_host_pack(a, x, sizeof(x), &nx), XF_OK);
    assert_int_equal(xf_host_pack(b, y, sizeof(y), &ny), XF_OK);
    assert_int_equal(nx, ny);
    assert_memory_equal(x, y, nx);
}

static void test_gcu_frame_decodes_like_unpack(void **state)
{
    uint8_t stream[400], one[XF_PACKET_MAX_LEN];
    size_t n = gcu_packet(one, sizeof(one), 7), len = 0, used = 0;
    xf_parser p;
    xf_frame f;
    xf_gcu_packet a, b;
    (void)state;
    /* noise first, then the same packet twice: each frame comes out of the parser's buffer */
    memset(stream, 0x11, 5);
    len = 5;
    memcpy(stream + len, one, n);
    len += n;
    memcpy(stream + len, one, n);
    len += n;
    assert_int_equal(xf_parser_init(&p, XF_DIR_GCU), XF_OK);
    for (int k = 0; k < 2; k++) {
        assert_int_equal(xf_parser_feed(&p, stream + used, len - used, &n, &f), XF_PARSE_FRAME);
        used += n;
        memset(&a, 0xA5, sizeof(a));
        memset(&b, 0x5A, sizeof(b));
        assert_int_equal(xf_frame_gcu(&f, &a), XF_OK);
        assert_int_equal(xf_gcu_unpack(f.data, f.len, &b), XF_OK);
        assert_packs_equal_gcu(&a, &b);
        assert_int_equal(a.order, b.order);
        assert_int_equal(a.params_len, 1);
        assert_int_equal(a.params[0], 0x02);
        assert_int_equal(a.sub.time_zone, -3);
    }
}

static void test_host_frame_decodes_like_unpack(void **state)
{
    uint8_t buf[XF_PACKET_MAX_LEN];
    size_t n = 0, used = 0;
    xf_host_packet h, a, b;
    xf_command c;
    xf_parser p;
    xf_frame f;
    (void)state;
    xf_host_packet_init(&h, 1);
    h.main.carrier_yaw = 24000;
    xf_command_init(&c, XF_ORDER_GAZE_GEO);
    c.latitude = 380300822;
    assert_int_equal(xf_host_set_command(&h, &c, NULL), XF_OK);
    assert_int_equal(xf_host_pack(&h, buf, sizeof(buf), &n), XF_OK);
    assert_int_equal(xf_parser_init(&p, XF_DIR_HOST), XF_OK);
    assert_int_equal(xf_parser_feed(&p, buf, n, &used, &f), XF_PARSE_FRAME);
    assert_int_equal(xf_frame_host(&f, &a), XF_OK);
    assert_int_equal(xf_host_unpack(buf, n, &b), XF_OK);
    assert_packs_equal_host(&a, &b);
    assert_int_equal(a.params_len, 12);
    assert_memory_equal(a.params, b.params, 12);
}

static void test_refused(void **state)
{
    uint8_t buf[XF_PACKET_MAX_LEN];
    size_t n = gcu_packet(buf, sizeof(buf), 1);
    xf_frame f;
    xf_gcu_packet g;
    xf_host_packet h;
    (void)state;
    f.data = buf;
    f.len = n;
    assert_int_equal(xf_frame_host(&f, &h), XF_ERR_HEADER); /* a GCU frame is not a host frame */
    f.len = n - 1u;
    assert_int_equal(xf_frame_gcu(&f, &g), XF_ERR_LENGTH); /* length field disagrees */
    f.len = 10;
    assert_int_equal(xf_frame_gcu(&f, &g), XF_ERR_LENGTH);
    f.len = n;
    assert_int_equal(xf_frame_gcu(NULL, &g), XF_ERR_ARG);
    assert_int_equal(xf_frame_gcu(&f, NULL), XF_ERR_ARG);
    f.data = NULL;
    assert_int_equal(xf_frame_gcu(&f, &g), XF_ERR_ARG);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_gcu_frame_decodes_like_unpack),
        cmocka_unit_test(test_host_frame_decodes_like_unpack),
        cmocka_unit_test(test_refused),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
