/*
 * cmdargs.c - the named commands of docs/cli.md ("zoom-to --factor 5.5", ...) and their
 * arguments, given as named arguments (text_arg: name and value), turned into an xf_command.
 *
 * Commands: one per order of the codec's table (xf_order_at), named by the codec
 * (xf_order_name, '-' for '_'). This module adds, per order, the arguments it takes and how each
 * maps onto xf_command members (kind + first member), and how they combine:
 *   OPT_REQUIRED  must be given;
 *   OPT_CHOICE    exactly one of the command's CHOICE arguments is given
 *                 (--start | --stop, --factor | --fraction, --on | --off);
 *                 a choice may need other arguments (--start needs --box),
 *                 which are then refused with the other choices.
 * Values are checked twice: here against what the argument accepts (so nothing is silently
 * saturated by xf_command_set), then by the codec's xf_command_check, whose bad_field is mapped
 * back to the argument. No getopt, no state: a program parses its own command line and hands the
 * pairs over.
 */
#include "cmdargs.h"

#include <ctype.h>
#include <stdlib.h>
#include <string.h>

/* ---- the commands: the codec's orders, with arguments ---------------------- */

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

#define GRID_BOX     "box corners on the 0..10000 screen grid, X0 <= X1 and Y0 <= Y1"
#define GRID_POINT   "a point on the 0..10000 screen grid"
#define CAMERAS_HELP "cameras: numbers (1, or 1,2 = 0x03), a hex mask (0x03) or all"

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
    {"--factor", K_ZOOM_RATE, XF_F_ZOOM, OPT_CHOICE, 0, 1.0, 3276.8, "X", "zoom factor 1.0..3276.8 (5.5 = 5.5x)"},
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

/* Old spellings that scripts rely on: an argument of an order that another name now says. */
static const struct cmd_alias {
    uint8_t order;
    const char *alias, *name;
} aliases[] = {
    {XF_ORDER_ZOOM_TO, "rate", "factor"}, /* zoom-to --rate R: the factor; --rate is the link's packet rate */
};

/* ---- the commands, from the codec's table --------------------------------- */

static int option_index(const cmd_spec *spec, const char *name);

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

int cmdargs_at(size_t i, cmd_spec *spec)
{
    const xf_order_info *info = xf_order_at(i);
    const char *name;
    size_t n;
    if (info == NULL) {
        return 0;
    }
    name = xf_order_name(info->order);
    spec->info = info;
    spec->extra = &extras[info->order];
    for (n = 0; name[n] != '\0' && n + 1u < sizeof(spec->name); n++) {
        spec->name[n] = (name[n] == '_') ? '-' : name[n];
    }
    spec->name[n] = '\0';
    return 1;
}

int cmdargs_find(const char *name, cmd_spec *spec)
{
    uint8_t order;
    size_t i;
    if (name == NULL || xf_order_from_name(name, &order) != XF_OK) {
        return 0;
    }
    for (i = 0; cmdargs_at(i, spec); i++) {
        if (spec->info->order == order) {
            return 1;
        }
    }
    return 0;
}

size_t cmdargs_option_count(const cmd_spec *spec)
{
    size_t n = spec->extra->nopts + (takes_cameras(spec) ? 1u : 0u), k;
    for (k = 0; k < sizeof(aliases) / sizeof(aliases[0]); k++) {
        n += (aliases[k].order == spec->info->order);
    }
    return n;
}

/* The argument row @p o described into @p info, under @p name. */
static void describe(const opt_spec *o, const char *name, cmdargs_info *info)
{
    memset(info, 0, sizeof(*info));
    info->name = name;
    switch ((opt_kind)o->kind) {
    case K_SWITCH: info->values = 0u; break;
    case K_BOX: info->values = 4u; break;
    case K_POINT:
    case K_OFFSET: info->values = 2u; break;
    default: info->values = 1u; break;
    }
    info->real = o->kind == K_DEG || o->kind == K_METRES || o->kind == K_ZOOM_RATE || o->kind == K_TENTHS;
    info->words = (o->kind == K_WORD) ? o->meta : NULL;
    info->lo = o->lo;
    info->hi = o->hi;
    info->field = xf_field_name((xf_field)o->field);
    info->help = o->help;
}

