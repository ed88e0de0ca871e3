/* capture.c - the text capture format of docs/capture-format.md (the program's record and replay). */
#define _DEFAULT_SOURCE /* timegm() */
#define _POSIX_C_SOURCE 200809L
#include <ctype.h>
#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <sys/time.h>
#include <sys/types.h>
#include <unistd.h>
#include <time.h>

#include "capture.h"
#include "jsonpkt.h"
#include "capture_pcap.h"
#include "xfgcu/xf_hal.h"

#define XF_CAPTURE_MAGIC "# xfgcu capture 1"
#define XF_CAPTURE_START "# start "
#define XF_CAPTURE_T_MAX 4294967295ull /* ms: the largest time a record holds */

int64_t xf_capture_wall_ms(void)
{
    struct timeval tv;
    gettimeofday(&tv, NULL);
    return (int64_t)tv.tv_sec * 1000 + tv.tv_usec / 1000;
}

/* Append @p n bytes of whole lines in one write (the stream is unbuffered: xf_capture_begin()). The
 * first failure keeps its errno, cuts the file back to its last whole line (a partial write may
 * have put part of this one there) and stops the writer: a capture never has a gap. */
static int xf__capture_put(xf_capture_writer *w, const char *text, size_t n)
{
    if (w->error != 0) {
        return -1;
    }
    errno = 0;
    if (fwrite(text, 1, n, w->f) != n) {
        w->error = (errno != 0) ? errno : EIO;
        if (w->kept >= 0 && ftruncate(fileno(w->f), (off_t)w->kept) != 0) {
            w->kept = -1; /* cannot be cut back: the last line may be partial */
        }
        return -1;
    }
    if (w->kept >= 0) {
        w->kept += (int64_t)n;
    }
    return 0;
}

xf_err xf_capture_begin(xf_capture_writer *w, FILE *f, const char *link_desc, int64_t start_ms)
{
    char head[512], start[40] = "";
    off_t at;
    int n;
    if (w == NULL || f == NULL) {
        return XF_ERR_ARG;
    }
    memset(w, 0, sizeof(*w));
    w->f = f;
    (void)setvbuf(f, NULL, _IONBF, 0); /* every line in one write, none left in a buffer */
    at = ftello(f);
    w->kept = (at >= 0) ? (int64_t)at : -1; /* a pipe: nothing to cut back */
    if (start_ms >= 0) {
        jsonpkt_utc_text(start_ms, start, sizeof(start));
    }
    n = snprintf(head, sizeof(head), "%s\n# link %.320s\n%s%s%s# time(s) dir(> host to GCU, < GCU to host) bytes\n",
                 XF_CAPTURE_MAGIC, link_desc != NULL ? link_desc : "-", start_ms >= 0 ? XF_CAPTURE_START : "", start,
                 start_ms >= 0 ? "\n" : "");
    return (n > 0 && xf__capture_put(w, head, (size_t)n) == 0) ? XF_OK : XF_ERR_IO;
}

void xf_capture_chunk(void *writer, xf_direction dir, const uint8_t *data, size_t len, uint32_t now_ms)
{
    static const char hex[] = "0123456789ABCDEF";
    xf_capture_writer *w = (xf_capture_writer *)writer;
    char line[32 + 3u * XF_CAPTURE_MAX_CHUNK];
    size_t off = 0;
    uint32_t t;
    if (w == NULL || w->f == NULL || w->error != 0) {
        return;
    }
    if (!w->started) {
        w->started = 1;
        w->start_ms = now_ms;
    }
    t = xf_ms_since(now_ms, w->start_ms);
    while (off < len) {
        size_t n = len - off, i, k; /* n at least 1: off < len */
        if (n > XF_CAPTURE_MAX_CHUNK) {
            n = XF_CAPTURE_MAX_CHUNK;
        }
        k = (size_t)snprintf(line, 32, "%u.%03u %c", (unsigned)(t / 1000u), (unsigned)(t % 1000u),
                             dir == XF_DIR_HOST ? '>' : '<');
        for (i = 0; i < n; i++) {
            line[k++] = ' ';
            line[k++] = hex[data[off + i] >> 4];
            line[k++] = hex[data[off + i] & 0x0Fu];
        }
        line[k++] = '\n';
        if (xf__capture_put(w, line, k) != 0) {
            return;
        }
        w->chunks++;
        w->bytes += (uint32_t)n;
        off += n;
    }
}

