/*
 * cmd_encode.c - `xfgcu encode [--protocol N] [--raw] --json OBJECT | COMMAND [ARGS]`.
 *
 * The packet is printed as upper-case hex bytes separated by single
 * spaces, one packet per line. --protocol may come before or after
 * COMMAND (and before `encode`, as a link option); the last one wins.
 * --json reads the object in engineering units, or wire integers with --raw
 * (the general option): the two forms decode --json prints.
 */
#define _POSIX_C_SOURCE 200809L /* getline */

#include <jansson.h>
#include <stdlib.h>
#include <errno.h>
#include <string.h>

#include "cli.h"
#include "cmdline.h"
#include "encode.h"
#include "hexin.h"
#include "jsonpkt.h"
#include "summary.h"

void help_encode(FILE *out)
{
    fputs("usage: xfgcu encode [--protocol 1|2] --json OBJECT\n"
          "       xfgcu encode [--protocol 1|2] COMMAND [ARGS]\n"
          "       xfgcu encode COMMAND --help\n\n"
          "Build a packet and print it as hex bytes (\"A8 E5 48 00 ...\").\n\n"
          "  --json OBJECT   the inverse of `decode --json`: an object with direction (\"host\",\n"
          "                  the default, or \"gcu\"), version (default --protocol), order (number\n"
          "                  or name), params (hex) and any fields by canonical name (missing\n"
          "                  fields are 0), in engineering units (\"cam_pitch\": -30.0), or as wire\n"
          "                  integers with --raw (\"cam_pitch\": -3000); reserved_main / reserved_sub\n"
          "                  as hex. A host packet may give \"command\": {...} instead of params, a\n"
          "                  GCU packet \"feedback\": {\"result\": ...}. OBJECT \"-\" reads JSON Lines\n"
          "                  on stdin; a bad line (a NUL byte, a truncated object, anything after\n"
          "                  it) is an error naming its line; a line that is no packet (decode's\n"
          "                  summary, an event of monitor or sim) is skipped.\n"
          "  COMMAND         a host packet with no carrier data (bytes 5-68 zero except\n"
          "                  sub_request = 0x01) carrying the command:\n\n",
          out);
    cmdargs_list(out);
    fputs("\n  --cameras CAMS: camera numbers (1, or 1,2 = 0x03), a hex mask (0x03) or all (0xFF); a\n"
          "                  decimal number is a camera: 3 is camera 3 (0x04).\n"
          "  --protocol 1|2: the version byte (default 1).\n"
          "  --raw:          --json OBJECT gives wire integers, not engineering units.\n",
          out);
}

static void print_hex(const uint8_t *buf, size_t len)
{
    char text[3 * XF_PACKET_MAX_LEN + 1];
    hex_format(buf, len, ' ', text);
    printf("%s\n", text);
}

/* ---- --json ------------------------------------------------------------------ */

/* One object: its packet in hex. A line that is no packet (decode's summary, monitor's and sim's
 * events) is skipped when @p lines: what those commands print, encode reads back. */
static int encode_object(const char *text, size_t len, uint8_t version, text_view view, const char *where, int lines)
{
    uint8_t buf[XF_PACKET_MAX_LEN];
    size_t n = 0;
    text_err e;
    json_t *obj;
    int rc;
    text_err_init(&e);
    obj = jsonpkt_parse(text, len, where, &e);
    if (lines && summary_not_packet(obj)) {
        json_decref(obj);
        return XFGCU_EXIT_OK;
    }
    rc = (obj != NULL) ? jsonpkt_to_wire(obj, version, view, where, buf, sizeof(buf), &n, &e) : TEXT_BAD;
    json_decref(obj);
    if (rc != TEXT_OK) {
        return cli_text_fail(&e, NULL);
    }
    print_hex(buf, n);
    return XFGCU_EXIT_OK;
}

/* "-": one object per line (the output of decode --json); blank lines are skipped. */
static int encode_lines(uint8_t version, text_view view)
{
    char *line = NULL;
    size_t cap = 0, number = 0;
    ssize_t got;
    int rc = XFGCU_EXIT_OK;
    while (rc == XFGCU_EXIT_OK && (got = getline(&line, &cap, stdin)) >= 0) {
        char where[48];
        size_t len = (size_t)got;
        number++;
        if (strspn(line, " \t\r\n") == len) {
            continue; /* a blank line (a NUL byte would stop strspn short: not blank) */
        }
        snprintf(where, sizeof(where), "encode: stdin line %zu", number);
        rc = encode_object(line, len, version, view, where, 1);
    }
    free(line);
    if (rc == XFGCU_EXIT_OK && ferror(stdin)) { /* closed, a directory, an I/O error: not an empty input */
        rc = cli_fail("encode: cannot read stdin: %s", strerror(errno));
    }
    return rc;
}

/* ---- COMMAND ------------------------------------------------------------------ */

static int encode_named(const cmd_line *l)
{
    uint8_t buf[XF_PACKET_MAX_LEN];
    size_t len = 0;
    text_err e;
    text_err_init(&e);
    if (encode_command(&l->spec, &l->cmd, l->version, buf, sizeof(buf), &len, &e) != TEXT_OK) {
        return cli_text_fail(&e, NULL);
    }
    print_hex(buf, len);
    return XFGCU_EXIT_OK;
}

int cmd_encode(const cli_link *link, int argc, char **argv)
{
    cmd_line l;
    int rc = cmd_line_parse(&l, "encode", link->protocol, 1, help_encode, argc, argv);
    if (rc != XFGCU_EXIT_OK || l.help) {
        return rc;
    }
    if (l.json != NULL) {
        return (strcmp(l.json, "-") == 0)
                   ? encode_lines(l.version, link->view)
                   : encode_object(l.json, strlen(l.json), l.version, link->view, "encode --json", 0);
    }
    if (!l.has_spec) {
        return cli_fail("encode: give --json OBJECT or a COMMAND (see 'xfgcu encode --help')");
    }
    return encode_named(&l);
}
