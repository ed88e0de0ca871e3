/*
 * user_tu.c - a user's translation unit for the compiler matrix (scripts/matrix.sh).
 *
 * The one file of a header-only user that defines XF_IMPLEMENTATION (so the
 * codec's definitions are compiled here, where the optimiser sees the caller's
 * buffers), it includes xfgcu/xfgcu.h; with its second file, user_tu_values.c
 * (which includes it without XF_IMPLEMENTATION, declarations only), it calls
 * every public codec function and function-like macro of the headers it
 * includes. The calls on the caller's buffers are here, this file's concern,
 * with small fixed-size buffers (1, 4, 16 bytes: the calls must fail cleanly,
 * XF_ERR_NO_SPACE, XF_ERR_TRUNCATED, ...) and large ones (XF_PACKET_MAX_LEN,
 * a 4096-byte stream). It must compile without a warning as C99 and as C++
 * with gcc and clang at every optimisation level: gcc's -Warray-bounds,
 * -Wstringop-overflow and -Wmaybe-uninitialized look into the inlined codec
 * at -O2 and above, with the caller's array sizes known.
 *
 * The two files are also a program: it checks its results (the vendor's
 * appendix-1 packet round-trips, the parser finds every frame of a noisy
 * stream fed in any chunking, small buffers give the documented errors) and
 * exits non-zero on any failed check. No test framework: only the library's
 * headers.
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#define XF_IMPLEMENTATION
/* The codec's internal checks on, as a user debugging it would: they must
 * compile warning-free in every configuration, and hold. */
#define XF_ASSERT(cond) ((cond) ? (void)0 : abort())
#include "xfgcu/xfgcu.h"
#include "user_tu.h"

/* XF_STATIC_ASSERT, at file scope as documented */
XF_STATIC_ASSERT(XF_PARAMS_MAX >= XF_PARAMS_KNOWN_MAX, params_hold_every_order);
XF_STATIC_ASSERT(XF_PACKET_MAX_LEN >= XF_PACKET_MIN_LEN + XF_PARAMS_KNOWN_MAX, longest_order_fits);

int utu_checks;
int utu_failures;

/* Always 0, read at run time (see hide()). */
static volatile size_t opaque_zero;

size_t hide(size_t v) { return v + opaque_zero; }

const uint8_t vendor_packet[72] = {
    0xA8, 0xE5, 0x48, 0x00, 0x01, 0x00, 0x00, 0x64, 0x00, 0x9C, 0xFF, 0x05, 0x94, 0xFB, 0x65, 0x00, 0xC0, 0x5D,
    0x70, 0x00, 0x90, 0xFF, 0x70, 0x00, 0x40, 0x80, 0xC0, 0xF7, 0x40, 0x80, 0x01, 0x00, 0x00, 0x00, 0x00, 0x00,
    0x00, 0x01, 0x24, 0xF2, 0xDF, 0x65, 0x16, 0xEE, 0xAA, 0x16, 0xA3, 0xA0, 0x00, 0x00, 0x13, 0xB0, 0x0C, 0x06,
    0x15, 0xE6, 0x08, 0x58, 0x2F, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0xE9, 0xD4,
};

/* ---- xf_crc.h ------------------------------------------------------------- */

static void test_crc(void)
{
    static const uint8_t check[9] = {'1', '2', '3', '4', '5', '6', '7', '8', '9'};
    static uint8_t big[4096];
    uint8_t b1[1];
    uint8_t b4[4];
    uint16_t crc;
    size_t i, cut;

    CHECK(xf_crc16(check, sizeof(check)) == 0x31C3u);
    CHECK(xf_crc16(NULL, 0) == 0u);
    CHECK(xf_crc16_update(0x1234u, NULL, 0) == 0x1234u);
    crc = xf_crc16_update(0, check, 4);
    CHECK(xf_crc16_update(crc, check + 4, 5) == 0x31C3u);

    b1[0] = '1';
    CHECK(xf_crc16(b1, sizeof(b1)) == xf_crc16(check, 1));
    XF_MEMCPY(b4, check, sizeof(b4));
    CHECK(xf_crc16(b4, sizeof(b4)) == xf_crc16(check, 4));
    CHECK(xf_crc16(b4, hide(sizeof(b4))) == xf_crc16(check, hide(4)));

    CHECK(xf_crc16(vendor_packet, 70) == 0xE9D4u);
    CHECK(xf_crc16(vendor_packet, sizeof(vendor_packet)) == 0u);

    for (i = 0; i < sizeof(big); i++) {
        big[i] = (uint8_t)((i * 131u + 7u) & 0xFFu);
    }
    crc = xf_crc16(big, sizeof(big));
    for (cut = 0; cut <= sizeof(big); cut += 1 + cut * 3) {
        CHECK(xf_crc16_update(xf_crc16(big, cut), big + cut, sizeof(big) - cut) == crc);
    }
}

/* ---- xf_packet.h -------------------------------------------------------- */

static void fill_vendor(xf_host_packet *p)
{
    xf_host_packet_init(p, XF_PROTOCOL_V1);
    p->main.pitch_ctrl = 100;
    p->main.yaw_ctrl = -100;
    p->main.status = XF_STATUS_INS_VALID | XF_STATUS_CTRL_VALID;
    p->main.carrier_roll = -1132;
    p->main.carrier_pitch = 101;
    p->main.carrier_yaw = 24000;
    p->main.accel_north = 112;
    p->main.accel_east = -112;
    p->main.accel_up = 112;
    p->main.vel_north = -32704;
    p->main.vel_east = -2112;
    p->main.vel_up = -32704;
    p->sub.sub_header = XF_SUB_HEADER;
    p->sub.longitude = 1709175332;
    p->sub.latitude = 380300822;
    p->sub.altitude = 41123;
    p->sub.satellites = 19;
    p->sub.gnss_ms = 352718000u;
    p->sub.gnss_week = 2278;
    p->sub.relative_height = 12120;
}

static void make_gcu(xf_gcu_packet *g, int16_t seq, uint8_t params_len)
{
    size_t i;
    XF_MEMSET(g, 0, sizeof(*g));
    g->version = XF_PROTOCOL_V2;
    g->main.gimbal_mode = XF_MODE_HEAD_LOCK;
    g->main.pod_status = XF_POD_TARGET_VALID | XF_POD_RANGING_ON;
    g->main.rel_angle_x = seq;
    g->main.cam_yaw = 35999;
    g->main.rate_z = -77;
    g->sub.sub_header = XF_SUB_HEADER;
    g->sub.gimbal_code = 40;
    g->sub.target_distance = 1234;
    g->sub.target_latitude = -380300822;
    g->sub.zoom_cam1 = 55;
    g->sub.camera_status = XF_CAMERA_RECORDING | XF_CAMERA_OSD_ON;
    g->sub.time_zone = -5;
    g->order = XF_ORDER_ZOOM_TO;
    g->params_len = params_len;
    for (i = 0; i < params_len && i < sizeof(g->params); i++) {
        g->params[i] = (uint8_t)((i * 7u + (size_t)(uint16_t)seq) & 0x7Fu);
    }
}

