/*
 * fuzz_parser_crcfix - the parser's recovery guarantee.
 *
 * The input is a program that builds a stream of items: noise, dense false
 * candidates, intact packets of either direction whose length field and
 * CRC the harness sets itself (so the fuzzer never has to solve a CRC),
 * truncated and corrupted packets, and false headers with bogus lengths.
 * Each direction runs twice: with 300 zero bytes after the stream (every
 * candidate has ended by then: nothing stays held), and with the stream
 * ending dead, followed by xf_parser_flush(); the frames of the second run
 * are those of the first that end within the stream.
 *
 * Besides every check of fuzz_common.h (the reference model after every
 * call, tests/parser_ref.h), it checks that, when no candidate was given up
 * (given_up == 0: the XF_PARSER_SLOTS slots sufficed), EVERY intact packet
 * inserted comes out of the parser of its direction, at its position, by
 * the call that feeds its last byte. The excused losses: the packet
 * overlaps a frame returned before it that starts before it (noise plus the
 * packet's first bytes, or a false candidate ending on the packet's last
 * byte, formed a frame with a right CRC), or a frame inside it ends first;
 * such frames are valid on the wire and the model agrees. When candidates
 * were given up, packets may be lost (the documented limit of the slots):
 * only the model's verdict applies.
 *
 * Input layout:
 *   byte 0          k = (byte & 7) + 1 chunk sizes follow (see fuzz_common.h)
 *   then items, each a tag byte t and its operands; kind = t & 7,
 *   dir = (t >> 3) & 1 (0 GCU, 1 host):
 *     0  noise: n, then n raw bytes
 *     1  false candidates: r, L: (r % 32 + 1) x [h0 h1 L 00]
 *     2,3 intact packet: size s, then body (see build_packet)
 *     4  truncated packet: size s, body, cut c: the first c % len bytes
 *     5  corrupted packet: size s, body, pos, x: byte pos % len ^= x | 1
 *     6  false header: h0 h1 L0 L1
 *     7  the last intact packet again
 */
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "fuzz_common.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

#define STREAM_CAP 16384u
#define TAIL_ZEROS 300u

typedef struct reader {
    const uint8_t *d;
    size_t n, i;
} reader;

static int rd_more(const reader *r) { return r->i < r->n; }
static uint8_t rd_u8(reader *r) { return (r->i < r->n) ? r->d[r->i++] : 0u; }

typedef struct expect_list {
    pr_frame *v;
    size_t n;
} expect_list;

/*
 * Build a packet of direction dir into pkt (XF_PACKET_MAX_LEN bytes):
 * size byte s: s < 0xC0: 72 + s % 13 bytes (the protocol's sizes), else
 * 72 + (s - 0xC0) * XF_PARAMS_MAX / 63. Body (bytes 4..len-3): tag bit 4
 * set: taken from the input (zero padded), clear: xorshift from one seed byte.
 */
static size_t build_packet(reader *r, uint8_t t, xf_direction dir, uint8_t *pkt)
{
    uint8_t s = rd_u8(r);
    size_t params = (s < 0xC0u) ? (size_t)(s % 13u) : (size_t)(s - 0xC0u) * XF_PARAMS_MAX / 63u;
    size_t len = XF_PACKET_MIN_LEN + params;
    size_t i;
    uint16_t crc;
    if (t & 0x10u) {
        for (i = 4; i < len - 2u; i++) {
            pkt[i] = rd_u8(r);
        }
    } else {
        uint32_t x = (uint32_t)rd_u8(r) * 2654435761u + 1u;
        for (i = 4; i < len - 2u; i++) {
            x ^= x << 13;
            x ^= x >> 17;
            x ^= x << 5;
            pkt[i] = (uint8_t)(x >> 24);
        }
    }
    pkt[0] = (dir == XF_DIR_HOST) ? XF_HOST_HEADER0 : XF_GCU_HEADER0;
    pkt[1] = (dir == XF_DIR_HOST) ? XF_HOST_HEADER1 : XF_GCU_HEADER1;
    pkt[2] = (uint8_t)(len & 0xFFu);
    pkt[3] = (uint8_t)(len >> 8);
    crc = xf_crc16(pkt, len - 2u);
    pkt[len - 2u] = (uint8_t)(crc >> 8);
    pkt[len - 1u] = (uint8_t)(crc & 0xFFu);
    FZ_CHECK(xf_packet_check(pkt, len, dir) == XF_OK);
    FZ_CHECK(pr_crc(pkt, len) == 0u); /* the model's own CRC agrees */
    return len;
}

