/*
 * main.c - xfgcu: link options, the table of commands, help and version.
 *
 *     xfgcu [LINK OPTIONS] COMMAND [ARGS...] [LINK OPTIONS]
 *     xfgcu --help | -h | --version | help [COMMAND] | COMMAND --help
 *
 * Link options are parsed here, before COMMAND, and after it by the
 * command's own loop (cli_set_anywhere()); they are checked together once
 * the command has parsed its line. The offline commands ignore them, the
 * online ones open the link they name (online.c).
 */
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "cmdargs.h"
#include "online.h"

/* Text on stderr with its control characters escaped (\n, \t, \r, \xHH): a message that
 * echoes the user's input stays one line, whatever the input holds. */
static void put_escaped(const char *text)
{
    const unsigned char *p = (const unsigned char *)text;
    for (; *p != '\0'; p++) {
        if (*p >= 0x20u && *p != 0x7Fu) {
            fputc(*p, stderr);
        } else if (*p == '\n' || *p == '\t' || *p == '\r') {
            fprintf(stderr, "\\%c", *p == '\n' ? 'n' : *p == '\t' ? 't' : 'r');
        } else {
            fprintf(stderr, "\\x%02X", (unsigned)*p);
        }
    }
}

int cli_report(int code, const char *where, const char *fmt, ...)
{
    char text[2048];
    int n;
    va_list ap;
    fflush(stdout); /* what was printed before the failure comes first */
    va_start(ap, fmt);
    n = vsnprintf(text, sizeof(text), fmt, ap);
    va_end(ap);
    fputs("xfgcu: ", stderr);
    if (where != NULL) {
        put_escaped(where);
        fputs(": ", stderr);
    }
    put_escaped(n >= 0 ? text : fmt);
    if (n >= (int)sizeof(text)) {
        fputs("...", stderr); /* said so, not cut silently */
    }
    fputc('\n', stderr);
    return code;
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
    {"decode", "[--json] [--pod-order le|be|auto] [--file FILE | HEX ...]",
     "decode packets in hex, logs and captures (stdin when no HEX)", cmd_decode, help_decode},
    {"encode", "[--protocol N] --json OBJECT | COMMAND [ARGS]", "build a packet and print it in hex", cmd_encode,
     help_encode},
    {"send", "COMMAND [ARGS] [--json]", "run a command on the GCU and print its result", cmd_send, help_send},
    {"point", "--pitch DEG --yaw DEG [--roll DEG] [--wait S] [--json]", "point the gimbal (Euler angle control)",
     cmd_point, help_point},
    {"rate", "--pitch DPS --yaw DPS --duration S [--json]", "turn the gimbal at a rate (head lock)", cmd_rate,
     help_rate},
    {"monitor", "[--json] [--count N] [--duration S] [--wait S]", "live telemetry", cmd_monitor, help_monitor},
    {"sim", "[--serial PATH | --pty | --udp [PORT] | --tcp [PORT]] [--json]", "a simulated GCU", cmd_sim, help_sim},
    {"demo", "", "simulator and client over loopback: a short tour", cmd_demo, help_demo},
    {"record", "[--pcap] FILE [--duration S] [--count N] [--force] [COMMAND [ARGS]]",
     "capture both directions with timestamps", cmd_record, help_record},
    {"replay", "FILE [--json] [--brief]", "decode a capture", cmd_replay, help_replay},
    {"probe", "[--move] [--json] [--window S]", "what the gimbal is and answers, safely", cmd_probe, help_probe},
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
          "       xfgcu --help | -h | --version | help [COMMAND] | COMMAND --help\n\n"
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
    fputs("link options (before or after COMMAND; exactly one of --serial, --udp, --tcp for the online\n"
          "commands; a command's own option of the same name wins, as zoom-to's --rate):\n"
          "  --serial PATH         serial device, e.g. /dev/ttyUSB0\n"
          "  --baud N              115200 (default), 250000, 500000 or 1000000\n"
          "  --udp HOST            the GCU's address for UDP\n"
          "  --gcu-port N          the GCU's UDP port (2337) or TCP port (2332)\n"
          "  --local-port N        local UDP port to receive on (2338; 0 = any free port)\n"
          "  --tcp HOST[:PORT]     connect as TCP client\n"
          "  --protocol 1|2        version byte sent (1)\n"
          "  --rate HZ             packets per second, 1..200 (50; the vendor recommends 30..50)\n"
          "  --timeout MS          how long to wait for the first reply and for a command's feedback (1000)\n"
          "  --reorder MS          the longest the network can delay one packet behind a later one (0:\n"
          "                        it keeps order, as serial, TCP and a wired LAN do); 0..1000, and a\n"
          "                        packet period plus twice it under 250 ms (114 at 50 Hz)\n"
          "  --trace               print every packet sent and received on stderr, one line each\n"
          "\nexit status: 0 success, 1 the GCU answered with failure, 2 usage error or bad input,\n"
          "3 link error or timeout.\n",
          out);
}

