/*
 * cmdline.c - the command line of encode, send and capture, as named arguments (cmdline.h).
 */
#include "cmdline.h"

#include <string.h>

/* The ids of the options cli_next() returns: the command's own are ID_OPT + their index. */
#define ID_OPT      256
#define ID_PROTOCOL 'p'
#define ID_HELP     'h'
#define ID_JSON     'j'
#define ID_FORCE    'f'
#define ID_JSON_OUT 'J' /* send's --json: the result as a JSON object */
#define ID_VERBOSE  'v' /* send's --verbose: the link's health after the result */

#define MAX_OPTIONS 17 /* a command's own options, then --protocol, --help, --force, --json, --verbose */

/* The command's options for getopt_long(), --protocol and --help when @p line (encode and send
 * take them after COMMAND too), and --force, --json and --verbose when @p force (send's). */
static void command_options(const cmd_spec *spec, int line, int force, struct option *opts)
{
    static const struct option extra[] = {{"protocol", required_argument, NULL, ID_PROTOCOL},
                                          {"help", no_argument, NULL, ID_HELP},
                                          {"force", no_argument, NULL, ID_FORCE},
                                          {"json", no_argument, NULL, ID_JSON_OUT},
                                          {"verbose", no_argument, NULL, ID_VERBOSE},
                                          {NULL, 0, NULL, 0}};
    size_t i, n = 0;
    int takes_value = 0;
    const char *name;
    for (i = 0; n + 6u < MAX_OPTIONS && (name = cmdargs_option(spec, i, &takes_value)) != NULL; i++) {
        opts[n].name = name;
        opts[n].has_arg = takes_value ? required_argument : no_argument;
        opts[n].flag = NULL;
        opts[n++].val = ID_OPT + (int)i;
    }
    for (i = 0; line && i < 2u; i++) {
        opts[n++] = extra[i];
    }
    for (i = 2; force && i < 5u; i++) {
        opts[n++] = extra[i];
    }
    opts[n] = extra[5];
}

/* --protocol: encode's 1 or 2; send's auto too (@p send), as CMDLINE_AUTO. */
static int take_protocol(const cli_args *a, int send, uint8_t *version)
{
    uint8_t v = (*version == CMDLINE_AUTO) ? XF_PROTOCOL_V1 : *version, version_auto = 0;
    int rc = send ? cli_value_protocol_auto(a, &v, &version_auto) : cli_value_protocol(a, &v);
    if (rc == XFGCU_EXIT_OK) {
        *version = version_auto ? (uint8_t)CMDLINE_AUTO : v;
    }
    return rc;
}

/* The first pass over the arguments of encode and send: --protocol (the last one wins) and
 * --help, wherever they are; nothing else is checked when --help is there. */
static int take_line_options(const char *where, int argc, char **argv, const struct option *opts, uint8_t *version,
                             int *help, int *force)
{
    cli_args a;
    int id, rc = XFGCU_EXIT_OK;
    cli_args_init(&a, argc, argv, CLI_IN_ORDER "h", opts, where); /* -h: --help */
    a.quiet = 1;
    while (rc == XFGCU_EXIT_OK && (id = cli_next(&a)) != CLI_END) {
        if (id == ID_PROTOCOL) {
            rc = take_protocol(&a, force != NULL, version);
        } else if (id == ID_HELP) {
            *help = 1;
        } else if (id == ID_FORCE && force != NULL) { /* only offered with a place for it */
            *force |= CMDLINE_FORCE;
        } else if (id == ID_JSON_OUT && force != NULL) {
            *force |= CMDLINE_JSON;
        } else if (id == ID_VERBOSE && force != NULL) {
            *force |= CMDLINE_VERBOSE;
        }
    }
    return rc;
}

/* The command of @p n named arguments for protocol @p version; CMDLINE_AUTO: for the first version
 * they fit (1, else 2), without notes (the version the GCU answers in is not known yet), and
 * version 1's error when they fit neither. */
static int build_named(const cmd_spec *spec, const char *who, const text_arg *args, size_t n, uint8_t version,
                       xf_command *cmd)
{
    text_err e, e2;
    text_err_init(&e);
    if (cmdargs_build(spec, args, n, version == CMDLINE_AUTO ? XF_PROTOCOL_V1 : version, who, cmd, &e) == TEXT_OK) {
        if (version != CMDLINE_AUTO) {
            cli_text_notes(&e);
        }
        return XFGCU_EXIT_OK;
    }
    text_err_init(&e2);
    if (version == CMDLINE_AUTO && cmdargs_build(spec, args, n, XF_PROTOCOL_V2, who, cmd, &e2) == TEXT_OK) {
        return XFGCU_EXIT_OK;
    }
    return cli_text_fail(&e, NULL);
}

/* The arguments of COMMAND (argv[0]) as named pairs into @p args (CMDLINE_ARGS of them at most),
 * then the command the text layer builds of them for protocol *version, read only now: a link
 * option after COMMAND may have set it. */
static int build(const cmd_spec *spec, const char *who, const struct option *opts, const char *hint, int argc,
                 char **argv, const uint8_t *version, xf_command *cmd, text_arg *args, size_t *n)
{
    char where[64];
    cli_args a;
    int id, rc = XFGCU_EXIT_OK;
    *n = 0;
    snprintf(where, sizeof(where), "%s %s", who, spec->name);
    cli_args_init(&a, argc, argv, CLI_IN_ORDER "h", opts, where);
    a.hint = hint;
    while (rc == XFGCU_EXIT_OK && (id = cli_next(&a)) != CLI_END) {
        if (id == CLI_BAD) {
            rc = XFGCU_EXIT_USAGE; /* said */
        } else if (id == CLI_ARG) {
            rc = cli_unexpected(&a);
        } else if (id >= ID_OPT && *n == CMDLINE_ARGS) {
            rc = cli_fail_in(where, "more than %d arguments", CMDLINE_ARGS);
        } else if (id >= ID_OPT) {
            args[*n].name = a.opt->name;
            args[(*n)++].value = a.value;
        }
    }
    return (rc == XFGCU_EXIT_OK) ? build_named(spec, who, args, *n, *version, cmd) : rc;
}

