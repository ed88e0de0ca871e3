/* capture_pcap.c - pcap captures through libpcap (capture_pcap.h, docs/capture-format.md). */
#define _DEFAULT_SOURCE /* u_char and friends, which <pcap/pcap.h> needs */
#include "capture_pcap.h"

#include <errno.h>
#include <pcap/pcap.h>
#include <stdint.h>
#include <string.h>
#include <sys/time.h>
#include <sys/types.h>
#include <unistd.h>

#include "xfgcu/xf_hal.h"

#define LINKTYPE_USER0 147 /* DLT_USER0: the same number in files and in libpcap */
#define IP_HDR         20u
#define UDP_HDR        8u
#define TCP_HDR        20u
#define MAX_PAYLOAD    4096u /* per record: a longer chunk takes several, as in the text format */
#define SNAPLEN        65535

/* ---- writing ---------------------------------------------------------------------------- */

static void put16(uint8_t *p, unsigned v)
{
    p[0] = (uint8_t)(v >> 8);
    p[1] = (uint8_t)v;
}

static void put32(uint8_t *p, uint32_t v)
{
    put16(p, v >> 16);
    put16(p + 2, v & 0xFFFFu);
}

/* The Internet checksum's running sum (RFC 1071), folded by the caller. */
static uint32_t sum16(uint32_t sum, const uint8_t *p, size_t n)
{
    size_t i;
    for (i = 0; i + 1u < n; i += 2u) {
        sum += (uint32_t)(p[i] << 8 | p[i + 1u]);
    }
    if (n % 2u != 0u) {
        sum += (uint32_t)(p[n - 1u] << 8);
    }
    return sum;
}

static unsigned fold(uint32_t sum)
{
    while (sum > 0xFFFFu) {
        sum = (sum & 0xFFFFu) + (sum >> 16);
    }
    return (unsigned)(~sum & 0xFFFFu);
}

/* The first failure: keep its errno, cut the file back to its last whole record (a partial write
 * may have left part of one) and write nothing more (pcap_writer_chunk() checks w->error). */
static void write_failed(pcap_writer *w)
{
    if (w->error == 0) {
        w->error = (errno != 0) ? errno : EIO;
    }
    if (w->kept >= 0 && ftruncate(fileno((FILE *)w->file), (off_t)w->kept) != 0) {
        w->kept = -1;
    }
}

/* libpcap writes through a FILE of its own on a duplicate of @p f's descriptor (the same file
 * and offset): pcap_dump_fopen() closes the FILE it is given when it cannot write the file header,
 * but not when it refuses a link type, so it is never given one that anybody else closes. */
static FILE *dump_stream(FILE *f)
{
    int fd = dup(fileno(f));
    FILE *g = (fd >= 0) ? fdopen(fd, "w") : NULL;
    if (g == NULL) {
        int e = errno;
        if (fd >= 0) {
            close(fd);
        }
        errno = e;
        return NULL;
    }
    (void)setvbuf(g, NULL, _IONBF, 0); /* every record reaches the file at once, none is left in a buffer */
    return g;
}

int pcap_writer_open(pcap_writer *w, FILE *f, pcap_kind kind, const pcap_ends *ends)
{
    int dlt = (kind == PCAP_KIND_SERIAL) ? LINKTYPE_USER0 : DLT_RAW;
    off_t at = ftello(f);
    FILE *g;
    pcap_t *p;
    memset(w, 0, sizeof(*w));
    w->file = f;
    w->kind = kind;
    if (ends != NULL) {
        w->ends = *ends;
    }
    w->seq[0] = 1000u; /* any start; both sides count from their own */
    w->seq[1] = 5000u;
    w->kept = (at >= 0) ? (int64_t)at : -1;
    p = pcap_open_dead_with_tstamp_precision(dlt, SNAPLEN, PCAP_TSTAMP_PRECISION_MICRO);
    if (p == NULL) {
        w->error = ENOMEM;
        return -1;
    }
    w->pcap = p;
    errno = 0;
    g = dump_stream(f);
    w->dumper = (g != NULL) ? pcap_dump_fopen(p, g) : NULL;
    if (w->dumper == NULL) {
        write_failed(w); /* the file header: cut back to nothing */
        return -1;
    }
    at = ftello(g);
    w->kept = (at >= 0 && w->kept >= 0) ? (int64_t)at : -1;
    return 0;
}

