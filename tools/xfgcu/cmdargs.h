/*
 * cmdargs.h - the named commands of cli.md ("zoom-to --rate 5.5", ...)
 * and their arguments, turned into an xf_command.
 *
 * Shared by `encode` and (later) `send`. The table of orders is the
 * codec's (xf_order_at); this module only adds, per order, which options
 * the command line takes and how each maps onto xf_command members.
 */
#ifndef XFGCU_CMDARGS_H
#define XFGCU_CMDARGS_H

#include <stdio.h>

#include "xfgcu/xfgcu.h"

typedef struct cmd_spec cmd_spec;

/**
 * Match argv[*i] against option @p name, as "--name VALUE" or
 * "--name=VALUE". On a match returns 1, sets *value (NULL when the value is
 * missing) and moves *i to the last argument used; otherwise returns 0.
 */
int cli_take_option(int argc, char **argv, int *i, const char *name, const char **value);

/** Validate a --protocol value (1 or 2); prints the error. @return an exit code. */
int cli_parse_protocol(const char *text, uint8_t *version);

/** The command named @p name ("zoom-to" or "zoom_to"), or NULL. */
const cmd_spec *cmdargs_find(const char *name);
/** The command's name as typed on the command line. */
const char *cmdargs_name(const cmd_spec *spec);

/**
 * Parse the arguments of a named command (argv[0] is its name) into @p cmd
 * and check them for protocol @p version. @p context prefixes messages
 * ("encode"). Prints any error. @return an exit code.
 */
int cmdargs_parse(const cmd_spec *spec, const char *context, int argc, char **argv, uint8_t version, xf_command *cmd);

/** Usage and option details of one command. */
void cmdargs_help(const cmd_spec *spec, const char *context, FILE *out);
/** One usage line per command, for `encode --help`. */
void cmdargs_list(FILE *out);

/* "[--protocol N] [--help] COMMAND [ARGS...]", as send and encode take it. */
typedef struct cmd_line {
    uint8_t version;
    int help;
    const cmd_spec *spec; /* NULL until COMMAND */
    int cargc;            /* the command's name and arguments, --protocol and --help taken out */
    char **cargv;         /* caller's storage, argc + 1 entries */
} cmd_line;

/* argv[*i] if it is --protocol, --help, or after COMMAND one of the command's: returns 1 with
 * *rc the exit status (XFGCU_EXIT_OK, or the one-line error's), 0 when it is none of these. */
int cmd_line_take(cmd_line *c, int argc, char **argv, int *i, int *rc);

/* argv[*i] where COMMAND is due: unknown options and commands are errors named for @p who. */
int cmd_line_command(cmd_line *c, const char *who, char *arg);

#endif /* XFGCU_CMDARGS_H */
