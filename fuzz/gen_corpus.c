/*
 * gen_corpus - writes the small committed seed corpus of the fuzz harnesses.
 *
 *     gen_corpus DIR     writes DIR/fuzz_parser_raw/... and DIR/fuzz_parser_crcfix/...
 *
 * Regenerate with `scripts/fuzz.sh corpus` (it overwrites only the files
 * named here; files the fuzzer added by hand stay). Deterministic.
 */
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "xfgcu/xfgcu.h"

#define BUF_CAP 8192u

typedef struct buf {
    uint8_t d[BUF_CAP];
    size_t n;
} buf;

static void put(buf *b, const uint8_t *d, size_t n)
{
    if (b->n + n > BUF_CAP) {
        fprintf(stderr, "gen_corpus: seed too large\n");
        exit(1);
    }
    memcpy(b->d + b->n, d, n);
    b->n += n;
}

static void put1(buf *b, uint8_t v) { put(b, &v, 1); }

static void put_bytes(buf *b, const char *hex)
{
    /* "8A 5E 48 00" */
    unsigned v;
    int used;
    while (sscanf(hex, " %2x%n", &v, &used) == 1) {
        put1(b, (uint8_t)v);
        hex += used;
    }
}

static void write_file(const char *dir, const char *harness, const char *name, const buf *b)
{
    char path[1024];
    FILE *f;
    snprintf(path, sizeof(path), "%s/%s/%s", dir, harness, name);
    f = fopen(path, "wb");
    if (f == NULL || fwrite(b->d, 1, b->n, f) != b->n || fclose(f) != 0) {
        fprintf(stderr, "gen_corpus: cannot write %s\n", path);
        exit(1);
    }
}

/* A GCU reply; order 0 gives 72 bytes, anything else 73 (one state byte). */
static void gcu_frame(buf *b, uint8_t order, uint8_t state, int16_t yaw, uint8_t version)
{
    xf_gcu_packet g;
    uint8_t out[XF_PACKET_MAX_LEN];
    size_t n = 0;
    memset(&g, 0, sizeof(g));
    g.version = version;
    g.main.gimbal_mode = XF_MODE_HEAD_LOCK;
    g.main.pod_status = XF_POD_RANGING_ON;
    g.main.rel_angle_z = yaw;
    g.main.cam_yaw = 9000;
    g.sub.sub_header = XF_SUB_HEADER;
    g.sub.gimbal_code = 30;
    g.sub.target_distance = -10;
    g.sub.zoom_cam1 = 55;
    g.order = order;
    if (order != 0u) {
        g.params_len = 1;
        g.params[0] = state;
    }
    if (xf_gcu_pack(&g, out, sizeof(out), &n) != XF_OK) {
        exit(1);
    }
    put(b, out, n);
}

/* A host packet carrying cmd. */
static void host_frame(buf *b, const xf_command *cmd, uint8_t version)
{
    xf_host_packet h;
    uint8_t out[XF_PACKET_MAX_LEN];
    size_t n = 0;
    xf_host_packet_init(&h, version);
    h.main.status = XF_STATUS_INS_VALID | XF_STATUS_CTRL_VALID;
    h.main.yaw_ctrl = 150;
    h.main.carrier_yaw = 18000;
    h.sub.sub_header = XF_SUB_HEADER;
    h.sub.longitude = 1139000000;
    h.sub.latitude = 225000000;
    h.sub.satellites = 12;
    if (cmd != NULL && xf_host_set_command(&h, cmd, NULL) != XF_OK) {
        exit(1);
    }
    if (xf_host_pack(&h, out, sizeof(out), &n) != XF_OK) {
        exit(1);
    }
    put(b, out, n);
}

static const char *vendor_example =
    "A8 E5 48 00 01 00 00 64 00 9C FF 05 94 FB 65 00 C0 5D 70 00 90 FF 70 00 40 80 C0 F7 40 80 01 00 00 00 "
    "00 00 00 01 24 F2 DF 65 16 EE AA 16 A3 A0 00 00 13 B0 0C 06 15 E6 08 58 2F 00 00 00 00 00 00 00 00 00 "
    "00 00 E9 D4";