int cmdargs_option_info(const cmd_spec *spec, size_t i, cmdargs_info *info)
{
    size_t k;
    if (i < spec->extra->nopts) {
        describe(&spec->extra->opts[i], spec->extra->opts[i].name + 2 /* after "--" */, info);
        return 1;
    }
    i -= spec->extra->nopts;
    if (takes_cameras(spec) && i-- == 0u) {
        memset(info, 0, sizeof(*info));
        info->name = "cameras";
        info->values = 1u;
        info->cameras = 1;
        info->lo = 1;
        info->hi = 255; /* a mask; the text's own syntax is checked by cmdargs_build */
        info->field = xf_field_name(XF_F_CAMERAS);
        info->help = CAMERAS_HELP;
        return 1;
    }
    for (k = 0; k < sizeof(aliases) / sizeof(aliases[0]); k++) {
        if (aliases[k].order == spec->info->order && i-- == 0u) {
            int at = option_index(spec, aliases[k].name);
            if (at < 0) {
                return 0; /* an alias of no argument: the table's own fault */
            }
            describe(&spec->extra->opts[at], aliases[k].alias, info);
            return 1;
        }
    }
    return 0;
}

const char *cmdargs_option(const cmd_spec *spec, size_t i, int *takes_value)
{
    cmdargs_info info;
    if (!cmdargs_option_info(spec, i, &info)) {
        return NULL;
    }
    *takes_value = info.values != 0u;
    return info.name;
}

/* ---- usage text --------------------------------------------------------- */

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
        fprintf(out, "  %-22s " CAMERAS_HELP "; default 0x%02X\n", "--cameras CAMS", info->default_cameras);
    }
}

void cmdargs_list(FILE *out)
{
    cmd_spec spec;
    size_t i;
    for (i = 0; cmdargs_at(i, &spec); i++) {
        char usage[512];
        usage_text(&spec, usage, sizeof(usage));
        fprintf(out, "  %-17s %s%s\n", spec.name, usage[0] != '\0' ? usage : "(no arguments)",
                spec.info->since > 1u ? "  [V0.2]" : "");
    }
}

/* ---- parsing ------------------------------------------------------------- */

typedef struct parse_state {
    const cmd_spec *spec;
    char where[64];              /* "encode zoom-to": the messages' prefix */
    const char *given[MAX_OPTS]; /* per argument: its value text (a switch: its name), NULL if absent */
    char as[MAX_OPTS][24];       /* per argument: "--" and the name it was given by (an old spelling too) */
    const char *cameras;         /* --cameras text, NULL if absent */
    xf_command cmd;
    text_err *err;
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
        if (text_parse_int(item, &vals[k++]) != 0) {
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
        return TEXT_OK;
    }
    if (text[0] == '0' && (text[1] == 'x' || text[1] == 'X')) {
        long long v;
        if (text_parse_int(text, &v) != 0 || v < 1 || v > 255) {
            return text_fail(st->err, st->where, "--cameras %s: a hex mask is 0x01..0xFF", text);
        }
        *mask = (uint8_t)v;
        return TEXT_OK;
    }
    do {
        char *end = NULL;
        long cam = (*p >= '0' && *p <= '9') ? strtol(p, &end, 10) : 0; /* no sign, no space */
        if (cam < 1 || cam > 8 || (*end != ',' && *end != '\0') || (*end == ',' && end[1] == '\0')) {
            return text_fail(st->err, st->where, "--cameras %s: expected %s", text, syntax);
        }
        if (m & (1u << (cam - 1))) {
            return text_fail(st->err, st->where, "--cameras %s: camera %ld given twice", text, cam);
        }
        m |= 1u << (cam - 1);
        p = (*end == ',') ? end + 1 : end;
    } while (*p != '\0');
    *mask = (uint8_t)m;
    return TEXT_OK;
}

/* The name argument @p o was given by: "--rate" for zoom-to's --factor, given so. */
static const char *shown(const parse_state *st, const opt_spec *o)
{
    size_t i = (size_t)(o - st->spec->extra->opts);
    return (st->as[i][0] != '\0') ? st->as[i] : o->name;
}

static int out_of_range(const parse_state *st, const opt_spec *o, const char *text)
{
    return text_fail(st->err, st->where, "%s %s is out of range: %s", shown(st, o), text, o->help);
}