/* ---- link options -------------------------------------------------------- */

enum {
    O_HELP = 'h',
    O_VERSION = 256,
    O_SERIAL,
    O_BAUD,
    O_UDP,
    O_TCP,
    O_GCU_PORT,
    O_LOCAL_PORT,
    O_PROTOCOL,
    O_RATE,
    O_TIMEOUT,
    O_REORDER,
    O_TRACE
};

static const struct option link_options[] = {
    {"help", no_argument, NULL, O_HELP},
    {"version", no_argument, NULL, O_VERSION},
    {"serial", required_argument, NULL, O_SERIAL},
    {"baud", required_argument, NULL, O_BAUD},
    {"udp", required_argument, NULL, O_UDP},
    {"tcp", required_argument, NULL, O_TCP},
    {"gcu-port", required_argument, NULL, O_GCU_PORT},
    {"local-port", required_argument, NULL, O_LOCAL_PORT},
    {"protocol", required_argument, NULL, O_PROTOCOL},
    {"rate", required_argument, NULL, O_RATE},
    {"timeout", required_argument, NULL, O_TIMEOUT},
    {"reorder", required_argument, NULL, O_REORDER},
    {"trace", no_argument, NULL, O_TRACE},
    {NULL, 0, NULL, 0},
};

static cli_link the_link; /* the options' values: main's, and the commands' (after COMMAND) */

/* --udp HOST, --tcp HOST[:PORT] (read as the library reads the spec "tcp:HOST[:PORT]") */
static int take_host(const cli_args *a, int port_allowed, const char **host)
{
    xf_link_spec spec;
    const char *reason = NULL;
    int rc = cli_value_text(a, port_allowed ? "HOST[:PORT]" : "HOST", host);
    if (rc == XFGCU_EXIT_OK && port_allowed && cli_tcp_spec(*host, &spec, &reason) != XF_OK) {
        rc = cli_fail("--%s %s: %s", a->opt->name, *host, reason);
    }
    return rc;
}

/* One link option, as cli_next() returned it. */
static int take_link_option(cli_link *l, const cli_args *a, int id)
{
    unsigned bit = 1u << (unsigned)(id - O_SERIAL);
    if (l->given & bit) {
        return cli_fail_in(a->context, "--%s given twice", a->opt->name); /* which one would count? */
    }
    l->given |= bit;
    switch (id) {
    case O_SERIAL: return cli_value_text(a, "a device path", &l->serial);
    case O_BAUD: l->has_baud = 1; return cli_value_baud(a, &l->baud, NULL);
    case O_UDP: return take_host(a, 0, &l->udp);
    case O_TCP: return take_host(a, 1, &l->tcp);
    case O_GCU_PORT: l->has_gcu_port = 1; return cli_value_long(a, 1, 65535, "a port 1..65535", &l->gcu_port, NULL);
    case O_LOCAL_PORT:
        l->has_local_port = 1;
        return cli_value_long(a, 0, 65535, "a port 0..65535 (0: any free port)", &l->local_port, NULL);
    case O_PROTOCOL: return cli_value_protocol(a, &l->protocol);
    case O_RATE: return cli_value_long(a, 1, 200, "packets per second, 1..200", &l->rate_hz, NULL);
    case O_REORDER: return cli_value_long(a, 0, 1000, "milliseconds, 0..1000", &l->reorder_ms, NULL);
    case O_TRACE: l->trace = 1; return XFGCU_EXIT_OK;
    default: return cli_value_long(a, 1, 3600000L, "milliseconds, 1..3600000", &l->timeout_ms, NULL);
    }
}