int cmd_line_build(cmd_line *l, uint8_t version, const char *why)
{
    text_err e;
    text_err_init(&e);
    if (cmdargs_build(&l->spec, l->args, l->nargs, version, "send", &l->cmd, &e) != TEXT_OK) {
        cli_text_notes(&e);
        return cli_fail("%s (%s)", e.message, why);
    }
    cli_text_notes(&e);
    return XFGCU_EXIT_OK;
}

int cmd_line_command(const cmd_spec *spec, const char *who, int argc, char **argv, const uint8_t *version,
                     xf_command *cmd)
{
    struct option opts[MAX_OPTIONS];
    text_arg args[CMDLINE_ARGS];
    size_t n = 0;
    char hint[64];
    snprintf(hint, sizeof(hint), "send %s", spec->name); /* no --help after COMMAND here: send's tells */
    command_options(spec, 0, 0, opts);
    return build(spec, who, opts, hint, argc, argv, version, cmd, args, &n);
}

/* COMMAND [ARGS] of encode's or send's line (argv[0] is COMMAND). */
static int command_of_line(cmd_line *l, const char *who, int argc, char **argv)
{
    struct option opts[MAX_OPTIONS];
    char where[64];
    int rc;
    if (l->json != NULL) {
        return cli_fail("%s: --json takes one OBJECT; unexpected '%s'", who, argv[0]);
    }
    if (!cmdargs_find(argv[0], &l->spec)) {
        return cli_fail("%s: unknown command '%s' (see 'xfgcu %s --help')", who, argv[0], who);
    }
    l->has_spec = 1;
    snprintf(where, sizeof(where), "%s %s", who, l->spec.name);
    command_options(&l->spec, 1, l->with_force, opts);
    rc = take_line_options(where, argc, argv, opts, &l->version, &l->help, l->with_force ? &l->force : NULL);
    if (rc != XFGCU_EXIT_OK || l->help) {
        return rc;
    }
    return build(&l->spec, who, opts, NULL, argc, argv, &l->version, &l->cmd, l->args, &l->nargs);
}

/* --json OBJECT, --json - or --json alone (JSON Lines on stdin): the next argument is the OBJECT
 * unless it is an option ("--raw"), so that `decode --json --raw | encode --json --raw` reads. */
static int take_json(cli_args *a, const char **json)
{
    if (*json != NULL) {
        return cli_fail_in(a->context, "--json given twice");
    }
    if (a->value == NULL && optind < a->argc && strncmp(a->argv[optind], "--", 2) != 0) {
        a->value = a->argv[optind++];
    }
    *json = (a->value != NULL) ? a->value : "-";
    return XFGCU_EXIT_OK;
}

int cmd_line_parse(cmd_line *l, const char *who, uint8_t version, int with_json, void (*help)(FILE *out), int argc,
                   char **argv)
{
    static const struct option opts[] = {{"protocol", required_argument, NULL, ID_PROTOCOL},
                                         {"help", no_argument, NULL, ID_HELP},
                                         {"json", optional_argument, NULL, ID_JSON},
                                         {NULL, 0, NULL, 0},
                                         {"force", no_argument, NULL, ID_FORCE},
                                         {"json", no_argument, NULL, ID_JSON_OUT},
                                         {"verbose", no_argument, NULL, ID_VERBOSE}};
    struct option with_force[6] = {opts[0], opts[1], opts[4], opts[5], opts[6], opts[3]}; /* send's */
    cli_args a;
    int id, rest, rc = XFGCU_EXIT_OK;
    memset(l, 0, sizeof(*l));
    l->version = version;
    l->with_force = !with_json;
    cli_args_init(&a, argc, argv, CLI_STOP, with_json ? opts : with_force, who);
    while (rc == XFGCU_EXIT_OK && (id = cli_next(&a)) != CLI_END) {
        switch (id) {
        case CLI_BAD: rc = XFGCU_EXIT_USAGE; break;
        case ID_PROTOCOL: rc = take_protocol(&a, l->with_force, &l->version); break;
        case ID_HELP: l->help = 1; break;
        case ID_FORCE: l->force |= CMDLINE_FORCE; break;
        case ID_JSON_OUT: l->force |= CMDLINE_JSON; break;
        case ID_VERBOSE: l->force |= CMDLINE_VERBOSE; break;
        default: rc = take_json(&a, &l->json); break;
        }
    }
    rest = cli_rest(&a);
    if (rc == XFGCU_EXIT_OK && l->json != NULL && strcmp(l->json, "-") == 0 && rest + 1 == argc &&
        strcmp(argv[rest], "-") == 0) {
        rest++; /* `--json --raw -`: the stdin of --json, after an option */
    }
    if (rc == XFGCU_EXIT_OK && rest < argc) {
        rc = command_of_line(l, who, argc - rest, argv + rest);
    }
    if (rc == XFGCU_EXIT_OK && l->help) {
        if (l->has_spec) {
            cmdargs_help(&l->spec, who, stdout);
        } else {
            help(stdout);
        }
    }
    return rc;
}
