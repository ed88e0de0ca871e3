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
 *     # start 2026-11-26T10:00:00.123Z
 *     0.000 > A8 E5 48 00 01 ...
 *     0.004 < 8A 5E 48 00 01 ...
 * @endcode
 *
 * Time in seconds from the start (millisecond resolution; "# start" gives
 * the wall-clock time of the first chunk, UTC), '>' host to
 * GCU, '<' GCU to host, the bytes exactly as the link moved them (a chunk
 * need not be a whole packet). Lines starting with '#' are comments.
 *
 * Blocking: the functions do blocking stdio on the caller's FILE, and wait
 * as long as the file does (a regular file: briefly). Write a capture from
 * the client loop only to a file that cannot stall it.
 *
 * Failures: the writer makes its FILE unbuffered and writes each line in
 * one write, so every chunk is in the file as soon as it is reported. The
 * first failed write (a full disk, a file size limit) stops the writer for
 * good and cuts the file back to its last whole line: what was written
 * before the failure stays a valid capture, with no partial line at its
 * end and no gap in it.
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
    int error;              /**< errno of the first failed write, 0 if none: nothing is written after it */
    int64_t kept;           /**< the file's size up to its last whole line; -1 when unknown (a pipe), or when
                                 it could not be cut back to it after a failure */
} xf_capture_writer;

/** The wall clock now, ms since 1970 (the start time a capture records). */
int64_t xf_capture_wall_ms(void);

/**
 * Write the header (with @p link_desc, may be NULL, and the start time) to @p f; the caller
 * owns f. Makes @p f unbuffered (call it before any other use of @p f). Blocking stdio.
 * @param w          the writer's storage
 * @param f          the file, open for writing (closed by the caller)
 * @param link_desc  one line describing the link, such as "tcp 192.168.144.108:2332" (NULL: "-")
 * @param start_ms   wall-clock time of the first chunk, ms since 1970 (xf_capture_wall_ms());
 *                   negative: not known, no "# start" line
 * @return ::XF_OK, ::XF_ERR_ARG (NULL @p w or @p f), ::XF_ERR_IO (the write
 *   failed; w->error holds errno)
 */
xf_err xf_capture_begin(xf_capture_writer *w, FILE *f, const char *link_desc, int64_t start_ms);
/**
 * Append one chunk (usable as an xf_tap_fn with the writer as user).
 * A chunk longer than ::XF_CAPTURE_MAX_CHUNK takes several lines, each
 * written at once. Errors are not returned: the first one's errno is kept in
 * xf_capture_writer.error, the file is cut back to its last whole line, and
 * nothing more is written. Blocking stdio. Does nothing for a NULL writer,
 * one never begun or one that failed.
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
    char error[160];    /**< why the last call failed (the line is in `line`) */
    int has_start;      /**< a "# start" line gave the wall-clock time of the first chunk */
    int64_t start_ms;   /**< that time, ms since 1970 */
    uint32_t last_ms;   /**< time of the last record: times never go back */
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
 * Comment and empty lines are skipped ("# start" is read). A time must be
 * digits, a point and three digits, at most 4294967.295 s, and not before
 * the previous line's; NUL bytes, bad hex and stray text are errors.
 * Blocking stdio; allocates (and
 * frees) a line buffer with getline(). @p rec may be partly written on
 * error.
 * @param r    the reader
 * @param rec  receives the record
 * @return ::XF_OK, ::XF_ERR_EOF (end of file: no more records),
 *   ::XF_ERR_FORMAT (malformed line), ::XF_ERR_IO (the read failed: errno
 *   says why), ::XF_ERR_ARG (NULL @p r or @p rec)
 */
xf_err xf_capture_next(xf_capture_reader *r, xf_capture_record *rec);

/* ---- either format: the text one or pcap (capture_pcap.h) ------------------------------ */

/** A capture of either format, being read. */
typedef struct capture_source {
    int is_pcap;
    xf_capture_reader text;
    void *pcap; /* pcap_reader, allocated */
    int has_start;
    int64_t start_ms; /**< wall clock of the first chunk, ms since 1970, when has_start */
    char error[240];  /**< "12: reason" (text: the line) or " record 5: reason" (pcap): print after "FILE:" */
} capture_source;

/**
 * Start reading @p f: pcap or pcapng (by its first byte), else the text format. The source owns
 * @p f from now on: capture_source_close() closes it (unless it is stdin).
 * @return ::XF_OK, ::XF_ERR_FORMAT (s->error says why), ::XF_ERR_IO (the same; out of memory too)
 */
xf_err capture_source_open(capture_source *s, FILE *f);
/** The next chunk: ::XF_OK, ::XF_ERR_EOF, ::XF_ERR_FORMAT or ::XF_ERR_IO (s->error says why). */
xf_err capture_source_next(capture_source *s, xf_capture_record *rec);
void capture_source_close(capture_source *s);

/**
 * Replay's printer, shared with `decode`: decode the capture in @p in (closed when done; @p name
 * names it in messages) and print every packet with its time, as a table or as JSON Lines
 * (@p json), then, when @p summary, the summary line (summary.h); @p pod is how pod_status is read
 * (a pod_reading of fieldtext.h), @p view the fields' view (a text_view). @return an exit code.
 */
int replay_capture(FILE *in, const char *name, int json, int pod, int view, int summary);

XF_END_DECLS

#endif /* XF_CAPTURE_H */