static int gcu_equal(const xf_gcu_packet *a, const xf_gcu_packet *b)
{
    return a->version == b->version && a->main.gimbal_mode == b->main.gimbal_mode &&
           a->main.pod_status == b->main.pod_status && a->main.rel_angle_x == b->main.rel_angle_x &&
           a->main.cam_yaw == b->main.cam_yaw && a->main.rate_z == b->main.rate_z &&
           a->sub.sub_header == b->sub.sub_header && a->sub.gimbal_code == b->sub.gimbal_code &&
           a->sub.target_distance == b->sub.target_distance && a->sub.target_latitude == b->sub.target_latitude &&
           a->sub.zoom_cam1 == b->sub.zoom_cam1 && a->sub.camera_status == b->sub.camera_status &&
           a->sub.time_zone == b->sub.time_zone && a->order == b->order && a->params_len == b->params_len &&
           memcmp(a->params, b->params, a->params_len) == 0;
}

static void test_vendor_packet(void)
{
    xf_host_packet p, q;
    xf_direction dir = XF_DIR_GCU;
    uint8_t exact[72];
    uint8_t big[XF_PACKET_MAX_LEN];
    size_t n = 0;

    CHECK(xf_packet_check(vendor_packet, sizeof(vendor_packet), XF_DIR_HOST) == XF_OK);
    CHECK(xf_packet_check(vendor_packet, sizeof(vendor_packet), XF_DIR_GCU) == XF_ERR_HEADER);
    CHECK(xf_packet_direction(vendor_packet, sizeof(vendor_packet), &dir) == XF_OK && dir == XF_DIR_HOST);

    XF_MEMSET(&p, 0x5A, sizeof(p));
    CHECK(xf_host_unpack(vendor_packet, sizeof(vendor_packet), &p) == XF_OK);
    CHECK(p.version == XF_PROTOCOL_V1 && p.main.pitch_ctrl == 100 && p.main.yaw_ctrl == -100);
    CHECK(p.main.status == 0x05u && p.main.carrier_roll == -1132 && p.main.carrier_yaw == 24000u);
    CHECK(p.main.vel_north == -32704 && p.main.vel_east == -2112 && p.main.sub_request == 1u);
    CHECK(p.sub.longitude == 1709175332 && p.sub.latitude == 380300822 && p.sub.altitude == 41123);
    CHECK(p.sub.satellites == 19u && p.sub.gnss_ms == 352718000u && p.sub.gnss_week == 2278);
    CHECK(p.sub.relative_height == 12120 && p.order == XF_ORDER_NULL && p.params_len == 0u);
    CHECK(xf_host_packet_size(&p) == 72u);

    /* unpack then pack gives the very same bytes */
    XF_MEMSET(exact, 0, sizeof(exact));
    CHECK(xf_host_pack(&p, exact, sizeof(exact), &n) == XF_OK && n == 72u);
    CHECK(memcmp(exact, vendor_packet, sizeof(exact)) == 0);

    /* built from values, into a packet-size buffer */
    fill_vendor(&q);
    n = 0;
    CHECK(xf_host_pack(&q, big, sizeof(big), &n) == XF_OK && n == 72u);
    CHECK(memcmp(big, vendor_packet, sizeof(vendor_packet)) == 0);
    CHECK(xf_host_pack(&q, big, hide(sizeof(big)), NULL) == XF_OK);
    CHECK(memcmp(big, vendor_packet, sizeof(vendor_packet)) == 0);
}