xf_err xf_capture_open(xf_capture_reader *r, FILE *f)
{
    char line[64];
    if (r == NULL || f == NULL) {
        return XF_ERR_ARG;
    }
    memset(r, 0, sizeof(*r));
    r->f = f;
    r->line = 1;
    if (fgets(line, sizeof(line), f) == NULL) {
        if (ferror(f)) {
            snprintf(r->error, sizeof(r->error), "cannot read: %s", strerror(errno));
            return XF_ERR_IO;
        }
        line[0] = '\0'; /* an empty file */
    }
    /* the whole line, exactly (a CR before its newline allowed): "# xfgcu capture 17" is not it */
    line[strcspn(line, "\r\n")] = '\0';
    if (strcmp(line, XF_CAPTURE_MAGIC) != 0 || strlen(line) + 2u >= sizeof(line)) {
        snprintf(r->error, sizeof(r->error), "not an xfgcu capture (expected \"%s\" or pcap)", XF_CAPTURE_MAGIC);
        return XF_ERR_FORMAT;
    }
    return XF_OK;
}

static xf_err xf__capture_bad(xf_capture_reader *r, const char *why)
{
    snprintf(r->error, sizeof(r->error), "%s", why);
    return XF_ERR_FORMAT;
}

static int xf__hexval(int c) { return isdigit(c) ? c - '0' : (isxdigit(c) ? (tolower(c) - 'a' + 10) : -1); }

/* @p n digits at *p, a number in lo..hi, then the character @p after (0: none); moves *p on. */
static int xf__field(const char **p, size_t n, int lo, int hi, char after, int *out)
{
    int v = 0;
    size_t k;
    for (k = 0; k < n; k++) {
        if (!isdigit((unsigned char)(*p)[k])) {
            return -1;
        }
        v = v * 10 + ((*p)[k] - '0');
    }
    if (v < lo || v > hi || (after != '\0' && (*p)[n] != after)) {
        return -1;
    }
    *out = v;
    *p += n + (after != '\0');
    return 0;
}

/* "# start 2026-11-26T10:00:00.123Z": the wall clock of the first chunk (every field in its range:
 * month 13 or hour 24 is not a time). */
static xf_err xf__capture_start(xf_capture_reader *r, const char *line)
{
    struct tm tm;
    int ms = 0;
    const char *p = line + strlen(XF_CAPTURE_START);
    memset(&tm, 0, sizeof(tm));
    if (xf__field(&p, 4, 1970, 9999, '-', &tm.tm_year) != 0 || xf__field(&p, 2, 1, 12, '-', &tm.tm_mon) != 0 ||
        xf__field(&p, 2, 1, 31, 'T', &tm.tm_mday) != 0 || xf__field(&p, 2, 0, 23, ':', &tm.tm_hour) != 0 ||
        xf__field(&p, 2, 0, 59, ':', &tm.tm_min) != 0 || xf__field(&p, 2, 0, 60, '.', &tm.tm_sec) != 0 ||
        xf__field(&p, 3, 0, 999, 'Z', &ms) != 0 || (*p != '\n' && *p != '\0' && *p != '\r')) {
        return xf__capture_bad(r, "bad start time (expected \"# start 2026-11-26T10:00:00.123Z\", UTC)");
    }
    tm.tm_year -= 1900;
    tm.tm_mon -= 1;
    r->start_ms = (int64_t)timegm(&tm) * 1000 + ms;
    r->has_start = 1;
    return XF_OK;
}