static int set_ints(parse_state *st, const opt_spec *o, const char *text, size_t n)
{
    long long v[4];
    size_t k;
    if (parse_int_list(text, v, n) != 0) {
        return text_fail(st->err, st->where, "%s %s: expected %s (integers)", shown(st, o), text, o->meta);
    }
    for (k = 0; k < n; k++) {
        if ((double)v[k] < o->lo || (double)v[k] > o->hi) {
            return out_of_range(st, o, text);
        }
    }
    for (k = 0; k < n; k++) {
        xf_command_set(&st->cmd, (xf_field)(o->field + k), (int32_t)v[k]);
    }
    return TEXT_OK;
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
            return TEXT_OK;
        }
        w = (bar != NULL) ? bar + 1 : NULL;
        index++;
    }
    return text_fail(st->err, st->where, "%s %s: expected one of %s", shown(st, o), text, o->meta);
}

/* Real-valued options: the physical value, checked, then converted to the raw member. */
static int set_real(parse_state *st, const opt_spec *o, const char *text)
{
    double v;
    int32_t raw;
    if (text_parse_real(text, &v) != 0) {
        return text_fail(st->err, st->where, "%s %s: expected a number", shown(st, o), text);
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
    return TEXT_OK;
}

static int set_value(parse_state *st, const opt_spec *o, const char *text)
{
    switch ((opt_kind)o->kind) {
    case K_SWITCH: xf_command_set(&st->cmd, (xf_field)o->field, (int32_t)o->lo); return TEXT_OK;
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
        return text_fail(st->err, st->where,
                         "--cameras needs a value: camera numbers (1 or 1,2), a hex mask (0x03) or all");
    }
    if (st->cameras != NULL) {
        return text_fail(st->err, st->where, "--cameras given twice");
    }
    st->cameras = text;
    return parse_cameras(st, text, &st->cmd.cameras);
}

/* Which choice was made; -1 for none. Refuses two. */
static int chosen_option(const parse_state *st, int *chosen)
{
    size_t i;
    *chosen = -1;
    for (i = 0; i < st->spec->extra->nopts; i++) {
        if ((st->spec->extra->opts[i].flags & OPT_CHOICE) != 0u && st->given[i] != NULL) {
            if (*chosen >= 0) {
                return text_fail(st->err, st->where, "%s and %s exclude each other",
                                 shown(st, &st->spec->extra->opts[*chosen]), shown(st, &st->spec->extra->opts[i]));
            }
            *chosen = (int)i;
        }
    }
    return TEXT_OK;
}

static int check_combination(const parse_state *st)
{
    const cmd_spec *s = st->spec;
    const opt_spec *opts = s->extra->opts;
    size_t i, k;
    int chosen;
    char choices[256];
    int rc = chosen_option(st, &chosen);
    if (rc != TEXT_OK) {
        return rc;
    }
    choices_text(s, " or ", choices, sizeof(choices));
    if (chosen < 0 && choices[0] != '\0') {
        return text_fail(st->err, st->where, "give %s", choices);
    }
    for (i = 0; i < s->extra->nopts; i++) {
        const opt_spec *o = &opts[i];
        int needed = chosen >= 0 && (opts[chosen].needs & NEED(i)) != 0u;
        if ((o->flags & OPT_REQUIRED) != 0u && st->given[i] == NULL) {
            return text_fail(st->err, st->where, "missing %s %s: %s", o->name, o->meta, o->help);
        }
        if (needed && st->given[i] == NULL) {
            return text_fail(st->err, st->where, "%s needs %s %s", shown(st, &opts[chosen]), o->name, o->meta);
        }
        if (!needed && (o->flags & (OPT_REQUIRED | OPT_CHOICE)) == 0u && st->given[i] != NULL) {
            for (k = 0; k < s->extra->nopts; k++) {
                if ((opts[k].needs & NEED(i)) != 0u) {
                    return text_fail(st->err, st->where, "%s goes only with %s", shown(st, o), opts[k].name);
                }
            }
        }
    }
    return TEXT_OK;
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
        return TEXT_OK;
    }
    for (i = 0; bad != XF_F_NONE && i < st->spec->extra->nopts; i++) {
        const opt_spec *o = &st->spec->extra->opts[i];
        if (st->given[i] != NULL && o->kind != K_SWITCH && option_covers(o, bad)) {
            if ((o->flags & OPT_BY_VERSION) != 0u) {
                return text_fail(st->err, st->where, "%s %s is out of range for protocol %u: %s", shown(st, o),
                                 st->given[i], (unsigned)version, o->help);
            }
            return out_of_range(st, o, st->given[i]);
        }
    }
    return text_fail(st->err, st->where, "%s%s%s", xf_strerror(err), bad != XF_F_NONE ? ": " : "",
                     bad != XF_F_NONE ? xf_field_name(bad) : "");
}