static void test_packet_small_buffers(void)
{
    xf_host_packet hp;
    xf_gcu_packet gp;
    xf_direction dir = XF_DIR_GCU;
    uint8_t b1[1];
    uint8_t b4[4];
    uint8_t b16[16];
    uint8_t b71[71];
    uint8_t big[XF_PACKET_MAX_LEN];
    size_t n = 7;
    size_t i;

    fill_vendor(&hp);
    make_gcu(&gp, 1, 1);

    /* packers: nothing written, XF_ERR_NO_SPACE */
    XF_MEMSET(b1, 0xEE, sizeof(b1));
    XF_MEMSET(b4, 0xEE, sizeof(b4));
    XF_MEMSET(b16, 0xEE, sizeof(b16));
    CHECK(xf_host_pack(&hp, b1, sizeof(b1), &n) == XF_ERR_NO_SPACE && n == 7u);
    CHECK(xf_host_pack(&hp, b4, sizeof(b4), &n) == XF_ERR_NO_SPACE);
    CHECK(xf_host_pack(&hp, b16, sizeof(b16), &n) == XF_ERR_NO_SPACE);
    CHECK(xf_host_pack(&hp, b71, sizeof(b71), &n) == XF_ERR_NO_SPACE);
    CHECK(xf_host_pack(&hp, b16, hide(sizeof(b16)), &n) == XF_ERR_NO_SPACE);
    CHECK(xf_gcu_pack(&gp, b1, sizeof(b1), &n) == XF_ERR_NO_SPACE);
    CHECK(xf_gcu_pack(&gp, b4, sizeof(b4), &n) == XF_ERR_NO_SPACE);
    CHECK(xf_gcu_pack(&gp, b16, sizeof(b16), &n) == XF_ERR_NO_SPACE);
    CHECK(xf_gcu_pack(&gp, b71, hide(sizeof(b71)), &n) == XF_ERR_NO_SPACE && n == 7u);
    CHECK(b1[0] == 0xEEu && b4[0] == 0xEEu && b4[3] == 0xEEu);
    for (i = 0; i < sizeof(b16); i++) {
        CHECK(b16[i] == 0xEEu);
    }
    CHECK(xf_host_pack(NULL, big, sizeof(big), &n) == XF_ERR_ARG);
    CHECK(xf_host_pack(&hp, NULL, sizeof(big), &n) == XF_ERR_ARG);
    CHECK(xf_gcu_pack(NULL, big, sizeof(big), &n) == XF_ERR_ARG);
    CHECK(xf_gcu_pack(&gp, NULL, sizeof(big), &n) == XF_ERR_ARG);

    /* parameters beyond what a packet holds: XF_ERR_RANGE */
    hp.params_len = (uint8_t)(XF_PARAMS_MAX + 1u);
    gp.params_len = (uint8_t)(XF_PARAMS_MAX + 1u);
    CHECK(xf_host_pack(&hp, big, sizeof(big), &n) == XF_ERR_RANGE);
    CHECK(xf_gcu_pack(&gp, big, sizeof(big), &n) == XF_ERR_RANGE);
    CHECK(xf_host_packet_size(&hp) == XF_PACKET_MIN_LEN + XF_PARAMS_MAX + 1u);
    CHECK(xf_gcu_packet_size(&gp) == XF_PACKET_MIN_LEN + XF_PARAMS_MAX + 1u);
    CHECK(xf_host_packet_size(NULL) == 0u && xf_gcu_packet_size(NULL) == 0u);
    xf_host_packet_init(NULL, XF_PROTOCOL_V2); /* does nothing */

    /* direction and check: truncated, header, length, CRC */
    b1[0] = XF_HOST_HEADER0;
    CHECK(xf_packet_direction(b1, sizeof(b1), &dir) == XF_ERR_TRUNCATED && dir == XF_DIR_GCU);
    CHECK(xf_packet_direction(NULL, 2, &dir) == XF_ERR_ARG);
    CHECK(xf_packet_direction(vendor_packet, 2, NULL) == XF_ERR_ARG);
    CHECK(xf_packet_check(b1, sizeof(b1), XF_DIR_HOST) == XF_ERR_TRUNCATED);
    CHECK(xf_packet_check(NULL, 72, XF_DIR_HOST) == XF_ERR_ARG);
#ifndef __cplusplus
    /* not a direction (in C++ the value is outside the enumeration's range) */
    CHECK(xf_packet_check(vendor_packet, sizeof(vendor_packet), (xf_direction)2) == XF_ERR_ARG);
#endif

    XF_MEMCPY(b4, vendor_packet, sizeof(b4));
    CHECK(xf_packet_direction(b4, sizeof(b4), &dir) == XF_OK && dir == XF_DIR_HOST);
    CHECK(xf_packet_check(b4, sizeof(b4), XF_DIR_HOST) == XF_ERR_TRUNCATED);
    CHECK(xf_packet_check(b4, hide(sizeof(b4)), XF_DIR_HOST) == XF_ERR_TRUNCATED);
    CHECK(xf_packet_check(b4, 3, XF_DIR_HOST) == XF_ERR_TRUNCATED);
    CHECK(xf_packet_check(b4, sizeof(b4), XF_DIR_GCU) == XF_ERR_HEADER);
    CHECK(xf_host_unpack(b4, sizeof(b4), &hp) == XF_ERR_TRUNCATED);
    CHECK(xf_gcu_unpack(b4, sizeof(b4), &gp) == XF_ERR_HEADER);
    b4[2] = 71; /* below the shortest packet */
    CHECK(xf_packet_check(b4, sizeof(b4), XF_DIR_HOST) == XF_ERR_LENGTH);
    xf_put_u16le(b4 + XF_OFF_LENGTH, (uint16_t)(XF_PACKET_MAX_LEN + 1u));
    CHECK(xf_packet_check(b4, sizeof(b4), XF_DIR_HOST) == XF_ERR_LENGTH);
    xf_put_u16le(b4 + XF_OFF_LENGTH, 300);
    CHECK(xf_packet_check(b4, hide(sizeof(b4)), XF_DIR_HOST) == XF_ERR_LENGTH);

    XF_MEMCPY(b16, vendor_packet, sizeof(b16));
    CHECK(xf_packet_check(b16, sizeof(b16), XF_DIR_HOST) == XF_ERR_TRUNCATED);
    CHECK(xf_host_unpack(b16, sizeof(b16), &hp) == XF_ERR_TRUNCATED);
    CHECK(xf_host_unpack(b16, sizeof(b16), NULL) == XF_ERR_ARG);
    CHECK(xf_gcu_unpack(b16, sizeof(b16), NULL) == XF_ERR_ARG);
    CHECK(xf_host_unpack(NULL, 72, &hp) == XF_ERR_ARG);
    CHECK(xf_gcu_unpack(NULL, 72, &gp) == XF_ERR_ARG);
    b16[0] = 0x00;
    CHECK(xf_packet_direction(b16, sizeof(b16), &dir) == XF_ERR_HEADER);

    XF_MEMCPY(b71, vendor_packet, sizeof(b71));
    CHECK(xf_packet_check(b71, sizeof(b71), XF_DIR_HOST) == XF_ERR_TRUNCATED);

    /* one byte too many, and a bad CRC */
    XF_MEMSET(big, 0, sizeof(big));
    XF_MEMCPY(big, vendor_packet, sizeof(vendor_packet));
    CHECK(xf_packet_check(big, 73, XF_DIR_HOST) == XF_ERR_LENGTH);
    CHECK(xf_host_unpack(big, sizeof(big), &hp) == XF_ERR_LENGTH);
    big[20] ^= 0x01u;
    CHECK(xf_packet_check(big, 72, XF_DIR_HOST) == XF_ERR_CRC);
    CHECK(xf_host_unpack(big, 72, &hp) == XF_ERR_CRC);
}

/* The low-level writers make the same bytes as the packer; the checked init
 * refuses another layout. */
static void test_packet_writers(void)
{
    static const uint8_t params[2] = {0x01, 0x02};
    xf_host_packet hp;
    xf_parser p;
    uint8_t a[XF_PACKET_MIN_LEN + 2u], b[XF_PACKET_MIN_LEN + 2u];
    size_t n = 0;
    xf_host_packet_init(&hp, XF_PROTOCOL_V1);
    hp.order = XF_ORDER_PALETTE;
    hp.params_len = 2;
    XF_MEMCPY(hp.params, params, 2u);
    CHECK(xf_host_pack(&hp, a, sizeof(a), &n) == XF_OK && n == sizeof(a));
    XF_MEMCPY(b, a, sizeof(b));
    XF_MEMSET(b, 0, XF_OFF_MAIN);
    XF_MEMSET(b + XF_OFF_ORDER, 0, sizeof(b) - XF_OFF_ORDER);
    xf_packet_put_header(b, XF_DIR_HOST, sizeof(b), XF_PROTOCOL_V1);
    xf_packet_put_tail(b, sizeof(b), XF_ORDER_PALETTE, params, 2u);
    CHECK(memcmp(a, b, sizeof(a)) == 0);
    CHECK(xf_parser_size() == sizeof(xf_parser) && xf_options_word() == XF_OPTIONS_WORD);
    CHECK(xf_parser_init_checked(&p, XF_DIR_GCU, XF_OPTIONS_WORD, sizeof(p)) == XF_OK);
    CHECK(xf_parser_init_checked(&p, XF_DIR_GCU, XF_OPTIONS_WORD, sizeof(p) + 1u) == XF_ERR_CONFIG);
    CHECK(xf_parser_init_checked(&p, XF_DIR_GCU, XF_OPTIONS_WORD ^ 1ul, sizeof(p)) == XF_ERR_CONFIG);
}

