/*
 * gen_corpus - writes the small committed seed corpus of the fuzz harnesses,
 * and the hand-made regression inputs of the parser's semantics.
 *
 *     gen_corpus DIR [REGDIR]   writes DIR/fuzz_parser_raw/... and DIR/fuzz_parser_crcfix/...,
 *                               and REGDIR/<harness>/sem-... when REGDIR is given
 *
 * Regenerate with `scripts/fuzz.sh corpus` (fuzz/corpus and fuzz/regressions;
 * it overwrites only the files named here; files added by hand stay).
 * Deterministic. The harnesses compare the parser with the reference model
 * (tests/parser_ref.h) on every input: these seeds only steer them to the
 * interesting cases; none states an outcome itself.
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

    /* frames after 100 bytes of noise (named after the ring of an earlier parser, which they wrapped) */
    b.n = 0;
    put_bytes(&b, "02 61 0B 25");
    for (i = 0; i < 100; i++) {
        put1(&b, (uint8_t)(i * 37 + 11));
    }
    for (i = 0; i < 5; i++) {
        gcu_frame(&b, (uint8_t)(i & 1 ? XF_ORDER_ZOOM_STOP : 0), 0x00, (int16_t)(i * 1000), 1);
    }
    write_file(dir, h, "ring-wrap", &b);

    /* intact frames inside a 255-byte claim and a 224-byte one: each comes out
     * at its own last byte, and the claims are dropped with it; the input ends
     * inside the last claim */
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

    /* the stream ends inside bogus claims: the packets inside them come out at their own end */
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

/* A packet of direction dir and length len, body (bytes 4 .. len-3) fill,
 * into p (XF_PACKET_LIMIT bytes); the caller may change the body and call
 * seal() again. */
static void seal(uint8_t *p, size_t len)
{
    uint16_t crc = xf_crc16(p, len - 2u);
    p[len - 2u] = (uint8_t)(crc >> 8);
    p[len - 1u] = (uint8_t)crc;
}

static void raw_packet(uint8_t *p, size_t len, uint8_t fill)
{
    memset(p, fill, len);
    p[0] = XF_GCU_HEADER0;
    p[1] = XF_GCU_HEADER1;
    p[2] = (uint8_t)len;
    p[3] = 0;
    p[4] = 1; /* version */
    seal(p, len);
}

static void put_fill(buf *b, uint8_t v, size_t n)
{
    size_t i;
    for (i = 0; i < n; i++) {
        put1(b, v);
    }
}