/* The argument named @p name (without "--"; an old spelling too): its index, or -1. */
static int option_index(const cmd_spec *spec, const char *name)
{
    size_t i, k;
    for (k = 0; k < sizeof(aliases) / sizeof(aliases[0]); k++) {
        if (aliases[k].order == spec->info->order && strcmp(aliases[k].alias, name) == 0) {
            name = aliases[k].name;
        }
    }
    for (i = 0; i < spec->extra->nopts; i++) {
        if (strcmp(spec->extra->opts[i].name + 2, name) == 0) {
            return (int)i;
        }
    }
    return -1;
}

/* One named argument into st->cmd. */
static int take_arg(parse_state *st, const text_arg *arg)
{
    int index = option_index(st->spec, arg->name);
    const opt_spec *o;
    if (strcmp(arg->name, "cameras") == 0 && takes_cameras(st->spec)) {
        return take_cameras(st, arg->value);
    }
    if (index < 0) {
        return text_fail(st->err, st->where, "unknown option '--%s'", arg->name);
    }
    o = &st->spec->extra->opts[index];
    snprintf(st->as[index], sizeof(st->as[index]), "--%s", arg->name);
    if (o->kind == K_SWITCH && arg->value != NULL) {
        return text_fail(st->err, st->where, "%s takes no value", st->as[index]);
    }
    if (o->kind != K_SWITCH && (arg->value == NULL || arg->value[0] == '\0')) {
        return text_fail(st->err, st->where, "%s needs a value: %s", st->as[index], o->meta);
    }
    if (st->given[index] != NULL) {
        return text_fail(st->err, st->where, "%s given twice", st->as[index]);
    }
    st->given[index] = (o->kind == K_SWITCH) ? o->name : arg->value;
    return set_value(st, o, st->given[index]);
}

/* Notes, never refusals: an order of another version than the packet's. */
static void version_notes(const parse_state *st, uint8_t version)
{
    const cmd_spec *spec = st->spec;
    if (spec->info->since > version) {
        /* a V0.1 GCU may or may not know the order */
        text_note(st->err, "%s is an order of protocol %u (V0.2); this packet says version %u (add --protocol 2)",
                  spec->name, (unsigned)spec->info->since, (unsigned)version);
    }
    if ((spec->info->flags & XF_ORDER_V1_ONLY) != 0u && version >= XF_PROTOCOL_V2) {
        /* newer firmware may have dropped it, or not */
        text_note(st->err, "%s is an order of protocol 1 (V0.1) that V0.2 no longer lists; a V0.2 GCU may ignore it",
                  spec->name);
    }
}

int cmdargs_build(const cmd_spec *spec, const text_arg *args, size_t n, uint8_t version, const char *who,
                  xf_command *cmd, text_err *e)
{
    parse_state st;
    size_t i;
    int rc = TEXT_OK;
    memset(&st, 0, sizeof(st));
    st.spec = spec;
    st.err = e;
    snprintf(st.where, sizeof(st.where), "%s%s%s", who != NULL ? who : "", who != NULL ? " " : "", spec->name);
    xf_command_init(&st.cmd, spec->info->order); /* the spec's default camera mask */
    for (i = 0; rc == TEXT_OK && i < n; i++) {
        rc = take_arg(&st, &args[i]);
    }
    if (rc == TEXT_OK) {
        rc = check_combination(&st);
    }
    if (rc == TEXT_OK) {
        rc = check_with_codec(&st, version);
    }
    if (rc != TEXT_OK) {
        return rc;
    }
    version_notes(&st, version);
    *cmd = st.cmd;
    return TEXT_OK;
}

void cmdargs_for_version(xf_command *cmd, uint8_t version)
{
    if (cmd->order == XF_ORDER_OSD) {
        cmd->value = xf_osd_value(cmd->value == 0u, version);
    }
}