/* A link option met after COMMAND (cli_set_anywhere()). */
static int take_anywhere(const cli_args *a, int id)
{
    int rc = take_link_option(&the_link, a, id);
    return (rc == XFGCU_EXIT_OK) ? cli_check_link_options(&the_link) : rc;
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

/* --tcp HOST:PORT or [ADDR]:PORT names its port (read as the library reads the spec). */
static int tcp_port_given(const char *tcp)
{
    xf_link_spec spec;
    return cli_tcp_spec(tcp, &spec, NULL) == XF_OK && spec.port_given;
}

/* Options that contradict each other, or name what the link has not, are usage errors. */
int cli_check_link_options(const cli_link *l)
{
    int n = (l->serial != NULL) + (l->udp != NULL) + (l->tcp != NULL);
    if (n > 1) {
        return cli_fail("give only one of --serial, --udp, --tcp");
    }
    if (l->has_baud && (l->udp != NULL || l->tcp != NULL)) {
        return cli_fail("--baud is for --serial, not --%s", l->udp != NULL ? "udp" : "tcp");
    }
    if ((l->has_gcu_port || l->has_local_port) && l->serial != NULL) {
        return cli_fail("--%s is for --udp or --tcp, not --serial", l->has_gcu_port ? "gcu-port" : "local-port");
    }
    if (l->has_local_port && l->tcp != NULL) {
        return cli_fail("--local-port is for --udp, not --tcp");
    }
    if (l->has_gcu_port && l->tcp != NULL && tcp_port_given(l->tcp)) {
        return cli_fail("--gcu-port and the port of --tcp %s: give the port once", l->tcp);
    }
    return XFGCU_EXIT_OK;
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

/* xfgcu help [COMMAND] */
static int help_command(int argc, char **argv)
{
    const command_entry *c;
    if (argc < 2) {
        print_help(stdout);
        return XFGCU_EXIT_OK;
    }
    if (argc > 2) {
        return cli_fail_in("help", "unexpected argument '%s' (try 'xfgcu help COMMAND')", argv[2]);
    }
    c = find_command(argv[1]);
    if (c == NULL) {
        return unknown_command(argv[1]);
    }
    c->help(stdout);
    return XFGCU_EXIT_OK;
}

static int dispatch(const cli_link *link, int argc, char **argv)
{
    const command_entry *c;
    if (strcmp(argv[0], "help") == 0) {
        return help_command(argc, argv);
    }
    c = find_command(argv[0]);
    if (c == NULL) {
        return unknown_command(argv[0]);
    }
    if (argc > 1 && (strcmp(argv[1], "--help") == 0 || strcmp(argv[1], "-h") == 0)) {
        c->help(stdout);
        return XFGCU_EXIT_OK;
    }
    return c->run(link, argc, argv);
}

int main(int argc, char **argv)
{
    cli_link *link = &the_link;
    cli_args a;
    int id, rc = XFGCU_EXIT_OK;
    link_defaults(link);
    cli_args_init(&a, argc, argv, CLI_STOP "h", link_options, NULL);
    while (rc == XFGCU_EXIT_OK && (id = cli_next(&a)) != CLI_END) {
        if (id == CLI_BAD) {
            return XFGCU_EXIT_USAGE;
        }
        if (id == O_HELP) {
            print_help(stdout);
            return XFGCU_EXIT_OK;
        }
        if (id == O_VERSION) {
            printf("xfgcu %s\n", XF_VERSION_STRING);
            return XFGCU_EXIT_OK;
        }
        rc = take_link_option(link, &a, id);
    }
    if (rc == XFGCU_EXIT_OK && cli_rest(&a) == argc) {
        rc = cli_fail("no command given (try 'xfgcu --help')");
    }
    if (rc == XFGCU_EXIT_OK) {
        rc = cli_check_link_options(link);
    }
    if (rc == XFGCU_EXIT_OK) {
        rc = cli_check_timing(link); /* for every command, as the other link options */
    }
    if (rc == XFGCU_EXIT_OK) {
        /* the commands' loops take them too; --help and --version (the first two) are their own */
        cli_set_anywhere(link_options + 2, take_anywhere);
        rc = dispatch(link, argc - cli_rest(&a), argv + cli_rest(&a));
    }
    /* output that did not reach its file is a failure, not a success */
    if (fflush(stdout) != 0 || ferror(stdout)) {
        return cli_fail("cannot write to stdout");
    }
    return rc;
}
