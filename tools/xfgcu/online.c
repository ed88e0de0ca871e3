/*
 * online.c - the link of the options, a client on it, and running one
 * command the protocol's way (see online.h).
 */
#define _POSIX_C_SOURCE 200809L /* sigaction */

#include "online.h"
#include "cmdargs.h"
#include "jsonpkt.h"
#include "linkopts.h"

#include <poll.h>
#include <math.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

/* ---- signals ------------------------------------------------------------------ */

static volatile sig_atomic_t stop_flag = 0;

static void on_signal(int sig)
{
    (void)sig;
    stop_flag = 1;
}

void cli_signals_init(void)
{
    struct sigaction sa;
    memset(&sa, 0, sizeof(sa));
    sa.sa_handler = on_signal;
    sigemptyset(&sa.sa_mask);
    sa.sa_flags = 0; /* no SA_RESTART: poll() returns at once */
    sigaction(SIGINT, &sa, NULL);
    sigaction(SIGTERM, &sa, NULL);
    sa.sa_handler = SIG_IGN;
    sigaction(SIGPIPE, &sa, NULL); /* a peer that went away is an error code, not a death */
}

int cli_stop_requested(void) { return stop_flag != 0; }

/* ---- helpers ------------------------------------------------------------------ */

double cli_seconds(uint32_t ms) { return (double)ms / 1000.0; }

double cli_wrap180(double deg) { return xf_units_wrap360(deg, -180.0); }

/* ---- opening ------------------------------------------------------------------ */

online *online_new(void)
{
    online *o = calloc(1, sizeof(*o));
    if (o == NULL) {
        cli_fail("out of memory");
    }
    return o;
}

static void settle(online *o)
{
    uint32_t start = xf_posix_now_ms();
    uint32_t limit = 2u * (uint32_t)o->opt->timeout_ms + (uint32_t)o->opt->reorder_ms;
    /* after Ctrl-C or SIGTERM, a person is waiting: only what the link needs for --reorder and a
     * few packets, then the note */
    uint32_t hurried = (uint32_t)o->opt->reorder_ms + 3000u / (uint32_t)o->opt->rate_hz;
    while (!xf_client_settled(&o->client) && xf_client_link(&o->client) != XF_LINK_DOWN &&
           xf_ms_since(xf_posix_now_ms(), start) < (cli_stop_requested() ? hurried : limit)) {
        online_poll(o, 10);
    }
    if (!xf_client_settled(&o->client) && xf_client_link(&o->client) != XF_LINK_DOWN) {
        cli_note("replies to the last command may still be on the link (%s): a command of the same order run "
                 "right after this one could take one for its own",
                 o->desc);
    }
}

void online_free(online *o)
{
    if (o == NULL) {
        return;
    }
    if (o->client_on) {
        settle(o);
    }
    xf_link_close(&o->link);
    free(o);
}

/* ---- waiting for the GCU (monitor --wait) ---------------------------------------------- */

/* online_open() began waiting at @p start and the GCU is not up: is there time left for it, by
 * online.wait_ms (never less than --timeout)? Past --timeout, a note says once that it waits, and @p why. */
static int keep_waiting(online *o, uint32_t start, const char *why)
{
    uint32_t waited = xf_ms_since(xf_posix_now_ms(), start);
    uint32_t limit = (o->wait_ms > (uint32_t)o->opt->timeout_ms) ? o->wait_ms : (uint32_t)o->opt->timeout_ms;
    if (o->wait_ms == 0u || cli_stop_requested() || (o->wait_ms != ONLINE_WAIT_FOREVER && waited >= limit)) {
        return 0;
    }
    if (o->wait_note && waited >= (uint32_t)o->opt->timeout_ms) {
        o->wait_note = 0;
        if (o->wait_ms == ONLINE_WAIT_FOREVER) {
            cli_note("waiting for the GCU on %s (%s); Ctrl-C to stop", o->desc[0] ? o->desc : o->option, why);
        } else {
            cli_note("waiting up to %.1f s for the GCU on %s (%s)", cli_seconds(o->wait_ms),
                     o->desc[0] ? o->desc : o->option, why);
        }
    }
    return 1;
}