static void gen_raw(const char *dir)
{
    const char *h = "fuzz_parser_raw";
    buf b;
    xf_command c;
    int i;

    /* the vendor's example, fed whole */
    b.n = 0;
    put_bytes(&b, "00 FF");
    put_bytes(&b, vendor_example);
    write_file(dir, h, "vendor-example-whole", &b);

    /* two GCU replies (72 and 73 bytes), one byte at a time */
    b.n = 0;
    put_bytes(&b, "00 01");
    gcu_frame(&b, 0x00, 0, 100, 1);
    gcu_frame(&b, XF_ORDER_ZOOM_IN, 0x02, -100, 2);
    write_file(dir, h, "gcu-72-73-bytewise", &b);

    /* noise, a frame, a false header, a frame; odd chunking with an empty feed */
    b.n = 0;
    put_bytes(&b, "03 03 07 00 40");
    put_bytes(&b, "00 11 8A 22 5E 8A 8A 5E 01");
    gcu_frame(&b, XF_ORDER_CALIBRATION, 0x02, 1, 1);
    put_bytes(&b, "8A 5E 48 00 33 44");
    gcu_frame(&b, XF_ORDER_TRACK, 0x01, 2, 1);
    write_file(dir, h, "noise-false-header", &b);

    /* dense false candidates before a frame */
    b.n = 0;
    put_bytes(&b, "01 0D 29");
    for (i = 0; i < 24; i++) {
        put_bytes(&b, "8A 5E 48 00");
    }
    gcu_frame(&b, 0x00, 0, 3, 1);
    write_file(dir, h, "dense-candidates", &b);

    /* nested bogus lengths (255, 200, 72) hiding two frames */
    b.n = 0;
    put_bytes(&b, "00 FF");
    put_bytes(&b, "8A 5E FF 00 8A 5E C8 00 8A 5E 48 00");
    gcu_frame(&b, XF_ORDER_SHUTTER, 0x00, 4, 1);
    gcu_frame(&b, XF_ORDER_RECORD, 0x00, 5, 1);
    put_bytes(&b, "8A 5E 00 01 8A 5E 47 00");
    write_file(dir, h, "nested-bogus-lengths", &b);

    /* a corrupted frame, then an intact one */
    b.n = 0;
    put_bytes(&b, "02 05 50 ");
    gcu_frame(&b, XF_ORDER_FOCUS, 0x00, 6, 1);
    b.d[b.n - 30] ^= 0x40;
    gcu_frame(&b, XF_ORDER_FOCUS, 0x00, 7, 1);
    write_file(dir, h, "corrupt-then-intact", &b);

    /* host packets with parameters */
    b.n = 0;
    put_bytes(&b, "01 20 49");
    xf_command_init(&c, XF_ORDER_TRACK);
    c.value = 1;
    c.x0 = 100;
    c.y0 = 200;
    c.x1 = 3000;
    c.y1 = 4000;
    host_frame(&b, &c, 1);
    xf_command_init(&c, XF_ORDER_GAZE_GEO);
    c.longitude = 1139000000;
    c.latitude = 225000000;
    c.altitude = 15000;
    host_frame(&b, &c, 1);
    xf_command_init(&c, XF_ORDER_ZOOM_TO);
    c.zoom = -55;
    host_frame(&b, &c, 1);
    xf_command_init(&c, XF_ORDER_TEMP_ALARM);
    c.value = 1;
    c.temp_high = 800;
    c.temp_low = -200;
    host_frame(&b, &c, 2);
    xf_command_init(&c, XF_ORDER_TIME_ZONE);
    c.hours = -2;
    host_frame(&b, &c, 2);
    write_file(dir, h, "host-commands", &b);

    /* both directions interleaved, a truncated frame at the end */
    b.n = 0;
    put_bytes(&b, "00 11");
    host_frame(&b, NULL, 1);
    gcu_frame(&b, 0x00, 0, 8, 1);
    xf_command_init(&c, XF_ORDER_EXTERNAL_TRACK);
    c.value = 2;
    c.dx = -300;
    c.dy = 1024;
    host_frame(&b, &c, 1);
    gcu_frame(&b, XF_ORDER_EXTERNAL_TRACK, 0x01, 9, 1);
    gcu_frame(&b, 0x00, 0, 10, 1);
    b.n -= 20;
    write_file(dir, h, "mixed-directions-truncated", &b);

    /* frames that wrap round the parser's ring after 100 bytes of noise */
    b.n = 0;
    put_bytes(&b, "02 61 0B 25");
    for (i = 0; i < 100; i++) {
        put1(&b, (uint8_t)(i * 37 + 11));
    }
    for (i = 0; i < 5; i++) {
        gcu_frame(&b, (uint8_t)(i & 1 ? XF_ORDER_ZOOM_STOP : 0), 0x00, (int16_t)(i * 1000), 1);
    }
    write_file(dir, h, "ring-wrap", &b);

    /* the input ends inside a 255-byte claim with an intact frame behind it
     * (a contender) and one that ends later (only a flush returns it) */
    b.n = 0;
    put_bytes(&b, "01 07");
    put_bytes(&b, "8A 5E FF 00 01 02 03");
    gcu_frame(&b, XF_ORDER_NEUTRAL, 0x00, 11, 1);
    put_bytes(&b, "8A 5E E0 00");
    gcu_frame(&b, 0x00, 0, 12, 1);
    gcu_frame(&b, XF_ORDER_OSD, 0x01, 13, 2);
    write_file(dir, h, "end-inside-bogus-claim", &b);

    /* a long (255-byte) packet with an unknown order */
    b.n = 0;
    put_bytes(&b, "00 FF");
    {
        uint8_t p[255];
        uint16_t crc;
        memset(p, 0x5A, sizeof(p));
        p[0] = XF_GCU_HEADER0;
        p[1] = XF_GCU_HEADER1;
        p[2] = 0xFF;
        p[3] = 0x00;
        p[4] = 1;
        p[XF_OFF_ORDER] = 0x99;
        crc = xf_crc16(p, 253);
        p[253] = (uint8_t)(crc >> 8);
        p[254] = (uint8_t)crc;
        put(&b, p, sizeof(p));
    }
    write_file(dir, h, "long-255-unknown-order", &b);
}

