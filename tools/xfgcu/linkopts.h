/*
 * linkopts.h - the options before COMMAND (docs/cli.md "Link options", "General options"): their
 * table for getopt_long, taking each one, the checks of their combination and timing, and the
 * link spec they name: --link SPEC and XFGCU_LINK with the grammar of xf_link_open()
 * (xfgcu/posix/xf_link.h, whose parser reads them), or --serial PATH, --udp HOST[:PORT],
 * --tcp HOST[:PORT] with --baud, --gcu-port and --local-port.
 *
 * One module: main.c and online.c call it, it calls neither.
 */
#ifndef XFGCU_LINKOPTS_H
#define XFGCU_LINKOPTS_H

#include <stdio.h>

#include "cli.h"
#include "xfgcu/posix/xf_link.h"

/** getopt ids of the options before COMMAND: --help and --version first, then those taken anywhere. */
enum {
    LO_HELP = 'h',
    LO_VERSION = 256,
    LO_SERIAL,
    LO_BAUD,
    LO_UDP,
    LO_TCP,
    LO_LINK,
    LO_GCU_PORT,
    LO_LOCAL_PORT,
    LO_PROTOCOL,
    LO_RATE,
    LO_TIMEOUT,
    LO_REORDER,
    LO_TRACE,
    LO_RAW
};

/** The options before COMMAND; from the third on (linkopts_table() + 2), they are taken after COMMAND too. */
const struct option *linkopts_table(void);

/** The defaults, with @p env_spec the value of XFGCU_LINK (NULL or empty: none). */
void linkopts_defaults(cli_link *l, const char *env_spec);

/** One option, as cli_next() returned it. @return an exit code. */
int linkopts_take(cli_link *l, const cli_args *a, int id);

/** Options that contradict each other (two links, --baud with a network link...): the usage error, or OK. */
int linkopts_check(const cli_link *l);

/**
 * --rate, --timeout and --reorder that cannot work together (the link reads stale between two
 * replies, or a timeout is shorter than a round trip): the usage error naming the option to
 * change, or OK.
 */
int linkopts_check_timing(const cli_link *l);

/** Does a link option (or XFGCU_LINK) name a link? Prints the usage error if not. @return an exit code. */
int linkopts_require(const cli_link *l, const char *context);

/**
 * The spec of the link the options name, and the option that named it for messages ("--tcp
 * 127.0.0.1:2332", "--link udp:...", "XFGCU_LINK=serial:..."). A bad spec is a usage error.
 * @return an exit code
 */
int linkopts_spec(const cli_link *l, xf_link_spec *spec, char *option, size_t cap);

#endif /* XFGCU_LINKOPTS_H */
