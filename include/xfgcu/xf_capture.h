/*
 * xf_capture.h - captures of a link's traffic, written and read back
 * (POSIX stdio; part of xfgcu::posix). The format is text, one chunk per
 * line, documented in docs/capture-format.md:
 *
 *     # xfgcu capture 1
 *     # link tcp 192.168.144.108:2332
 *     0.000 > A8 E5 48 00 01 ...
 *     0.004 < 8A 5E 48 00 01 ...
 *
 * Time in seconds from the start (millisecond resolution), '>' host to
 * GCU, '<' GCU to host, the bytes exactly as the link moved them (a chunk
 * need not be a whole packet). Lines starting with '#' are comments.
 */
#ifndef XF_CAPTURE_H
#define XF_CAPTURE_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include "xf_error.h"
#include "xf_protocol.h"

XF_BEGIN_DECLS

#define XF_CAPTURE_MAX_CHUNK 4096u /**< bytes per line at most (a longer chunk is split) */

typedef struct xf_capture_writer {
    FILE *f;
    uint32_t start_ms;
    uint8_t started;
    uint32_t chunks, bytes;
    int error; /**< errno of the first failed write, 0 if none */
} xf_capture_writer;

/** Write the header (with @p link_desc, may be NULL) to @p f; the caller owns f. */
xf_err xf_capture_begin(xf_capture_writer *w, FILE *f, const char *link_desc);
/** Append one chunk (usable as an xf_tap_fn with the writer as user). */
void xf_capture_chunk(void *writer, xf_direction dir, const uint8_t *data, size_t len, uint32_t now_ms);

/** One chunk read back. */
typedef struct xf_capture_record {
    uint32_t t_ms; /**< from the start of the capture */
    xf_direction dir;
    size_t len;
    uint8_t data[XF_CAPTURE_MAX_CHUNK];
} xf_capture_record;

typedef struct xf_capture_reader {
    FILE *f;
    unsigned long line; /**< of the last record read, for error messages */
    char error[160];
} xf_capture_reader;

/** Start reading @p f; XF_ERR_PARAMS if it is not an xfgcu capture. */
xf_err xf_capture_open(xf_capture_reader *r, FILE *f);
/**
 * Read the next record: XF_OK, XF_ERR_CLOSED at the end of the file, or
 * XF_ERR_PARAMS for a malformed line (r->error says which line and why).
 */
xf_err xf_capture_next(xf_capture_reader *r, xf_capture_record *rec);

XF_END_DECLS

#endif /* XF_CAPTURE_H */
