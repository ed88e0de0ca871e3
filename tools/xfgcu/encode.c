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
#include <string.h>

#include "cli.h"
#include "cmdargs.h"
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
    fputs("\n  --cameras MASK: a number (1, 0x03), a list of cameras (1,2 = 0x03) or all (0xFF).\n"
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
    return rc;
}

/* ---- arguments ------------------------------------------------------------------ */

typedef struct encode_args {
    cmd_line line;    /* [--protocol N] [--help] COMMAND ARGS */
    const char *json; /* --json OBJECT */
} encode_args;

/* Before COMMAND: --protocol, --json, --help. After it, everything but --protocol and --help is the command's. */
static int take_arg(encode_args *a, int argc, char **argv, int *i)
{
    const char *v = NULL;
    int rc;
    if (cmd_line_take(&a->line, argc, argv, i, &rc)) {
        return rc;
    }
    if (cli_take_option(argc, argv, i, "--json", &v)) {
        if (v == NULL) {
            return cli_fail("encode: --json needs an OBJECT (or - for JSON Lines on stdin)");
        }
        if (a->json != NULL) {
            return cli_fail("encode: --json given twice");
        }
        a->json = v;
        return XFGCU_EXIT_OK;
    }
    if (argv[*i][0] != '-' && a->json != NULL) {
        return cli_fail("encode: --json takes one OBJECT; unexpected '%s'", argv[*i]);
    }
    return cmd_line_command(&a->line, "encode", argv[*i]);
}

static int encode_named(const encode_args *a)
{
    xf_command cmd;
    xf_host_packet pkt;
    uint8_t buf[XF_PACKET_MAX_LEN];
    size_t len = 0;
    const char *bad = NULL;
    xf_err err;
    int rc = cmdargs_parse(a->line.spec, "encode", a->line.cargc, a->line.cargv, a->line.version, &cmd);
    if (rc != XFGCU_EXIT_OK) {
        return rc;
    }
    xf_host_packet_init(&pkt, a->line.version); /* no carrier data; sub_request = 0x01 */
    err = xf_host_set_command(&pkt, &cmd, &bad);
    if (err == XF_OK) {
        err = xf_host_pack(&pkt, buf, sizeof(buf), &len);
    }
    if (err != XF_OK) {
        return cli_fail("encode %s: %s%s%s", cmdargs_name(a->line.spec), xf_strerror(err), bad != NULL ? ": " : "",
                        bad != NULL ? bad : "");
    }
    print_hex(buf, len);
    return XFGCU_EXIT_OK;
}

static int run(encode_args *a)
{
    if (a->line.help) {
        if (a->line.spec != NULL) {
            cmdargs_help(a->line.spec, "encode", stdout);
        } else {
            help_encode(stdout);
        }
        return XFGCU_EXIT_OK;
    }
    if (a->json != NULL) {
        return (strcmp(a->json, "-") == 0) ? encode_lines(a->line.version)
                                           : encode_object(a->json, a->line.version, "encode --json");
    }
    if (a->line.spec == NULL) {
        return cli_fail("encode: give --json OBJECT or a COMMAND (see 'xfgcu encode --help')");
    }
    return encode_named(a);
}

int cmd_encode(const cli_link *link, int argc, char **argv)
{
    encode_args a;
    int i, rc = XFGCU_EXIT_OK;
    memset(&a, 0, sizeof(a));
    a.line.version = link->protocol;
    a.line.cargv = calloc((size_t)argc + 1u, sizeof(*a.line.cargv));
    if (a.line.cargv == NULL) {
        return cli_fail("encode: out of memory");
    }
    for (i = 1; i < argc && rc == XFGCU_EXIT_OK; i++) {
        rc = take_arg(&a, argc, argv, &i);
    }
    if (rc == XFGCU_EXIT_OK) {
        rc = run(&a);
    }
    free(a.line.cargv);
    return rc;
}
