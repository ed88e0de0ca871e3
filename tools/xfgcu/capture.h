/**
 * @file
 * @brief Captures of a link's traffic, written and read back (POSIX stdio;
 * a helper of the xfgcu program, not part of the library).
 *
 * The format is text, one chunk per line, documented in
 * docs/capture-format.md:
 *
 * @code{.unparsed}
 *     # xfgcu capture 1
 *     # link tcp 192.168.144.108:2332
 *     0.000 > A8 E5 48 00 01 ...
 *     0.004 < 8A 5E 48 00 01 ...
 * @endcode
 *
 * Time in seconds from the start (millisecond resolution), '>' host to
 * GCU, '<' GCU to host, the bytes exactly as the link moved them (a chunk
 * need not be a whole packet). Lines starting with '#' are comments.
 *
 * Blocking: the functions do blocking stdio on the caller's FILE, and wait
 * as long as the file does (a regular file: briefly). Write a capture from
 * the client loop only to a file that cannot stall it.
 */
#ifndef XF_CAPTURE_H
#define XF_CAPTURE_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include "xfgcu/xf_error.h"
#include "xfgcu/xf_protocol.h"

XF_BEGIN_DECLS

#define XF_CAPTURE_MAX_CHUNK 4096u /**< bytes per line at most (a longer chunk is split) */

/** A capture being written; set up with xf_capture_begin(). */
typedef struct xf_capture_writer {
    FILE *f;           /**< the file (the caller's) */
    uint32_t start_ms; /**< the time of the first chunk: times are counted from it */
    uint8_t started;   /**< a chunk has been written */
    /** @var xf_capture_writer::chunks
     *  lines written */
    uint32_t chunks, bytes; /**< bytes written */
    int error;              /**< errno of the first failed write, 0 if none */
} xf_capture_writer;

/**
 * Write the header (with @p link_desc, may be NULL) to @p f; the caller owns f.
 * Blocking stdio.
 * @param w          the writer's storage
 * @param f          the file, open for writing (closed by the caller)
 * @param link_desc  one line describing the link, such as "tcp 192.168.144.108:2332" (NULL: "-")
 * @return ::XF_OK, ::XF_ERR_ARG (NULL @p w or @p f), ::XF_ERR_IO (the write
 *   failed; w->error holds errno)
 */
xf_err xf_capture_begin(xf_capture_writer *w, FILE *f, const char *link_desc);
/**
 * Append one chunk (usable as an xf_tap_fn with the writer as user).
 * A chunk longer than ::XF_CAPTURE_MAX_CHUNK takes several lines. Errors are
 * not returned: the first one's errno is kept in xf_capture_writer.error.
 * Blocking stdio. Does nothing for a NULL writer or one never begun.
 * @param writer  the xf_capture_writer
 * @param dir     ::XF_DIR_HOST (host to GCU, '>') or ::XF_DIR_GCU ('<')
 * @param data    the bytes as the link moved them
 * @param len     number of bytes
 * @param now_ms  the time, ms; the first chunk's is time 0
 */
void xf_capture_chunk(void *writer, xf_direction dir, const uint8_t *data, size_t len, uint32_t now_ms);

/** One chunk read back. */
typedef struct xf_capture_record {
    uint32_t t_ms;                      /**< from the start of the capture */
    xf_direction dir;                   /**< who sent the bytes */
    size_t len;                         /**< number of bytes in data */
    uint8_t data[XF_CAPTURE_MAX_CHUNK]; /**< the bytes */
} xf_capture_record;

/** A capture being read; set up with xf_capture_open(). */
typedef struct xf_capture_reader {
    FILE *f;            /**< the file (the caller's) */
    unsigned long line; /**< of the last record read, for error messages */
    char error[160];    /**< why the last call failed: line number and reason */
} xf_capture_reader;

/**
 * Start reading @p f; XF_ERR_FORMAT if it is not an xfgcu capture.
 * Reads the first line. Blocking stdio.
 * @param r  the reader's storage
 * @param f  the file, open for reading (closed by the caller)
 * @return ::XF_OK, ::XF_ERR_ARG (NULL @p r or @p f), ::XF_ERR_FORMAT (not an
 *   xfgcu capture, or empty; r->error says why), ::XF_ERR_IO (the read
 *   failed: errno says why)
 */
xf_err xf_capture_open(xf_capture_reader *r, FILE *f);
/**
 * Read the next record: XF_OK, XF_ERR_EOF at the end of the file, or
 * XF_ERR_FORMAT for a malformed line (r->error says which line and why).
 *
 * Comment and empty lines are skipped. Blocking stdio; allocates (and
 * frees) a line buffer with getline(). @p rec may be partly written on
 * error.
 * @param r    the reader
 * @param rec  receives the record
 * @return ::XF_OK, ::XF_ERR_EOF (end of file: no more records),
 *   ::XF_ERR_FORMAT (malformed line), ::XF_ERR_IO (the read failed: errno
 *   says why), ::XF_ERR_ARG (NULL @p r or @p rec)
 */
xf_err xf_capture_next(xf_capture_reader *r, xf_capture_record *rec);

XF_END_DECLS

#endif /* XF_CAPTURE_H */