/* What a silent GCU's user should check, for the one line: the versions tried, the link's own
 * settings by its kind, power and wiring, and probe. */
static void silence_hint(const online *o, char *buf, size_t cap)
{
    unsigned both = (1u << XF_PROTOCOL_V1) | (1u << XF_PROTOCOL_V2);
    const char *tried = ((o->versions_sent & both) == both) ? "protocol versions 1 and 2 tried"
                        : o->opt->version_auto              ? "one protocol version tried: give a longer --timeout"
                                                            : "one protocol version sent: --protocol auto tries both";
    const char *check = (o->link.spec.kind == XF_LINK_KIND_SERIAL) ? "the device and --baud"
                        : (o->link.spec.kind == XF_LINK_KIND_UDP)
                            ? "the address, the GCU's UDP port and the local port it answers to (--local-port)"
                            : "the address and TCP port";
    snprintf(buf, cap, " (%s): check %s, the GCU's power and wiring, then try 'xfgcu probe' on this link", tried,
             check);
}

/* The one line when a wait (online.wait_ms) ends with no GCU. */
static int waited_in_vain(const online *o, uint32_t start, const char *why)
{
    const char *where = o->desc[0] ? o->desc : o->option;
    char hint[256] = "";
    if (cli_stop_requested()) {
        return cli_fail_link("%s: interrupted while waiting for the GCU on %s", o->context, where);
    }
    if (o->client_on) { /* the link opened: the GCU is silent */
        silence_hint(o, hint, sizeof(hint));
    }
    return cli_fail_link("no answer from the GCU on %s within %.1f s%s%s%s", where,
                         cli_seconds(xf_ms_since(xf_posix_now_ms(), start)), why ? ": " : "", why ? why : "", hint);
}

static int open_link(online *o, uint32_t start)
{
    uint32_t slice = (o->wait_ms > 0u) ? 100u : (uint32_t)o->opt->timeout_ms; /* waiting: look at signals often */
    xf_err err;
    xf_link_spec spec;
    int rc = linkopts_spec(o->opt, &spec, o->option, sizeof(o->option));
    if (rc != XFGCU_EXIT_OK) {
        return rc;
    }
    for (;;) { /* with a wait, a link that cannot open yet (no device, TCP refused) is tried again */
        err = o->link.is_open ? XF_OK : xf_link_open_spec(&o->link, &spec);
        if (err == XF_OK && xf_link_wait(&o->link, slice) == XF_OK) {
            break;
        }
        if (!keep_waiting(o, start, xf_link_error(&o->link)->text)) {
            return (o->wait_ms > 0u) ? waited_in_vain(o, start, xf_link_error(&o->link)->text)
                                     : cli_fail_link("%s: %s", o->option, xf_link_error(&o->link)->text);
        }
        if (!o->link.is_open) {
            (void)poll(NULL, 0, 100);
        }
    }
    (void)xf_link_describe(&o->link, o->desc, sizeof(o->desc));
    return xf_link_hal(&o->link, &o->raw) == XF_OK ? XFGCU_EXIT_OK : cli_fail_link("%s: not open", o->option);
}

/* The tap's clock: the one the commands step the client with. */
static uint32_t tap_clock(void *user)
{
    (void)user;
    return xf_posix_now_ms();
}

