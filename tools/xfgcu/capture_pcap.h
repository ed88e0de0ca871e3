/*
 * capture_pcap.h - captures in pcap (libpcap), written by `record --pcap` and read
 * by `replay` and `decode` (docs/capture-format.md, "pcap").
 *
 * Link types written:
 *   - serial: LINKTYPE_USER0 (147): one record per chunk, a direction byte
 *     ('>' host to GCU, '<' GCU to host) then the bytes as the link moved them;
 *   - UDP and TCP: LINKTYPE_RAW (101): an IPv4 header and a UDP or TCP header
 *     made up around each chunk, with the link's real addresses and ports,
 *     so that Wireshark's port and TCP reassembly machinery applies.
 * Read: those, and Ethernet (1) and Linux cooked (113) captures of IPv4
 * UDP or TCP (what tcpdump and Wireshark make); pcapng too.
 */
#ifndef XFGCU_CAPTURE_PCAP_H
#define XFGCU_CAPTURE_PCAP_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "xfgcu/xfgcu.h"

#define PCAP_DIR_HOST_BYTE '>' /* LINKTYPE_USER0: the first byte of a record, host to GCU */
#define PCAP_DIR_GCU_BYTE  '<' /* ... GCU to host */

/** What the writer wraps each chunk in. */
typedef enum pcap_kind { PCAP_KIND_SERIAL, PCAP_KIND_UDP, PCAP_KIND_TCP } pcap_kind;

/** The two ends of a network link, IPv4, host byte order (0.0.0.0 when unknown). */
typedef struct pcap_ends {
    uint32_t host_ip, gcu_ip;
    uint16_t host_port, gcu_port;
} pcap_ends;

/** A pcap being written (opaque parts behind pointers). */
typedef struct pcap_writer {
    void *pcap, *dumper; /* pcap_t (dead), pcap_dumper_t (libpcap's FILE, on a duplicate descriptor) */
    void *file;          /* the FILE given to pcap_writer_open(): to cut the file back, closed at the end */
    pcap_kind kind;
    pcap_ends ends;
    uint32_t seq[2];       /* TCP: next sequence number of each direction */
    uint16_t ip_id;        /* IPv4 identification, counted */
    int64_t start_wall_us; /* wall clock at the first chunk */
    uint32_t start_ms;     /* the monotonic time of the first chunk */
    int started;
    uint32_t chunks, bytes;
    int error;    /* errno of the first failure, 0 if none: nothing is written after it */
    int64_t kept; /* the file's size up to its last whole record; -1: unknown, or could not be cut back to it */
} pcap_writer;

/**
 * Start writing to @p f (its descriptor: each record reaches the file at once, unbuffered). The
 * writer owns @p f from now on, whether this succeeds or not: pcap_writer_close() closes it.
 * 0, or -1 with w->error (a file header that could not be written is cut back to nothing).
 */
int pcap_writer_open(pcap_writer *w, FILE *f, pcap_kind kind, const pcap_ends *ends);
/** Append one chunk: an xf_tap_fn with the writer as user. The first failed write's errno is
 *  kept in w->error, the file is cut back to its last whole record, and nothing more is written. */
void pcap_writer_chunk(void *writer, xf_direction dir, const uint8_t *data, size_t len, uint32_t now_ms);
/** Flush and close (the FILE too; also after a failed pcap_writer_open()). @return 0, or the errno of the first
 * failure. */
int pcap_writer_close(pcap_writer *w);

/** Does a file starting with byte @p first look like pcap or pcapng (not the text format)? */
int pcap_magic_byte(int first);

/** A pcap being read. */
typedef struct pcap_reader {
    void *pcap; /* pcap_t */
    int linktype;
    unsigned long record; /* number of the last record read, from 1 */
    int64_t first_us;     /* time of the first record */
    int64_t last_us;
    int started;
    int have_host; /* UDP/TCP: the host's end is known (the sender of the first datagram or segment) */
    uint32_t host_ip;
    uint16_t host_port;
    const uint8_t *rest; /* a payload longer than one record: what is left of it */
    size_t rest_len;
    xf_direction rest_dir;
    uint32_t rest_ms;
    char error[200];
} pcap_reader;

/** Open @p f: the reader owns it from now on (pcap_reader_close() closes it; a failure has). 0, or -1 with r->error. */
int pcap_reader_open(pcap_reader *r, FILE *f);
/**
 * The next chunk: 1 with *dir, *t_ms (from the first record), data (at most @p cap bytes: a longer
 * payload comes in several calls) and *len; 0 at the end; -1 with r->error (bad record).
 * Records that carry no xfgcu traffic (other protocols, empty segments) are skipped.
 */
int pcap_reader_next(pcap_reader *r, xf_direction *dir, uint32_t *t_ms, uint8_t *data, size_t cap, size_t *len);
/** The wall-clock time of the first record, in ms since 1970 (valid once a record was read). */
int64_t pcap_reader_start_ms(const pcap_reader *r);
void pcap_reader_close(pcap_reader *r);

#endif /* XFGCU_CAPTURE_PCAP_H */
