/*
 * cmdargs.c - numbers, options, and the arguments of every named command.
 *
 * Each command is a row: its order and the options it takes. An option
 * says how its text becomes xf_command members (kind + first member) and
 * how it combines with the others:
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
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"

/* ---- numbers and options ------------------------------------------------ */

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

int cli_take_option(int argc, char **argv, int *i, const char *name, const char **value)
{
    const char *arg = argv[*i];
    size_t n = strlen(name);
    if (strncmp(arg, name, n) != 0) {
        return 0;
    }
    if (arg[n] == '=') {
        *value = arg + n + 1;
        return 1;
    }
    if (arg[n] != '\0') {
        return 0;
    }
    if (*i + 1 < argc) {
        (*i)++;
        *value = argv[*i];
    } else {
        *value = NULL;
    }
    return 1;
}

int cli_parse_protocol(const char *text, uint8_t *version)
{
    long long v;
    if (text == NULL) {
        return cli_fail("--protocol needs a value: 1 or 2");
    }
    if (cli_parse_int(text, &v) != 0 || (v != 1 && v != 2)) {
        return cli_fail("--protocol %s: must be 1 or 2", text);
    }
    *version = (uint8_t)v;
    return XFGCU_EXIT_OK;
}

/* ---- the table of commands ---------------------------------------------- */

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

struct cmd_spec {
    const char *name; /* as typed: canonical name with '-' for '_' */
    uint8_t order;
    uint8_t nopts;
    const opt_spec *opts;
    const char *summary;
};

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
    {"--box", K_BOX, XF_F_X0, 0, 0, 0, 10000, "X0,Y0,X1,Y1", GRID_BOX},
};
static const opt_spec click_opts[] = {
    {"--at", K_POINT, XF_F_X0, OPT_REQUIRED, 0, 0, 10000, "X,Y", GRID_POINT},
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
    {"--box", K_BOX, XF_F_X0, 0, 0, 0, 10000, "X0,Y0,X1,Y1", GRID_BOX},
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
    {"--at", K_POINT, XF_F_X0, 0, 0, 0, 10000, "X,Y", GRID_POINT},
};
static const opt_spec on_off_opts[] = {
    SWITCH("--on", 1, 0, "on"),
    SWITCH("--off", 0, 0, "off"),
};

