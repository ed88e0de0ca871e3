/*
 * linux_serial.c - a gimbal on a UART (TTL, 8N1): calibrate, then feed it
 * the carrier's attitude while printing what it reports.
 *
 *   linux_serial [DEVICE [BAUD]]   e.g. /dev/ttyUSB0 115200
 *   (no DEVICE: a built-in simulator on a pseudo-terminal)
 */
#include <stdio.h>
#include <stdlib.h>

#include "xfgcu/xf_client.h"
#include "xfgcu/posix/xf_posix.h"
#include "xfgcu/posix/xf_simlink.h"
#include "xfgcu/posix/xf_poll.h"
#include "xfgcu/xf_sim.h"

static void on_result(void *user, const xf_cmd_result *r)
{
    (void)user;
    printf("  %s: %s after %u ms\n", xf_order_name(r->order), xf_cmd_status_name((xf_cmd_status)r->status),
           (unsigned)r->elapsed_ms);
}

int main(int argc, char **argv)
{
    static xf_simlink gcu_link;
    static xf_sim sim;
    static xf_serial serial;
    static xf_client client;
    xf_client *clients[1] = {&client};
    xf_sim *sims[1] = {&sim};
    size_t n_sims = 0;
    const char *device = (argc > 1) ? argv[1] : NULL;
    uint32_t baud = (argc > 2) ? (uint32_t)strtoul(argv[2], NULL, 10) : 115200u;
    xf_client_config cc;
    xf_hal hal;
    xf_command cmd;
    uint32_t id = 0, start;

    if (device == NULL) {
        xf_hal sim_hal;
        if (xf_simlink_open_pty(&gcu_link, NULL) != XF_OK) {
            fprintf(stderr, "linux_serial: %s\n", gcu_link.error.text);
            return 3;
        }
        xf_simlink_hal(&gcu_link, &sim_hal);
        xf_sim_init(&sim, NULL);
        xf_sim_attach(&sim, &sim_hal);
        n_sims = 1;
        device = gcu_link.pty_path;
        printf("simulated GCU on %s\n", device);
    }
    if (xf_serial_open(&serial, device, baud) != XF_OK) {
        fprintf(stderr, "linux_serial: %s\n", serial.error.text);
        return 3;
    }
    xf_serial_hal(&serial, &hal);
    xf_client_config_init(&cc);
    cc.on_result = on_result;
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
        printf("%s (hw %u, fw %u) via %s: yaw %.2f deg, relative yaw %.2f deg\n", model ? model : "unknown model",
               t->hw_version, t->fw_version, xf_serial_backend(&serial), (double)xf_cdeg(t->cam_yaw),
               (double)xf_cdeg(t->rel_angle_z));
    }
    xf_serial_close(&serial);
    return xf_client_command_status(&client, id, NULL) == XF_CMD_OK ? 0 : 1;
}
