/*
 * cmdargs.c - numbers, options, and the arguments of every named command.
 *
 * Options: every loop of the program is getopt_long() through cli_next()
 * (cli.h), which adds the program's own one-line messages.
 *
 * Commands: one per order of the codec's table (xf_order_at), named by the
 * codec (xf_order_name, '-' for '_'). The command line adds, per order, the
 * options it takes and how each maps onto xf_command members (kind + first
 * member), and how they combine:
 *   OPT_REQUIRED  must be given;
 *   OPT_CHOICE    exactly one of the command's CHOICE options is given
 *                 (--start | --stop, --rate | --fraction, --on | --off);
 *                 a choice may need other options (--start needs --box),
 *                 which are then refused with the other choices.
 * Values are checked twice: here against what the option accepts (so
 * nothing is silently saturated by xf_command_set), then by the codec's
 * xf_command_check, whose bad_field is mapped back to the option.
 */
#include "cmdargs.h"

#include <ctype.h>
#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"

/* ---- numbers ------------------------------------------------------------- */

int cli_parse_int(const char *s, long long *out)
{
    const char *p = s;
    int neg = 0, base = 10;
    char *end = NULL;
    unsigned long long u;
    if (*p == '+' || *p == '-') {
        neg = (*p == '-');
        p++;
    }
    if (p[0] == '0' && (p[1] == 'x' || p[1] == 'X')) {
        base = 16;
        p += 2;
    }
    /* strtoull would also take spaces and a second sign: only digits may follow */
    if (!((*p >= '0' && *p <= '9') || (base == 16 && ((*p >= 'a' && *p <= 'f') || (*p >= 'A' && *p <= 'F'))))) {
        return -1;
    }
    errno = 0;
    u = strtoull(p, &end, base);
    if (errno != 0 || *end != '\0') {
        return -1;
    }
    if (neg) {
        if (u > (unsigned long long)LLONG_MAX + 1u) {
            return -1;
        }
        *out = (u == (unsigned long long)LLONG_MAX + 1u) ? LLONG_MIN : -(long long)u;
    } else {
        if (u > (unsigned long long)LLONG_MAX) {
            return -1;
        }
        *out = (long long)u;
    }
    return 0;
}

int cli_parse_real(const char *s, double *out)
{
    char *end = NULL;
    double v;
    if (!((*s >= '0' && *s <= '9') || *s == '-' || *s == '+' || *s == '.')) {
        return -1; /* no leading space, no "nan" or "inf" */
    }
    errno = 0;
    v = strtod(s, &end);
    if (errno != 0 || end == s || *end != '\0' || !isfinite(v)) {
        return -1;
    }
    *out = v;
    return 0;
}

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
    if (rc == XFGCU_EXIT_OK && (cli_parse_real(a->value, out) != 0 || *out < lo || *out > hi)) {
        rc = value_not(a, what);
    }
    return rc;
}