/* IPv4 and UDP or TCP headers in front of @p n payload bytes going @p dir; returns the header size. */
static size_t net_headers(pcap_writer *w, xf_direction dir, const uint8_t *data, size_t n, uint8_t *out)
{
    int tcp = (w->kind == PCAP_KIND_TCP);
    size_t l4 = tcp ? TCP_HDR : UDP_HDR, total = IP_HDR + l4 + n;
    uint32_t src = (dir == XF_DIR_HOST) ? w->ends.host_ip : w->ends.gcu_ip;
    uint32_t dst = (dir == XF_DIR_HOST) ? w->ends.gcu_ip : w->ends.host_ip;
    unsigned sport = (dir == XF_DIR_HOST) ? w->ends.host_port : w->ends.gcu_port;
    unsigned dport = (dir == XF_DIR_HOST) ? w->ends.gcu_port : w->ends.host_port;
    uint8_t *ip = out, *l = out + IP_HDR, pseudo[12];
    memset(out, 0, IP_HDR + l4);
    ip[0] = 0x45; /* IPv4, 20-byte header */
    put16(ip + 2, (unsigned)total);
    put16(ip + 4, w->ip_id++);
    ip[6] = 0x40; /* don't fragment */
    ip[8] = 64;   /* TTL */
    ip[9] = tcp ? 6 : 17;
    put32(ip + 12, src);
    put32(ip + 16, dst);
    put16(ip + 10, fold(sum16(0, ip, IP_HDR)));
    put16(l, sport);
    put16(l + 2, dport);
    if (tcp) {
        put32(l + 4, w->seq[dir]);
        put32(l + 8, w->seq[1 - dir]); /* everything the other side sent is acknowledged */
        l[12] = 0x50;                  /* 20-byte header */
        l[13] = 0x18;                  /* PSH, ACK */
        put16(l + 14, 65535);
        w->seq[dir] += (uint32_t)n;
    } else {
        put16(l + 4, (unsigned)(UDP_HDR + n));
    }
    memcpy(pseudo, ip + 12, 8);
    pseudo[8] = 0;
    pseudo[9] = ip[9];
    put16(pseudo + 10, (unsigned)(l4 + n));
    put16(l + (tcp ? 16 : 6), fold(sum16(sum16(sum16(0, pseudo, 12), l, l4), data, n)));
    return IP_HDR + l4;
}

static void write_record(pcap_writer *w, xf_direction dir, const uint8_t *data, size_t n, uint32_t now_ms)
{
    static uint8_t buf[IP_HDR + TCP_HDR + MAX_PAYLOAD];
    struct pcap_pkthdr h;
    int64_t us = w->start_wall_us + (int64_t)xf_ms_since(now_ms, w->start_ms) * 1000;
    size_t head;
    if (w->kind == PCAP_KIND_SERIAL) {
        buf[0] = (uint8_t)((dir == XF_DIR_HOST) ? PCAP_DIR_HOST_BYTE : PCAP_DIR_GCU_BYTE);
        head = 1;
    } else {
        head = net_headers(w, dir, data, n, buf);
    }
    memcpy(buf + head, data, n);
    h.ts.tv_sec = (time_t)(us / 1000000);
    h.ts.tv_usec = (suseconds_t)(us % 1000000);
    h.caplen = h.len = (bpf_u_int32)(head + n);
    errno = 0;
    pcap_dump((u_char *)w->dumper, &h, buf); /* the record header, then the data: two writes, unbuffered */
    if (ferror(pcap_dump_file((pcap_dumper_t *)w->dumper))) {
        write_failed(w);
        return;
    }
    if (w->kept >= 0) {
        w->kept += (int64_t)(sizeof(uint32_t) * 4u + h.caplen); /* the record header: 4 words */
    }
    w->chunks++;
    w->bytes += (uint32_t)n;
}

void pcap_writer_chunk(void *writer, xf_direction dir, const uint8_t *data, size_t len, uint32_t now_ms)
{
    pcap_writer *w = (pcap_writer *)writer;
    if (w == NULL || w->dumper == NULL || w->error != 0) {
        return;
    }
    if (!w->started) {
        struct timeval tv;
        gettimeofday(&tv, NULL);
        w->started = 1;
        w->start_ms = now_ms;
        w->start_wall_us = (int64_t)tv.tv_sec * 1000000 + tv.tv_usec;
    }
    while (len > 0u && w->error == 0) {
        size_t n = (len > MAX_PAYLOAD) ? MAX_PAYLOAD : len;
        write_record(w, dir, data, n, now_ms);
        data += n;
        len -= n;
    }
}

