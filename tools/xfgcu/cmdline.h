/*
 * cmdline.h - `[--protocol N] [--help] [--json OBJECT] COMMAND [ARGS]` as encode and send take it,
 * and capture's COMMAND [ARGS]: getopt_long over the options the command takes (the text layer
 * lists them: cmdargs_option()), turned into named arguments that the layer builds the
 * xf_command from (cmdargs_build()).
 */
#ifndef XFGCU_CMDLINE_H
#define XFGCU_CMDLINE_H

#include <stdio.h>

#include "cli.h"
#include "cmdargs.h"

#define CMDLINE_FORCE   1 /**< send's --force: an order the GCU's model lacks goes all the same */
#define CMDLINE_JSON    2 /**< send's --json: the result as one JSON object */
#define CMDLINE_VERBOSE 4 /**< send's --verbose: the link's health after the result */

#define CMDLINE_AUTO 0  /**< cmd_line.version of send's --protocol auto: checked for both versions, built later */
#define CMDLINE_ARGS 32 /**< named arguments of one command: more is a usage error */

typedef struct cmd_line {
    uint8_t version;  /**< the last --protocol, else the default; CMDLINE_AUTO for send's auto */
    int help;         /**< --help given (the command's arguments are then not checked) */
    const char *json; /**< encode's --json OBJECT, or NULL */
    int with_force;   /**< send: --force and --json are among its options */
    int force;        /**< send's CMDLINE_FORCE and CMDLINE_JSON */
    int has_spec;     /**< COMMAND was given: spec and cmd hold it */
    cmd_spec spec;    /**< COMMAND */
    xf_command cmd;   /**< its arguments, built (unless help); with CMDLINE_AUTO, for version 1 when they fit it */
    text_arg args[CMDLINE_ARGS]; /**< the named arguments of COMMAND, for cmd_line_build() */
    size_t nargs;
} cmd_line;

/**
 * Parse argv[1..] of encode (@p with_json) or send into @p l, with @p version as the default of
 * --protocol. With --help, prints the help of COMMAND, or @p help without one. Prints any error.
 * @return an exit code.
 */
int cmd_line_parse(cmd_line *l, const char *who, uint8_t version, int with_json, void (*help)(FILE *out), int argc,
                   char **argv);

/**
 * Build l->cmd again for protocol @p version (send with --protocol auto, once the GCU has answered:
 * its ranges and meanings), printing the notes; @p why is added to an error in brackets ("the GCU
 * answers in protocol 1"). Prints any error. @return an exit code.
 */
int cmd_line_build(cmd_line *l, uint8_t version, const char *why);

/**
 * COMMAND [ARGS] (argv[0] is COMMAND, of @p spec) with only the command's own options, as capture
 * takes it. *@p version is read once every argument is taken, so a link option after COMMAND that
 * sets it (cli_set_anywhere()) counts. Prints any error. @return an exit code.
 */
int cmd_line_command(const cmd_spec *spec, const char *who, int argc, char **argv, const uint8_t *version,
                     xf_command *cmd);

#endif /* XFGCU_CMDLINE_H */