/* "12.345 >" or "12.345 <" at the start of @p p: the time and direction; *end after them. */
static xf_err xf__capture_time(xf_capture_reader *r, const char *p, xf_capture_record *rec, const char **end)
{
    unsigned long long sec = 0, ms = 0, t;
    size_t k = 0;
    if (*p == '-') {
        return xf__capture_bad(r, "negative time");
    }
    while (k < 12u && isdigit((unsigned char)p[k])) {
        sec = sec * 10u + (unsigned)(p[k++] - '0');
    }
    if (k == 0u || p[k] != '.') {
        return xf__capture_bad(r, "expected a time like 12.345 (seconds)");
    }
    p += k + 1u;
    for (k = 0; k < 3u && isdigit((unsigned char)p[k]); k++) {
        ms = ms * 10u + (unsigned)(p[k] - '0');
    }
    if (k != 3u || p[3] != ' ') {
        return xf__capture_bad(r, "expected three digits of milliseconds, then a space");
    }
    t = sec * 1000u + ms;
    if (t > XF_CAPTURE_T_MAX) {
        return xf__capture_bad(r, "time too large (at most 4294967.295 s)");
    }
    if (t < r->last_ms) {
        return xf__capture_bad(r, "the time goes back (before the previous line's)");
    }
    p += 4;
    if ((*p != '>' && *p != '<') || (p[1] != ' ' && p[1] != '\n' && p[1] != '\0' && p[1] != '\r')) {
        return xf__capture_bad(r, "expected '>' or '<' after the time");
    }
    rec->t_ms = r->last_ms = (uint32_t)t;
    rec->dir = (*p == '>') ? XF_DIR_HOST : XF_DIR_GCU;
    *end = p + 1;
    return XF_OK;
}

/* The bytes of a record line after the direction: " XX XX ..." to the end of the line. */
static xf_err xf__capture_bytes(xf_capture_reader *r, const char *p, xf_capture_record *rec)
{
    rec->len = 0;
    while (*p == ' ') {
        /* p[2] only when p[1] is a digit (not the terminator), p[3] only when p[2] is */
        int hi = xf__hexval((unsigned char)p[1]), lo = (hi < 0) ? -1 : xf__hexval((unsigned char)p[2]);
        if (hi < 0 || lo < 0 || (p[3] != ' ' && p[3] != '\n' && p[3] != '\r' && p[3] != '\0')) {
            return xf__capture_bad(r, "bad byte (expected two hex digits)");
        }
        if (rec->len >= XF_CAPTURE_MAX_CHUNK) {
            return xf__capture_bad(r, "more than 4096 bytes on one line");
        }
        rec->data[rec->len++] = (uint8_t)(hi * 16 + lo);
        p += 3;
    }
    if ((*p == '\r' && p[1] != '\n' && p[1] != '\0') || (*p != '\n' && *p != '\0' && *p != '\r')) {
        return xf__capture_bad(r, "unexpected text after the bytes");
    }
    return XF_OK;
}

static xf_err xf__capture_line(xf_capture_reader *r, const char *line, size_t got, xf_capture_record *rec)
{
    /* A full line: time, direction and 3 characters per byte. */
    static const size_t line_max = 32u + 3u * XF_CAPTURE_MAX_CHUNK;
    const char *p = NULL;
    xf_err err;
    if (strlen(line) != got) {
        return xf__capture_bad(r, "NUL byte in the line");
    }
    if (got > line_max) {
        return xf__capture_bad(r, "line too long");
    }
    err = xf__capture_time(r, line, rec, &p);
    return (err == XF_OK) ? xf__capture_bytes(r, p, rec) : err;
}

