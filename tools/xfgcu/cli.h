/*
 * cli.h - what the modules of the xfgcu program share: exit codes, the
 * one-line error reporter, number parsing, the options that come before
 * COMMAND, and the entry point of each command.
 *
 * Contract: docs/cli.md. Every failure prints exactly one line
 * "xfgcu: ..." to stderr and maps to one of the exit codes below.
 */
#ifndef XFGCU_CLI_H
#define XFGCU_CLI_H

#include <stdint.h>
#include <stdio.h>

#include "xfgcu/xfgcu.h"

#define XFGCU_EXIT_OK     0 /**< success */
#define XFGCU_EXIT_FAILED 1 /**< the GCU answered with failure */
#define XFGCU_EXIT_USAGE  2 /**< usage error or bad input */
#define XFGCU_EXIT_LINK   3 /**< link error or timeout */

#if defined(__GNUC__) || defined(__clang__)
#define CLI_PRINTF(fmt, args) __attribute__((format(printf, fmt, args)))
#else
#define CLI_PRINTF(fmt, args)
#endif

/** Print "xfgcu: <message>\n" to stderr; returns XFGCU_EXIT_USAGE so callers can `return cli_fail(...)`. */
int cli_fail(const char *fmt, ...) CLI_PRINTF(1, 2);
/** Same line; returns XFGCU_EXIT_LINK (link error or timeout). */
int cli_fail_link(const char *fmt, ...) CLI_PRINTF(1, 2);
/** Print "xfgcu: note: <message>\n" to stderr (not a failure). */
void cli_note(const char *fmt, ...) CLI_PRINTF(1, 2);

/**
 * Parse a whole string as an integer: decimal, or hex with a 0x prefix,
 * optional sign. Leading zeros are decimal (never octal).
 * @return 0, or -1 if @p s is not an integer or overflows.
 */
int cli_parse_int(const char *s, long long *out);
/** Parse a whole string as a finite decimal number. @return 0 or -1. */
int cli_parse_real(const char *s, double *out);

/** The options before COMMAND (cli.md "Link options"), already validated. */
typedef struct cli_link {
    const char *serial; /**< --serial PATH, or NULL */
    const char *udp;    /**< --udp HOST, or NULL */
    const char *tcp;    /**< --tcp HOST[:PORT], or NULL */
    long baud;          /**< --baud, default 115200 */
    long gcu_port;      /**< --gcu-port, 0 = the link's default */
    long local_port;    /**< --local-port, default 2338; 0 = any free port */
    uint8_t protocol;   /**< --protocol, default 1 */
    long rate_hz;       /**< --rate, 1..200, default 50 */
    long timeout_ms;    /**< --timeout, default 1000 */
} cli_link;

/** A command's entry point: argv[0] is the command's name. Returns an exit code. */
typedef int (*cli_run_fn)(const cli_link *link, int argc, char **argv);

int cmd_decode(const cli_link *link, int argc, char **argv);
int cmd_encode(const cli_link *link, int argc, char **argv);
int cmd_send(const cli_link *link, int argc, char **argv);
int cmd_point(const cli_link *link, int argc, char **argv);
int cmd_rate(const cli_link *link, int argc, char **argv);
int cmd_monitor(const cli_link *link, int argc, char **argv);
int cmd_sim(const cli_link *link, int argc, char **argv);
int cmd_demo(const cli_link *link, int argc, char **argv);
int cmd_record(const cli_link *link, int argc, char **argv);
int cmd_replay(const cli_link *link, int argc, char **argv);
void help_decode(FILE *out);
void help_encode(FILE *out);
void help_send(FILE *out);
void help_point(FILE *out);
void help_rate(FILE *out);
void help_monitor(FILE *out);
void help_sim(FILE *out);
void help_demo(FILE *out);
void help_record(FILE *out);
void help_replay(FILE *out);
/** The link options, as `xfgcu --help` lists them (for the online commands' help). */
void help_link_options(FILE *out);

#endif /* XFGCU_CLI_H */