int cli_value_long(const cli_args *a, long lo, long hi, const char *what, long *out, int *given)
{
    long long v = 0;
    int rc = value_given(a, what, given);
    if (rc == XFGCU_EXIT_OK && (cli_parse_int(a->value, &v) != 0 || v < lo || v > hi)) {
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

/* ---- the commands: the codec's orders, with options ---------------------- */

typedef enum opt_kind {
    K_SWITCH,    /* no value: stores `lo` in the member */
    K_INT,       /* integer in [lo, hi] */
    K_WORD,      /* one of the '|'-separated words of `meta`: stores its index */
    K_POINT,     /* X,Y: two consecutive members, each in [lo, hi] */
    K_BOX,       /* X0,Y0,X1,Y1: four consecutive members, each in [lo, hi] */
    K_OFFSET,    /* DX,DY: two consecutive members, each in [lo, hi] */
    K_DEG,       /* degrees in [lo, hi] -> 1e-7 deg */
    K_METRES,    /* metres in [lo, hi] -> mm */
    K_ZOOM_RATE, /* zoom rate in [lo, hi] -> ZZ = -(rate x 10) */
    K_TENTHS     /* degC in [lo, hi] -> 0.1 degC */
} opt_kind;

#define OPT_REQUIRED   0x01u
#define OPT_CHOICE     0x02u
#define OPT_BY_VERSION 0x04u /* the codec's range depends on the protocol version */

typedef struct opt_spec {
    const char *name;
    uint8_t kind;     /* opt_kind */
    uint8_t field;    /* xf_field: the (first) member set */
    uint8_t flags;    /* OPT_* */
    uint8_t needs;    /* CHOICE: bit i = option i of the row goes with this choice */
    double lo, hi;    /* accepted range; K_SWITCH: lo is the value stored */
    const char *meta; /* value placeholder in usage; K_WORD: the words */
    const char *help; /* what it means and accepts (also quoted in range errors) */
} opt_spec;

#define MAX_OPTS 4

/* What the command line adds to an order of the codec: its options, and a line of help. */
typedef struct cmd_extra {
    uint8_t nopts;
    const opt_spec *opts;
    const char *summary;
} cmd_extra;

#define NEED(i) ((uint8_t)(1u << (i)))
#define SWITCH(nm, v, needs, what)                                                                                     \
    {                                                                                                                  \
        nm, K_SWITCH, XF_F_VALUE, OPT_CHOICE, needs, v, v, NULL, what                                                  \
    }
#define OPTS(a) (uint8_t)(sizeof(a) / sizeof((a)[0])), a
#define NO_OPTS 0, NULL

#define GRID_BOX   "box corners on the 0..10000 screen grid, X0 <= X1 and Y0 <= Y1"
#define GRID_POINT "a point on the 0..10000 screen grid"

static const opt_spec gaze_geo_opts[] = {
    {"--lat", K_DEG, XF_F_LATITUDE, OPT_REQUIRED, 0, -90, 90, "DEG", "latitude, -90..90 degrees"},
    {"--lon", K_DEG, XF_F_LONGITUDE, OPT_REQUIRED, 0, -180, 180, "DEG", "longitude, -180..180 degrees"},
    {"--alt", K_METRES, XF_F_ALTITUDE, OPT_REQUIRED, 0, -2147483, 2147483, "M", "altitude, -2147483..2147483 m"},
};
static const opt_spec track_opts[] = {
    SWITCH("--start", 1, NEED(2), "start tracking the target in the box"),
    SWITCH("--stop", 0, 0, "stop tracking"),
    {"--box", K_BOX, XF_F_X0, 0, 0, 0, XF_GRID_MAX, "X0,Y0,X1,Y1", GRID_BOX},
};
static const opt_spec click_opts[] = {
    {"--at", K_POINT, XF_F_X0, OPT_REQUIRED, 0, 0, XF_GRID_MAX, "X,Y", GRID_POINT},
};
static const opt_spec external_track_opts[] = {
    SWITCH("--start", 2, NEED(2), "track (streamed: send it with each new offset)"),
    SWITCH("--stop", 0, 0, "stop tracking"),
    {"--offset", K_OFFSET, XF_F_DX, 0, 0, INT16_MIN, INT16_MAX, "DX,DY",
     "target offset from the screen centre, -1024..1024 each; both >= 3071: target lost"},
};
static const opt_spec zoom_to_opts[] = {
    {"--rate", K_ZOOM_RATE, XF_F_ZOOM, OPT_CHOICE, 0, 1.0, 3276.8, "R", "zoom rate 1.0..3276.8 (5.5 = 5.5x)"},
    {"--fraction", K_INT, XF_F_ZOOM, OPT_CHOICE, 0, 1, 10000, "N", "fraction of the zoom range, 1 (min)..10000 (max)"},
};
static const opt_spec palette_opts[] = {
    {"--mode", K_INT, XF_F_VALUE, OPT_REQUIRED | OPT_BY_VERSION, 0, 0, 255, "N",
     "palette 0..100 (protocol 1) or 0..10 (protocol 2); 0 = next palette"},
};
static const opt_spec night_vision_opts[] = {
    {"--mode", K_WORD, XF_F_VALUE, OPT_REQUIRED, 0, 0, 2, "off|on|auto", "night vision off, on or auto"},
};
static const opt_spec osd_opts[] = {
    SWITCH("--show", 0, 0, "show the OSD"),
    SWITCH("--hide", 1, 0, "hide the OSD"),
};
static const opt_spec pip_opts[] = {
    {"--mode", K_INT, XF_F_VALUE, OPT_REQUIRED | OPT_BY_VERSION, 0, 0, 255, "N",
     "0 = next view (protocol 1); 0..4 (protocol 2): 0 = next, 1..4 = go to mode N"},
};
static const opt_spec lighting_opts[] = {
    {"--level", K_INT, XF_F_VALUE, OPT_REQUIRED, 0, 0, 255, "N",
     "light intensity 0..255 (light on also turns night vision on)"},
};
static const opt_spec ranging_opts[] = {
    SWITCH("--on", 2, 0, "continuous laser ranging on"),
    SWITCH("--off", 0, 0, "laser ranging off"),
};
static const opt_spec osd_coordinate_opts[] = {
    SWITCH("--carrier", 0, 0, "the OSD shows the carrier's coordinates"),
    SWITCH("--target", 1, 0, "the OSD shows the target's coordinates"),
};
static const opt_spec auto_flip_opts[] = {
    SWITCH("--on", 0, 0, "image auto-flip on"),
    SWITCH("--off", 1, 0, "image auto-flip off"),
};
static const opt_spec time_zone_opts[] = {
    {"--hours", K_INT, XF_F_HOURS, OPT_REQUIRED, 0, -12, 14, "N", "hours from UTC, -12..14"},
};
static const opt_spec area_temp_opts[] = {
    SWITCH("--on", 1, NEED(2), "measure the temperature in the box"),
    SWITCH("--off", 0, 0, "stop measuring"),
    {"--box", K_BOX, XF_F_X0, 0, 0, 0, XF_GRID_MAX, "X0,Y0,X1,Y1", GRID_BOX},
};
static const opt_spec temp_alarm_opts[] = {
    SWITCH("--on", 1, NEED(2) | NEED(3), "alarm outside [--low, --high]"),
    SWITCH("--off", 0, 0, "alarm off"),
    {"--high", K_TENTHS, XF_F_TEMP_HIGH, 0, 0, -3276.8, 3276.7, "C", "high threshold, -3276.8..3276.7 degC"},
    {"--low", K_TENTHS, XF_F_TEMP_LOW, 0, 0, -3276.8, 3276.7, "C",
     "low threshold, -3276.8..3276.7 degC, not above --high"},
};
static const opt_spec isotherm_opts[] = {
    SWITCH("--on", 1, NEED(2) | NEED(3), "isotherm on: highlight [--low, --high]"),
    SWITCH("--off", 0, 0, "isotherm off"),
    {"--high", K_TENTHS, XF_F_TEMP_HIGH, 0, 0, -3276.8, 3276.7, "C", "top of the range, -3276.8..3276.7 degC"},
    {"--low", K_TENTHS, XF_F_TEMP_LOW, 0, 0, -3276.8, 3276.7, "C",
     "bottom of the range, -3276.8..3276.7 degC, not above --high"},
};
static const opt_spec spot_temp_opts[] = {
    SWITCH("--on", 1, NEED(2), "measure the temperature at the point"),
    SWITCH("--off", 0, 0, "stop measuring"),
    {"--at", K_POINT, XF_F_X0, 0, 0, 0, XF_GRID_MAX, "X,Y", GRID_POINT},
};
static const opt_spec on_off_opts[] = {
    SWITCH("--on", 1, 0, "on"),
    SWITCH("--off", 0, 0, "off"),
};

/*
 * Per order of the codec (xf_order_lookup), by its code: the options and the
 * summary. The names, the parameters, their order and defaults are the
 * codec's; an order it adds gets a command at once, without options until
 * it has a row here (the tests check that every order has one).
 */
static const cmd_extra extras[256] = {
    [XF_ORDER_NULL] = {NO_OPTS, "the null order: goes between two commands of the same order"},
    [XF_ORDER_CALIBRATION] = {NO_OPTS, "calibrate the gimbal (keep it still)"},
    [XF_ORDER_NEUTRAL] = {NO_OPTS, "back to neutral without changing mode"},
    [XF_ORDER_OSD_COORDINATE] = {OPTS(osd_coordinate_opts), "which coordinates the OSD shows"},
    [XF_ORDER_AUTO_FLIP] = {OPTS(auto_flip_opts), "image auto-flip on or off"},
    [XF_ORDER_TIME_ZONE] = {OPTS(time_zone_opts), "set the GCU's time zone"},
    [XF_ORDER_ANGLE_CONTROL] = {NO_OPTS, "angle control mode (\"FPV\" in V2.0.4)"},
    [XF_ORDER_HEAD_LOCK] = {NO_OPTS, "head lock mode"},
    [XF_ORDER_HEAD_FOLLOW] = {NO_OPTS, "head follow mode"},
    [XF_ORDER_ORTHOVIEW] = {NO_OPTS, "orthoview mode: pitch locked at -90 degrees"},
    [XF_ORDER_EULER] = {NO_OPTS, "Euler angle control mode"},
    [XF_ORDER_GAZE_GEO] = {OPTS(gaze_geo_opts), "point at a geo-coordinate (needs carrier INS data)"},
    [XF_ORDER_GAZE_LOCK] = {NO_OPTS, "keep aiming at the point now in the centre (needs carrier INS data)"},
    [XF_ORDER_TRACK] = {OPTS(track_opts), "track a target with the gimbal's image processor"},
    [XF_ORDER_CLICK_TO_AIM] = {OPTS(click_opts), "aim at a point of the picture"},
    [XF_ORDER_EXTERNAL_TRACK] = {OPTS(external_track_opts), "track with offsets from an external detector"},
    [XF_ORDER_FPV] = {NO_OPTS, "FPV mode: control quantities relative to the carrier"},
    [XF_ORDER_SHUTTER] = {NO_OPTS, "take a picture"},
    [XF_ORDER_RECORD] = {NO_OPTS, "start or stop recording (toggle)"},
    [XF_ORDER_ZOOM_IN] = {NO_OPTS, "zoom in continuously"},
    [XF_ORDER_ZOOM_OUT] = {NO_OPTS, "zoom out continuously"},
    [XF_ORDER_ZOOM_STOP] = {NO_OPTS, "stop zooming"},
    [XF_ORDER_ZOOM_TO] = {OPTS(zoom_to_opts), "zoom to a rate or to a fraction of the zoom range"},
    [XF_ORDER_FOCUS] = {NO_OPTS, "focus"},
    [XF_ORDER_PALETTE] = {OPTS(palette_opts), "choose the thermal palette"},
    [XF_ORDER_NIGHT_VISION] = {OPTS(night_vision_opts), "night vision off, on or auto"},
    [XF_ORDER_AREA_TEMP] = {OPTS(area_temp_opts), "area temperature measurement"},
    [XF_ORDER_TEMP_ALARM] = {OPTS(temp_alarm_opts), "temperature alarm"},
    [XF_ORDER_ISOTHERM] = {OPTS(isotherm_opts), "isotherm (in-range highlighting)"},
    [XF_ORDER_SPOT_TEMP] = {OPTS(spot_temp_opts), "spot temperature measurement"},
    [XF_ORDER_OSD] = {OPTS(osd_opts), "show or hide the OSD"},
    [XF_ORDER_PIP] = {OPTS(pip_opts), "picture-in-picture view"},
    [XF_ORDER_TARGET_DETECTION] = {OPTS(on_off_opts), "target detection on or off"},
    [XF_ORDER_DIGITAL_ZOOM] = {OPTS(on_off_opts), "digital zoom of the zoom camera on or off"},
    [XF_ORDER_LIGHTING] = {OPTS(lighting_opts), "set the light's intensity"},
    [XF_ORDER_RANGING] = {OPTS(ranging_opts), "laser ranging on or off"},
};

/* ---- the commands, from the codec's table --------------------------------- */

struct cmd_spec {
    const xf_order_info *info; /* the codec's row */
    const cmd_extra *extra;    /* what the command line adds */
    char name[32];             /* as typed: the canonical name with '-' for '_' */
};

/* The commands in the order of the codec's table, named once. */
static const cmd_spec *spec_at(size_t i)
{
    static cmd_spec specs[XF_ORDER_COUNT];
    static int named = 0;
    size_t k, n;
    for (k = 0; !named && k < XF_ORDER_COUNT; k++) {
        const char *name = xf_order_name(xf_order_at(k)->order);
        specs[k].info = xf_order_at(k);
        specs[k].extra = &extras[specs[k].info->order];
        for (n = 0; name[n] != '\0' && n + 1u < sizeof(specs[k].name); n++) {
            specs[k].name[n] = (name[n] == '_') ? '-' : name[n];
        }
    }
    named = 1;
    return (i < XF_ORDER_COUNT) ? &specs[i] : NULL;
}

const cmd_spec *cmdargs_find(const char *name)
{
    uint8_t order;
    size_t i;
    if (xf_order_from_name(name, &order) != XF_OK) {
        return NULL;
    }
    for (i = 0; spec_at(i) != NULL; i++) {
        if (spec_at(i)->info->order == order) {
            return spec_at(i);
        }
    }
    return NULL;
}

const char *cmdargs_name(const cmd_spec *spec) { return spec->name; }

/* ---- usage text --------------------------------------------------------- */

static int takes_cameras(const cmd_spec *spec)
{
    size_t i;
    for (i = 0; i < spec->info->nfields; i++) {
        if (spec->info->fields[i] == XF_F_CAMERAS) {
            return 1;
        }
    }
    return 0;
}

static void append(char *buf, size_t cap, const char *s)
{
    size_t n = strlen(buf);
    if (n + 1u < cap) {
        snprintf(buf + n, cap - n, "%s", s);
    }
}

static void append_opt(char *buf, size_t cap, const opt_spec *o)
{
    append(buf, cap, o->name);
    if (o->meta != NULL) {
        append(buf, cap, " ");
        append(buf, cap, o->meta);
    }
}

/* "--start --box X0,Y0,X1,Y1 | --stop" (with @p sep " | ") */
static void choices_text(const cmd_spec *spec, const char *sep, char *buf, size_t cap)
{
    size_t i, k;
    int first = 1;
    buf[0] = '\0';
    for (i = 0; i < spec->extra->nopts; i++) {
        const opt_spec *o = &spec->extra->opts[i];
        if ((o->flags & OPT_CHOICE) == 0u) {
            continue;
        }
        append(buf, cap, first ? "" : sep);
        append_opt(buf, cap, o);
        for (k = 0; k < spec->extra->nopts; k++) {
            if ((o->needs & NEED(k)) != 0u) {
                append(buf, cap, " ");
                append_opt(buf, cap, &spec->extra->opts[k]);
            }
        }
        first = 0;
    }
}

static void usage_text(const cmd_spec *spec, char *buf, size_t cap)
{
    size_t i;
    char choices[256];
    buf[0] = '\0';
    choices_text(spec, " | ", choices, sizeof(choices));
    if (choices[0] != '\0') {
        append(buf, cap, "(");
        append(buf, cap, choices);
        append(buf, cap, ")");
    }
    for (i = 0; i < spec->extra->nopts; i++) {
        if ((spec->extra->opts[i].flags & OPT_REQUIRED) != 0u) {
            append(buf, cap, buf[0] != '\0' ? " " : "");
            append_opt(buf, cap, &spec->extra->opts[i]);
        }
    }
    if (takes_cameras(spec)) {
        append(buf, cap, buf[0] != '\0' ? " [--cameras CAMS]" : "[--cameras CAMS]");
    }
}

void cmdargs_help(const cmd_spec *spec, const char *context, FILE *out)
{
    const xf_order_info *info = spec->info;
    const char *summary = spec->extra->summary;
    size_t i, nparams = xf_order_params_len(info->order);
    char usage[512];
    usage_text(spec, usage, sizeof(usage));
    fprintf(out, "usage: xfgcu %s [--protocol 1|2] %s%s%s\n\n", context, spec->name, usage[0] != '\0' ? " " : "",
            usage);
    if (summary != NULL) {
        fprintf(out, "%c%s.\n", toupper((unsigned char)summary[0]), summary + 1);
    }
    fprintf(out, "order 0x%02X %s, protocol %u%s", info->order, xf_order_name(info->order), (unsigned)info->since,
            info->since > 1u ? " (V0.2) and later" : " and later");
    fprintf(out, "; %zu parameter byte%s.\n", nparams, nparams == 1u ? "" : "s");
    if (spec->extra->nopts > 0u || takes_cameras(spec)) {
        fprintf(out, "\noptions:\n");
    }
    for (i = 0; i < spec->extra->nopts; i++) {
        char left[64] = "";
        append_opt(left, sizeof(left), &spec->extra->opts[i]);
        fprintf(out, "  %-22s %s\n", left, spec->extra->opts[i].help);
    }
    if (takes_cameras(spec)) {
        fprintf(out, "  %-22s cameras: numbers (1, or 1,2 = 0x03), a hex mask (0x03) or all; default 0x%02X\n",
                "--cameras CAMS", info->default_cameras);
    }
}

void cmdargs_list(FILE *out)
{
    const cmd_spec *spec;
    size_t i;
    for (i = 0; (spec = spec_at(i)) != NULL; i++) {
        char usage[512];
        usage_text(spec, usage, sizeof(usage));
        fprintf(out, "  %-17s %s%s\n", spec->name, usage[0] != '\0' ? usage : "(no arguments)",
                spec->info->since > 1u ? "  [V0.2]" : "");
    }
}

/* ---- parsing ------------------------------------------------------------- */

typedef struct parse_state {
    const cmd_spec *spec;
    char where[64];              /* "encode zoom-to": the messages' prefix */
    const char *given[MAX_OPTS]; /* per option: its value text (a switch: its name), NULL if absent */
    const char *cameras;         /* --cameras text, NULL if absent */
    xf_command cmd;
} parse_state;

/* Split "a,b,c" into exactly @p n integers. */
static int parse_int_list(const char *text, long long *vals, size_t n)
{
    char item[32];
    size_t k = 0;
    const char *p = text;
    for (;;) {
        const char *comma = strchr(p, ',');
        size_t len = (comma != NULL) ? (size_t)(comma - p) : strlen(p);
        if (k == n || len == 0u || len >= sizeof(item)) {
            return -1;
        }
        memcpy(item, p, len);
        item[len] = '\0';
        if (cli_parse_int(item, &vals[k++]) != 0) {
            return -1;
        }
        if (comma == NULL) {
            break;
        }
        p = comma + 1;
    }
    return (k == n) ? 0 : -1;
}

/* --cameras, one syntax: "all", a mask in hex ("0x03"), or camera numbers 1..8 separated by
 * commas ("1", "1,2"). A decimal number is always a camera, never a mask: "3" is camera 3
 * (0x04), and "3," (an empty item) is refused, as are a camera given twice and the mask 0. */
static int parse_cameras(const parse_state *st, const char *text, uint8_t *mask)
{
    static const char syntax[] = "camera numbers 1..8 (1 or 1,2), a hex mask (0x03) or all";
    const char *p = text;
    unsigned m = 0;
    if (strcmp(text, "all") == 0) {
        *mask = XF_CAM_ALL;
        return XFGCU_EXIT_OK;
    }
    if (text[0] == '0' && (text[1] == 'x' || text[1] == 'X')) {
        long long v;
        if (cli_parse_int(text, &v) != 0 || v < 1 || v > 255) {
            return cli_fail_in(st->where, "--cameras %s: a hex mask is 0x01..0xFF", text);
        }
        *mask = (uint8_t)v;
        return XFGCU_EXIT_OK;
    }
    do {
        char *end = NULL;
        long cam = (*p >= '0' && *p <= '9') ? strtol(p, &end, 10) : 0; /* no sign, no space */
        if (cam < 1 || cam > 8 || (*end != ',' && *end != '\0') || (*end == ',' && end[1] == '\0')) {
            return cli_fail_in(st->where, "--cameras %s: expected %s", text, syntax);
        }
        if (m & (1u << (cam - 1))) {
            return cli_fail_in(st->where, "--cameras %s: camera %ld given twice", text, cam);
        }
        m |= 1u << (cam - 1);
        p = (*end == ',') ? end + 1 : end;
    } while (*p != '\0');
    *mask = (uint8_t)m;
    return XFGCU_EXIT_OK;
}

static int out_of_range(const parse_state *st, const opt_spec *o, const char *text)
{
    return cli_fail_in(st->where, "%s %s is out of range: %s", o->name, text, o->help);
}

static int set_ints(parse_state *st, const opt_spec *o, const char *text, size_t n)
{
    long long v[4];
    size_t k;
    if (parse_int_list(text, v, n) != 0) {
        return cli_fail_in(st->where, "%s %s: expected %s (integers)", o->name, text, o->meta);
    }
    for (k = 0; k < n; k++) {
        if ((double)v[k] < o->lo || (double)v[k] > o->hi) {
            return out_of_range(st, o, text);
        }
    }
    for (k = 0; k < n; k++) {
        xf_command_set(&st->cmd, (xf_field)(o->field + k), (int32_t)v[k]);
    }
    return XFGCU_EXIT_OK;
}

static int set_word(parse_state *st, const opt_spec *o, const char *text)
{
    const char *w = o->meta;
    int32_t index = 0;
    size_t len = strlen(text);
    while (w != NULL) {
        const char *bar = strchr(w, '|');
        size_t wl = (bar != NULL) ? (size_t)(bar - w) : strlen(w);
        if (wl == len && strncmp(w, text, len) == 0) {
            xf_command_set(&st->cmd, (xf_field)o->field, index);
            return XFGCU_EXIT_OK;
        }
        w = (bar != NULL) ? bar + 1 : NULL;
        index++;
    }
    return cli_fail_in(st->where, "%s %s: expected one of %s", o->name, text, o->meta);
}

/* Real-valued options: the physical value, checked, then converted to the raw member. */
static int set_real(parse_state *st, const opt_spec *o, const char *text)
{
    double v;
    int32_t raw;
    if (cli_parse_real(text, &v) != 0) {
        return cli_fail_in(st->where, "%s %s: expected a number", o->name, text);
    }
    if (v < o->lo || v > o->hi) {
        return out_of_range(st, o, text);
    }
    switch ((opt_kind)o->kind) {
    case K_DEG: raw = xf_deg7_raw(v); break;
    case K_METRES: raw = xf_mm_raw(v); break;
    case K_ZOOM_RATE: raw = xf_units_round(-v * 10.0, INT16_MIN, -10); break; /* 5.5x -> -55 */
    default: raw = xf_units_round(v * 10.0, INT16_MIN, INT16_MAX); break;     /* K_TENTHS */
    }
    xf_command_set(&st->cmd, (xf_field)o->field, raw);
    return XFGCU_EXIT_OK;
}

static int set_value(parse_state *st, const opt_spec *o, const char *text)
{
    switch ((opt_kind)o->kind) {
    case K_SWITCH: xf_command_set(&st->cmd, (xf_field)o->field, (int32_t)o->lo); return XFGCU_EXIT_OK;
    case K_INT: return set_ints(st, o, text, 1);
    case K_POINT:
    case K_OFFSET: return set_ints(st, o, text, 2);
    case K_BOX: return set_ints(st, o, text, 4);
    case K_WORD: return set_word(st, o, text);
    default: return set_real(st, o, text);
    }
}

static int take_cameras(parse_state *st, const char *text)
{
    if (text == NULL) {
        return cli_fail_in(st->where, "--cameras needs a value: camera numbers (1 or 1,2), a hex mask (0x03) or all");
    }
    if (st->cameras != NULL) {
        return cli_fail_in(st->where, "--cameras given twice");
    }
    st->cameras = text;
    return parse_cameras(st, text, &st->cmd.cameras);
}

/* The ids of the options cli_next() returns: the command's own are ID_OPT + their index in its row. */
#define ID_OPT      256
#define ID_CAMERAS  'c'
#define ID_PROTOCOL 'p'
#define ID_HELP     'h'
#define ID_JSON     'j'
#define ID_FORCE    'f'
#define ID_JSON_OUT 'J' /* send's --json: the result as a JSON object */

static int take_option(parse_state *st, const cli_args *a, int id)
{
    const opt_spec *o;
    size_t index = (size_t)(id - ID_OPT);
    if (id == ID_CAMERAS) {
        return take_cameras(st, a->value);
    }
    if (id < ID_OPT) {
        return XFGCU_EXIT_OK; /* --protocol and --help: the first pass took them */
    }
    o = &st->spec->extra->opts[index];
    if (o->kind != K_SWITCH && a->value == NULL) {
        return cli_fail_in(st->where, "%s needs a value: %s", o->name, o->meta);
    }
    if (st->given[index] != NULL) {
        return cli_fail_in(st->where, "%s given twice", o->name);
    }
    st->given[index] = (o->kind == K_SWITCH) ? o->name : a->value;
    return set_value(st, o, st->given[index]);
}

/* Which choice was made; -1 for none. Refuses two. */
static int chosen_option(const parse_state *st, int *chosen)
{
    size_t i;
    *chosen = -1;
    for (i = 0; i < st->spec->extra->nopts; i++) {
        if ((st->spec->extra->opts[i].flags & OPT_CHOICE) != 0u && st->given[i] != NULL) {
            if (*chosen >= 0) {
                return cli_fail_in(st->where, "%s and %s exclude each other", st->spec->extra->opts[*chosen].name,
                                   st->spec->extra->opts[i].name);
            }
            *chosen = (int)i;
        }
    }
    return XFGCU_EXIT_OK;
}

static int check_combination(const parse_state *st)
{
    const cmd_spec *s = st->spec;
    const opt_spec *opts = s->extra->opts;
    size_t i, k;
    int chosen;
    char choices[256];
    int rc = chosen_option(st, &chosen);
    if (rc != XFGCU_EXIT_OK) {
        return rc;
    }
    choices_text(s, " or ", choices, sizeof(choices));
    if (chosen < 0 && choices[0] != '\0') {
        return cli_fail_in(st->where, "give %s", choices);
    }
    for (i = 0; i < s->extra->nopts; i++) {
        const opt_spec *o = &opts[i];
        int needed = chosen >= 0 && (opts[chosen].needs & NEED(i)) != 0u;
        if ((o->flags & OPT_REQUIRED) != 0u && st->given[i] == NULL) {
            return cli_fail_in(st->where, "missing %s %s: %s", o->name, o->meta, o->help);
        }
        if (needed && st->given[i] == NULL) {
            return cli_fail_in(st->where, "%s needs %s %s", opts[chosen].name, o->name, o->meta);
        }
        if (!needed && (o->flags & (OPT_REQUIRED | OPT_CHOICE)) == 0u && st->given[i] != NULL) {
            for (k = 0; k < s->extra->nopts; k++) {
                if ((opts[k].needs & NEED(i)) != 0u) {
                    return cli_fail_in(st->where, "%s goes only with %s", o->name, opts[k].name);
                }
            }
        }
    }
    return XFGCU_EXIT_OK;
}

static int option_covers(const opt_spec *o, xf_field field)
{
    size_t k, span = (o->kind == K_BOX) ? 4u : (o->kind == K_POINT || o->kind == K_OFFSET) ? 2u : 1u;
    for (k = 0; k < span; k++) {
        if ((xf_field)(o->field + k) == field) {
            return 1;
        }
    }
    return 0;
}

/* The codec's own range check; its bad_field names the member, mapped back to the option given. */
static int check_with_codec(const parse_state *st, uint8_t version)
{
    xf_field bad = XF_F_NONE;
    size_t i;
    xf_err err = xf_command_check(&st->cmd, version, &bad);
    if (err == XF_OK) {
        return XFGCU_EXIT_OK;
    }
    for (i = 0; bad != XF_F_NONE && i < st->spec->extra->nopts; i++) {
        const opt_spec *o = &st->spec->extra->opts[i];
        if (st->given[i] != NULL && o->kind != K_SWITCH && option_covers(o, bad)) {
            if ((o->flags & OPT_BY_VERSION) != 0u) {
                return cli_fail_in(st->where, "%s %s is out of range for protocol %u: %s", o->name, st->given[i],
                                   (unsigned)version, o->help);
            }
            return out_of_range(st, o, st->given[i]);
        }
    }
    return cli_fail_in(st->where, "%s%s%s", xf_strerror(err), bad != XF_F_NONE ? ": " : "",
                       bad != XF_F_NONE ? xf_field_name(bad) : "");
}

/* The command's options for getopt_long(), with --cameras where the order takes a mask,
 * --protocol and --help when @p line (encode and send take them after COMMAND too), and
 * --force and --json when @p force (send's). */
static void command_options(const cmd_spec *spec, int line, int force, struct option *opts)
{
    static const struct option extra[] = {{"cameras", required_argument, NULL, ID_CAMERAS},
                                          {"protocol", required_argument, NULL, ID_PROTOCOL},
                                          {"help", no_argument, NULL, ID_HELP},
                                          {NULL, 0, NULL, 0},
                                          {"force", no_argument, NULL, ID_FORCE},
                                          {"json", no_argument, NULL, ID_JSON_OUT}};
    size_t i, n = 0;
    for (i = 0; i < spec->extra->nopts; i++) {
        const opt_spec *o = &spec->extra->opts[i];
        opts[n].name = o->name + 2; /* after "--" */
        opts[n].has_arg = (o->kind == K_SWITCH) ? no_argument : required_argument;
        opts[n].flag = NULL;
        opts[n++].val = ID_OPT + (int)i;
    }
    if (takes_cameras(spec)) {
        opts[n++] = extra[0];
    }
    for (i = 1; line && i < 3u; i++) {
        opts[n++] = extra[i];
    }
    if (force) {
        opts[n++] = extra[4];
        opts[n++] = extra[5];
    }
    opts[n] = extra[3];
}

/* The first pass over the arguments of encode and send: --protocol (the last one wins) and
 * --help, wherever they are; nothing else is checked when --help is there. */
static int take_line_options(const parse_state *st, int argc, char **argv, const struct option *opts, uint8_t *version,
                             int *help, int *force)
{
    cli_args a;
    int id, rc = XFGCU_EXIT_OK;
    cli_args_init(&a, argc, argv, CLI_IN_ORDER "h", opts, st->where); /* -h: --help */
    a.quiet = 1;
    while (rc == XFGCU_EXIT_OK && (id = cli_next(&a)) != CLI_END) {
        if (id == ID_PROTOCOL) {
            rc = cli_value_protocol(&a, version);
        } else if (id == ID_HELP) {
            *help = 1;
        } else if (id == ID_FORCE && force != NULL) { /* only offered with a place for it */
            *force |= CMDARGS_FORCE;
        } else if (id == ID_JSON_OUT && force != NULL) {
            *force |= CMDARGS_JSON;
        }
    }
    return rc;
}

/* The arguments of COMMAND (argv[0]) into st->cmd, then the checks for protocol *version, read
 * only now: a link option after COMMAND may have set it (record's line). */
static int parse_checked(parse_state *st, const struct option *opts, const char *hint, int argc, char **argv,
                         const uint8_t *version, xf_command *cmd)
{
    const cmd_spec *spec = st->spec;
    cli_args a;
    int id, rc = XFGCU_EXIT_OK;
    xf_command_init(&st->cmd, spec->info->order); /* the spec's default camera mask */
    cli_args_init(&a, argc, argv, CLI_IN_ORDER "h", opts, st->where);
    a.hint = hint;
    while (rc == XFGCU_EXIT_OK && (id = cli_next(&a)) != CLI_END) {
        rc = (id == CLI_BAD) ? XFGCU_EXIT_USAGE : (id == CLI_ARG) ? cli_unexpected(&a) : take_option(st, &a, id);
    }
    if (rc == XFGCU_EXIT_OK) {
        rc = check_combination(st);
    }
    if (rc == XFGCU_EXIT_OK) {
        rc = check_with_codec(st, *version);
    }
    if (rc != XFGCU_EXIT_OK) {
        return rc;
    }
    if (spec->info->since > *version) {
        /* Warn, never refuse: a V0.1 GCU may or may not know the order. */
        cli_note("%s is an order of protocol %u (V0.2); this packet says version %u (add --protocol 2)", spec->name,
                 (unsigned)spec->info->since, (unsigned)*version);
    }
    if ((spec->info->flags & XF_ORDER_V1_ONLY) != 0u && *version >= XF_PROTOCOL_V2) {
        /* Warn, never refuse: newer firmware may have dropped it, or not. */
        cli_note("%s is an order of protocol 1 (V0.1) that V0.2 no longer lists; a V0.2 GCU may ignore it", spec->name);
    }
    *cmd = st->cmd;
    return XFGCU_EXIT_OK;
}

static void parse_init(parse_state *st, const cmd_spec *spec, const char *who)
{
    memset(st, 0, sizeof(*st));
    st->spec = spec;
    snprintf(st->where, sizeof(st->where), "%s %s", who, spec->name);
}

int cmdargs_parse(const cmd_spec *spec, const char *who, int argc, char **argv, uint8_t *version, int *help, int *force,
                  xf_command *cmd)
{
    struct option opts[MAX_OPTS + 6];
    parse_state st;
    int rc;
    parse_init(&st, spec, who);
    command_options(spec, 1, force != NULL, opts);
    rc = take_line_options(&st, argc, argv, opts, version, help, force);
    if (rc != XFGCU_EXIT_OK || *help) {
        return rc;
    }
    return parse_checked(&st, opts, NULL, argc, argv, version, cmd);
}

int cmdargs_parse_command(const cmd_spec *spec, const char *who, int argc, char **argv, const uint8_t *version,
                          xf_command *cmd)
{
    struct option opts[MAX_OPTS + 6];
    parse_state st;
    char hint[64];
    parse_init(&st, spec, who);
    snprintf(hint, sizeof(hint), "send %s", spec->name); /* no --help after COMMAND here: send's tells */
    command_options(spec, 0, 0, opts);
    return parse_checked(&st, opts, hint, argc, argv, version, cmd);
}

/* ---- encode and send: [--protocol N] [--help] [--json OBJECT] COMMAND [ARGS] ---- */

static int take_json(const cli_args *a, const char **json)
{
    if (a->value == NULL) {
        return cli_fail_in(a->context, "--json needs an OBJECT (or - for JSON Lines on stdin)");
    }
    if (*json != NULL) {
        return cli_fail_in(a->context, "--json given twice");
    }
    *json = a->value;
    return XFGCU_EXIT_OK;
}

/* COMMAND [ARGS] of a line (argv[0] is COMMAND). */
static int command_of_line(cmd_line *l, const char *who, int argc, char **argv)
{
    if (l->json != NULL) {
        return cli_fail("%s: --json takes one OBJECT; unexpected '%s'", who, argv[0]);
    }
    if ((l->spec = cmdargs_find(argv[0])) == NULL) {
        return cli_fail("%s: unknown command '%s' (see 'xfgcu %s --help')", who, argv[0], who);
    }
    return cmdargs_parse(l->spec, who, argc, argv, &l->version, &l->help, l->with_force ? &l->force : NULL, &l->cmd);
}

void cmdargs_for_version(xf_command *cmd, uint8_t version)
{
    if (cmd->order == XF_ORDER_OSD) {
        cmd->value = xf_osd_value(cmd->value == 0u, version);
    }
}

int cmd_line_parse(cmd_line *l, const char *who, uint8_t version, int with_json, void (*help)(FILE *out), int argc,
                   char **argv)
{
    static const struct option opts[] = {{"protocol", required_argument, NULL, ID_PROTOCOL},
                                         {"help", no_argument, NULL, ID_HELP},
                                         {"json", required_argument, NULL, ID_JSON},
                                         {NULL, 0, NULL, 0},
                                         {"force", no_argument, NULL, ID_FORCE},
                                         {"json", no_argument, NULL, ID_JSON_OUT}};
    struct option with_force[5] = {opts[0], opts[1], opts[4], opts[5], opts[3]}; /* send: --force, --json */
    cli_args a;
    int id, rest, rc = XFGCU_EXIT_OK;
    memset(l, 0, sizeof(*l));
    l->version = version;
    l->with_force = !with_json;
    cli_args_init(&a, argc, argv, CLI_STOP, with_json ? opts : with_force, who);
    while (rc == XFGCU_EXIT_OK && (id = cli_next(&a)) != CLI_END) {
        switch (id) {
        case CLI_BAD: rc = XFGCU_EXIT_USAGE; break;
        case ID_PROTOCOL: rc = cli_value_protocol(&a, &l->version); break;
        case ID_HELP: l->help = 1; break;
        case ID_FORCE: l->force |= CMDARGS_FORCE; break;
        case ID_JSON_OUT: l->force |= CMDARGS_JSON; break;
        default: rc = take_json(&a, &l->json); break;
        }
    }
    rest = cli_rest(&a);
    if (rc == XFGCU_EXIT_OK && rest < argc) {
        rc = command_of_line(l, who, argc - rest, argv + rest);
    }
    if (rc == XFGCU_EXIT_OK && l->help) {
        if (l->spec != NULL) {
            cmdargs_help(l->spec, who, stdout);
        } else {
            help(stdout);
        }
    }
    return rc;
}