/* --trace: one line per packet on stderr, "trace SECONDS > order ..." (sent) or "<" (received). */
static void trace_packet(const online *o, xf_direction dir, const uint8_t *data, size_t len, uint32_t now_ms)
{
    uint8_t order = data[XF_OFF_ORDER];
    const char *name = xf_order_name(order);
    char extra[160] = "";
    if (dir == XF_DIR_GCU) {
        xf_gcu_packet g;
        xf_feedback fb;
        if (xf_gcu_unpack(data, len, &g) == XF_OK) {
            /* the unit rule: degrees, or with --raw the wire integers (monitor's names) */
            int n = (o->opt->view == TEXT_RAW)
                        ? snprintf(extra, sizeof(extra), ", mode 0x%02X, cam_roll %d cam_pitch %d cam_yaw %u",
                                   g.main.gimbal_mode, g.main.cam_roll, g.main.cam_pitch, (unsigned)g.main.cam_yaw)
                        : snprintf(extra, sizeof(extra), ", mode 0x%02X, roll %.2f pitch %.2f yaw %.2f deg",
                                   g.main.gimbal_mode, (double)xf_cdeg(g.main.cam_roll),
                                   (double)xf_cdeg(g.main.cam_pitch), (double)xf_cdeg(g.main.cam_yaw));
            if (n > 0 && xf_feedback_decode(order, g.params, g.params_len, &fb) == XF_OK && fb.has_state) {
                snprintf(extra + n, sizeof(extra) - (size_t)n, ", state 0x%02X", fb.state);
            }
        }
    } else if (data[XF_OFF_HOST_STATUS] & XF_STATUS_CTRL_VALID) {
        snprintf(extra, sizeof(extra), ", control valid");
    }
    fprintf(stderr, "trace %.3f %s %s (0x%02X), %u bytes%s\n", cli_seconds(xf_ms_since(now_ms, o->t0_ms)),
            dir == XF_DIR_HOST ? ">" : "<", name != NULL ? name : "unknown", order, (unsigned)len, extra);
}

static void online_on_bytes(void *user, xf_direction dir, const uint8_t *data, size_t len, uint32_t now_ms)
{
    online *o = (online *)user;
    if (dir == XF_DIR_HOST && data[XF_OFF_VERSION] < 8u) {
        o->versions_sent |= 1u << data[XF_OFF_VERSION];
    }
    if (o->opt->trace) {
        trace_packet(o, dir, data, len, now_ms);
    }
    if (o->hooks.on_bytes != NULL) {
        o->hooks.on_bytes(o->hooks.user, dir, data, len, now_ms);
    }
}

static void online_on_link(void *user, xf_link_state state)
{
    online *o = (online *)user;
    if (o->opt->trace) {
        fprintf(stderr, "trace %.3f link %s\n", cli_seconds(xf_ms_since(xf_posix_now_ms(), o->t0_ms)),
                xf_link_state_name(state));
    }
    if (o->hooks.on_link != NULL) {
        o->hooks.on_link(o->hooks.user, state);
    }
}

static int start_client(online *o, const online_hooks *hooks)
{
    xf_client_config cc;
    xf_err err;
    xf_client_config_init(&cc);
    cc.protocol_version = o->opt->protocol;
    cc.rate_hz = (uint16_t)o->opt->rate_hz;
    cc.command_timeout_ms = (uint32_t)o->opt->timeout_ms;
    cc.reorder_ms = (uint16_t)o->opt->reorder_ms;
    /* given: the user's bound, 0 included; a serial line and TCP keep order, so there is nothing to judge */
    cc.reorder_fixed = (uint8_t)(o->opt->has_reorder != 0 || xf_link_keeps_order(&o->link.spec));
    cc.version_auto = o->opt->version_auto;
    if (hooks != NULL) {
        o->hooks = *hooks;
    }
    cc.on_bytes = online_on_bytes; /* --trace, then the command's */
    cc.on_link = online_on_link;
    cc.user = o;
    o->hal = o->raw;
    if (hooks != NULL && hooks->tap != NULL) {
        xf_tap_init(&o->tap, &o->raw, hooks->tap, tap_clock, hooks->user, &o->hal);
    }
    err = xf_client_init(&o->client, &o->hal, &cc);
    o->client_on = (err == XF_OK || err == XF_WARN_RATE);
    if (err == XF_WARN_RATE) {
        cli_note("--rate %ld: outside the 30-50 packets per second the vendor recommends; going on", o->opt->rate_hz);
    } else if (err != XF_OK) {
        const char *why = xf_client_config_problem(&cc);
        return cli_fail("%s: cannot start the client: %s", o->context, why != NULL ? why : xf_strerror(err));
    }
    return XFGCU_EXIT_OK;
}