static void test_packet_large(void)
{
    xf_gcu_packet g, back;
    xf_host_packet h, hback;
    uint8_t big[XF_PACKET_MAX_LEN];
    uint8_t b73[73];
    size_t n = 0;

    /* the longest packet the build allows, both directions */
    make_gcu(&g, -1234, (uint8_t)XF_PARAMS_MAX);
    CHECK(xf_gcu_packet_size(&g) == XF_PACKET_MAX_LEN);
    CHECK(xf_gcu_pack(&g, big, sizeof(big), &n) == XF_OK && n == XF_PACKET_MAX_LEN);
    CHECK(xf_packet_check(big, n, XF_DIR_GCU) == XF_OK);
    CHECK(xf_crc16(big, n) == 0u);
    XF_MEMSET(&back, 0, sizeof(back));
    CHECK(xf_gcu_unpack(big, n, &back) == XF_OK && gcu_equal(&g, &back));
    CHECK(xf_gcu_pack(&g, big, sizeof(big) - 1u, &n) == XF_ERR_NO_SPACE);

    xf_host_packet_init(&h, XF_PROTOCOL_V2);
    CHECK(h.version == XF_PROTOCOL_V2 && h.main.sub_request == XF_SUB_HEADER && h.params_len == 0u);
    h.order = 0xEEu; /* the raw escape hatch: any order, any bytes */
    h.params_len = (uint8_t)XF_PARAMS_MAX;
    XF_MEMSET(h.params, 0x8A, sizeof(h.params));
    CHECK(xf_host_packet_size(&h) == XF_PACKET_MAX_LEN);
    CHECK(xf_host_pack(&h, big, hide(sizeof(big)), &n) == XF_OK && n == XF_PACKET_MAX_LEN);
    CHECK(xf_host_unpack(big, n, &hback) == XF_OK);
    CHECK(hback.order == 0xEEu && hback.params_len == XF_PARAMS_MAX && hback.params[XF_PARAMS_MAX - 1u] == 0x8Au);

    /* a 73-byte reply in an exact buffer */
    make_gcu(&g, 7, 1);
    CHECK(xf_gcu_pack(&g, b73, sizeof(b73), &n) == XF_OK && n == 73u);
    CHECK(xf_gcu_unpack(b73, sizeof(b73), &back) == XF_OK && gcu_equal(&g, &back));
    CHECK(xf_gcu_unpack(b73, 72, &back) == XF_ERR_TRUNCATED);
}

/* ---- xf_command.h ------------------------------------------------------- */

static void test_command_encode_small(void)
{
    /* vendor appendix 4: track start, box (100,100)-(105,105), camera 1 */
    static const uint8_t track_bytes[10] = {0x01, 0x01, 0x64, 0x00, 0x64, 0x00, 0x69, 0x00, 0x69, 0x00};
    /* click_to_aim x=10000 y=5000 */
    static const uint8_t click_bytes[5] = {0x01, 0x10, 0x27, 0x88, 0x13};
    /* all cameras to 5.5x: ZZ = -55 */
    static const uint8_t zoom_bytes[3] = {0xFF, 0xC9, 0xFF};
    xf_command c, d;
    uint8_t p1[1];
    uint8_t p4[4];
    uint8_t p16[16];
    size_t n = 77;
    xf_field bad = XF_F_NONE;

    xf_command_init(&c, XF_ORDER_TRACK);
    c.value = 1;
    c.x0 = 100;
    c.y0 = 100;
    c.x1 = 105;
    c.y1 = 105;
    XF_MEMSET(p1, 0xEE, sizeof(p1));
    XF_MEMSET(p4, 0xEE, sizeof(p4));
    CHECK(xf_command_encode(&c, XF_PROTOCOL_V1, p1, sizeof(p1), &n, &bad) == XF_ERR_NO_SPACE && n == 77u);
    CHECK(xf_command_encode(&c, XF_PROTOCOL_V1, p4, sizeof(p4), &n, &bad) == XF_ERR_NO_SPACE);
    CHECK(xf_command_encode(&c, XF_PROTOCOL_V1, p4, hide(sizeof(p4)), &n, &bad) == XF_ERR_NO_SPACE);
    CHECK(p1[0] == 0xEEu && p4[0] == 0xEEu && p4[3] == 0xEEu);
    CHECK(xf_command_encode(&c, XF_PROTOCOL_V1, NULL, 0, &n, &bad) == XF_ERR_ARG);
    CHECK(xf_command_encode(NULL, XF_PROTOCOL_V1, p16, sizeof(p16), &n, &bad) == XF_ERR_ARG);
    CHECK(xf_command_encode(&c, XF_PROTOCOL_V1, p16, sizeof(p16), &n, &bad) == XF_OK && n == 10u);
    CHECK(memcmp(p16, track_bytes, sizeof(track_bytes)) == 0);
    CHECK(xf_command_encode(&c, XF_PROTOCOL_V1, p16, hide(10), NULL, NULL) == XF_OK);

    /* decode: wrong lengths are XF_ERR_PARAMS, nothing written */
    XF_MEMSET(&d, 0x5A, sizeof(d));
    CHECK(xf_command_decode(XF_ORDER_TRACK, p1, sizeof(p1), XF_PROTOCOL_V1, &d, &bad) == XF_ERR_PARAMS);
    CHECK(xf_command_decode(XF_ORDER_TRACK, p4, sizeof(p4), XF_PROTOCOL_V1, &d, &bad) == XF_ERR_PARAMS);
    CHECK(xf_command_decode(XF_ORDER_TRACK, p16, sizeof(p16), XF_PROTOCOL_V1, &d, &bad) == XF_ERR_PARAMS);
    CHECK(xf_command_decode(XF_ORDER_TRACK, p4, hide(sizeof(p4)), XF_PROTOCOL_V1, &d, &bad) == XF_ERR_PARAMS);
    CHECK(xf_command_decode(XF_ORDER_TRACK, NULL, 0, XF_PROTOCOL_V1, &d, &bad) == XF_ERR_PARAMS);
    CHECK(d.order == 0x5Au);
    CHECK(xf_command_decode(XF_ORDER_TRACK, NULL, 10, XF_PROTOCOL_V1, &d, &bad) == XF_ERR_ARG);
    CHECK(xf_command_decode(XF_ORDER_TRACK, p16, 10, XF_PROTOCOL_V1, NULL, &bad) == XF_ERR_ARG);
    CHECK(xf_command_decode(0xFF, p4, sizeof(p4), XF_PROTOCOL_V1, &d, &bad) == XF_ERR_NOT_FOUND);
    CHECK(xf_command_decode(XF_ORDER_TRACK, p16, 10, XF_PROTOCOL_V1, &d, &bad) == XF_OK);
    CHECK(memcmp(&c, &d, sizeof(c)) == 0);
    CHECK(xf_command_decode(XF_ORDER_NULL, NULL, 0, XF_PROTOCOL_V1, &d, NULL) == XF_OK && d.order == XF_ORDER_NULL);
    CHECK(xf_command_decode(XF_ORDER_SHUTTER, p1, 0, XF_PROTOCOL_V1, &d, NULL) == XF_ERR_PARAMS);

    /* the 5-byte order: 4 is too few, exactly 5 in a 16-byte buffer */
    xf_command_init(&c, XF_ORDER_CLICK_TO_AIM);
    c.x0 = 10000;
    c.y0 = 5000;
    CHECK(xf_command_encode(&c, XF_PROTOCOL_V1, p4, sizeof(p4), &n, NULL) == XF_ERR_NO_SPACE);
    CHECK(xf_command_encode(&c, XF_PROTOCOL_V1, p16, sizeof(p16), &n, NULL) == XF_OK && n == 5u);
    CHECK(memcmp(p16, click_bytes, sizeof(click_bytes)) == 0);

    /* a 3-byte order in a 4-byte buffer, a 1-byte one in a 1-byte buffer */
    xf_command_init(&c, XF_ORDER_ZOOM_TO);
    c.cameras = XF_CAM_ALL;
    c.zoom = xf_zoom_to_rate_raw(5.5f);
    CHECK(xf_command_encode(&c, XF_PROTOCOL_V1, p1, sizeof(p1), &n, NULL) == XF_ERR_NO_SPACE);
    CHECK(xf_command_encode(&c, XF_PROTOCOL_V1, p4, sizeof(p4), &n, NULL) == XF_OK && n == 3u);
    CHECK(memcmp(p4, zoom_bytes, sizeof(zoom_bytes)) == 0);
    CHECK(xf_command_decode(XF_ORDER_ZOOM_TO, p4, 3, XF_PROTOCOL_V1, &d, NULL) == XF_OK && d.zoom == -55);
    xf_command_init(&c, XF_ORDER_SHUTTER);
    CHECK(xf_command_encode(&c, XF_PROTOCOL_V1, p1, sizeof(p1), &n, NULL) == XF_OK && n == 1u && p1[0] == XF_CAM1);
    CHECK(xf_command_decode(XF_ORDER_SHUTTER, p1, sizeof(p1), XF_PROTOCOL_V1, &d, NULL) == XF_OK);
    xf_command_init(&c, XF_ORDER_NULL);
    CHECK(xf_command_encode(&c, XF_PROTOCOL_V1, NULL, 0, &n, NULL) == XF_OK && n == 0u);

    /* the longest order (12 bytes) into 4 and 16 */
    xf_command_init(&c, XF_ORDER_GAZE_GEO);
    c.longitude = xf_deg7_raw(170.9175332);
    c.latitude = xf_deg7_raw(-38.0300822);
    c.altitude = xf_mm_raw(41.123);
    CHECK(xf_command_encode(&c, XF_PROTOCOL_V1, p4, sizeof(p4), &n, NULL) == XF_ERR_NO_SPACE);
    CHECK(xf_command_encode(&c, XF_PROTOCOL_V1, p16, sizeof(p16), &n, NULL) == XF_OK && n == 12u);
    CHECK(xf_get_s32le(p16) == 1709175332 && xf_get_s32le(p16 + 4) == -380300822 && xf_get_s32le(p16 + 8) == 41123);
    CHECK(xf_command_decode(XF_ORDER_GAZE_GEO, p16, 12, XF_PROTOCOL_V1, &d, NULL) == XF_OK);
    CHECK(memcmp(&c, &d, sizeof(c)) == 0);

    /* a range error on decode names the member */
    p16[0] = 0; /* cameras */
    bad = XF_F_NONE;
    CHECK(xf_command_decode(XF_ORDER_TRACK, p16, 10, XF_PROTOCOL_V1, &d, &bad) == XF_ERR_RANGE && bad == XF_F_CAMERAS);
}