/* Same order as the codec's table; every order of the protocol has a row (checked by the tests). */
static const cmd_spec commands[] = {
    {"null", XF_ORDER_NULL, NO_OPTS, "the null order: goes between two commands of the same order"},
    {"calibration", XF_ORDER_CALIBRATION, NO_OPTS, "calibrate the gimbal (keep it still)"},
    {"neutral", XF_ORDER_NEUTRAL, NO_OPTS, "back to neutral without changing mode"},
    {"osd-coordinate", XF_ORDER_OSD_COORDINATE, OPTS(osd_coordinate_opts), "which coordinates the OSD shows"},
    {"auto-flip", XF_ORDER_AUTO_FLIP, OPTS(auto_flip_opts), "image auto-flip on or off"},
    {"time-zone", XF_ORDER_TIME_ZONE, OPTS(time_zone_opts), "set the GCU's time zone"},
    {"angle-control", XF_ORDER_ANGLE_CONTROL, NO_OPTS, "angle control mode (\"FPV\" in V2.0.4)"},
    {"head-lock", XF_ORDER_HEAD_LOCK, NO_OPTS, "head lock mode"},
    {"head-follow", XF_ORDER_HEAD_FOLLOW, NO_OPTS, "head follow mode"},
    {"orthoview", XF_ORDER_ORTHOVIEW, NO_OPTS, "orthoview mode: pitch locked at -90 degrees"},
    {"euler", XF_ORDER_EULER, NO_OPTS, "Euler angle control mode"},
    {"gaze-geo", XF_ORDER_GAZE_GEO, OPTS(gaze_geo_opts), "point at a geo-coordinate (needs carrier INS data)"},
    {"gaze-lock", XF_ORDER_GAZE_LOCK, NO_OPTS, "keep aiming at the point now in the centre (needs carrier INS data)"},
    {"track", XF_ORDER_TRACK, OPTS(track_opts), "track a target with the gimbal's image processor"},
    {"click-to-aim", XF_ORDER_CLICK_TO_AIM, OPTS(click_opts), "aim at a point of the picture"},
    {"external-track", XF_ORDER_EXTERNAL_TRACK, OPTS(external_track_opts),
     "track with offsets from an external detector"},
    {"fpv", XF_ORDER_FPV, NO_OPTS, "FPV mode: control quantities relative to the carrier"},
    {"shutter", XF_ORDER_SHUTTER, NO_OPTS, "take a picture"},
    {"record", XF_ORDER_RECORD, NO_OPTS, "start or stop recording (toggle)"},
    {"zoom-in", XF_ORDER_ZOOM_IN, NO_OPTS, "zoom in continuously"},
    {"zoom-out", XF_ORDER_ZOOM_OUT, NO_OPTS, "zoom out continuously"},
    {"zoom-stop", XF_ORDER_ZOOM_STOP, NO_OPTS, "stop zooming"},
    {"zoom-to", XF_ORDER_ZOOM_TO, OPTS(zoom_to_opts), "zoom to a rate or to a fraction of the zoom range"},
    {"focus", XF_ORDER_FOCUS, NO_OPTS, "focus"},
    {"palette", XF_ORDER_PALETTE, OPTS(palette_opts), "choose the thermal palette"},
    {"night-vision", XF_ORDER_NIGHT_VISION, OPTS(night_vision_opts), "night vision off, on or auto"},
    {"area-temp", XF_ORDER_AREA_TEMP, OPTS(area_temp_opts), "area temperature measurement"},
    {"temp-alarm", XF_ORDER_TEMP_ALARM, OPTS(temp_alarm_opts), "temperature alarm"},
    {"isotherm", XF_ORDER_ISOTHERM, OPTS(isotherm_opts), "isotherm (in-range highlighting)"},
    {"spot-temp", XF_ORDER_SPOT_TEMP, OPTS(spot_temp_opts), "spot temperature measurement"},
    {"osd", XF_ORDER_OSD, OPTS(osd_opts), "show or hide the OSD"},
    {"pip", XF_ORDER_PIP, OPTS(pip_opts), "picture-in-picture view"},
    {"target-detection", XF_ORDER_TARGET_DETECTION, OPTS(on_off_opts), "target detection on or off"},
    {"digital-zoom", XF_ORDER_DIGITAL_ZOOM, OPTS(on_off_opts), "digital zoom of the zoom camera on or off"},
    {"lighting", XF_ORDER_LIGHTING, OPTS(lighting_opts), "set the light's intensity"},
    {"ranging", XF_ORDER_RANGING, OPTS(ranging_opts), "laser ranging on or off"},
};

#define N_COMMANDS (sizeof(commands) / sizeof(commands[0]))

const cmd_spec *cmdargs_find(const char *name)
{
    uint8_t order;
    size_t i;
    if (xf_order_from_name(name, &order) != XF_OK) {
        return NULL;
    }
    for (i = 0; i < N_COMMANDS; i++) {
        if (commands[i].order == order) {
            return &commands[i];
        }
    }
    return NULL;
}

const char *cmdargs_name(const cmd_spec *spec) { return spec->name; }

/* ---- usage text --------------------------------------------------------- */