/* Debugging a reproducer: XFGCU_FUZZ_DUMP=FILE writes the stream built. */
static void dump_stream(const uint8_t *s, size_t n)
{
    const char *path = getenv("XFGCU_FUZZ_DUMP");
    FILE *f;
    if (path == NULL || path[0] == '\0') {
        return;
    }
    f = fopen(path, "wb");
    if (f != NULL) {
        (void)fwrite(s, 1, n, f);
        (void)fclose(f);
    }
}

/* Every expected packet is among the frames found, or excused (see above). */
static void check_recovered(const expect_list *want, const pr_frame *got, size_t ngot)
{
    size_t i, j = 0;
    for (i = 0; i < want->n; i++) {
        const pr_frame *e = &want->v[i];
        while (j < ngot && got[j].start + got[j].len <= e->start) {
            j++;
        }
        if (j < ngot && got[j].start == e->start) {
            FZ_CHECK(got[j].len == e->len);
            continue;
        }
        if (j < ngot && got[j].start < e->start) {
            continue; /* swallowed by a valid frame that starts before it */
        }
        if (j < ngot && got[j].start < e->start + e->len && got[j].start + got[j].len < e->start + e->len) {
            continue; /* an intact frame inside it ends first: returned instead */
        }
        fprintf(stderr, "intact packet at %zu (len %zu) not recovered\n", e->start, e->len);
        FZ_CHECK(0 && "with no candidate given up, every intact packet is recovered");
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static uint8_t stream[STREAM_CAP + TAIL_ZEROS];
    uint8_t pkt[XF_PACKET_MAX_LEN];
    uint8_t last[XF_PACKET_MAX_LEN];
    size_t last_len = 0;
    xf_direction last_dir = XF_DIR_GCU;
    expect_list want[2];
    pr_frame *got, *got_b;
    size_t n = 0, nsizes = 0, max_items, d;
    const uint8_t *sizes = NULL;
    reader r;
    fz_plan plan;

    r.d = data;
    r.n = size;
    r.i = 0;
    if (size > 0u) {
        nsizes = (size_t)(data[0] & 7u) + 1u;
        if (nsizes >= size) {
            return 0;
        }
        sizes = data + 1;
        r.i = 1u + nsizes;
    }

    max_items = STREAM_CAP / XF_PACKET_MIN_LEN + 1u;
    for (d = 0; d < 2u; d++) {
        want[d].v = (pr_frame *)malloc(max_items * sizeof(pr_frame));
        want[d].n = 0;
        FZ_CHECK(want[d].v != NULL);
    }

    while (rd_more(&r) && n < STREAM_CAP) {
        uint8_t t = rd_u8(&r);
        xf_direction dir = (t & 0x08u) ? XF_DIR_HOST : XF_DIR_GCU;
        uint8_t h0 = (dir == XF_DIR_HOST) ? XF_HOST_HEADER0 : XF_GCU_HEADER0;
        uint8_t h1 = (dir == XF_DIR_HOST) ? XF_HOST_HEADER1 : XF_GCU_HEADER1;
        size_t len, k;
        switch (t & 7u) {
        case 0: {
            size_t cnt = rd_u8(&r);
            for (k = 0; k < cnt && rd_more(&r) && n < STREAM_CAP; k++) {
                stream[n++] = rd_u8(&r);
            }
            break;
        }
        case 1: {
            size_t reps = (size_t)(rd_u8(&r) % 32u) + 1u;
            uint8_t l = rd_u8(&r);
            for (k = 0; k < reps && n + 4u <= STREAM_CAP; k++) {
                stream[n++] = h0;
                stream[n++] = h1;
                stream[n++] = l;
                stream[n++] = 0;
            }
            break;
        }
        case 2:
        case 3:
            len = build_packet(&r, t, dir, pkt);
            if (n + len > STREAM_CAP) {
                n = STREAM_CAP; /* stop here */
                break;
            }
            memcpy(stream + n, pkt, len);
            want[dir == XF_DIR_HOST].v[want[dir == XF_DIR_HOST].n].start = n;
            want[dir == XF_DIR_HOST].v[want[dir == XF_DIR_HOST].n].len = len;
            want[dir == XF_DIR_HOST].n++;
            n += len;
            memcpy(last, pkt, len);
            last_len = len;
            last_dir = dir;
            break;
        case 4:
            len = build_packet(&r, t, dir, pkt);
            len = rd_u8(&r) % len;
            if (n + len > STREAM_CAP) {
                len = STREAM_CAP - n;
            }
            memcpy(stream + n, pkt, len);
            n += len;
            break;
        case 5: {
            size_t pos;
            len = build_packet(&r, t, dir, pkt);
            pos = rd_u8(&r) % len;
            pkt[pos] ^= (uint8_t)(rd_u8(&r) | 1u);
            if (n + len > STREAM_CAP) {
                len = STREAM_CAP - n;
            }
            memcpy(stream + n, pkt, len);
            n += len;
            break;
        }
        case 6:
            if (n + 4u <= STREAM_CAP) {
                stream[n++] = h0;
                stream[n++] = h1;
                stream[n++] = rd_u8(&r);
                stream[n++] = rd_u8(&r);
            } else {
                n = STREAM_CAP;
            }
            break;
        default:
            if (last_len == 0u) {
                break;
            }
            if (n + last_len > STREAM_CAP) {
                n = STREAM_CAP;
                break;
            }
            memcpy(stream + n, last, last_len);
            want[last_dir == XF_DIR_HOST].v[want[last_dir == XF_DIR_HOST].n].start = n;
            want[last_dir == XF_DIR_HOST].v[want[last_dir == XF_DIR_HOST].n].len = last_len;
            want[last_dir == XF_DIR_HOST].n++;
            n += last_len;
            break;
        }
    }
    /* Run A: 300 zero bytes end the stream, so every candidate has ended:
     * only the last three zeros stay held (they might begin a header). Run B: the stream stops dead after the last
     * item, and xf_parser_flush() drops what is held; the frames are run A's that end within the stream (a frame comes
     * out at its own last byte, whatever follows it). */
    memset(stream + n, 0, TAIL_ZEROS);
    dump_stream(stream, n + TAIL_ZEROS);

    got = (pr_frame *)malloc(((n + TAIL_ZEROS) / XF_PACKET_MIN_LEN + 1u) * sizeof(pr_frame));
    got_b = (pr_frame *)malloc((n / XF_PACKET_MIN_LEN + 1u) * sizeof(pr_frame));
    FZ_CHECK(got != NULL && got_b != NULL);
    for (d = 0; d < 2u; d++) {
        xf_direction dir = (d == 0u) ? XF_DIR_GCU : XF_DIR_HOST;
        fz_result a, b;
        size_t i;
        fz_plan_init(&plan, sizes, nsizes);
        fz_feed_checked(stream, n + TAIL_ZEROS, dir, &plan, FZ_END_FLUSH, got, &a);
        FZ_CHECK(a.pending == 3u);
        if (a.given_up == 0u) {
            check_recovered(&want[d], got, a.nframes);
        }

        fz_plan_init(&plan, sizes, nsizes);
        fz_feed_checked(stream, n, dir, &plan, FZ_END_FLUSH, got_b, &b);
        if (b.given_up == 0u) {
            check_recovered(&want[d], got_b, b.nframes);
        }
        FZ_CHECK(b.given_up <= a.given_up); /* the zeros may complete a header pair begun at the end */
        FZ_CHECK(b.nframes <= a.nframes);
        for (i = 0; i < a.nframes; i++) {
            if (i < b.nframes) {
                FZ_CHECK(got_b[i].start == got[i].start && got_b[i].len == got[i].len);
            } else {
                FZ_CHECK(got[i].start + got[i].len > n);
            }
        }
    }
    free(got_b);
    free(got);
    free(want[0].v);
    free(want[1].v);
    return 0;
}