/* Every order encoded into and decoded from buffers of 1, 4 and 16 bytes:
 * XF_ERR_NO_SPACE / XF_ERR_PARAMS exactly when its parameters do not fit or
 * have another length; the feedback of every order from one byte. */
static void test_every_order_small(void)
{
    uint8_t p1[1];
    uint8_t p4[4];
    uint8_t p16[16];
    size_t i;
    for (i = 0; i < XF_ORDER_COUNT; i++) {
        const xf_order_info *info = xf_order_at(i);
        xf_command c, d;
        xf_feedback fb;
        size_t plen, n = 0;
        uint8_t order;
        if (info == NULL) {
            CHECK(info != NULL);
            continue;
        }
        order = info->order;
        plen = xf_order_params_len(order);
        xf_command_init(&c, order);
        if (order == XF_ORDER_ZOOM_TO) {
            c.zoom = -10;
        }
        XF_MEMSET(p1, 0, sizeof(p1));
        XF_MEMSET(p4, 0, sizeof(p4));
        XF_MEMSET(p16, 0, sizeof(p16));
        CHECK(xf_command_encode(&c, XF_PROTOCOL_V2, p1, sizeof(p1), &n, NULL) ==
              ((plen <= sizeof(p1)) ? XF_OK : XF_ERR_NO_SPACE));
        CHECK(xf_command_encode(&c, XF_PROTOCOL_V2, p4, sizeof(p4), &n, NULL) ==
              ((plen <= sizeof(p4)) ? XF_OK : XF_ERR_NO_SPACE));
        CHECK(xf_command_encode(&c, XF_PROTOCOL_V2, p16, sizeof(p16), &n, NULL) == XF_OK && n == plen);
        CHECK(xf_command_decode(order, p1, sizeof(p1), XF_PROTOCOL_V2, &d, NULL) ==
              ((plen == sizeof(p1)) ? XF_OK : XF_ERR_PARAMS));
        CHECK(xf_command_decode(order, p4, sizeof(p4), XF_PROTOCOL_V2, &d, NULL) ==
              ((plen == sizeof(p4)) ? XF_OK : XF_ERR_PARAMS));
        CHECK(xf_command_decode(order, p16, sizeof(p16), XF_PROTOCOL_V2, &d, NULL) == XF_ERR_PARAMS);
        CHECK(xf_command_decode(order, p16, n, XF_PROTOCOL_V2, &d, NULL) == XF_OK && d.order == order);
        p1[0] = XF_STATE_SUCCESS;
        CHECK(xf_feedback_decode(order, p1, sizeof(p1), &fb) == XF_OK && fb.result == XF_RESULT_OK);
        CHECK(xf_feedback_decode(order, p16, 0, &fb) == XF_OK && fb.has_state == 0u);
    }
}

