/*
 * tcp_client.c - drive a gimbal over Ethernet (TCP, the recommended link):
 * head-lock mode, a slow pan, a photo, and the telemetry as it comes.
 *
 *   tcp_client [SPEC]                    default: a built-in simulator on 127.0.0.1
 *   tcp_client tcp:192.168.144.108       a real GCU (port 2332)
 *   tcp_client tcp:127.0.0.1:2332        e.g. `xfgcu sim --tcp`
 *   (any spec works: udp:HOST, serial:/dev/ttyUSB0; see xfgcu/posix/xf_link.h)
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
    printf("  %s: %s\n", xf_order_name(r->order), xf_cmd_status_name(r->status));
}

int main(int argc, char **argv)
{
    static xf_simlink gcu_link; /* only used without a SPEC */
    static xf_sim sim;
    static xf_link link; /* a TCP link here; any link the spec names */
    static xf_client client;
    xf_client *clients[1] = {&client};
    xf_sim *sims[1] = {&sim};
    size_t n_sims = (argc > 1) ? 0u : 1u; /* a SPEC, or a simulated GCU to step */
    const char *spec = example_spec("tcp_client", argc > 1 ? argv[1] : NULL, XF_SIMLINK_TCP, &gcu_link, &sim);
    xf_client_config cc;
    xf_hal hal;
    xf_command cmd;
    uint32_t start, last_print = 0;

    if (example_link_open("tcp_client", &link, spec, &hal) != 0) { /* then it connects, and reconnects, by itself */
        return 3;
    }
    xf_client_config_init(&cc);
    cc.on_result = on_result;
    cc.reorder_fixed = (uint8_t)xf_link_keeps_order(&link.spec); /* TCP and serial keep order; UDP is judged */
    xf_client_init(&client, &hal, &cc);

    xf_command_init(&cmd, XF_ORDER_HEAD_LOCK);
    xf_client_submit(&client, &cmd, NULL, NULL);
    xf_command_init(&cmd, XF_ORDER_SHUTTER);
    xf_client_submit(&client, &cmd, NULL, NULL);

    start = xf_posix_now_ms();
    while (xf_ms_since(xf_posix_now_ms(), start) < 3000u) {
        uint32_t now = xf_posix_now_ms();
        xf_telemetry_units u; /* the client keeps wire integers: physical units on read */
        const xf_telemetry *t = xf_client_telemetry(&client);
        xf_client_set_rates(&client, 0.0f, -5.0f, 20.0f, now); /* refresh, or the watchdog stops the gimbal */
        xf_posix_poll(clients, 1, sims, n_sims, 20);
        if (xf_ms_since(now, last_print) >= 500u) {
            last_print = now;
            xf_telemetry_convert(t, &u);
            printf("link %-5s  mode %-10s  pitch %7.2f  yaw %7.2f  zoom %4.1fx\n",
                   xf_link_state_name(xf_client_link(&client)), t->have_main ? xf_mode_name(t->gimbal_mode) : "-",
                   (double)u.cam_pitch_deg, (double)u.cam_yaw_deg, (double)u.zoom_cam1);
        }
    }
    xf_link_close(&link);
    return xf_client_link(&client) == XF_LINK_UP ? 0 : 3;
}
