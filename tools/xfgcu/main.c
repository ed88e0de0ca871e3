/*
 * main.c - xfgcu: link options, the table of commands, help and version.
 *
 *     xfgcu [LINK OPTIONS] COMMAND [ARGS...] [LINK OPTIONS]
 *     xfgcu --help | -h | --version | help [COMMAND] | COMMAND --help
 *
 * Link options (linkopts.c) are parsed here, before COMMAND, and after it by
 * the command's own loop (cli_set_anywhere()); they are checked together once
 * the command has parsed its line. The offline commands ignore them, the
 * online ones open the link they name (online.c).
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "cmdargs.h"
#include "linkopts.h"

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
    {"capture", "[--pcap] FILE [--duration S] [--count N] [--force] [COMMAND [ARGS]]",
     "capture both directions with timestamps", cmd_capture, help_capture},
    {"replay", "FILE [--json] [--brief]", "decode a capture", cmd_replay, help_replay},
    {"probe", "[--move] [--json] [--window S]", "what the gimbal is and answers, safely", cmd_probe, help_probe},
};

#define N_COMMANDS (sizeof(commands) / sizeof(commands[0]))

/* `xfgcu record FILE`: the old name of capture, kept for the scripts that use it (the camera
 * order record is `xfgcu send record`). Not listed; docs/cli.md says it is deprecated. */
static const command_entry record_alias = {"record", "", "", cmd_capture, help_capture};

static const command_entry *find_command(const char *name)
{
    size_t i;
    for (i = 0; i < N_COMMANDS; i++) {
        if (strcmp(commands[i].name, name) == 0) {
            return &commands[i];
        }
    }
    return (strcmp(name, record_alias.name) == 0) ? &record_alias : NULL;
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

/* ---- link options -------------------------------------------------------- */

static cli_link the_link; /* the options' values: main's, and the commands' (after COMMAND) */

/* A link option met after COMMAND (cli_set_anywhere()). */
static int take_anywhere(const cli_args *a, int id)
{
    int rc = linkopts_take(&the_link, a, id);
    return (rc == XFGCU_EXIT_OK) ? linkopts_check(&the_link) : rc;
}

/* ---- dispatch ------------------------------------------------------------- */

static int unknown_command(const char *name)
{
    cmd_spec spec;
    if (name[0] == '-') {
        return cli_fail("unknown option '%s' (try 'xfgcu --help')", name);
    }
    if (cmdargs_find(name, &spec)) {
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
    linkopts_defaults(link, getenv("XFGCU_LINK"));
    cli_args_init(&a, argc, argv, CLI_STOP "h", linkopts_table(), NULL);
    while (rc == XFGCU_EXIT_OK && (id = cli_next(&a)) != CLI_END) {
        if (id == CLI_BAD) {
            return XFGCU_EXIT_USAGE;
        }
        if (id == LO_HELP) {
            print_help(stdout);
            return XFGCU_EXIT_OK;
        }
        if (id == LO_VERSION) {
            printf("xfgcu %s\n", XF_VERSION_STRING);
            return XFGCU_EXIT_OK;
        }
        rc = linkopts_take(link, &a, id);
    }
    if (rc == XFGCU_EXIT_OK && cli_rest(&a) == argc) {
        rc = cli_fail("no command given (try 'xfgcu --help')");
    }
    if (rc == XFGCU_EXIT_OK) {
        rc = linkopts_check(link);
    }
    if (rc == XFGCU_EXIT_OK) {
        rc = linkopts_check_timing(link); /* for every command, as the other link options */
    }
    if (rc == XFGCU_EXIT_OK) {
        /* the commands' loops take them too; --help and --version (the first two) are their own */
        cli_set_anywhere(linkopts_table() + 2, take_anywhere);
        rc = dispatch(link, argc - cli_rest(&a), argv + cli_rest(&a));
    }
    /* output that did not reach its file is a failure, not a success */
    if (fflush(stdout) != 0 || ferror(stdout)) {
        return cli_fail("cannot write to stdout");
    }
    return rc;
}
