/*
 * cli.h - what the modules of the xfgcu program share: exit codes, the one-line error reporter
 * (report.c), option parsing (getopt_long, args.c), the general and link options (linkopts.c),
 * and the entry point of each command. The protocol as text and JSON is the xfgcu::text
 * library's (tools/text): the program parses its command line and hands the layer named
 * arguments, and prints the layer's messages with its own hints.
 *
 * Contract: docs/cli.md. Every failure prints exactly one line
 * "xfgcu: ..." to stderr and maps to one of the exit codes below.
 */
#ifndef XFGCU_CLI_H
#define XFGCU_CLI_H

#include <getopt.h>
#include <stdint.h>
#include <stdio.h>

#include "fieldtext.h"
#include "text_err.h"
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

/**
 * Print "xfgcu: [<where>: ]<message>\n" to stderr (stdout is flushed first, so that what was
 * printed before the failure comes first) and return @p code. The macros below are the uses.
 */
int cli_report(int code, const char *where, const char *fmt, ...) CLI_PRINTF(3, 4);
/** A usage error or bad input: returns XFGCU_EXIT_USAGE so callers can `return cli_fail(...)`. */
#define cli_fail(...) cli_report(XFGCU_EXIT_USAGE, NULL, __VA_ARGS__)
/** The same, prefixed "<where>: " ("decode", "encode zoom-to", "stdin line 3"). */
#define cli_fail_in(where, ...) cli_report(XFGCU_EXIT_USAGE, (where), __VA_ARGS__)
/** A link error or timeout: returns XFGCU_EXIT_LINK. */
#define cli_fail_link(...) cli_report(XFGCU_EXIT_LINK, NULL, __VA_ARGS__)
/** "xfgcu: note: <message>" (a warning, not a failure). */
#define cli_note(...) ((void)cli_report(XFGCU_EXIT_OK, "note", __VA_ARGS__))

/** The notes of the text layer's context, each as a note line. */
void cli_text_notes(const text_err *e);
/**
 * The text layer's failure: its notes, then its message as the one line, with
 * " (see 'xfgcu HINT --help')" when @p hint is not NULL. @return XFGCU_EXIT_USAGE
 */
int cli_text_fail(const text_err *e, const char *hint);

/* ---- options ----------------------------------------------------------------
 * Every option loop is getopt_long() over a `struct option` table whose `val`
 * is what cli_next() returns (an id > 1: not CLI_ARG). cli_next() keeps the
 * program's contract where getopt_long() is looser: long options are taken
 * by their whole name only (no abbreviations), no short option clusters, no
 * messages of getopt's own; its errors are the one-line "xfgcu: ..." ones. */

#define CLI_IN_ORDER "-:" /**< options and arguments mixed, in the order given */
#define CLI_STOP     "+:" /**< options up to the first argument (COMMAND); cli_rest() says where it is */

enum {
    CLI_BAD = -2, /**< an unknown option, or a value given to one that takes none: the error is printed */
    CLI_END = -1, /**< no more arguments */
    CLI_ARG = 1   /**< an argument that is not an option: cli_args.value */
};

/** A getopt_long() loop over argv[1..argc-1]. */
typedef struct cli_args {
    int argc;
    char **argv;
    const char *optstring;     /**< CLI_IN_ORDER or CLI_STOP, then the short options ("h") */
    const struct option *opts; /**< the long options, ended by a zero row */
    const char *context;       /**< "decode", "encode zoom-to": the messages' prefix; NULL before COMMAND */
    const char *hint;          /**< "see 'xfgcu HINT --help'" for unknown options; NULL: the context */
    int quiet;                 /**< print nothing: a pass that only looks for some options */
    const struct option *opt;  /**< the option cli_next() returned */
    const char *value;         /**< its value (NULL when none was given), or the argument */
    int index;                 /**< where it is in argv */
    int tail;                  /**< CLI_IN_ORDER: the arguments after "--" are served from here */
} cli_args;

/** Start a loop (getopt's state is reset): @p optstring and @p opts as in cli_args. */
void cli_args_init(cli_args *a, int argc, char **argv, const char *optstring, const struct option *opts,
                   const char *context);
/**
 * The next option's `val`, CLI_ARG, CLI_END or CLI_BAD. An option whose
 * value is missing is returned with cli_args.value NULL: the cli_value_*
 * functions then say what it needs.
 */