static void test_host_set_command(void)
{
    xf_host_packet p, back;
    xf_command c, d;
    uint8_t buf[XF_PACKET_MAX_LEN];
    uint8_t b16[16];
    size_t n = 0;
    xf_field bad = XF_F_NONE;

    xf_host_packet_init(&p, XF_PROTOCOL_V2);
    xf_command_init(&c, XF_ORDER_AREA_TEMP);
    c.value = 1;
    c.x0 = 1000;
    c.y0 = 2000;
    c.x1 = 3000;
    c.y1 = 4000;
    CHECK(xf_host_set_command(&p, &c, &bad) == XF_OK && p.order == XF_ORDER_AREA_TEMP && p.params_len == 10u);
    CHECK(xf_host_set_command(NULL, &c, &bad) == XF_ERR_ARG);
    CHECK(xf_host_set_command(&p, NULL, &bad) == XF_ERR_ARG);
    CHECK(xf_host_pack(&p, b16, sizeof(b16), &n) == XF_ERR_NO_SPACE);
    CHECK(xf_host_pack(&p, buf, sizeof(buf), &n) == XF_OK && n == 82u);
    CHECK(xf_host_unpack(buf, n, &back) == XF_OK && back.order == XF_ORDER_AREA_TEMP);
    CHECK(xf_command_decode(back.order, back.params, back.params_len, back.version, &d, &bad) == XF_OK);
    CHECK(memcmp(&c, &d, sizeof(c)) == 0);

    /* a failed check leaves the packet alone */
    c.x1 = 10;
    CHECK(xf_host_set_command(&p, &c, &bad) == XF_ERR_RANGE && bad == XF_F_X1);
    CHECK(p.order == XF_ORDER_AREA_TEMP && p.params_len == 10u);
    xf_command_init(&c, 0x99);
    CHECK(xf_host_set_command(&p, &c, NULL) == XF_ERR_NOT_FOUND);
}

static void test_feedback(void)
{
    xf_feedback fb;
    uint8_t b1[1];
    uint8_t b4[4] = {0x00, 0x01, 0x02, 0x03};
    int r;

    CHECK(xf_feedback_decode(XF_ORDER_NULL, NULL, 0, &fb) == XF_OK && fb.has_state == 0u && fb.order == 0u);
    b1[0] = XF_STATE_OPERATING;
    CHECK(xf_feedback_decode(XF_ORDER_CALIBRATION, b1, sizeof(b1), &fb) == XF_OK);
    CHECK(fb.has_state == 1u && fb.state == 2u && fb.result == XF_RESULT_OPERATING && fb.failed_cameras == 0u);
    /* 0x02 from a camera-mask order: camera 2 failed */
    CHECK(xf_feedback_decode(XF_ORDER_ZOOM_TO, b1, sizeof(b1), &fb) == XF_OK);
    CHECK(fb.result == XF_RESULT_FAILED && fb.failed_cameras == 2u);
    CHECK(xf_feedback_decode(XF_ORDER_SHUTTER, b1, hide(sizeof(b1)), &fb) == XF_OK);
    CHECK(fb.result == XF_RESULT_FAILED && fb.failed_cameras == 0u);
    CHECK(xf_feedback_decode(XF_ORDER_SHUTTER, b4, sizeof(b4), &fb) == XF_OK && fb.result == XF_RESULT_OK);
    CHECK(xf_feedback_decode(0xFF, b4 + 3, 1, &fb) == XF_OK && fb.result == XF_RESULT_FAILED);
    CHECK(xf_feedback_decode(XF_ORDER_SHUTTER, NULL, 1, &fb) == XF_ERR_ARG);
    CHECK(xf_feedback_decode(XF_ORDER_SHUTTER, b1, 1, NULL) == XF_ERR_ARG);

    for (r = XF_RESULT_OK; r <= XF_RESULT_OPERATING; r++) {
        uint8_t order = (r == XF_RESULT_OPERATING) ? (uint8_t)XF_ORDER_CALIBRATION : (uint8_t)XF_ORDER_PALETTE;
        b1[0] = xf_feedback_state(order, (xf_result)r, XF_CAM2);
        CHECK(xf_feedback_decode(order, b1, sizeof(b1), &fb) == XF_OK && fb.result == (uint8_t)r);
    }
    CHECK(xf_feedback_state(XF_ORDER_PALETTE, XF_RESULT_FAILED, 0) == XF_STATE_FAILURE);
    CHECK(xf_feedback_state(XF_ORDER_PALETTE, XF_RESULT_FAILED, 0x03) == 0x03u);
    CHECK(xf_feedback_state(XF_ORDER_SHUTTER, XF_RESULT_FAILED, 0x03) == XF_STATE_FAILURE);
    CHECK(xf_feedback_state(XF_ORDER_SHUTTER, XF_RESULT_OK, 0) == XF_STATE_SUCCESS);
}

/* ---- xf_parser.h -------------------------------------------------------- */

#define STREAM_LEN 4096u
#define MAX_FRAMES 128u

static uint8_t stream[STREAM_LEN];
static int16_t stream_seq[MAX_FRAMES];
static unsigned stream_frames;
static size_t stream_frame_bytes;

/* A 4096-byte GCU stream: noise with no header byte, false headers (a header
 * pair and the length 72, then garbage), and packets of 72, 73 and
 * XF_PACKET_MAX_LEN bytes carrying their sequence number in rel_angle_x.
 * A false header right before a packet ends inside it, so with one slot
 * (XF_PARSER_SLOTS=1) it would crowd the packet out, as documented: that
 * build gets no false headers. */
#define FALSE_HEADERS (XF_PARSER_SLOTS >= 2)
static void build_stream(void)
{
    uint32_t rng = 0x12345678u;
    size_t pos = 0;
    int16_t seq = 0;
    XF_MEMSET(stream, 0, sizeof(stream));
    stream_frames = 0;
    stream_frame_bytes = 0;
    for (;;) {
        xf_gcu_packet g;
        size_t noise, k, n = 0;
        uint8_t plen;
        rng = rng * 1103515245u + 12345u;
        noise = (size_t)((rng >> 16) % 23u);
        plen = (seq % 5 == 4) ? (uint8_t)XF_PARAMS_MAX : (uint8_t)(seq % 2);
        if (FALSE_HEADERS && seq % 4 == 1) {
            noise += 4u; /* room for a false header */
        }
        if (pos + noise + XF_PACKET_MIN_LEN + plen > sizeof(stream) || stream_frames == MAX_FRAMES) {
            break;
        }
        for (k = 0; k < noise; k++) {
            rng = rng * 1103515245u + 12345u;
            stream[pos + k] = (uint8_t)(rng >> 24);
            if (stream[pos + k] == XF_GCU_HEADER0) {
                stream[pos + k] = 0x8Bu;
            }
        }
        if (FALSE_HEADERS && seq % 4 == 1) {
            stream[pos + noise - 4u] = XF_GCU_HEADER0;
            stream[pos + noise - 3u] = XF_GCU_HEADER1;
            stream[pos + noise - 2u] = 72u;
            stream[pos + noise - 1u] = 0u;
        }
        pos += noise;
        make_gcu(&g, seq, plen);
        CHECK(xf_gcu_pack(&g, stream + pos, sizeof(stream) - pos, &n) == XF_OK && n == XF_PACKET_MIN_LEN + plen);
        pos += n;
        stream_seq[stream_frames++] = seq;
        stream_frame_bytes += n;
        seq++;
    }
    /* the tail: noise, then a packet cut short, which only flush gives up */
    while (pos < sizeof(stream) - 40u) {
        stream[pos] = 0x11u;
        pos++;
    }
    {
        xf_gcu_packet g;
        uint8_t tmp[XF_PACKET_MAX_LEN];
        size_t n = 0;
        make_gcu(&g, 999, 0);
        CHECK(xf_gcu_pack(&g, tmp, sizeof(tmp), &n) == XF_OK);
        XF_MEMCPY(stream + pos, tmp, sizeof(stream) - pos);
    }
}

