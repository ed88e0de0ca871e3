/*
 * cmdargs.h - the named commands of docs/cli.md ("zoom-to --factor 5.5", ...) and their
 * arguments, turned into an xf_command.
 *
 * The commands are the codec's orders (xf_order_at, xf_order_name); this module adds, per order,
 * which arguments it takes and how each maps onto xf_command members. Arguments come as named
 * pairs ({"factor", "5.5"}, {"show", NULL}): a program builds them from its own command line, a
 * binding from its keyword arguments; nothing here parses argv or keeps state.
 */
#ifndef XFGCU_CMDARGS_H
#define XFGCU_CMDARGS_H

#include <stddef.h>
#include <stdio.h>

#include "text_err.h"
#include "xfgcu/xfgcu.h"

struct cmd_extra;

/** A command: the codec's row of its order, and what this module adds. Filled by cmdargs_find(). */
typedef struct cmd_spec {
    const xf_order_info *info;     /**< the codec's row */
    const struct cmd_extra *extra; /**< the arguments it takes */
    char name[32];                 /**< as typed: the canonical name with '-' for '_' ("zoom-to") */
} cmd_spec;

/** One named argument: its name without "--" ("factor", "cameras"), and its value as text (NULL for a switch). */
typedef struct text_arg {
    const char *name;
    const char *value;
} text_arg;

/** The command named @p name ("zoom-to" or "zoom_to") into @p spec. @return 1, or 0 when there is none. */
int cmdargs_find(const char *name, cmd_spec *spec);
/** The @p i-th command, in the order of the codec's table, into @p spec. @return 1, or 0 past the last. */
int cmdargs_at(size_t i, cmd_spec *spec);

/** How many arguments the command takes by name: its own, "cameras" where it takes a mask, old spellings. */
size_t cmdargs_option_count(const cmd_spec *spec);
/** The @p i-th of them ("box"), and whether it takes a value (*@p takes_value); NULL past the last. */
const char *cmdargs_option(const cmd_spec *spec, size_t i, int *takes_value);

/** What one argument takes, for a binding that checks its values before it builds (cmdargs_option_info()). */
typedef struct cmdargs_info {
    const char *name;  /**< without "--" ("factor"); an old spelling ("rate") is an entry of its own */
    unsigned values;   /**< 0: a switch; 1: one value; 2 or 4: that many integers, comma-separated */
    int real;          /**< 1: a decimal number; 0: integers, a word or cameras */
    const char *words; /**< the '|'-separated words it takes ("off|on|auto"), or NULL */
    int cameras;       /**< 1: the cameras (numbers, a hex mask or "all": cmdargs_build checks the text) */
    double lo, hi;     /**< each value's range; the codec may narrow it by version (palette, pip) */
    const char *field; /**< the xf_command member it sets (the first of several): xf_field_name() */
    const char *help;  /**< what it means and accepts, one line */
} cmdargs_info;

/** The @p i-th argument of cmdargs_option(), described into @p info. @return 1, or 0 past the last. */
int cmdargs_option_info(const cmd_spec *spec, size_t i, cmdargs_info *info);

/**
 * Build @p cmd from @p n named arguments, checked for protocol @p version: each argument against
 * what it accepts, their combination (--start needs --box), then the codec's own ranges. An
 * order of another version than @p version is a note in @p e, not an error. @p who prefixes the
 * messages with the command's name ("encode" gives "encode zoom-to: ..."; NULL: the name alone).
 * @return TEXT_OK, or TEXT_BAD with @p e saying why.
 */
int cmdargs_build(const cmd_spec *spec, const text_arg *args, size_t n, uint8_t version, const char *who,
                  xf_command *cmd, text_err *e);

/**
 * The switches of osd (--show, --hide) are built with V0.1's values (0 shows); give @p cmd the
 * value that means the same for a GCU that speaks @p version (xf_osd_value()). Other commands
 * are left alone.
 */
void cmdargs_for_version(xf_command *cmd, uint8_t version);

/** Usage and argument details of one command; @p context is what comes before its name ("encode"). */
void cmdargs_help(const cmd_spec *spec, const char *context, FILE *out);
/** One usage line per command, for `encode --help` and `send --help`. */
void cmdargs_list(FILE *out);

#endif /* XFGCU_CMDARGS_H */
