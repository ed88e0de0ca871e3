/*
 * args.c - every option loop of the program: getopt_long() through cli_next() (cli.h), which
 * adds the program's own rules (whole long names only, no clusters) and one-line messages, and
 * the checked values of options.
 */
#include <string.h>

#include "cli.h"
#include "xfgcu/posix/xf_posix.h" /* xf_serial_baud_ok() */

/* ---- options ------------------------------------------------------------- */

void cli_args_init(cli_args *a, int argc, char **argv, const char *optstring, const struct option *opts,
                   const char *context)
{
    memset(a, 0, sizeof(*a));
    a->argc = argc;
    a->argv = argv;
    a->optstring = optstring;
    a->opts = opts;
    a->context = context;
    optind = 0; /* glibc: a new scan from argv[1], its state reset */
    opterr = 0; /* getopt prints nothing: the errors are ours */
}

/* The row that "--name" or "--name=VALUE" names exactly, or NULL. */
static const struct option *long_option(const struct option *opts, const char *text)
{
    size_t n = strcspn(text + 2, "=");
    if (strncmp(text, "--", 2) != 0) {
        return NULL;
    }
    for (; opts->name != NULL; opts++) {
        if (strlen(opts->name) == n && strncmp(opts->name, text + 2, n) == 0) {
            return opts;
        }
    }
    return NULL;
}

/* An unknown option (@p o NULL), or a value given to option @p o, which takes none. */
static int bad_option(const cli_args *a, const char *text, const struct option *o)
{
    const char *hint = (a->hint != NULL) ? a->hint : a->context;
    if (a->quiet) {
        return CLI_BAD;
    }
    if (o != NULL) {
        (void)cli_fail_in(a->context, "--%s takes no value", o->name);
    } else if (hint == NULL) {
        (void)cli_fail("unknown option '%s' (try 'xfgcu --help')", text);
    } else {
        (void)cli_fail_in(a->context, "unknown option '%s' (see 'xfgcu %s --help')", text, hint);
    }
    return CLI_BAD;
}

/* The options taken anywhere on the line (main.c's link options), when a command has no option
 * of that name: cli_set_anywhere(). */
static const struct option *anywhere_opts;
static cli_anywhere_fn anywhere_take;

void cli_set_anywhere(const struct option *opts, cli_anywhere_fn take)
{
    anywhere_opts = opts;
    anywhere_take = take;
}

/* argv[a->index] is not an option of this loop: one of the anywhere options? Then take it (its
 * value "--name=V" or the next argument) and return 1, or CLI_BAD when its value is bad. */
static int taken_anywhere(cli_args *a, const char *text)
{
    const struct option *o = (anywhere_opts != NULL) ? long_option(anywhere_opts, text) : NULL;
    const char *eq = strchr(text, '=');
    cli_args g;
    if (o == NULL || anywhere_take == NULL) {
        return 0;
    }
    g = *a;
    g.opt = o;
    g.value = (eq != NULL) ? eq + 1 : NULL;
    if (o->has_arg == no_argument && eq != NULL) {
        return bad_option(a, text, o);
    }
    if (o->has_arg == required_argument && eq == NULL && optind < a->argc) {
        g.value = a->argv[optind++];
    }
    if (a->quiet) {
        return 1; /* a pass that only looks: skip it, value and all */
    }
    return (anywhere_take(&g, o->val) == XFGCU_EXIT_OK) ? 1 : CLI_BAD;
}

/* getopt_long() returned @p id for argv[a->index]: the option, if its whole name was given. */
static int checked_option(cli_args *a, int id)
{
    const char *text = a->argv[a->index];
    const struct option *o = long_option(a->opts, text);
    if (text[1] != '-') { /* a short option: alone, not in a cluster */
        if (id == '?' || id == ':' || text[2] != '\0') {
            return bad_option(a, text, NULL);
        }
        for (o = a->opts; o->name != NULL && o->val != id; o++) {
        }
        a->opt = o; /* its long form (-h: --help) */
        return id;
    }
    if (o == NULL || (id != '?' && id != ':' && id != o->val)) {
        return bad_option(a, text, NULL); /* unknown, ambiguous or abbreviated */
    }
    if (id == '?') {
        return bad_option(a, text, o); /* "--name=VALUE" for an option without a value */
    }
    a->opt = o; /* id ':' (the value is missing) comes back as the option, with no value */
    return o->val;
}

