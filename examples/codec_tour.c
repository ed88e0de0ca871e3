/*
 * codec_tour.c - the codec in one page: build a host packet from carrier
 * data and a command, decode the vendor's appendix-1 packet, fake a GCU
 * reply, and recover it from a noisy byte stream.
 */
#include <stdio.h>
#include <string.h>

#include "xfgcu/xfgcu.h"

static void print_hex(const char *label, const uint8_t *b, size_t n)
{
    size_t i;
    printf("%s (%zu bytes):", label, n);
    for (i = 0; i < n; i++) {
        printf("%s%02X", (i % 24u == 0u) ? "\n  " : " ", b[i]);
    }
    printf("\n");
}

static int host_packet_with_zoom(uint8_t *out, size_t cap, size_t *len)
{
    xf_host_packet pkt;
    xf_command cmd;
    xf_field bad = XF_F_NONE;
    int err;

    xf_host_packet_init(&pkt, XF_PROTOCOL_V1);
    pkt.main.status = XF_STATUS_INS_VALID;
    pkt.main.carrier_roll = xf_carrier_roll_raw(-11.32f);
    pkt.main.carrier_pitch = xf_carrier_pitch_raw(1.01f);
    pkt.main.carrier_yaw = xf_carrier_yaw_raw(240.0f);
    pkt.sub.sub_header = XF_SUB_HEADER;
    pkt.sub.latitude = xf_deg7_raw(38.0300822);
    pkt.sub.longitude = xf_deg7_raw(170.9175332);

    xf_command_init(&cmd, XF_ORDER_ZOOM_TO);
    cmd.zoom = xf_zoom_to_rate_raw(5.5f); /* 5.5x on camera 1 */
    err = xf_host_set_command(&pkt, &cmd, &bad);
    if (err != XF_OK) {
        printf("zoom_to: %s (%s)\n", xf_strerror(err), bad != XF_F_NONE ? xf_field_name(bad) : "-");
        return err;
    }
    return xf_host_pack(&pkt, out, cap, len);
}

