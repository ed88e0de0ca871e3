/* capture.c - the text capture format of docs/capture-format.md (the program's record and replay). */
#define _POSIX_C_SOURCE 200809L
#include <ctype.h>
#include <errno.h>
#include <stdlib.h>
#include <string.h>

#include "capture.h"
#include "xfgcu/xf_hal.h"

#define XF_CAPTURE_MAGIC "# xfgcu capture 1"

xf_err xf_capture_begin(xf_capture_writer *w, FILE *f, const char *link_desc)
{
    if (w == NULL || f == NULL) {
        return XF_ERR_ARG;
    }
    memset(w, 0, sizeof(*w));
    w->f = f;
    if (fprintf(f, "%s\n# link %s\n# time(s) dir(> host to GCU, < GCU to host) bytes\n", XF_CAPTURE_MAGIC,
                link_desc != NULL ? link_desc : "-") < 0) {
        w->error = errno;
        return XF_ERR_IO;
    }
    return XF_OK;
}

void xf_capture_chunk(void *writer, xf_direction dir, const uint8_t *data, size_t len, uint32_t now_ms)
{
    xf_capture_writer *w = (xf_capture_writer *)writer;
    size_t off = 0;
    uint32_t t;
    if (w == NULL || w->f == NULL) {
        return;
    }
    if (!w->started) {
        w->started = 1;
        w->start_ms = now_ms;
    }
    t = xf_ms_since(now_ms, w->start_ms);
    while (off < len) {
        size_t n = len - off; /* at least 1: off < len */
        size_t i;
        int bad;
        if (n > XF_CAPTURE_MAX_CHUNK) {
            n = XF_CAPTURE_MAX_CHUNK;
        }
        bad = fprintf(w->f, "%u.%03u %c", (unsigned)(t / 1000u), (unsigned)(t % 1000u),
                      dir == XF_DIR_HOST ? '>' : '<') < 0;
        for (i = 0; i < n && !bad; i++) {
            bad = fprintf(w->f, " %02X", data[off + i]) < 0;
        }
        if (bad || fputc('\n', w->f) == EOF) {
            if (w->error == 0) {
                w->error = errno != 0 ? errno : EIO;
            }
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
    if (fgets(line, sizeof(line), f) == NULL) {
        if (ferror(f)) {
            snprintf(r->error, sizeof(r->error), "line 1: %s", strerror(errno));
            return XF_ERR_IO;
        }
        line[0] = '\0'; /* an empty file */
    }
    if (strncmp(line, XF_CAPTURE_MAGIC, strlen(XF_CAPTURE_MAGIC)) != 0) {
        snprintf(r->error, sizeof(r->error), "line 1: not an xfgcu capture (expected \"%s\")", XF_CAPTURE_MAGIC);
        return XF_ERR_FORMAT;
    }
    r->line = 1;
    return XF_OK;
}

static xf_err xf__capture_bad(xf_capture_reader *r, const char *why)
{
    snprintf(r->error, sizeof(r->error), "line %lu: %s", r->line, why);
    return XF_ERR_FORMAT;
}

static int xf__hexval(int c) { return isdigit(c) ? c - '0' : (isxdigit(c) ? (tolower(c) - 'a' + 10) : -1); }

xf_err xf_capture_next(xf_capture_reader *r, xf_capture_record *rec)
{
    /* A full line: time, direction and 3 characters per byte. */
    static const size_t line_max = 32u + 3u * XF_CAPTURE_MAX_CHUNK;
    char *line = NULL;
    size_t cap = 0;
    ssize_t got;
    xf_err result = XF_ERR_EOF;
    if (r == NULL || rec == NULL) {
        return XF_ERR_ARG;
    }
    while ((got = getline(&line, &cap, r->f)) >= 0) {
        char *p = line, *end;
        unsigned long sec, ms = 0;
        r->line++;
        if (line[0] == '#' || line[0] == '\n' || line[0] == '\0') {
            continue;
        }
        if ((size_t)got > line_max) {
            result = xf__capture_bad(r, "line too long");
            break;
        }
        sec = strtoul(p, &end, 10);
        if (end == p || *end != '.' || !isdigit((unsigned char)end[1])) {
            result = xf__capture_bad(r, "expected a time like 12.345");
            break;
        }
        p = end + 1;
        ms = strtoul(p, &end, 10);
        if (end - p != 3 || (*end != ' ')) {
            result = xf__capture_bad(r, "expected three digits of milliseconds");
            break;
        }
        p = end + 1;
        if ((*p != '>' && *p != '<') || (p[1] != ' ' && p[1] != '\n')) {
            result = xf__capture_bad(r, "expected '>' or '<'");
            break;
        }
        rec->t_ms = (uint32_t)(sec * 1000u + ms);
        rec->dir = (*p == '>') ? XF_DIR_HOST : XF_DIR_GCU;
        rec->len = 0;
        p++;
        result = XF_OK;
        while (*p == ' ') {
            int hi = xf__hexval((unsigned char)p[1]), lo = xf__hexval((unsigned char)p[2]);
            if (hi < 0 || lo < 0 || rec->len >= XF_CAPTURE_MAX_CHUNK) {
                result = xf__capture_bad(r, "bad byte (expected two hex digits)");
                break;
            }
            rec->data[rec->len++] = (uint8_t)(hi * 16 + lo);
            p += 3;
        }
        if (result == XF_OK && *p != '\n' && *p != '\0' && *p != '\r') {
            result = xf__capture_bad(r, "unexpected text after the bytes");
        }
        break;
    }
    if (got < 0 && ferror(r->f)) {
        snprintf(r->error, sizeof(r->error), "line %lu: %s", r->line + 1u, strerror(errno));
        result = XF_ERR_IO;
    }
    free(line);
    return result;
}