/* The rules of the parser's semantics, each as a small input (fuzz/README.md). */
static void gen_regressions(const char *dir)
{
    const char *h = "fuzz_parser_raw";
    uint8_t p[XF_PACKET_LIMIT];
    buf b;
    int i, plan;
    static const char *plans[2] = {"00 01", "02 03 40 FF"}; /* byte by byte; 3, 64, then the rest */
    static const char *names[2][6] = {
        {"sem-frame-inside-long-claim-bytewise", "sem-false-later-than-frame-bytewise",
         "sem-false-inside-frame-bytewise", "sem-false-sooner-loses-frame-bytewise", "sem-truncated-then-real-bytewise",
         "sem-same-end-bytewise"},
        {"sem-frame-inside-long-claim-chunks", "sem-false-later-than-frame-chunks", "sem-false-inside-frame-chunks",
         "sem-false-sooner-loses-frame-chunks", "sem-truncated-then-real-chunks", "sem-same-end-chunks"},
    };

    for (plan = 0; plan < 2; plan++) {
        /* a frame inside a false candidate with a bogus long length (255):
         * returned at its own last byte; the false one is dropped with it */
        b.n = 0;
        put_bytes(&b, plans[plan]);
        put_bytes(&b, "8A 5E FF 00 11 22 33");
        gcu_frame(&b, XF_ORDER_ZOOM_IN, 0x00, 21, 1);
        put_fill(&b, 0x00, 260);
        write_file(dir, h, names[plan][0], &b);

        /* 17 nested false candidates (255) that end after a frame: the ones
         * that would end last are given up, whatever the slots (up to 16);
         * the frame survives */
        b.n = 0;
        put_bytes(&b, plans[plan]);
        for (i = 0; i < 17; i++) {
            put_bytes(&b, "8A 5E FF 00");
        }
        gcu_frame(&b, 0x00, 0, 22, 1);
        put_fill(&b, 0x00, 300);
        write_file(dir, h, names[plan][1], &b);

        /* the same with lengths an 84-byte build accepts: a frame of 84 whose
         * body holds 17 false candidates (84) that end after it */
        b.n = 0;
        put_bytes(&b, plans[plan]);
        raw_packet(p, 84, 0x11);
        for (i = 0; i < 17; i++) {
            memcpy(p + 4 + 4 * i, "\x8A\x5E\x54\x00", 4);
        }
        seal(p, 84);
        put(&b, p, 84);
        put_fill(&b, 0x00, 100);
        write_file(dir, h, names[plan][2], &b);

        /* 16 false candidates (84) that end sooner than a frame of 84 that
         * starts after them: with up to 16 slots the frame is given up (the
         * documented loss) and the false ones fail their CRC */
        b.n = 0;
        put_bytes(&b, plans[plan]);
        for (i = 0; i < 16; i++) {
            put_bytes(&b, "8A 5E 54 00");
        }
        raw_packet(p, 84, 0x22);
        put(&b, p, 84);
        gcu_frame(&b, 0x00, 0, 23, 1);
        put_fill(&b, 0x00, 100);
        write_file(dir, h, names[plan][3], &b);

        /* truncated packets followed by real ones: an 84-byte one cut at 40
         * (its candidate fails inside the next frame), a 255-byte one cut at
         * 40 (dropped when the frame inside it is returned) */
        b.n = 0;
        put_bytes(&b, plans[plan]);
        raw_packet(p, 84, 0x33);
        put(&b, p, 40);
        gcu_frame(&b, 0x00, 0, 24, 1);
        raw_packet(p, 255, 0x44);
        p[2] = 0xFF;
        seal(p, 255);
        put(&b, p, 40);
        gcu_frame(&b, XF_ORDER_TRACK, 0x01, 25, 1);
        put_fill(&b, 0x00, 10);
        write_file(dir, h, names[plan][4], &b);

        /* candidates that end on the same byte. A false one (84) and a
         * frame (72) at 12: both pending (K >= 2), the earlier start is
         * examined first (a CRC error), then the frame. Then, for each K in
         * 1..16: K false ones (84) fill the slots, and a frame of 80 after
         * them ends with the last of them: not admitted (it does not end
         * sooner), given up. Zero bytes between the parts. */
        b.n = 0;
        put_bytes(&b, plans[plan]);
        put_bytes(&b, "8A 5E 54 00 00 00 00 00 00 00 00 00");
        raw_packet(p, 72, 0x55);
        put(&b, p, 72);
        put_fill(&b, 0x00, 20);
        for (i = 1; i <= 16; i++) {
            int k;
            for (k = 0; k < i; k++) {
                put_bytes(&b, "8A 5E 54 00");
            }
            raw_packet(p, 80, (uint8_t)(0x60 + i));
            put(&b, p, 80);
            put_fill(&b, 0x00, 20);
        }
        write_file(dir, h, names[plan][5], &b);
    }

    /* the input ends with partial headers (h0 h1 L held), reset instead of flush */
    b.n = 0;
    put_bytes(&b, "08 01");
    gcu_frame(&b, 0x00, 0, 26, 1);
    put_bytes(&b, "8A 5E 01 02 8A 5E 48");
    write_file(dir, h, "sem-partial-header-at-end-reset", &b);

    h = "fuzz_parser_crcfix";
    /* frames inside bogus claims of either direction, byte by byte */
    b.n = 0;
    put_bytes(&b, "00 01");
    put_bytes(&b, "06 FF 00  00 03 01 02 03  02 00 11  06 C8 00  03 01 12  0E FF 00  0A 05 13");
    write_file(dir, h, "sem-frame-inside-bogus-claim", &b);
    /* 17 false candidates (255) that end later, then a packet, both directions */
    b.n = 0;
    put_bytes(&b, "00 FF");
    put_bytes(&b, "01 10 FF  02 00 22  09 10 FF  0A 00 23");
    write_file(dir, h, "sem-false-later-than-packet", &b);
    /* 16 false candidates (84) that end sooner than a packet of 84 after them: it is given up */
    b.n = 0;
    put_bytes(&b, "00 01");
    put_bytes(&b, "01 0F 54  02 0C 33  02 00 34");
    write_file(dir, h, "sem-false-sooner-loses-packet", &b);
    /* truncated packets (84 and 255, cut at 40), each followed by an intact one */
    b.n = 0;
    put_bytes(&b, "02 03 40 FF");
    put_bytes(&b, "04 0C 44 28  02 00 55  04 FF 66 28  02 01 77");
    write_file(dir, h, "sem-truncated-then-real", &b);
}

int main(int argc, char **argv)
{
    if (argc != 2 && argc != 3) {
        fprintf(stderr, "usage: gen_corpus DIR [REGDIR]\n");
        return 2;
    }
    gen_raw(argv[1]);
    gen_crcfix(argv[1]);
    if (argc == 3) {
        gen_regressions(argv[2]);
    }
    return 0;
}
