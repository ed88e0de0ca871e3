/*
 * cmdargs.h - the named commands of cli.md ("zoom-to --rate 5.5", ...)
 * and their arguments, turned into an xf_command.
 *
 * Shared by `encode`, `send` and `record`. The commands are the codec's
 * orders (xf_order_at, xf_order_name); this module only adds, per order,
 * which options the command line takes and how each maps onto xf_command
 * members.
 */
#ifndef XFGCU_CMDARGS_H
#define XFGCU_CMDARGS_H

#include <stdio.h>

#include "xfgcu/xfgcu.h"

typedef struct cmd_spec cmd_spec;

/** The command named @p name ("zoom-to" or "zoom_to"), or NULL. */
const cmd_spec *cmdargs_find(const char *name);
/** The command's name as typed on the command line. */
const char *cmdargs_name(const cmd_spec *spec);

#define CMDARGS_FORCE 1 /**< send's --force */
#define CMDARGS_JSON  2 /**< send's --json */

/**
 * Parse the arguments of a named command (argv[0] is its name) into @p cmd
 * and check them for protocol *@p version, as encode and send take them:
 * --protocol (into *@p version) and --help (*@p help, non-NULL; with it
 * nothing else is parsed) too, wherever they are. @p who prefixes messages
 * ("encode"). With @p force (send), --force and --json set CMDARGS_FORCE
 * and CMDARGS_JSON in *@p force. Prints any error.
 * @return an exit code.
 */
int cmdargs_parse(const cmd_spec *spec, const char *who, int argc, char **argv, uint8_t *version, int *help, int *force,
                  xf_command *cmd);

/**
 * The same for a command that takes only COMMAND's own options (record's COMMAND, Python's
 * encode). *@p version is read once every argument is taken, so a link option after COMMAND
 * that sets it (record's line: cli_set_anywhere()) counts.
 * @return an exit code.
 */
int cmdargs_parse_command(const cmd_spec *spec, const char *who, int argc, char **argv, const uint8_t *version,
                          xf_command *cmd);

/** Usage and option details of one command. */
void cmdargs_help(const cmd_spec *spec, const char *context, FILE *out);
/** One usage line per command, for `encode --help`. */
void cmdargs_list(FILE *out);

/* `who [--protocol N] [--help] [--json OBJECT] COMMAND [ARGS]`, as encode and send take it. */
/**
 * The switches of osd (--show, --hide) are parsed with V0.1's values (0
 * shows); give @p cmd the value that means the same for a GCU that speaks
 * @p version (xf_osd_value()). Other commands are left alone.
 */
void cmdargs_for_version(xf_command *cmd, uint8_t version);

typedef struct cmd_line {
    uint8_t version;      /* the last --protocol, else the default */
    int help;             /* --help given (the command's arguments are then not parsed) */
    const char *json;     /* encode's --json OBJECT, or NULL */
    int with_force;       /* send: --force is one of its options */
    int force;            /* send's CMDARGS_FORCE (--force: an order the GCU's model lacks goes all the same)
                             and CMDARGS_JSON (--json: the result as one JSON object) */
    const cmd_spec *spec; /* COMMAND, or NULL */
    xf_command cmd;       /* its arguments, parsed (unless help) */
} cmd_line;

/**
 * Parse argv[1..] of encode (@p with_json) or send into @p l, with
 * @p version as the default of --protocol. With --help, prints the help of
 * COMMAND, or @p help without one. Prints any error. @return an exit code.
 */
int cmd_line_parse(cmd_line *l, const char *who, uint8_t version, int with_json, void (*help)(FILE *out), int argc,
                   char **argv);

#endif /* XFGCU_CMDARGS_H */