/* One frame returned by the parser: decode it and check it is the next one expected. */
static void take_frame(const xf_frame *f, unsigned *got, size_t *bytes)
{
    xf_gcu_packet g, want;
    xf_host_packet h;
    CHECK(*got < stream_frames);
    if (*got >= stream_frames) {
        return;
    }
    XF_MEMSET(&g, 0, sizeof(g));
    CHECK(xf_frame_gcu(f, &g) == XF_OK);
    CHECK(xf_frame_host(f, &h) == XF_ERR_HEADER);
    CHECK(xf_packet_check(f->data, f->len, XF_DIR_GCU) == XF_OK);
    make_gcu(&want, stream_seq[*got], g.params_len);
    CHECK(gcu_equal(&g, &want));
    *bytes += f->len;
    (*got)++;
}

/* Feed the stream through fixed-size local arrays of CHUNK bytes, as a
 * driver reading a UART FIFO would. */
#define FEED_THROUGH(NAME, CHUNK)                                                                                      \
    static void NAME(xf_parser *p, unsigned *got, size_t *bytes)                                                       \
    {                                                                                                                  \
        uint8_t chunk[CHUNK];                                                                                          \
        size_t off;                                                                                                    \
        for (off = 0; off < sizeof(stream); off += sizeof(chunk)) {                                                    \
            const uint8_t *d = chunk;                                                                                  \
            size_t left = sizeof(chunk);                                                                               \
            XF_MEMCPY(chunk, stream + off, sizeof(chunk));                                                             \
            for (;;) {                                                                                                 \
                size_t used = 0;                                                                                       \
                xf_frame f;                                                                                            \
                xf_parse_status r = xf_parser_feed(p, d, left, &used, &f);                                             \
                CHECK(r == XF_PARSE_FRAME || r == XF_PARSE_MORE);                                                      \
                CHECK(used <= left);                                                                                   \
                if (r != XF_PARSE_FRAME) {                                                                             \
                    CHECK(used == left);                                                                               \
                    break;                                                                                             \
                }                                                                                                      \
                take_frame(&f, got, bytes);                                                                            \
                d += used;                                                                                             \
                left -= used;                                                                                          \
            }                                                                                                          \
        }                                                                                                              \
    }

XF_STATIC_ASSERT(STREAM_LEN % 16u == 0u, stream_is_whole_chunks);
FEED_THROUGH(feed_by_1, 1)
FEED_THROUGH(feed_by_4, 4)
FEED_THROUGH(feed_by_16, 16)

/* The whole stream in one call (and the frames after the first from what is left). */
static void feed_whole(xf_parser *p, unsigned *got, size_t *bytes)
{
    const uint8_t *d = stream;
    size_t left = hide(sizeof(stream));
    size_t used = 0;
    xf_frame f;
    while (xf_parser_feed(p, d, left, &used, &f) == XF_PARSE_FRAME) {
        take_frame(&f, got, bytes);
        d += used;
        left -= used;
    }
    CHECK(used == left);
}

static void run_stream(void (*feed)(xf_parser *, unsigned *, size_t *), const char *how)
{
    xf_parser p;
    xf_frame f;
    unsigned got = 0;
    size_t bytes = 0;
    int r;
    CHECK(xf_parser_init(&p, XF_DIR_GCU) == XF_OK);
    CHECK(xf_parser_pending(&p) == 0u);
    feed(&p, &got, &bytes);
    CHECK(xf_parser_pending(&p) > 0u); /* the packet cut short */
    while ((r = xf_parser_flush(&p, &f)) == XF_PARSE_FRAME) {
        take_frame(&f, &got, &bytes);
    }
    CHECK(r == XF_PARSE_MORE);
    CHECK(xf_parser_pending(&p) == 0u);
    if (got != stream_frames) {
        fprintf(stderr, "user_tu.c: fed %s: %u frames, expected %u\n", how, got, stream_frames);
    }
    CHECK(got == stream_frames);
    CHECK(p.stats.frames == stream_frames);
    CHECK(bytes == stream_frame_bytes);
    CHECK(p.stats.bytes_in == STREAM_LEN);
    CHECK(p.stats.bytes_in == bytes + p.stats.bytes_skipped + xf_parser_pending(&p));
    CHECK(p.stats.crc_errors > 0u || !FALSE_HEADERS); /* the false headers */
    CHECK(xf_parser_flush(&p, &f) == XF_PARSE_MORE);
}

static void test_parser_stream(void)
{
    build_stream();
    CHECK(stream_frames > 20u);
    run_stream(feed_by_1, "1 byte at a time");
    run_stream(feed_by_4, "4 bytes at a time");
    run_stream(feed_by_16, "16 bytes at a time");
    run_stream(feed_whole, "whole");
}