xf_err xf_capture_next(xf_capture_reader *r, xf_capture_record *rec)
{
    char *line = NULL;
    size_t cap = 0;
    ssize_t got;
    xf_err result = XF_ERR_EOF;
    if (r == NULL || rec == NULL) {
        return XF_ERR_ARG;
    }
    errno = 0;
    while ((got = getline(&line, &cap, r->f)) >= 0) {
        r->line++;
        if (strncmp(line, XF_CAPTURE_START, strlen(XF_CAPTURE_START)) == 0) {
            result = xf__capture_start(r, line);
            if (result != XF_OK) {
                break;
            }
            result = XF_ERR_EOF;
            errno = 0;
            continue;
        }
        if ((line[0] == '#' && strlen(line) == (size_t)got) || line[0] == '\n' ||
            (line[0] == '\r' && line[1] == '\n')) {
            errno = 0;
            continue;
        }
        result = xf__capture_line(r, line, (size_t)got, rec);
        break;
    }
    if (got < 0 && (ferror(r->f) || errno == ENOMEM)) { /* out of memory is not the end of the file */
        r->line++;
        snprintf(r->error, sizeof(r->error), "cannot read: %s", strerror(errno));
        result = XF_ERR_IO;
    }
    free(line);
    return result;
}

/* ---- either format ----------------------------------------------------------------------- */

xf_err capture_source_open(capture_source *s, FILE *f)
{
    int c;
    memset(s, 0, sizeof(*s));
    c = getc(f);
    if (c == EOF && ferror(f)) {
        snprintf(s->error, sizeof(s->error), "1: cannot read: %s", strerror(errno));
        return XF_ERR_IO;
    }
    if (c != EOF) {
        (void)ungetc(c, f);
    }
    s->is_pcap = pcap_magic_byte(c);
    if (!s->is_pcap) {
        xf_err err = xf_capture_open(&s->text, f);
        snprintf(s->error, sizeof(s->error), "%lu: %s", s->text.line, s->text.error);
        return err;
    }
    s->pcap = calloc(1, sizeof(pcap_reader));
    if (s->pcap == NULL) {
        snprintf(s->error, sizeof(s->error), " out of memory");
        return XF_ERR_IO;
    }
    if (pcap_reader_open((pcap_reader *)s->pcap, f) != 0) {
        snprintf(s->error, sizeof(s->error), " %s", ((pcap_reader *)s->pcap)->error);
        free(s->pcap);
        s->pcap = NULL;
        return XF_ERR_FORMAT;
    }
    return XF_OK;
}

static xf_err capture_source_pcap(capture_source *s, xf_capture_record *rec)
{
    pcap_reader *p = (pcap_reader *)s->pcap;
    int got = pcap_reader_next(p, &rec->dir, &rec->t_ms, rec->data, sizeof(rec->data), &rec->len);
    if (got < 0) {
        snprintf(s->error, sizeof(s->error), " %s", p->error);
        return XF_ERR_FORMAT;
    }
    if (got > 0 && !s->has_start) {
        s->has_start = 1;
        s->start_ms = pcap_reader_start_ms(p);
    }
    return (got > 0) ? XF_OK : XF_ERR_EOF;
}

xf_err capture_source_next(capture_source *s, xf_capture_record *rec)
{
    xf_err err;
    if (s->is_pcap) {
        return capture_source_pcap(s, rec);
    }
    err = xf_capture_next(&s->text, rec);
    s->has_start = s->text.has_start;
    s->start_ms = s->text.start_ms;
    snprintf(s->error, sizeof(s->error), "%lu: %s", s->text.line, s->text.error);
    return err;
}

void capture_source_close(capture_source *s)
{
    if (s->pcap != NULL) {
        pcap_reader_close((pcap_reader *)s->pcap); /* closes the FILE too */
        free(s->pcap);
        s->pcap = NULL;
    } else if (s->text.f != NULL && s->text.f != stdin) {
        fclose(s->text.f);
    }
    s->text.f = NULL;
}
