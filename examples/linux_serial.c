/*
 * linux_serial.c - a gimbal on a UART (TTL, 8N1): calibrate, then feed it
 * the carrier's attitude while printing what it reports.
 *
 *   linux_serial [SPEC]   e.g. serial:/dev/ttyUSB0 or serial:/dev/ttyUSB0,baud=115200
 *   (no SPEC: a built-in simulator on a pseudo-terminal)
 */
#include <stdio.h>

#include "xfgcu/xf_client.h"
#include "xfgcu/posix/xf_link.h"
#include "xfgcu/posix/xf_posix.h"
#include "xfgcu/posix/xf_simlink.h"
#include "xfgcu/posix/xf_poll.h"
#include "xfgcu/xf_sim.h"
#include "example_links.h"

static void on_result(void *user, const xf_cmd_result *r)
{
    (void)user;
    printf("  %s: %s after %u ms\n", xf_order_name(r->order), xf_cmd_status_name(r->status), (unsigned)r->elapsed_ms);
}

int main(int argc, char **argv)
{
    static xf_simlink gcu_link; /* only used without a SPEC */
    static xf_sim sim;
    static xf_link link; /* a serial port here; any link the spec names */
    static xf_client client;
    xf_client *clients[1] = {&client};
    xf_sim *sims[1] = {&sim};
    size_t n_sims = (argc > 1) ? 0u : 1u; /* a SPEC, or a simulated GCU to step */
    char where[300];
    const char *spec = example_spec("linux_serial", argc > 1 ? argv[1] : NULL, XF_SIMLINK_PTY, &gcu_link, &sim);
    xf_client_config cc;
    xf_hal hal;
    xf_command cmd;
    uint32_t id = 0, start;

    if (example_link_open("linux_serial", &link, spec, &hal) != 0) {
        return 3;
    }
    if (n_sims > 0u) {
        printf("simulated GCU on %s\n", gcu_link.pty_path);
    }
    (void)xf_link_describe(&link, where, sizeof(where)); /* "serial /dev/ttyUSB0 at 115200 baud" */
    xf_client_config_init(&cc);
    cc.on_result = on_result;
    cc.reorder_fixed = (uint8_t)xf_link_keeps_order(&link.spec); /* a serial line keeps order */
    xf_client_init(&client, &hal, &cc);

    xf_command_init(&cmd, XF_ORDER_CALIBRATION); /* keep the gimbal still meanwhile */
    xf_client_submit(&client, &cmd, &id, NULL);

    start = xf_posix_now_ms();
    while (xf_client_command_status(&client, id, NULL) <= XF_CMD_OPERATING &&
           xf_ms_since(xf_posix_now_ms(), start) < 5000u) {
        xf_carrier carrier = {0.5f, -1.0f, 90.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f}; /* from your INS */
        xf_client_set_carrier(&client, &carrier, xf_posix_now_ms());
        xf_posix_poll(clients, 1, sims, n_sims, 20);
    }
    {
        const xf_telemetry *t = xf_client_telemetry(&client);
        const char *model = xf_gimbal_model(t->gimbal_code);
        /* versions are in tenths (31: 3.1), models shown with their code, as xfgcu shows them */
        printf("%s (code %u), hardware %u.%u, firmware %u.%u, on %s: yaw %.2f deg, relative yaw %.2f deg\n",
               model ? model : "unknown model", t->gimbal_code, t->hw_version / 10u, t->hw_version % 10u,
               t->fw_version / 10u, t->fw_version % 10u, where, (double)xf_cdeg(t->cam_yaw),
               (double)xf_cdeg(t->rel_angle_z));
    }
    xf_link_close(&link);
    return xf_client_command_status(&client, id, NULL) == XF_CMD_OK ? 0 : 1;
}