static void gen_crcfix(const char *dir)
{
    const char *h = "fuzz_parser_crcfix";
    buf b;
    int i;

    /* GCU packets from seeds, then repeats */
    b.n = 0;
    put_bytes(&b, "00 FF");
    put_bytes(&b, "02 00 11  02 01 22  07 07 07  0A 05 33");
    write_file(dir, h, "packets-repeats", &b);

    /* noise, dense false candidates, a packet; byte-wise chunks */
    b.n = 0;
    put_bytes(&b, "00 01");
    put_bytes(&b, "00 05 8A 5E 01 02 8A  01 10 48  02 01 44  09 08 48  0A 02 55");
    write_file(dir, h, "noise-dense-packet", &b);

    /* false headers with lengths 255 and 72 around packets, mixed chunking */
    b.n = 0;
    put_bytes(&b, "03 05 00 4D 81");
    put_bytes(&b, "06 FF 00  02 00 01  06 48 00  06 00 01  03 0C 02  0E FF 00  0A 05 03");
    write_file(dir, h, "false-headers", &b);

    /* truncated and corrupted packets before intact ones */
    b.n = 0;
    put_bytes(&b, "01 40 FF");
    put_bytes(&b, "04 00 10 30  02 00 11  05 01 12 40 07  02 01 13  0C 00 14 47  0A 00 15");
    write_file(dir, h, "truncated-corrupted", &b);

    /* the stream ends inside bogus claims: only a flush returns the last packets */
    b.n = 0;
    put_bytes(&b, "00 FF");
    put_bytes(&b, "02 00 21  06 FF 00  02 01 22  06 F0 00  02 00 23  0A 01 24  07");
    write_file(dir, h, "end-inside-bogus-claims", &b);

    /* long packets (s >= 0xC0), body from the input for one */
    b.n = 0;
    put_bytes(&b, "00 FF");
    put_bytes(&b, "02 FF 01  03 E0 02  12 C4");
    for (i = 0; i < 77; i++) { /* 83-byte packet: 77 body bytes */
        put1(&b, (uint8_t)(i == 10 ? 0x8A : i == 11 ? 0x5E : i == 12 ? 0x48 : i));
    }
    put_bytes(&b, "07");
    write_file(dir, h, "long-packets-input-body", &b);
}

int main(int argc, char **argv)
{
    if (argc != 2) {
        fprintf(stderr, "usage: gen_corpus DIR\n");
        return 2;
    }
    gen_raw(argv[1]);
    gen_crcfix(argv[1]);
    return 0;
}