int pcap_writer_close(pcap_writer *w)
{
    if (w->dumper != NULL) {
        if (pcap_dump_flush((pcap_dumper_t *)w->dumper) != 0 && w->error == 0) {
            w->error = (errno != 0) ? errno : EIO;
        }
        pcap_dump_close((pcap_dumper_t *)w->dumper); /* closes libpcap's FILE */
        w->dumper = NULL;
    }
    if (w->pcap != NULL) {
        pcap_close((pcap_t *)w->pcap);
        w->pcap = NULL;
    }
    if (w->file != NULL) {
        if (fclose((FILE *)w->file) != 0 && w->error == 0) {
            w->error = errno;
        }
        w->file = NULL;
    }
    return w->error;
}

/* ---- reading ---------------------------------------------------------------------------- */

int pcap_magic_byte(int first)
{
    /* pcap a1b2c3d4 / a1b23c4d in either byte order, pcapng 0a0d0d0a */
    return first == 0xA1 || first == 0xD4 || first == 0x4D || first == 0x0A;
}

int pcap_reader_open(pcap_reader *r, FILE *f)
{
    char err[PCAP_ERRBUF_SIZE] = "";
    memset(r, 0, sizeof(r[0]));
    r->pcap = pcap_fopen_offline_with_tstamp_precision(f, PCAP_TSTAMP_PRECISION_MICRO, err);
    if (r->pcap == NULL) {
        fclose(f);
        snprintf(r->error, sizeof(r->error), "not a capture: %.150s", err);
        return -1;
    }
    r->linktype = pcap_datalink((pcap_t *)r->pcap);
    if (r->linktype != LINKTYPE_USER0 && r->linktype != DLT_RAW && r->linktype != DLT_EN10MB &&
        r->linktype != DLT_LINUX_SLL) {
        snprintf(r->error, sizeof(r->error),
                 "link type %d is not one xfgcu reads (USER0 147, RAW 101, Ethernet 1, Linux cooked 113)", r->linktype);
        pcap_close((pcap_t *)r->pcap); /* and the FILE */
        r->pcap = NULL;
        return -1;
    }
    return 0;
}

static int bad(pcap_reader *r, const char *why)
{
    snprintf(r->error, sizeof(r->error), "record %lu: %s", r->record, why);
    return -1;
}

/* The IPv4 packet in a record, after its link-layer header; NULL when the record carries none. */
static const uint8_t *ip_of(const pcap_reader *r, const uint8_t *p, size_t n, size_t *ip_len)
{
    size_t skip = 0, type_at = 0;
    if (r->linktype == DLT_EN10MB) {
        skip = 14;
        type_at = 12;
    } else if (r->linktype == DLT_LINUX_SLL) {
        skip = 16;
        type_at = 14;
    }
    if (n < skip + IP_HDR || (skip > 0u && (p[type_at] != 0x08 || p[type_at + 1u] != 0x00))) {
        return NULL;
    }
    if ((p[skip] >> 4) != 4) {
        return NULL;
    }
    *ip_len = n - skip;
    return p + skip;
}

/* UDP or TCP payload of an IPv4 packet, its direction by the host's end; 0: none, -1 bad. */
static int transport(pcap_reader *r, const uint8_t *ip, size_t n, xf_direction *dir, const uint8_t **payload,
                     size_t *len)
{
    size_t ihl = (size_t)(ip[0] & 0x0Fu) * 4u, total = (size_t)(ip[2] << 8 | ip[3]), l4;
    size_t fixed = (ip[9] == 6) ? 20u : UDP_HDR; /* the transport header's fixed part */
    uint32_t src = (uint32_t)ip[12] << 24 | (uint32_t)ip[13] << 16 | (uint32_t)ip[14] << 8 | ip[15];
    uint16_t sport;
    const uint8_t *l;
    if (ip[9] != 6 && ip[9] != 17) {
        return 0;
    }
    if (ihl < IP_HDR || total < ihl || total > n) {
        return bad(r, "truncated or malformed IPv4 packet");
    }
    l = ip + ihl;
    if (total < ihl + fixed) { /* before reading its fields */
        return bad(r, "truncated or malformed UDP or TCP header");
    }
    l4 = (ip[9] == 6) ? (size_t)(l[12] >> 4) * 4u : UDP_HDR;
    if (total < ihl + l4 || l4 < fixed) {
        return bad(r, "truncated or malformed UDP or TCP header");
    }
    sport = (uint16_t)(l[0] << 8 | l[1]);
    *payload = l + l4;
    *len = total - ihl - l4;
    if (*len == 0u) {
        return 0; /* a bare TCP acknowledgement */
    }
    if (!r->have_host) { /* the host speaks first (docs/protocol.md section 1) */
        r->have_host = 1;
        r->host_ip = src;
        r->host_port = sport;
    }
    *dir = (src == r->host_ip && sport == r->host_port) ? XF_DIR_HOST : XF_DIR_GCU;
    return 1;
}

