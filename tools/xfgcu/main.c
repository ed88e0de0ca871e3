/*
 * main.c - xfgcu: link options, the table of commands, help and version.
 *
 *     xfgcu [LINK OPTIONS] COMMAND [ARGS...]
 *     xfgcu --help | --version | COMMAND --help
 *
 * Link options are parsed and validated here, before COMMAND, for every
 * command (cli.md); the offline commands ignore them, the online ones
 * open the link they name (online.c).
 */
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "cmdargs.h"

static void vfail(const char *fmt, va_list ap) CLI_PRINTF(1, 0);

static void vfail(const char *fmt, va_list ap)
{
    fflush(stdout); /* what was printed before the failure comes first */
    fputs("xfgcu: ", stderr);
    vfprintf(stderr, fmt, ap);
    fputc('\n', stderr);
}

int cli_fail(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vfail(fmt, ap);
    va_end(ap);
    return XFGCU_EXIT_USAGE;
}

int cli_fail_link(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vfail(fmt, ap);
    va_end(ap);
    return XFGCU_EXIT_LINK;
}

void cli_note(const char *fmt, ...)
{
    va_list ap;
    fputs("xfgcu: note: ", stderr);
    va_start(ap, fmt);
    vfprintf(stderr, fmt, ap);
    va_end(ap);
    fputc('\n', stderr);
}

/* ---- commands ------------------------------------------------------------ */

typedef struct command_entry {
    const char *name;
    const char *usage; /* arguments after the name */
    const char *what;  /* one line */
    cli_run_fn run;
    void (*help)(FILE *out);
} command_entry;

static const command_entry commands[] = {
    {"decode", "[--json] [HEX ...]", "decode packets given in hex (stdin when no HEX)", cmd_decode, help_decode},
    {"encode", "[--protocol N] --json OBJECT | COMMAND [ARGS]", "build a packet and print it in hex", cmd_encode,
     help_encode},
    {"send", "COMMAND [ARGS]", "run a command on the GCU and print its result", cmd_send, help_send},
    {"point", "--pitch DEG --yaw DEG [--roll DEG]", "point the gimbal (Euler angle control)", cmd_point, help_point},
    {"rate", "--pitch DPS --yaw DPS --duration S", "turn the gimbal at a rate (head lock)", cmd_rate, help_rate},
    {"monitor", "[--json] [--count N] [--duration S]", "live telemetry", cmd_monitor, help_monitor},
    {"sim", "[--serial PATH | --pty | --udp [PORT] | --tcp [PORT]]", "a simulated GCU", cmd_sim, help_sim},
    {"demo", "", "simulator and client over loopback: a short tour", cmd_demo, help_demo},
    {"record", "FILE [--duration S] [--count N] [COMMAND [ARGS]]", "capture both directions with timestamps",
     cmd_record, help_record},
    {"replay", "FILE [--json] [--brief]", "decode a capture", cmd_replay, help_replay},
};

#define N_COMMANDS (sizeof(commands) / sizeof(commands[0]))

static const command_entry *find_command(const char *name)
{
    size_t i;
    for (i = 0; i < N_COMMANDS; i++) {
        if (strcmp(commands[i].name, name) == 0) {
            return &commands[i];
        }
    }
    return NULL;
}

static void print_help(FILE *out)
{
    size_t i;
    fputs("usage: xfgcu [LINK OPTIONS] COMMAND [ARGS...]\n"
          "       xfgcu --help | --version | COMMAND --help\n\n"
          "Talk to, decode and build packets of XFRobot gimbals (GCU private protocol V0.1 and V0.2).\n\n"
          "commands:\n",
          out);
    for (i = 0; i < N_COMMANDS; i++) {
        char left[96];
        snprintf(left, sizeof(left), "%s %s", commands[i].name, commands[i].usage);
        fprintf(out, "  %-58s %s\n", left, commands[i].what);
    }
    fputs("\n", out);
    help_link_options(out);
    fputs("\nFirst time? Run 'xfgcu demo': a simulated gimbal and a short tour, no hardware needed.\n"
          "'xfgcu COMMAND --help' tells more about each command.\n",
          out);
}

void help_link_options(FILE *out)
{
    fputs("link options (before COMMAND; exactly one of --serial, --udp, --tcp for the online commands):\n"
          "  --serial PATH         serial device, e.g. /dev/ttyUSB0\n"
          "  --baud N              115200 (default), 250000, 500000 or 1000000\n"
          "  --udp HOST            the GCU's address for UDP\n"
          "  --gcu-port N          the GCU's UDP port (2337) or TCP port (2332)\n"
          "  --local-port N        local UDP port to receive on (2338; 0 = any free port)\n"
          "  --tcp HOST[:PORT]     connect as TCP client\n"
          "  --protocol 1|2        version byte sent (1)\n"
          "  --rate HZ             packets per second, 1..200 (50; the vendor recommends 30..50)\n"
          "  --timeout MS          how long to wait for the first reply and for a command's feedback (1000)\n"
          "\nexit status: 0 success, 1 the GCU answered with failure, 2 usage error or bad input,\n"
          "3 link error or timeout.\n",
          out);
}

/* ---- link options -------------------------------------------------------- */

static int parse_long_in(const char *opt, const char *text, long lo, long hi, const char *what, long *out)
{
    long long v;
    if (text == NULL) {
        return cli_fail("%s needs a value: %s", opt, what);
    }
    if (cli_parse_int(text, &v) != 0 || v < lo || v > hi) {
        return cli_fail("%s %s: must be %s", opt, text, what);
    }
    *out = (long)v;
    return XFGCU_EXIT_OK;
}