/* Why the GCU may be silent, from the link's own error, when it has one. */
static const char *link_error(const online *o)
{
    const char *text = xf_link_error(&o->link)->text;
    return xf_client_health(&o->client)->transport_closed && text[0] != '\0' ? text : NULL;
}

/* The first reply within --timeout, or within the wait (online.wait_ms) that began at @p wait_start. */
static int wait_first_reply(online *o, uint32_t wait_start)
{
    uint32_t start = xf_posix_now_ms();
    uint32_t limit = (uint32_t)o->opt->timeout_ms;
    const char *why;
    char hint[256];
    while (xf_client_link(&o->client) != XF_LINK_UP) {
        if (cli_stop_requested()) {
            return cli_fail_link("%s: interrupted while waiting for the GCU on %s", o->context, o->desc);
        }
        if (xf_ms_since(xf_posix_now_ms(), start) >= limit) {
            why = link_error(o);
            if (keep_waiting(o, wait_start, why ? why : "no answer yet")) {
                online_poll(o, 20);
                continue;
            }
            if (o->wait_ms > 0u) {
                return waited_in_vain(o, wait_start, why);
            }
            silence_hint(o, hint, sizeof(hint));
            return cli_fail_link("no answer from the GCU on %s within %u ms%s%s%s", o->desc, (unsigned)limit,
                                 why ? ": " : "", why ? why : "", hint);
        }
        online_poll(o, 20);
    }
    o->up_ms = xf_ms_since(xf_posix_now_ms(), start);
    return XFGCU_EXIT_OK;
}

int online_open(online *o, const cli_link *opt, const char *context, const online_hooks *hooks)
{
    int rc = linkopts_require(opt, context);
    o->opt = opt;
    o->context = context;
    if (rc == XFGCU_EXIT_OK) {
        rc = linkopts_check(opt);
    }
    if (rc == XFGCU_EXIT_OK) {
        rc = linkopts_check_timing(opt); /* before anything is opened: a usage error, not a link error */
    }
    if (rc == XFGCU_EXIT_OK) {
        o->t0_ms = xf_posix_now_ms();
        rc = open_link(o, o->t0_ms);
    }
    if (rc == XFGCU_EXIT_OK) {
        rc = start_client(o, hooks);
    }
    if (rc == XFGCU_EXIT_OK) {
        rc = wait_first_reply(o, o->t0_ms);
    }
    return rc;
}

int online_run_mode(online *o, uint8_t order, int json, xf_cmd_result *r)
{
    xf_command cmd;
    int rc;
    xf_client_clear_control(&o->client); /* nothing the mode before would read its own way */
    xf_command_init(&cmd, order);
    rc = online_run(o, &cmd, r, NULL, NULL);
    if (rc == XFGCU_EXIT_OK && json) {
        json_t *obj = online_result_json(r);
        if (obj != NULL) {
            json_object_set_new(obj, "step", json_string("mode"));
            json_object_set_new(obj, "link", json_string(o->desc));
        }
        (void)cli_json_line(obj);
    }
    return rc;
}

int online_run_in_mode(const cli_link *opt, const char *context, uint8_t order, const char *what, int json,
                       online_mode_fn then, const void *args)
{
    online *o = online_new();
    xf_cmd_result r;
    int rc = (o != NULL) ? XFGCU_EXIT_OK : XFGCU_EXIT_USAGE;
    cli_signals_init();
    if (rc == XFGCU_EXIT_OK) {
        rc = online_open(o, opt, context, NULL);
    }
    if (rc == XFGCU_EXIT_OK) {
        rc = online_run_mode(o, order, json, &r);
    }
    if (rc == XFGCU_EXIT_OK) {
        rc = online_result_exit(o, what, &r);
    }
    if (rc == XFGCU_EXIT_OK) {
        rc = then(o, args);
    }
    online_free(o);
    return rc;
}

