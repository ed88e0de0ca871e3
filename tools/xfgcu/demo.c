/*
 * demo.c - the harness of `xfgcu demo` (see demo.h).
 */
#include "demo.h"

#include <stdarg.h>
#include <string.h>

#include "online.h"

/* ---- the simulator and the client ------------------------------------------------ */

static void on_bytes(void *user, xf_direction dir, const uint8_t *data, size_t len, uint32_t now_ms)
{
    demo *d = (demo *)user;
    uint8_t order;
    (void)now_ms;
    if (!d->logging || dir != XF_DIR_HOST || len <= XF_OFF_ORDER) {
        return;
    }
    order = data[XF_OFF_ORDER];
    if (d->log_n > 0 && d->log_order[d->log_n - 1] == order) {
        d->log_count[d->log_n - 1]++;
    } else if (d->log_n < DEMO_LOG_MAX) {
        d->log_order[d->log_n] = order;
        d->log_count[d->log_n] = 1;
        d->log_n++;
    }
}

static int start_sim(demo *d)
{
    xf_sim_config sc;
    xf_hal hal;
    if (xf_simlink_open_tcp(&d->gcu_link, "127.0.0.1", 0) != XF_OK) {
        return cli_fail_link("demo: cannot start the simulated GCU: %s", d->gcu_link.error.text);
    }
    xf_simlink_hal(&d->gcu_link, &hal);
    xf_sim_config_init(&sc);
    sc.calibration_ms = 1000; /* a real gimbal takes longer; the tour is short */
    if (xf_sim_init(&d->sim, &sc) != XF_OK || xf_sim_attach(&d->sim, &hal) != XF_OK) {
        return cli_fail("demo: cannot start the simulated GCU");
    }
    return XFGCU_EXIT_OK;
}

static int start_client(demo *d)
{
    char spec[128];
    xf_client_config cc;
    xf_hal hal;
    (void)xf_simlink_host_spec(&d->gcu_link, spec, sizeof(spec));
    if (xf_link_open(&d->link, spec) != XF_OK || xf_link_wait(&d->link, 2000) != XF_OK ||
        xf_link_hal(&d->link, &hal) != XF_OK) {
        return cli_fail_link("demo: cannot connect to the simulated GCU: %s", xf_link_error(&d->link)->text);
    }
    xf_client_config_init(&cc);
    cc.on_bytes = on_bytes;
    cc.user = d;
    if (xf_client_init(&d->client, &hal, &cc) != XF_OK) {
        return cli_fail("demo: cannot start the client");
    }
    return XFGCU_EXIT_OK;
}

int demo_start(demo *d)
{
    int rc = start_sim(d);
    if (rc == XFGCU_EXIT_OK) {
        rc = start_client(d);
    }
    d->t0 = xf_posix_now_ms();
    d->mark = d->t0;
    return rc;
}

void demo_stop(demo *d)
{
    xf_link_close(&d->link);
    xf_simlink_close(&d->gcu_link);
}

/* ---- the loop ------------------------------------------------------------------------- */

static void refresh(demo *d, uint32_t now)
{
    if (d->rates_on) {
        xf_client_set_rates(&d->client, 0.0f, d->rate_pitch, d->rate_yaw, now); /* every loop: the watchdog */
    }
    xf_client_set_gnss(&d->client, &d->gnss, now);
}

static void poll_once(demo *d)
{
    xf_client *clients[1];
    xf_sim *sims[1];
    clients[0] = &d->client;
    sims[0] = &d->sim;
    refresh(d, xf_posix_now_ms());
    (void)xf_posix_poll(clients, 1, sims, 1, 10);
}

int demo_pump(demo *d, uint32_t ms)
{
    uint32_t start = xf_posix_now_ms();
    while (xf_ms_since(xf_posix_now_ms(), start) < ms) {
        if (cli_stop_requested()) {
            return 0;
        }
        poll_once(d);
    }
    return 1;
}

long demo_pump_until(demo *d, uint32_t ms, int (*done)(const demo *d))
{
    uint32_t start = xf_posix_now_ms();
    while (!done(d)) {
        if (cli_stop_requested() || xf_ms_since(xf_posix_now_ms(), start) >= ms) {
            return -1;
        }
        poll_once(d);
    }
    return (long)xf_ms_since(xf_posix_now_ms(), start);
}

