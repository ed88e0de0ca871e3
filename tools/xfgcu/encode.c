/*
 * encode.c - `xfgcu encode [--protocol N] --json OBJECT | COMMAND [ARGS]`.
 *
 * The packet is printed as upper-case hex bytes separated by single
 * spaces, one packet per line. --protocol may come before or after
 * COMMAND (and before `encode`, as a link option); the last one wins.
 */
#define _POSIX_C_SOURCE 200809L /* getline */

#include <jansson.h>
#include <stdlib.h>
#include <errno.h>
#include <string.h>

#include "cli.h"
#include "cmdargs.h"
#include "encode.h"
#include "hexin.h"
#include "jsonpkt.h"

void help_encode(FILE *out)
{
    fputs("usage: xfgcu encode [--protocol 1|2] --json OBJECT\n"
          "       xfgcu encode [--protocol 1|2] COMMAND [ARGS]\n"
          "       xfgcu encode COMMAND --help\n\n"
          "Build a packet and print it as hex bytes (\"A8 E5 48 00 ...\").\n\n"
          "  --json OBJECT   the inverse of `decode --json`: an object with direction (\"host\",\n"
          "                  the default, or \"gcu\"), version (default --protocol), order (number\n"
          "                  or name), params (hex) and any fields by canonical name (missing\n"
          "                  fields are 0); reserved_main / reserved_sub as hex. A host packet\n"
          "                  may give \"command\": {...} instead of params, a GCU packet\n"
          "                  \"feedback\": {\"result\": ...}. OBJECT \"-\" reads JSON Lines on stdin.\n"
          "  COMMAND         a host packet with no carrier data (bytes 5-68 zero except\n"
          "                  sub_request = 0x01) carrying the command:\n\n",
          out);
    cmdargs_list(out);
    fputs("\n  --cameras CAMS: camera numbers (1, or 1,2 = 0x03), a hex mask (0x03) or all (0xFF); a\n"
          "                  decimal number is a camera: 3 is camera 3 (0x04).\n"
          "  --protocol 1|2: the version byte (default 1).\n",
          out);
}

static void print_hex(const uint8_t *buf, size_t len)
{
    char text[3 * XF_PACKET_MAX_LEN + 1];
    hex_format(buf, len, ' ', text);
    printf("%s\n", text);
}

/* ---- --json ------------------------------------------------------------------ */

static int encode_object(const char *text, uint8_t version, const char *where)
{
    json_error_t error;
    uint8_t buf[XF_PACKET_MAX_LEN];
    size_t len = 0;
    int rc;
    json_t *obj = json_loads(text, JSON_REJECT_DUPLICATES, &error);
    if (obj == NULL) {
        return cli_fail("%s: invalid JSON at column %d: %s", where, error.column, error.text);
    }
    rc = jsonpkt_to_wire(obj, version, where, buf, sizeof(buf), &len);
    json_decref(obj);
    if (rc == XFGCU_EXIT_OK) {
        print_hex(buf, len);
    }
    return rc;
}

/* "-": one object per line (the output of decode --json); blank lines are skipped. */
static int encode_lines(uint8_t version)
{
    char *line = NULL;
    size_t cap = 0, number = 0;
    int rc = XFGCU_EXIT_OK;
    while (rc == XFGCU_EXIT_OK && getline(&line, &cap, stdin) >= 0) {
        char where[48];
        number++;
        if (strspn(line, " \t\r\n") == strlen(line)) {
            continue;
        }
        snprintf(where, sizeof(where), "encode: stdin line %zu", number);
        rc = encode_object(line, version, where);
    }
    free(line);
    if (rc == XFGCU_EXIT_OK && ferror(stdin)) { /* closed, a directory, an I/O error: not an empty input */
        rc = cli_fail("encode: cannot read stdin: %s", strerror(errno));
    }
    return rc;
}

/* ---- COMMAND ------------------------------------------------------------------ */

int encode_command(const cmd_spec *spec, const xf_command *command, uint8_t version, uint8_t *out, size_t cap,
                   size_t *len)
{
    xf_host_packet pkt;
    xf_command cmd = *command;
    xf_field bad = XF_F_NONE;
    xf_err err;
    cmdargs_for_version(&cmd, version); /* --protocol N: N's meaning */
    xf_host_packet_init(&pkt, version); /* no carrier data; sub_request = 0x01 */
    err = xf_host_set_command(&pkt, &cmd, &bad);
    if (err == XF_OK) {
        err = xf_host_pack(&pkt, out, cap, len);
    }
    if (err != XF_OK) {
        return cli_fail("encode %s: %s%s%s", cmdargs_name(spec), xf_strerror(err), bad != XF_F_NONE ? ": " : "",
                        bad != XF_F_NONE ? xf_field_name(bad) : "");
    }
    return XFGCU_EXIT_OK;
}

static int encode_named(const cmd_line *l)
{
    uint8_t buf[XF_PACKET_MAX_LEN];
    size_t len = 0;
    int rc = encode_command(l->spec, &l->cmd, l->version, buf, sizeof(buf), &len);
    if (rc == XFGCU_EXIT_OK) {
        print_hex(buf, len);
    }
    return rc;
}

int cmd_encode(const cli_link *link, int argc, char **argv)
{
    cmd_line l;
    int rc = cmd_line_parse(&l, "encode", link->protocol, 1, help_encode, argc, argv);
    if (rc != XFGCU_EXIT_OK || l.help) {
        return rc;
    }
    if (l.json != NULL) {
        return (strcmp(l.json, "-") == 0) ? encode_lines(l.version) : encode_object(l.json, l.version, "encode --json");
    }
    if (l.spec == NULL) {
        return cli_fail("encode: give --json OBJECT or a COMMAND (see 'xfgcu encode --help')");
    }
    return encode_named(&l);
}