/* The direction and payload of one record; 0 when it carries none. */
static int payload_of(pcap_reader *r, const uint8_t *p, size_t n, xf_direction *dir, const uint8_t **payload,
                      size_t *len)
{
    const uint8_t *ip;
    size_t ip_len = 0;
    if (r->linktype == LINKTYPE_USER0) {
        if (n < 1u || (p[0] != PCAP_DIR_HOST_BYTE && p[0] != PCAP_DIR_GCU_BYTE)) {
            return bad(r, "expected a direction byte '>' or '<' (LINKTYPE_USER0)");
        }
        *dir = (p[0] == PCAP_DIR_HOST_BYTE) ? XF_DIR_HOST : XF_DIR_GCU;
        *payload = p + 1;
        *len = n - 1u;
        return *len > 0u;
    }
    ip = ip_of(r, p, n, &ip_len);
    return (ip != NULL) ? transport(r, ip, ip_len, dir, payload, len) : 0;
}

/* Take at most @p cap bytes of the pending payload. */
static int serve(pcap_reader *r, xf_direction *dir, uint32_t *t_ms, uint8_t *data, size_t cap, size_t *len)
{
    size_t n = (r->rest_len < cap) ? r->rest_len : cap;
    memcpy(data, r->rest, n);
    *len = n;
    *dir = r->rest_dir;
    *t_ms = r->rest_ms;
    r->rest += n;
    r->rest_len -= n;
    return 1;
}

static int timestamp(pcap_reader *r, const struct pcap_pkthdr *h, uint32_t *t_ms)
{
    int64_t us;
    if ((int64_t)h->ts.tv_sec > (INT64_MAX - 999999) / 1000000 || (int64_t)h->ts.tv_sec < 0 || h->ts.tv_usec < 0) {
        return bad(r, "its time is out of range");
    }
    us = (int64_t)h->ts.tv_sec * 1000000 + h->ts.tv_usec;
    if (!r->started) {
        r->started = 1;
        r->first_us = r->last_us = us;
    }
    if (us < r->last_us) {
        return bad(r, "its time is before the previous record's");
    }
    if ((us - r->first_us) / 1000 > (int64_t)UINT32_MAX) {
        return bad(r, "more than 49 days after the first record");
    }
    r->last_us = us;
    *t_ms = (uint32_t)((us - r->first_us) / 1000);
    return 0;
}

int pcap_reader_next(pcap_reader *r, xf_direction *dir, uint32_t *t_ms, uint8_t *data, size_t cap, size_t *len)
{
    struct pcap_pkthdr *h;
    const u_char *p;
    int got;
    if (r->rest_len > 0u) {
        return serve(r, dir, t_ms, data, cap, len);
    }
    while ((got = pcap_next_ex((pcap_t *)r->pcap, &h, &p)) == 1) {
        const uint8_t *payload = NULL;
        size_t n = 0;
        int has;
        r->record++;
        if (h->caplen < h->len) {
            return bad(r, "cut short when captured (snap length)");
        }
        if (timestamp(r, h, &r->rest_ms) != 0) {
            return -1;
        }
        has = payload_of(r, p, h->caplen, &r->rest_dir, &payload, &n);
        if (has < 0) {
            return -1;
        }
        if (has > 0) {
            r->rest = payload;
            r->rest_len = n;
            return serve(r, dir, t_ms, data, cap, len);
        }
    }
    if (got == PCAP_ERROR_BREAK) {
        return 0;
    }
    snprintf(r->error, sizeof(r->error), "record %lu: %s", r->record + 1u, pcap_geterr((pcap_t *)r->pcap));
    return -1;
}

int64_t pcap_reader_start_ms(const pcap_reader *r) { return r->first_us / 1000; }

void pcap_reader_close(pcap_reader *r)
{
    if (r->pcap != NULL) {
        pcap_close((pcap_t *)r->pcap); /* closes the FILE */
        r->pcap = NULL;
    }
}