static int takes_cameras(const cmd_spec *spec)
{
    const xf_order_info *info = xf_order_lookup(spec->order);
    size_t i;
    for (i = 0; info != NULL && i < info->nfields; i++) {
        if (info->fields[i] == XF_F_CAMERAS) {
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
    for (i = 0; i < spec->nopts; i++) {
        const opt_spec *o = &spec->opts[i];
        if ((o->flags & OPT_CHOICE) == 0u) {
            continue;
        }
        append(buf, cap, first ? "" : sep);
        append_opt(buf, cap, o);
        for (k = 0; k < spec->nopts; k++) {
            if ((o->needs & NEED(k)) != 0u) {
                append(buf, cap, " ");
                append_opt(buf, cap, &spec->opts[k]);
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
    for (i = 0; i < spec->nopts; i++) {
        if ((spec->opts[i].flags & OPT_REQUIRED) != 0u) {
            append(buf, cap, buf[0] != '\0' ? " " : "");
            append_opt(buf, cap, &spec->opts[i]);
        }
    }
    if (takes_cameras(spec)) {
        append(buf, cap, buf[0] != '\0' ? " [--cameras MASK]" : "[--cameras MASK]");
    }
}

void cmdargs_help(const cmd_spec *spec, const char *context, FILE *out)
{
    const xf_order_info *info = xf_order_lookup(spec->order);
    char usage[512];
    size_t i;
    usage_text(spec, usage, sizeof(usage));
    fprintf(out, "usage: xfgcu %s [--protocol 1|2] %s%s%s\n\n", context, spec->name, usage[0] != '\0' ? " " : "",
            usage);
    fprintf(out, "%c%s.\norder 0x%02X %s, protocol %u%s", toupper((unsigned char)spec->summary[0]), spec->summary + 1,
            spec->order, xf_order_name(info->order), (unsigned)info->since,
            info->since > 1u ? " (V0.2) and later" : " and later");
    fprintf(out, "; %zu parameter byte%s.\n", xf_order_params_len(spec->order),
            xf_order_params_len(spec->order) == 1u ? "" : "s");
    if (spec->nopts > 0u || takes_cameras(spec)) {
        fprintf(out, "\noptions:\n");
    }
    for (i = 0; i < spec->nopts; i++) {
        char left[64] = "";
        append_opt(left, sizeof(left), &spec->opts[i]);
        fprintf(out, "  %-22s %s\n", left, spec->opts[i].help);
    }
    if (takes_cameras(spec)) {
        fprintf(out, "  %-22s camera mask: a number (1, 0x03), a list (1,2 = cameras 1 and 2) or all; default 0x%02X\n",
                "--cameras MASK", info->default_cameras);
    }
}

void cmdargs_list(FILE *out)
{
    size_t i;
    for (i = 0; i < N_COMMANDS; i++) {
        char usage[512];
        const xf_order_info *info = xf_order_lookup(commands[i].order);
        usage_text(&commands[i], usage, sizeof(usage));
        fprintf(out, "  %-17s %s%s\n", commands[i].name, usage[0] != '\0' ? usage : "(no arguments)",
                info != NULL && info->since > 1u ? "  [V0.2]" : "");
    }
}

/* ---- parsing ------------------------------------------------------------- */

typedef struct parse_state {
    const cmd_spec *spec;
    const char *context;
    const char *given[MAX_OPTS]; /* per option: its value text (a switch: its name), NULL if absent */
    const char *cameras;         /* --cameras text, NULL if absent */
    xf_command cmd;
} parse_state;

static int fail_cmd(const parse_state *st, const char *fmt, ...) CLI_PRINTF(2, 3);

/* "xfgcu: encode track: <message>" */
static int fail_cmd(const parse_state *st, const char *fmt, ...)
{
    char msg[512];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof(msg), fmt, ap);
    va_end(ap);
    return cli_fail("%s %s: %s", st->context, st->spec->name, msg);
}

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

/* A camera mask: a number (1, 0x03), a list of camera numbers (1,2) or "all". 0 means no camera: refused. */
static int parse_cameras(const parse_state *st, const char *text, uint8_t *mask)
{
    long long v;
    if (strcmp(text, "all") == 0) {
        *mask = XF_CAM_ALL;
        return XFGCU_EXIT_OK;
    }
    if (strchr(text, ',') != NULL) {
        const char *p = text;
        unsigned m = 0;
        while (*p != '\0') {
            char *end = NULL;
            long cam = (*p >= '0' && *p <= '9') ? strtol(p, &end, 10) : 0; /* no sign, no space */
            if (cam < 1 || cam > 8 || (*end != ',' && *end != '\0')) {
                return fail_cmd(st, "--cameras %s: a list holds camera numbers 1..8, like 1,2", text);
            }
            m |= 1u << (cam - 1);
            p = (*end == ',') ? end + 1 : end;
        }
        *mask = (uint8_t)m;
        return XFGCU_EXIT_OK;
    }
    if (cli_parse_int(text, &v) != 0 || v < 1 || v > 255) {
        return fail_cmd(st, "--cameras %s: expected a mask 1..255 (1, 0x03), a list of cameras 1..8 (1,2) or all",
                        text);
    }
    *mask = (uint8_t)v;
    return XFGCU_EXIT_OK;
}

static int out_of_range(const parse_state *st, const opt_spec *o, const char *text)
{
    return fail_cmd(st, "%s %s is out of range: %s", o->name, text, o->help);
}

static int set_ints(parse_state *st, const opt_spec *o, const char *text, size_t n)
{
    long long v[4];
    size_t k;
    if (parse_int_list(text, v, n) != 0) {
        return fail_cmd(st, "%s %s: expected %s (integers)", o->name, text, o->meta);
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
    return fail_cmd(st, "%s %s: expected one of %s", o->name, text, o->meta);
}

/* Real-valued options: the physical value, checked, then converted to the raw member. */
static int set_real(parse_state *st, const opt_spec *o, const char *text)
{
    double v;
    int32_t raw;
    if (cli_parse_real(text, &v) != 0) {
        return fail_cmd(st, "%s %s: expected a number", o->name, text);
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

static const opt_spec *find_opt(const parse_state *st, const char *arg, size_t *index)
{
    size_t i;
    for (i = 0; i < st->spec->nopts; i++) {
        const char *name = st->spec->opts[i].name;
        size_t n = strlen(name);
        if (strncmp(arg, name, n) == 0 && (arg[n] == '\0' || arg[n] == '=')) {
            *index = i;
            return &st->spec->opts[i];
        }
    }
    return NULL;
}

static int take_cameras(parse_state *st, int argc, char **argv, int *i)
{
    const char *text = NULL;
    if (!takes_cameras(st->spec) || !cli_take_option(argc, argv, i, "--cameras", &text)) {
        return -1; /* not --cameras for this command */
    }
    if (text == NULL) {
        return fail_cmd(st, "--cameras needs a value: a mask (1, 0x03), a list (1,2) or all");
    }
    if (st->cameras != NULL) {
        return fail_cmd(st, "--cameras given twice");
    }
    st->cameras = text;
    return parse_cameras(st, text, &st->cmd.cameras);
}

static int take_arg(parse_state *st, int argc, char **argv, int *i)
{
    const char *arg = argv[*i];
    const char *text = NULL;
    size_t index = 0;
    const opt_spec *o;
    int rc = take_cameras(st, argc, argv, i);
    if (rc >= 0) {
        return rc;
    }
    o = find_opt(st, arg, &index);
    if (o == NULL) {
        return (arg[0] == '-')
                   ? fail_cmd(st, "unknown option '%s' (see 'xfgcu %s %s --help')", arg, st->context, st->spec->name)
                   : fail_cmd(st, "unexpected argument '%s'", arg);
    }
    if (o->kind == K_SWITCH) {
        if (strchr(arg, '=') != NULL) {
            return fail_cmd(st, "%s takes no value", o->name);
        }
        text = o->name;
    } else if (!cli_take_option(argc, argv, i, o->name, &text) || text == NULL) {
        return fail_cmd(st, "%s needs a value: %s", o->name, o->meta);
    }
    if (st->given[index] != NULL) {
        return fail_cmd(st, "%s given twice", o->name);
    }
    st->given[index] = text;
    return set_value(st, o, text);
}

/* Which choice was made; -1 for none. Refuses two. */
static int chosen_option(const parse_state *st, int *chosen)
{
    size_t i;
    *chosen = -1;
    for (i = 0; i < st->spec->nopts; i++) {
        if ((st->spec->opts[i].flags & OPT_CHOICE) != 0u && st->given[i] != NULL) {
            if (*chosen >= 0) {
                return fail_cmd(st, "%s and %s exclude each other", st->spec->opts[*chosen].name,
                                st->spec->opts[i].name);
            }
            *chosen = (int)i;
        }
    }
    return XFGCU_EXIT_OK;
}

static int check_combination(const parse_state *st)
{
    const cmd_spec *s = st->spec;
    size_t i, k;
    int chosen;
    char choices[256];
    int rc = chosen_option(st, &chosen);
    if (rc != XFGCU_EXIT_OK) {
        return rc;
    }
    choices_text(s, " or ", choices, sizeof(choices));
    if (chosen < 0 && choices[0] != '\0') {
        return fail_cmd(st, "give %s", choices);
    }
    for (i = 0; i < s->nopts; i++) {
        const opt_spec *o = &s->opts[i];
        int needed = chosen >= 0 && (s->opts[chosen].needs & NEED(i)) != 0u;
        if ((o->flags & OPT_REQUIRED) != 0u && st->given[i] == NULL) {
            return fail_cmd(st, "missing %s %s: %s", o->name, o->meta, o->help);
        }
        if (needed && st->given[i] == NULL) {
            return fail_cmd(st, "%s needs %s %s", s->opts[chosen].name, o->name, o->meta);
        }
        if (!needed && (o->flags & (OPT_REQUIRED | OPT_CHOICE)) == 0u && st->given[i] != NULL) {
            for (k = 0; k < s->nopts; k++) {
                if ((s->opts[k].needs & NEED(i)) != 0u) {
                    return fail_cmd(st, "%s goes only with %s", o->name, s->opts[k].name);
                }
            }
        }
    }
    return XFGCU_EXIT_OK;
}

static int option_covers(const opt_spec *o, const char *field)
{
    size_t k, span = (o->kind == K_BOX) ? 4u : (o->kind == K_POINT || o->kind == K_OFFSET) ? 2u : 1u;
    for (k = 0; k < span; k++) {
        if (strcmp(xf_field_name((xf_field)(o->field + k)), field) == 0) {
            return 1;
        }
    }
    return 0;
}

/* The codec's own range check; its bad_field names the member, mapped back to the option given. */
static int check_with_codec(const parse_state *st, uint8_t version)
{
    const char *bad = NULL;
    size_t i;
    xf_err err = xf_command_check(&st->cmd, version, &bad);
    if (err == XF_OK) {
        return XFGCU_EXIT_OK;
    }
    for (i = 0; bad != NULL && i < st->spec->nopts; i++) {
        const opt_spec *o = &st->spec->opts[i];
        if (st->given[i] != NULL && o->kind != K_SWITCH && option_covers(o, bad)) {
            if ((o->flags & OPT_BY_VERSION) != 0u) {
                return fail_cmd(st, "%s %s is out of range for protocol %u: %s", o->name, st->given[i],
                                (unsigned)version, o->help);
            }
            return out_of_range(st, o, st->given[i]);
        }
    }
    return fail_cmd(st, "%s%s%s", xf_strerror(err), bad != NULL ? ": " : "", bad != NULL ? bad : "");
}

int cmdargs_parse(const cmd_spec *spec, const char *context, int argc, char **argv, uint8_t version, xf_command *cmd)
{
    parse_state st;
    int i, rc;
    const xf_order_info *info = xf_order_lookup(spec->order);
    memset(&st, 0, sizeof(st));
    st.spec = spec;
    st.context = context;
    xf_command_init(&st.cmd, spec->order); /* the spec's default camera mask */
    for (i = 1; i < argc; i++) {
        rc = take_arg(&st, argc, argv, &i);
        if (rc != XFGCU_EXIT_OK) {
            return rc;
        }
    }
    rc = check_combination(&st);
    if (rc == XFGCU_EXIT_OK) {
        rc = check_with_codec(&st, version);
    }
    if (rc != XFGCU_EXIT_OK) {
        return rc;
    }
    if (info != NULL && info->since > version) {
        /* Warn, never refuse: a V0.1 GCU may or may not know the order. */
        cli_note("%s is an order of protocol %u (V0.2); this packet says version %u (add --protocol 2)", spec->name,
                 (unsigned)info->since, (unsigned)version);
    }
    *cmd = st.cmd;
    return XFGCU_EXIT_OK;
}

int cmd_line_take(cmd_line *c, int argc, char **argv, int *i, int *rc)
{
    const char *v = NULL;
    *rc = XFGCU_EXIT_OK;
    if (cli_take_option(argc, argv, i, "--protocol", &v)) {
        *rc = cli_parse_protocol(v, &c->version);
    } else if (strcmp(argv[*i], "--help") == 0) {
        c->help = 1;
    } else if (c->spec != NULL) {
        c->cargv[c->cargc++] = argv[*i];
    } else {
        return 0;
    }
    return 1;
}

int cmd_line_command(cmd_line *c, const char *who, char *arg)
{
    if (arg[0] == '-') {
        return cli_fail("%s: unknown option '%s' (see 'xfgcu %s --help')", who, arg, who);
    }
    if ((c->spec = cmdargs_find(arg)) == NULL) {
        return cli_fail("%s: unknown command '%s' (see 'xfgcu %s --help')", who, arg, who);
    }
    c->cargv[c->cargc++] = arg;
    return XFGCU_EXIT_OK;
}