/* ---- the loop ---------------------------------------------------------------------- */

void online_poll(online *o, int max_wait_ms)
{
    xf_client *clients[1];
    clients[0] = &o->client;
    (void)xf_posix_poll(clients, 1, NULL, 0, max_wait_ms);
}

void online_linger(online *o, uint32_t packets)
{
    uint32_t start = xf_posix_now_ms();
    uint32_t target = xf_client_health(&o->client)->packets_sent + packets;
    uint32_t limit = 200u + packets * 3u * 1000u / (uint32_t)o->opt->rate_hz;
    while ((int32_t)(xf_client_health(&o->client)->packets_sent - target) < 0 &&
           xf_ms_since(xf_posix_now_ms(), start) < limit) {
        online_poll(o, 20);
    }
}

/* ---- JSON lines ------------------------------------------------------------------ */

json_t *cli_json_times(json_t *obj)
{
    struct timespec mono, wall;
    clock_gettime(CLOCK_MONOTONIC, &mono);
    clock_gettime(CLOCK_REALTIME, &wall);
    return jsonpkt_times(obj, &mono, &wall);
}

json_t *online_field_json(const online *o, const char *name, int64_t raw)
{
    return jsonpkt_value(xf_wire_field_find(XF_WIRE_GCU, name), raw, xf_client_telemetry(&o->client)->version,
                         o->opt->view);
}

int cli_json_line(json_t *obj)
{
    char *text = jsonpkt_dumps(obj); /* the text layer's numbers: each value with the digits of its step */
    json_decref(obj);
    if (text == NULL) {
        return -1;
    }
    puts(text);
    free(text);
    fflush(stdout);
    return 0;
}

static const char *status_key(xf_cmd_status st)
{
    switch (st) {
    case XF_CMD_OK: return "ok";
    case XF_CMD_FAILED: return "failed";
    case XF_CMD_TIMEOUT: return "timeout";
    case XF_CMD_LINK_LOST: return "link_lost";
    case XF_CMD_CANCELLED: return "cancelled";
    case XF_CMD_OPERATING: return "operating";
    default: return xf_cmd_status_name(st);
    }
}

json_t *online_result_json(const xf_cmd_result *r)
{
    const char *name = xf_order_name(r->order);
    json_t *o = cli_json_times(json_object());
    if (o == NULL) {
        return NULL;
    }
    json_object_set_new(o, "status", json_string(status_key(r->status)));
    json_object_set_new(o, "order", json_integer(r->order));
    json_object_set_new(o, "order_name", name != NULL ? json_string(name) : json_null());
    json_object_set_new(o, "state", json_integer(r->state));
    json_object_set_new(o, "failed_cameras", json_integer(r->failed_cameras));
    json_object_set_new(o, "packets", json_integer(r->packets));
    json_object_set_new(o, "elapsed_ms", json_integer((json_int_t)r->elapsed_ms));
    return o;
}

/* ---- one command ------------------------------------------------------------------- */

static void report_progress(uint32_t id, online_progress_fn progress, void *user, uint32_t *since, int *reported)
{
    uint32_t now = xf_posix_now_ms();
    xf_cmd_result r;
    if (progress == NULL || (*reported && xf_ms_since(now, *since) / 5000u < (uint32_t)*reported)) {
        return;
    }
    if (!*reported) {
        *since = now;
    }
    memset(&r, 0, sizeof(r));
    r.id = id;
    r.status = XF_CMD_OPERATING;
    r.state = XF_STATE_OPERATING;
    progress(user, &r, xf_ms_since(now, *since));
    (*reported)++;
}

