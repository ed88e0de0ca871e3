/*
 * cmd_send.c - `xfgcu [LINK] send COMMAND [ARGS]`.
 *
 * The command runs the protocol's way (the client does it): null packets
 * until one's reply is back, the command in every packet until a reply
 * carries its execution state. The result goes to stdout as one line ("ok",
 * "failed cameras 0x02", "failed", "timeout", "link lost"), or with --json
 * as one object, preceded by "operating" lines while a calibration runs; a
 * failure also prints its one line on stderr. Exit 0 ok, 1 failed, 3
 * timeout or link lost.
 *
 * It returns as soon as the result is known: the null that separates this
 * command from the next one of the same order is the next client's first
 * packet (every client starts with nulls). Closing waits for the client to
 * settle (online_free()): with --reorder that also means its last packet has
 * landed, since the null whose reply settles it went out that long after.
 */
#include <string.h>

#include "cli.h"
#include "cmdline.h"
#include "online.h"

void help_send(FILE *out)
{
    fputs("usage: xfgcu [LINK OPTIONS] send COMMAND [ARGS] [--protocol auto|1|2] [--force] [--json] [--verbose]\n"
          "       xfgcu send COMMAND --help\n\n"
          "Run one command on the GCU the way the protocol wants: null packets until the reply to one\n"
          "is back, then the command in every packet until a reply carries its execution state.\n"
          "Prints the result on stdout:\n"
          "  ok                       the GCU executed it (exit 0)\n"
          "  failed cameras 0x02      it failed on the cameras of the mask (orders that report one; exit 1)\n"
          "  failed                   it failed (exit 1)\n"
          "  operating                calibration in progress (then the final state)\n"
          "  timeout                  no execution state within --timeout ms (exit 3)\n"
          "  link lost                the link went down before the answer (exit 3)\n"
          "  interrupted              Ctrl-C or SIGTERM before the answer (exit 3)\n"
          "With --json: one object per line instead, {\"status\": \"ok\", \"order\": 32, ...} with\n"
          "time_mono and time_utc, the version the GCU answered and the client's judgement of the link\n"
          "(\"health\"; docs/cli.md lists the keys). --verbose: a second line with the same judgement.\n\n"
          "With --protocol auto (the default) the arguments are checked for the version the GCU answers\n"
          "in (pip --mode 3 needs V0.2), once it has answered.\n\n"
          "An order that the model the GCU reports does not have (by the vendor's V2.0.6 support list)\n"
          "is not sent: one line on stderr says so (exit 1); --force sends it all the same.\n\n"
          "commands (the same names and arguments as `xfgcu encode`):\n",
          out);
    cmdargs_list(out);
    fputs("\n  --cameras CAMS: camera numbers (1, or 1,2 = 0x03), a hex mask (0x03) or all (0xFF); a\n"
          "                  decimal number is a camera: 3 is camera 3 (0x04).\n\n",
          out);
    help_link_options(out);
    fputs("\nexample: xfgcu --tcp 192.168.144.108 send zoom-to --factor 5.5\n", out);
}

static void on_operating(void *user, const xf_cmd_result *r, uint32_t operating_ms)
{
    if (*(const int *)user) {
        json_t *o = online_result_json(r);
        if (o != NULL) {
            json_object_set_new(o, "operating_ms", json_integer((json_int_t)operating_ms));
        }
        (void)cli_json_line(o);
        return;
    }
    if (operating_ms == 0u) {
        printf("operating\n");
    } else {
        printf("operating (%.0f s)\n", cli_seconds(operating_ms));
    }
    fflush(stdout);
}

/* --json: the result, the command, the link and the client's health. */
static void result_json(const online *o, const xf_cmd_result *r, const char *name)
{
    json_t *obj = online_result_json(r);
    if (obj != NULL) {
        json_object_set_new(obj, "command", json_string(name));
        json_object_set_new(obj, "link", json_string(o->desc));
        json_object_set_new(obj, "version_answered", json_integer(xf_client_health(&o->client)->version_answered));
        json_object_set_new(obj, "health", online_health_json(o));
    }
    (void)cli_json_line(obj);
}

/* --protocol auto: the command for the version the GCU answers in, now that it has. */
static int build_for_gcu(const online *o, cmd_line *l)
{
    char why[64];
    uint8_t version = xf_client_gcu_version(&o->client);
    snprintf(why, sizeof(why), "the GCU answers in protocol %u", (unsigned)version);
    return cmd_line_build(l, version, why);
}

static int run_send(const cli_link *link, cmd_line *l)
{
    online *o = online_new();
    xf_cmd_result r;
    char text[256], what[64];
    int json = (l->force & CMDLINE_JSON) != 0;
    int rc = (o != NULL) ? online_open(o, link, "send", NULL) : XFGCU_EXIT_USAGE;
    if (rc == XFGCU_EXIT_OK && link->version_auto) {
        rc = build_for_gcu(o, l);
    }
    if (rc == XFGCU_EXIT_OK) {
        o->submit_flags = (l->force & CMDLINE_FORCE) ? XF_SUBMIT_ANY_MODEL : 0u;
        rc = online_run(o, &l->cmd, &r, on_operating, &json);
    }
    if (rc == XFGCU_EXIT_OK) {
        if (json) {
            result_json(o, &r, l->spec.name);
        } else {
            online_result_text(&r, text, sizeof(text));
            printf("%s\n", text);
        }
        if ((l->force & CMDLINE_VERBOSE) && !json) { /* --json has it in its object */
            online_health_text(o, text, sizeof(text));
            printf("link: %s\n", text);
        }
        fflush(stdout);
        snprintf(what, sizeof(what), "send %s", l->spec.name);
        rc = online_result_exit(o, what, &r);
    }
    online_free(o);
    return rc;
}

int cmd_send(const cli_link *link, int argc, char **argv)
{
    cmd_line l;
    cli_link with_version;
    int rc = cmd_line_parse(&l, "send", link->version_auto ? (uint8_t)CMDLINE_AUTO : link->protocol, 0, help_send, argc,
                            argv);
    if (rc != XFGCU_EXIT_OK || l.help) {
        return rc;
    }
    with_version = *link; /* after the line: link options may follow COMMAND */
    if (!l.has_spec) {
        return cli_fail("send: which command? (see 'xfgcu send --help')");
    }
    with_version.version_auto = (uint8_t)(l.version == CMDLINE_AUTO);
    if (l.version != CMDLINE_AUTO) {
        with_version.protocol = l.version;
    }
    cli_signals_init();
    return run_send(&with_version, &l);
}