static int parse_baud(const char *text, long *baud)
{
    long v = 0;
    int rc = parse_long_in("--baud", text, 1, 100000000L, "115200, 250000, 500000 or 1000000", &v);
    if (rc != XFGCU_EXIT_OK) {
        return rc;
    }
    if (v != 115200L && v != 250000L && v != 500000L && v != 1000000L) {
        return cli_fail("--baud %s: must be 115200, 250000, 500000 or 1000000", text);
    }
    *baud = v;
    return XFGCU_EXIT_OK;
}

static int parse_host(const char *opt, const char *text, int port_allowed)
{
    const char *colon;
    if (text == NULL || text[0] == '\0') {
        return cli_fail("%s needs a value: %s", opt, port_allowed ? "HOST[:PORT]" : "HOST");
    }
    colon = strrchr(text, ':');
    /* HOST:PORT, or [IPv6]:PORT; a bare IPv6 address has several colons and no port */
    if (port_allowed && colon != NULL && (strchr(text, ':') == colon || colon[-1] == ']')) {
        long long v;
        if (cli_parse_int(colon + 1, &v) != 0 || v < 1 || v > 65535) {
            return cli_fail("%s %s: PORT must be 1..65535", opt, text);
        }
    }
    return XFGCU_EXIT_OK;
}

/* One link option at argv[*i]; returns -1 when argv[*i] is none. */
static int take_link_option(cli_link *l, int argc, char **argv, int *i)
{
    const char *v = NULL;
    if (cli_take_option(argc, argv, i, "--serial", &v)) {
        l->serial = v;
        return (v == NULL || v[0] == '\0') ? cli_fail("--serial needs a value: a device path") : XFGCU_EXIT_OK;
    }
    if (cli_take_option(argc, argv, i, "--baud", &v)) {
        return parse_baud(v, &l->baud);
    }
    if (cli_take_option(argc, argv, i, "--udp", &v)) {
        l->udp = v;
        return parse_host("--udp", v, 0);
    }
    if (cli_take_option(argc, argv, i, "--tcp", &v)) {
        l->tcp = v;
        return parse_host("--tcp", v, 1);
    }
    if (cli_take_option(argc, argv, i, "--gcu-port", &v)) {
        return parse_long_in("--gcu-port", v, 1, 65535, "a port 1..65535", &l->gcu_port);
    }
    if (cli_take_option(argc, argv, i, "--local-port", &v)) {
        return parse_long_in("--local-port", v, 0, 65535, "a port 0..65535 (0: any free port)", &l->local_port);
    }
    if (cli_take_option(argc, argv, i, "--protocol", &v)) {
        return cli_parse_protocol(v, &l->protocol);
    }
    if (cli_take_option(argc, argv, i, "--rate", &v)) {
        return parse_long_in("--rate", v, 1, 200, "packets per second, 1..200", &l->rate_hz);
    }
    if (cli_take_option(argc, argv, i, "--timeout", &v)) {
        return parse_long_in("--timeout", v, 1, 3600000L, "milliseconds, 1..3600000", &l->timeout_ms);
    }
    return -1;
}

static void link_defaults(cli_link *l)
{
    memset(l, 0, sizeof(*l));
    l->baud = 115200L;
    l->local_port = 2338L;
    l->protocol = XF_PROTOCOL_V1;
    l->rate_hz = 50L;
    l->timeout_ms = 1000L;
}

static int check_one_link(const cli_link *l)
{
    int n = (l->serial != NULL) + (l->udp != NULL) + (l->tcp != NULL);
    return (n > 1) ? cli_fail("give only one of --serial, --udp, --tcp") : XFGCU_EXIT_OK;
}

/* ---- dispatch ------------------------------------------------------------- */

static int unknown_command(const char *name)
{
    if (name[0] == '-') {
        return cli_fail("unknown option '%s' (try 'xfgcu --help')", name);
    }
    if (cmdargs_find(name) != NULL) {
        return cli_fail("unknown command '%s': it is an order, try 'xfgcu encode %s' or 'xfgcu send %s'", name, name,
                        name);
    }
    return cli_fail("unknown command '%s' (try 'xfgcu --help')", name);
}

static int dispatch(const cli_link *link, int argc, char **argv)
{
    const command_entry *c = find_command(argv[0]);
    if (c == NULL) {
        return unknown_command(argv[0]);
    }
    if (argc > 1 && strcmp(argv[1], "--help") == 0) {
        c->help(stdout);
        return XFGCU_EXIT_OK;
    }
    return c->run(link, argc, argv);
}

int main(int argc, char **argv)
{
    cli_link link;
    int i, rc;
    link_defaults(&link);
    for (i = 1; i < argc && argv[i][0] == '-'; i++) {
        if (strcmp(argv[i], "--help") == 0 || strcmp(argv[i], "-h") == 0) {
            print_help(stdout);
            return XFGCU_EXIT_OK;
        }
        if (strcmp(argv[i], "--version") == 0) {
            printf("xfgcu %s\n", XF_VERSION_STRING);
            return XFGCU_EXIT_OK;
        }
        rc = take_link_option(&link, argc, argv, &i);
        if (rc >= 0 && rc != XFGCU_EXIT_OK) {
            return rc;
        }
        if (rc < 0) {
            return unknown_command(argv[i]);
        }
    }
    if (i == argc) {
        return cli_fail("no command given (try 'xfgcu --help')");
    }
    rc = check_one_link(&link);
    if (rc == XFGCU_EXIT_OK) {
        rc = dispatch(&link, argc - i, argv + i);
    }
    /* output that did not reach its file is a failure, not a success */
    if (fflush(stdout) != 0 || ferror(stdout)) {
        return cli_fail("cannot write to stdout");
    }
    return rc;
}