int online_run(online *o, const xf_command *cmd, xf_cmd_result *result, online_progress_fn progress, void *user)
{
    uint32_t id = 0, since = 0;
    int reported = 0;
    xf_field bad = XF_F_NONE;
    xf_command sent = *cmd;
    xf_err err;
    cmdargs_for_version(&sent, xf_client_gcu_version(&o->client)); /* the GCU has answered: its meaning */
    err = xf_client_submit_opt(&o->client, &sent, o->submit_flags, &id, &bad);
    memset(result, 0, sizeof(*result));
    result->order = cmd->order;
    if (err == XF_ERR_UNSUPPORTED) {
        const xf_telemetry *t = xf_client_telemetry(&o->client);
        const char *model = xf_gimbal_model(t->gimbal_code);
        return cli_report(XFGCU_EXIT_FAILED, NULL,
                          "%s %s: the GCU's model %s (code %u) does not support it, by V2.0.6's support list; "
                          "xfgcu send --force sends it all the same",
                          o->context, xf_order_name(cmd->order), model != NULL ? model : "?", (unsigned)t->gimbal_code);
    }
    if (err != XF_OK) {
        return cli_fail("%s %s: %s%s%s", o->context, xf_order_name(cmd->order), xf_strerror(err),
                        bad != XF_F_NONE ? ": " : "", bad != XF_F_NONE ? xf_field_name(bad) : "");
    }
    /* the library's wait, in slices: between them, a signal cancels and progress is shown */
    while ((err = xf_posix_wait(&o->client, id, 20, result, NULL, 0)) == XF_ERR_TIMEOUT) {
        if (cli_stop_requested()) {
            xf_client_cancel_all(&o->client); /* the next slice sees it cancelled */
        } else if (result->status == XF_CMD_OPERATING) {
            report_progress(id, progress, user, &since, &reported);
        }
    }
    if (err != XF_OK) { /* forgotten (cannot happen with one command at a time), or poll() failed */
        memset(result, 0, sizeof(*result));
        result->id = id;
        result->order = cmd->order;
        result->status = XF_CMD_TIMEOUT;
    }
    return XFGCU_EXIT_OK;
}

void online_result_text(const xf_cmd_result *r, char *buf, size_t cap)
{
    switch (r->status) {
    case XF_CMD_OK: snprintf(buf, cap, "ok"); break;
    case XF_CMD_FAILED:
        if (r->failed_cameras != 0u) {
            snprintf(buf, cap, "failed cameras 0x%02X", r->failed_cameras);
        } else {
            snprintf(buf, cap, "failed");
        }
        break;
    case XF_CMD_TIMEOUT: snprintf(buf, cap, "timeout"); break;
    case XF_CMD_LINK_LOST: snprintf(buf, cap, "link lost"); break;
    case XF_CMD_CANCELLED: snprintf(buf, cap, "interrupted"); break;
    default: snprintf(buf, cap, "%s", xf_cmd_status_name(r->status)); break;
    }
}

int online_result_exit(const online *o, const char *what, const xf_cmd_result *r)
{
    char text[64];
    const char *why;
    online_result_text(r, text, sizeof(text));
    switch (r->status) {
    case XF_CMD_OK: return XFGCU_EXIT_OK;
    case XF_CMD_FAILED:
        cli_fail("%s: the GCU answered %s (state 0x%02X) on %s", what, text, r->state, o->desc);
        return XFGCU_EXIT_FAILED;
    case XF_CMD_TIMEOUT:
        return cli_fail_link("%s: no execution state from the GCU on %s within %ld ms", what, o->desc,
                             o->opt->timeout_ms);
    case XF_CMD_CANCELLED: return cli_fail_link("%s: interrupted before the GCU answered on %s", what, o->desc);
    default:
        why = link_error(o);
        return cli_fail_link("%s: link lost on %s%s%s", what, o->desc, why ? ": " : "", why ? why : "");
    }
}

void online_attitude_text(const xf_telemetry *t, char *buf, size_t cap)
{
    snprintf(buf, cap, "roll %.2f pitch %.2f yaw %.2f deg", (double)xf_cdeg(t->cam_roll), (double)xf_cdeg(t->cam_pitch),
             (double)xf_cdeg(t->cam_yaw));
}