int cli_next(cli_args *a);
/** An option with an optional value given without '=' ("--tcp 2332"): take the next argument as its
 * value, unless it starts with '-'. */
void cli_optional_next(cli_args *a);
/** After CLI_END: the index of the first argument not parsed (CLI_STOP: COMMAND; argc when none). */
int cli_rest(const cli_args *a);
/** The error for an argument (CLI_ARG) nobody takes: "CONTEXT: unexpected argument 'X' (see ...)". */
int cli_unexpected(const cli_args *a);
/** Takes one of the anywhere options: @p a holds it (opt, value), @p id is its `val`. @return an exit code. */
typedef int (*cli_anywhere_fn)(const cli_args *a, int id);
/**
 * Options accepted after COMMAND too (the link options): from now on, a loop that meets a long
 * option it does not know looks it up in @p opts and, if found, gives it to @p take instead of
 * failing. A command's own option of the same name wins (send zoom-to --rate is the zoom's rate).
 */
void cli_set_anywhere(const struct option *opts, cli_anywhere_fn take);

/* The value of the option cli_next() returned, checked. @p what says what it must be, in the
 * messages "[CONTEXT: ]--opt needs a value: WHAT" and "[CONTEXT: ]--opt TEXT: must be WHAT".
 * With @p given (may be NULL), a second time is an error. Each returns an exit code. */
int cli_value_real(const cli_args *a, double lo, double hi, const char *what, double *out, int *given);
int cli_value_long(const cli_args *a, long lo, long hi, const char *what, long *out, int *given);
/** A text that must not be empty. */
int cli_value_text(const cli_args *a, const char *what, const char **out);
/** --protocol: 1 or 2. */
int cli_value_protocol(const cli_args *a, uint8_t *version);
/** --protocol of the commands that talk to a GCU: auto, 1 or 2. auto sets *@p version_auto (and leaves
 *  *@p version, the version tried first); 1 or 2 sets *@p version and clears *@p version_auto. */
int cli_value_protocol_auto(const cli_args *a, uint8_t *version, uint8_t *version_auto);
/** --baud: 115200, 250000, 500000 or 1000000 (xf_serial_baud_ok()). */
int cli_value_baud(const cli_args *a, long *baud, int *given);

/** The options before COMMAND (cli.md "Link options" and "General options"), already validated. */
typedef struct cli_link {
    const char *serial;   /**< --serial PATH, or NULL */
    const char *udp;      /**< --udp HOST[:PORT], or NULL */
    const char *tcp;      /**< --tcp HOST[:PORT], or NULL */
    const char *spec;     /**< --link SPEC, or NULL */
    const char *env_spec; /**< XFGCU_LINK, or NULL: the link when no option names one */
    long baud;            /**< --baud, default 115200 */
    long gcu_port;        /**< --gcu-port, 0 = the link's default */
    long local_port;      /**< --local-port, default 2338; 0 = any free port */
    uint8_t protocol;     /**< --protocol 1|2: the version sent; with auto, the one tried first (1) */
    uint8_t version_auto; /**< --protocol auto (the default): xf_client_config.version_auto */
    long rate_hz;         /**< --rate, 1..200, default 50 */
    long timeout_ms;      /**< --timeout, default 1000 */
    long reorder_ms;      /**< --reorder, 0..1000, default 0 (xf_client_config.reorder_ms) */
    int has_reorder;      /**< --reorder given: the bound is fixed (xf_client_config.reorder_fixed) */
    int trace;            /**< --trace: every packet on stderr, one line each */
    text_view view;       /**< --raw: TEXT_RAW; TEXT_ENGINEERING by default */
    int has_baud, has_gcu_port, has_local_port; /**< given: for options that only one kind of link takes */
    unsigned given;                             /**< a bit per link option given: twice is a usage error */
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
int cmd_capture(const cli_link *link, int argc, char **argv);
int cmd_replay(const cli_link *link, int argc, char **argv);
int cmd_probe(const cli_link *link, int argc, char **argv);
void help_decode(FILE *out);
void help_encode(FILE *out);
void help_send(FILE *out);
void help_point(FILE *out);
void help_rate(FILE *out);
void help_monitor(FILE *out);
void help_sim(FILE *out);
void help_demo(FILE *out);
void help_capture(FILE *out);
void help_replay(FILE *out);
void help_probe(FILE *out);
/** The link options, as `xfgcu --help` lists them (for the online commands' help); linkopts.c. */
void help_link_options(FILE *out);

#endif /* XFGCU_CLI_H */