static void test_parser_edges(void)
{
    xf_parser p;
    xf_frame f;
    xf_host_packet h;
    xf_gcu_packet g;
    uint8_t b1[1] = {0};
    uint8_t b4[4];
    uint8_t b16[16];
    size_t used = 99, i;
    unsigned found = 0;
    xf_direction dir = XF_DIR_GCU;

    CHECK(xf_parser_init(NULL, XF_DIR_GCU) == XF_ERR_ARG);
#ifndef __cplusplus
    CHECK(xf_parser_init(&p, (xf_direction)7) == XF_ERR_ARG);
#endif
    CHECK(xf_parser_init(&p, XF_DIR_HOST) == XF_OK);
    CHECK(xf_parser_feed(NULL, b1, 0, &used, &f) == XF_PARSE_ERR_ARG);
    CHECK(xf_parser_feed(&p, b1, 0, &used, NULL) == XF_PARSE_ERR_ARG);
    CHECK(xf_parser_feed(&p, NULL, 1, &used, &f) == XF_PARSE_ERR_ARG);
    CHECK(xf_parser_feed(&p, NULL, 0, &used, &f) == XF_PARSE_MORE && used == 0u);
    CHECK(xf_parser_flush(NULL, &f) == XF_PARSE_ERR_ARG);
    CHECK(xf_parser_flush(&p, NULL) == XF_PARSE_ERR_ARG);
    CHECK((int)XF_PARSE_ERR_ARG == (int)XF_ERR_ARG); /* its negative values are the xf_err codes */
    CHECK(xf_parser_pending(NULL) == 0u);
    xf_parser_reset(NULL); /* does nothing */

    /* the vendor packet, 1 byte at a time through a 1-byte array */
    for (i = 0; i < sizeof(vendor_packet); i++) {
        b1[0] = vendor_packet[i];
        if (xf_parser_feed(&p, b1, sizeof(b1), &used, &f) == XF_PARSE_FRAME) {
            CHECK(used == 1u && i == sizeof(vendor_packet) - 1u);
            CHECK(f.len == sizeof(vendor_packet) && memcmp(f.data, vendor_packet, f.len) == 0);
            CHECK(xf_frame_host(&f, &h) == XF_OK && h.sub.longitude == 1709175332);
            CHECK(xf_frame_gcu(&f, &g) == XF_ERR_HEADER);
            found++;
        } else {
            CHECK(used == 1u && xf_parser_pending(&p) == i + 1u);
        }
    }
    CHECK(found == 1u && xf_parser_pending(&p) == 0u);

    /* a header pair and its length in 2- and 3-byte arrays */
    {
        uint8_t b2[2];
        uint8_t b3[3];
        XF_MEMCPY(b2, vendor_packet, sizeof(b2));
        XF_MEMCPY(b3, vendor_packet + 2, sizeof(b3));
        CHECK(xf_parser_feed(&p, b2, sizeof(b2), &used, &f) == XF_PARSE_MORE && used == sizeof(b2));
        CHECK(xf_parser_feed(&p, b3, sizeof(b3), &used, &f) == XF_PARSE_MORE && used == sizeof(b3));
        CHECK(xf_parser_pending(&p) == 5u);
        CHECK(xf_crc16(b2, sizeof(b2)) == xf_crc16(vendor_packet, 2));
        CHECK(xf_crc16_update(xf_crc16(b2, sizeof(b2)), b3, sizeof(b3)) == xf_crc16(vendor_packet, 5));
        CHECK(xf_packet_direction(b2, sizeof(b2), &dir) == XF_OK && dir == XF_DIR_HOST);
        CHECK(xf_packet_check(b3, sizeof(b3), XF_DIR_HOST) == XF_ERR_HEADER);
        xf_parser_reset(&p);
        CHECK(xf_parser_feed(&p, b2, sizeof(b2), &used, &f) == XF_PARSE_MORE && xf_parser_pending(&p) == 2u);
        xf_parser_reset(&p);
    }

    /* 4 and 16 bytes of it, then reset: dropped bytes count as skipped */
    XF_MEMCPY(b4, vendor_packet, sizeof(b4));
    XF_MEMCPY(b16, vendor_packet + 4, sizeof(b16));
    CHECK(xf_parser_feed(&p, b4, sizeof(b4), NULL, &f) == XF_PARSE_MORE);
    CHECK(xf_parser_feed(&p, b16, sizeof(b16), &used, &f) == XF_PARSE_MORE && used == sizeof(b16));
    CHECK(xf_parser_pending(&p) == 20u);
    i = p.stats.bytes_skipped;
    xf_parser_reset(&p);
    CHECK(xf_parser_pending(&p) == 0u && p.stats.bytes_skipped == i + 20u);
    /* then a whole packet in one chunk: returned from the parser's own bytes, a copy */
    CHECK(xf_parser_feed(&p, vendor_packet, sizeof(vendor_packet), &used, &f) == XF_PARSE_FRAME);
    CHECK(used == sizeof(vendor_packet) && f.len == sizeof(vendor_packet));
    CHECK(f.data >= p.buf && f.data + f.len <= p.buf + sizeof(p.buf) && xf_crc16(f.data, f.len) == 0u &&
          f.data[2] == vendor_packet[2] && f.data[70] == vendor_packet[70]);
    CHECK(p.stats.frames == 2u && p.stats.bytes_in == 72u + 7u + 20u + 72u);

    /* the frame decoders refuse what the parser would not return */
    f.data = b4;
    f.len = sizeof(b4);
    CHECK(xf_frame_host(&f, &h) == XF_ERR_LENGTH);
    CHECK(xf_frame_gcu(&f, &g) == XF_ERR_LENGTH);
    f.data = b16;
    f.len = hide(sizeof(b16));
    CHECK(xf_frame_host(&f, &h) == XF_ERR_LENGTH);
    f.data = NULL;
    CHECK(xf_frame_host(&f, &h) == XF_ERR_ARG);
    CHECK(xf_frame_gcu(&f, &g) == XF_ERR_ARG);
    CHECK(xf_frame_host(NULL, &h) == XF_ERR_ARG);
    CHECK(xf_frame_gcu(NULL, &g) == XF_ERR_ARG);
    f.data = vendor_packet;
    f.len = sizeof(vendor_packet);
    CHECK(xf_frame_host(&f, NULL) == XF_ERR_ARG);
    CHECK(xf_frame_gcu(&f, NULL) == XF_ERR_ARG);

    /* a packet cut short and flushed: no frame, every byte skipped */
    CHECK(xf_parser_init(&p, XF_DIR_HOST) == XF_OK);
    CHECK(xf_parser_feed(&p, vendor_packet, 71, &used, &f) == XF_PARSE_MORE && used == 71u);
    CHECK(xf_parser_pending(&p) == 71u);
    CHECK(xf_parser_flush(&p, &f) == XF_PARSE_MORE);
    CHECK(xf_parser_pending(&p) == 0u && p.stats.bytes_skipped == 71u && p.stats.frames == 0u);
}

int main(void)
{
    CHECK(XF_VERSION_MAJOR >= 0 && XF_VERSION_STRING[0] != '\0');
    test_strerror();
    test_bytes();
    test_crc();
    test_protocol();
    test_vendor_packet();
    test_packet_small_buffers();
    test_packet_writers();
    test_packet_large();
    test_order_table();
    test_names();
    test_command_get_set();
    test_command_check();
    test_command_encode_small();
    test_every_order_small();
    test_host_set_command();
    test_feedback();
    test_parser_stream();
    test_parser_edges();
    test_units();
    test_wire_fields();
    if (utu_failures != 0) {
        fprintf(stderr, "user_tu: %d of %d checks failed\n", utu_failures, utu_checks);
        return 1;
    }
    printf("user_tu: %d checks passed\n", utu_checks);
    return 0;
}