/* ---- the client's health ------------------------------------------------------------ */

json_t *online_health_json(const online *o)
{
    const xf_health *h = xf_client_health(&o->client);
    json_t *obj = json_object();
    if (obj == NULL) {
        return NULL;
    }
    json_object_set_new(obj, "version_setting",
                        o->opt->version_auto ? json_string("auto") : json_integer(o->opt->protocol));
    json_object_set_new(obj, "version_sent", json_integer(h->version_sent));
    json_object_set_new(obj, "version_answered", h->version_answered ? json_integer(h->version_answered) : json_null());
    json_object_set_new(obj, "gcu_version", h->replies ? json_integer(xf_client_gcu_version(&o->client)) : json_null());
    json_object_set_new(obj, "in_order", json_boolean(h->in_order));
    json_object_set_new(obj, "out_of_turn", json_integer((json_int_t)h->out_of_turn));
    json_object_set_new(obj, "reorder_ms", json_integer(h->reorder_ms));
    json_object_set_new(obj, "reorder_fixed", json_boolean(o->opt->has_reorder || xf_link_keeps_order(&o->link.spec)));
    json_object_set_new(obj, "replies", json_integer((json_int_t)h->replies));
    json_object_set_new(obj, "given_up", json_integer((json_int_t)xf_client_parser_stats(&o->client)->given_up));
    return obj;
}

void online_health_text(const online *o, char *buf, size_t cap)
{
    const xf_health *h = xf_client_health(&o->client);
    char version[64];
    if (h->version_answered != 0u) {
        snprintf(version, sizeof(version), "protocol version %u answered (%s)", (unsigned)h->version_answered,
                 o->opt->version_auto ? "auto" : "--protocol");
    } else {
        snprintf(version, sizeof(version), "no protocol version answered yet (sending %u)", (unsigned)h->version_sent);
    }
    snprintf(buf, cap, "%s, link %s, reorder bound %u ms%s, %lu replies out of turn, %lu frames given up", version,
             h->in_order ? "in order" : "not shown in order", (unsigned)h->reorder_ms,
             o->opt->has_reorder ? " (--reorder)" : "", (unsigned long)h->out_of_turn,
             (unsigned long)xf_client_parser_stats(&o->client)->given_up);
}

/* ---- packets outside the client (probe's questions) -------------------------------- */

xf_err online_raw_send(online *o, const uint8_t *data, size_t len)
{
    xf_err err = o->hal.write(o->hal.ctx, data, len);
    if (err == XF_OK) {
        online_on_bytes(o, XF_DIR_HOST, data, len, xf_posix_now_ms());
    }
    return err;
}

unsigned online_raw_read(online *o, uint32_t ms, void (*got)(void *user, const uint8_t *data, size_t len), void *user)
{
    xf_parser parser;
    uint8_t buf[256];
    uint32_t start = xf_posix_now_ms(), waited;
    unsigned n = 0;
    (void)xf_parser_init(&parser, XF_DIR_GCU);
    while ((waited = xf_ms_since(xf_posix_now_ms(), start)) < ms) {
        struct pollfd pfd;
        size_t got_len = 0, taken = 0, used = 0;
        xf_frame frame;
        pfd.fd = xf_hal_fd(&o->hal);
        pfd.events = POLLIN;
        (void)poll(&pfd, pfd.fd >= 0 ? 1u : 0u, (int)(ms - waited));
        if (xf_hal_read(&o->hal, buf, sizeof(buf), &got_len) != XF_OK) {
            break;
        }
        while (xf_parser_feed(&parser, buf + taken, got_len - taken, &used, &frame) == XF_PARSE_FRAME) {
            taken += used;
            online_on_bytes(o, XF_DIR_GCU, frame.data, frame.len, xf_posix_now_ms());
            got(user, frame.data, frame.len);
            n++;
        }
    }
    return n;
}