int main(void)
{
    static const uint8_t appendix1[72] = {
        0xA8, 0xE5, 0x48, 0x00, 0x01, 0x00, 0x00, 0x64, 0x00, 0x9C, 0xFF, 0x05, 0x94, 0xFB, 0x65, 0x00, 0xC0, 0x5D,
        0x70, 0x00, 0x90, 0xFF, 0x70, 0x00, 0x40, 0x80, 0xC0, 0xF7, 0x40, 0x80, 0x01, 0x00, 0x00, 0x00, 0x00, 0x00,
        0x00, 0x01, 0x24, 0xF2, 0xDF, 0x65, 0x16, 0xEE, 0xAA, 0x16, 0xA3, 0xA0, 0x00, 0x00, 0x13, 0xB0, 0x0C, 0x06,
        0x15, 0xE6, 0x08, 0x58, 0x2F, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0xE9, 0xD4,
    };
    uint8_t buf[XF_PACKET_MAX_LEN];
    uint8_t stream[400];
    size_t len = 0, n = 0, used;
    xf_host_packet host;
    xf_gcu_packet gcu;
    xf_parser parser;
    xf_frame frame;
    int64_t unix_ms = 0;
    /* line noise: a header with an impossible length, stray header bytes */
    const uint8_t noise[] = {0x8A, 0x5E, 0x13, 0x00, 0x13, 0x8A, 0x8A, 0x5E, 0x01};

    printf("xfgcu %s codec tour\n\n", XF_VERSION_STRING);

    if (host_packet_with_zoom(buf, sizeof(buf), &len) != XF_OK) {
        return 1;
    }
    print_hex("1. host packet: carrier attitude + zoom_to 5.5x", buf, len);

    if (xf_host_unpack(appendix1, sizeof(appendix1), &host) != XF_OK) {
        printf("appendix 1 did not decode\n");
        return 1;
    }
    printf("\n2. vendor appendix 1 decoded: pitch_ctrl=%d yaw_ctrl=%d carrier_roll=%.2f deg "
           "carrier_yaw=%.2f deg satellites=%u\n",
           host.main.pitch_ctrl, host.main.yaw_ctrl, (double)xf_cdeg(host.main.carrier_roll),
           (double)xf_cdeg(host.main.carrier_yaw), (unsigned)host.sub.satellites);
    if (xf_gnss_to_unix_ms(host.sub.gnss_week, host.sub.gnss_ms, XF_LEAP_SECONDS_2017, &unix_ms) == XF_OK) {
        printf("   GNSS week %d + %u ms = Unix %lld ms\n", host.sub.gnss_week, (unsigned)host.sub.gnss_ms,
               (long long)unix_ms);
    }

    memset(&gcu, 0, sizeof(gcu));
    gcu.version = XF_PROTOCOL_V1;
    gcu.main.gimbal_mode = XF_MODE_HEAD_LOCK;
    gcu.main.cam_pitch = -4500;
    gcu.main.cam_yaw = 9000;
    gcu.sub.sub_header = XF_SUB_HEADER;
    gcu.sub.gimbal_code = 52;
    gcu.sub.zoom_cam1 = 55;
    gcu.order = XF_ORDER_ZOOM_TO;
    gcu.params_len = 1;
    gcu.params[0] = xf_feedback_state(XF_ORDER_ZOOM_TO, XF_RESULT_OK, 0);
    if (xf_gcu_pack(&gcu, buf, sizeof(buf), &len) != XF_OK) {
        return 1;
    }
    /* noise, the first 30 bytes of a reply (a link cut mid-packet), the
     * reply, more noise, the reply again */
    memcpy(stream, noise, sizeof(noise));
    n = sizeof(noise);
    memcpy(stream + n, buf, 30);
    n += 30;
    memcpy(stream + n, buf, len);
    n += len;
    memcpy(stream + n, noise, sizeof(noise));
    n += sizeof(noise);
    memcpy(stream + n, buf, len);
    n += len;

    printf("\n3. GCU replies recovered from %zu bytes of noisy stream, fed 7 bytes at a time:\n", n);
    xf_parser_init(&parser, XF_DIR_GCU);
    for (used = 0; used < n;) {
        size_t chunk = (n - used < 7u) ? (n - used) : 7u;
        const uint8_t *p = stream + used;
        size_t c;
        while (xf_parser_feed(&parser, p, chunk, &c, &frame) == XF_PARSE_FRAME) {
            xf_feedback fb;
            if (xf_gcu_unpack(frame.data, frame.len, &gcu) == XF_OK &&
                xf_feedback_decode(gcu.order, gcu.params, gcu.params_len, &fb) == XF_OK) {
                float zoom = xf_zoom_x(gcu.sub.zoom_cam1);
                printf(
                    "   %s mode, pitch %.2f deg, yaw %.2f deg, zoom %.1fx, gimbal %s (code %u); feedback to %s: %s\n",
                    xf_mode_name(gcu.main.gimbal_mode), (double)xf_cdeg(gcu.main.cam_pitch),
                    (double)xf_cdeg(gcu.main.cam_yaw), (double)zoom, xf_gimbal_model(gcu.sub.gimbal_code),
                    gcu.sub.gimbal_code, xf_order_name(fb.order), fb.result == XF_RESULT_OK ? "ok" : "failed");
            }
            p += c;
            chunk -= c;
        }
        used += (size_t)(p - (stream + used)) + chunk;
    }
    printf("   parser: %u frames, %u CRC errors, %u length errors, %u bytes skipped\n", parser.stats.frames,
           parser.stats.crc_errors, parser.stats.length_errors, parser.stats.bytes_skipped);
    return parser.stats.frames == 2u ? 0 : 1;
}