xf_cmd_status demo_command(demo *d, const xf_command *cmd, const char *what, xf_cmd_status want, xf_cmd_result *out)
{
    xf_cmd_result r;
    uint32_t id = 0;
    char text[64];
    xf_cmd_status st;
    int operating = 0;
    memset(&r, 0, sizeof(r));
    demo_sent("%s (order 0x%02X) in every packet until a reply carries its state", what, cmd->order);
    if (xf_client_submit(&d->client, cmd, &id, NULL) != XF_OK) {
        demo_check(d, 0, "%s: the client refused it", what);
        return XF_CMD_UNKNOWN;
    }
    while ((st = xf_client_command_status(&d->client, id, &r)) <= XF_CMD_OPERATING && st != XF_CMD_UNKNOWN) {
        if (st == XF_CMD_OPERATING && !operating) {
            operating = 1;
            demo_got("%s: operating...", xf_order_name(cmd->order));
        }
        if (cli_stop_requested()) {
            xf_client_cancel_all(&d->client);
        }
        poll_once(d);
    }
    online_result_text(&r, text, sizeof(text));
    demo_got("%s: %s (%u packet%s, %u ms)", xf_order_name(cmd->order), text, (unsigned)r.packets,
             r.packets == 1u ? "" : "s", (unsigned)r.elapsed_ms);
    demo_check(d, st == want, "%s: expected %s, got %s", what, xf_cmd_status_name(want), text);
    if (out != NULL) {
        *out = r;
    }
    return st;
}

void demo_rates(demo *d, float pitch_dps, float yaw_dps)
{
    d->rates_on = 1;
    d->rate_pitch = pitch_dps;
    d->rate_yaw = yaw_dps;
}

void demo_rates_off(demo *d)
{
    d->rates_on = 0;
    xf_client_set_rates(&d->client, 0.0f, 0.0f, 0.0f, xf_posix_now_ms());
    (void)demo_pump(d, 100); /* a few packets of zero rates: the gimbal holds */
    xf_client_clear_control(&d->client);
}

void demo_log_start(demo *d)
{
    d->log_n = 0;
    d->logging = 1;
}

void demo_log_text(demo *d, char *buf, size_t cap)
{
    int i;
    size_t n = 0;
    buf[0] = '\0';
    d->logging = 0;
    for (i = 0; i < d->log_n && n + 1u < cap; i++) {
        const char *name = xf_order_name(d->log_order[i]);
        int w = snprintf(buf + n, cap - n, "%s%s x%u", i > 0 ? ", " : "", name ? name : "?", (unsigned)d->log_count[i]);
        n += (w > 0) ? (size_t)w : 0u;
    }
}

const xf_telemetry *demo_tele(const demo *d) { return xf_client_telemetry(&d->client); }

double demo_since(const demo *d) { return cli_seconds(xf_ms_since(xf_posix_now_ms(), d->mark)); }

void demo_mark(demo *d) { d->mark = xf_posix_now_ms(); }

/* ---- printing --------------------------------------------------------------------------- */

static void line(const char *prefix, const char *fmt, va_list ap) CLI_PRINTF(2, 0);

static void line(const char *prefix, const char *fmt, va_list ap)
{
    fputs(prefix, stdout);
    vprintf(fmt, ap);
    putchar('\n');
    fflush(stdout);
}

void demo_step(demo *d, const char *fmt, ...)
{
    va_list ap;
    char prefix[32];
    d->step++;
    snprintf(prefix, sizeof(prefix), "\n[%2d] ", d->step);
    va_start(ap, fmt);
    line(prefix, fmt, ap);
    va_end(ap);
    demo_mark(d);
}

void demo_line(const char *prefix, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    line(prefix, fmt, ap);
    va_end(ap);
}

int demo_check(demo *d, int ok, const char *fmt, ...)
{
    va_list ap;
    char msg[160];
    if (ok) {
        return 1;
    }
    va_start(ap, fmt);
    vsnprintf(msg, sizeof(msg), fmt, ap);
    va_end(ap);
    printf("     !! %s\n", msg);
    fflush(stdout);
    if (d->failure[0] == '\0') {
        snprintf(d->failure, sizeof(d->failure), "step %d: %s", d->step, msg);
    }
    return 0;
}