/* cli_next() without the anywhere options it takes (0: one was taken, look again). */
static int next_once(cli_args *a)
{
    int id;
    a->opt = NULL;
    a->value = NULL;
    if (a->tail == 0) {
        a->index = (optind > 0) ? optind : 1; /* no permutation: getopt reads argv[optind] */
        id = getopt_long(a->argc, a->argv, a->optstring, a->opts, NULL);
        if (id != -1) {
            const char *text = a->argv[a->index];
            int took;
            a->value = optarg;
            if (id == CLI_ARG) {
                return CLI_ARG;
            }
            if (id == '?' && long_option(a->opts, text) == NULL && (took = taken_anywhere(a, text)) != 0) {
                return (took == CLI_BAD) ? CLI_BAD : 0; /* taken: on to the next */
            }
            return checked_option(a, id);
        }
        a->tail = optind; /* CLI_STOP: COMMAND; CLI_IN_ORDER: what follows "--" */
    }
    if (a->optstring[0] != '-' || a->tail >= a->argc) {
        return CLI_END;
    }
    a->index = a->tail++;
    a->value = a->argv[a->index];
    return CLI_ARG;
}

int cli_next(cli_args *a)
{
    int id;
    while ((id = next_once(a)) == 0) {
    }
    return id;
}

void cli_optional_next(cli_args *a)
{
    if (a->value == NULL && optind < a->argc && a->argv[optind][0] != '-') {
        a->value = a->argv[optind++];
    }
}

int cli_rest(const cli_args *a) { return a->tail; }

int cli_unexpected(const cli_args *a)
{
    return cli_fail_in(a->context, "unexpected argument '%s' (see 'xfgcu %s --help')", a->value,
                       (a->hint != NULL) ? a->hint : a->context);
}

/* The value is there, and the option was not given before. */
static int value_given(const cli_args *a, const char *what, int *given)
{
    if (given != NULL && *given) {
        return cli_fail_in(a->context, "--%s given twice", a->opt->name);
    }
    if (given != NULL) {
        *given = 1;
    }
    if (a->value == NULL || a->value[0] == '\0') {
        return cli_fail_in(a->context, "--%s needs a value: %s", a->opt->name, what);
    }
    return XFGCU_EXIT_OK;
}

static int value_not(const cli_args *a, const char *what)
{
    return cli_fail_in(a->context, "--%s %s: must be %s", a->opt->name, a->value, what);
}

int cli_value_real(const cli_args *a, double lo, double hi, const char *what, double *out, int *given)
{
    int rc = value_given(a, what, given);
    if (rc == XFGCU_EXIT_OK && (text_parse_real(a->value, out) != 0 || *out < lo || *out > hi)) {
        rc = value_not(a, what);
    }
    return rc;
}

int cli_value_long(const cli_args *a, long lo, long hi, const char *what, long *out, int *given)
{
    long long v = 0;
    int rc = value_given(a, what, given);
    if (rc == XFGCU_EXIT_OK && (text_parse_int(a->value, &v) != 0 || v < lo || v > hi)) {
        rc = value_not(a, what);
    }
    if (rc == XFGCU_EXIT_OK) {
        *out = (long)v;
    }
    return rc;
}

int cli_value_text(const cli_args *a, const char *what, const char **out)
{
    int rc = value_given(a, what, NULL);
    if (rc == XFGCU_EXIT_OK) {
        *out = a->value;
    }
    return rc;
}

int cli_value_protocol(const cli_args *a, uint8_t *version)
{
    long v = 0;
    int rc = cli_value_long(a, XF_PROTOCOL_V1, XF_PROTOCOL_V2, "1 or 2", &v, NULL);
    if (rc == XFGCU_EXIT_OK) {
        *version = (uint8_t)v;
    }
    return rc;
}

int cli_value_protocol_auto(const cli_args *a, uint8_t *version, uint8_t *version_auto)
{
    long v = 0;
    int rc;
    if (a->value != NULL && strcmp(a->value, "auto") == 0) {
        *version_auto = 1u;
        return XFGCU_EXIT_OK;
    }
    rc = cli_value_long(a, XF_PROTOCOL_V1, XF_PROTOCOL_V2, "auto, 1 or 2", &v, NULL);
    if (rc == XFGCU_EXIT_OK) {
        *version = (uint8_t)v;
        *version_auto = 0u;
    }
    return rc;
}

int cli_value_baud(const cli_args *a, long *baud, int *given)
{
    static const char what[] = "115200, 250000, 500000 or 1000000";
    int rc = cli_value_long(a, 1, 100000000L, what, baud, given);
    if (rc == XFGCU_EXIT_OK && !xf_serial_baud_ok((uint32_t)*baud)) {
        rc = cli_fail_in(a->context, "--baud %s: must be %s", a->value, what);
    }
    return rc;
}
