/*
 * udp_client.c - a gimbal over UDP: the host listens on 2338 and sends to
 * the GCU's 2337. Zooms to 5x, points with Euler angles, prints telemetry.
 *
 *   udp_client [GCU_HOST]        default: a built-in simulator on 127.0.0.1
 */
#include <stdio.h>

#include "xfgcu/xf_client.h"
#include "xfgcu/posix/xf_posix.h"
#include "xfgcu/posix/xf_simlink.h"
#include "xfgcu/posix/xf_poll.h"
#include "xfgcu/xf_sim.h"

int main(int argc, char **argv)
{
    static xf_simlink gcu_link;
    static xf_sim sim;
    static xf_udp udp;
    static xf_client client;
    xf_client *clients[1] = {&client};
    xf_sim *sims[1] = {&sim};
    size_t n_sims = 0;
    xf_udp_config uc;
    xf_hal hal;
    xf_command cmd;
    uint32_t start;

    xf_udp_config_init(&uc);
    if (argc > 1) {
        uc.gcu_host = argv[1];
    } else {
        xf_hal sim_hal;
        if (xf_simlink_open_udp(&gcu_link, "127.0.0.1", 0) != XF_OK) {
            fprintf(stderr, "udp_client: %s\n", gcu_link.error.text);
            return 3;
        }
        xf_simlink_hal(&gcu_link, &sim_hal);
        xf_sim_init(&sim, NULL);
        xf_sim_attach(&sim, &sim_hal);
        n_sims = 1;
        uc.gcu_host = "127.0.0.1";
        uc.gcu_port = gcu_link.port;
        uc.local_port = 0; /* any free port: leave 2338 to a real setup */
    }
    if (xf_udp_open(&udp, &uc) != XF_OK) {
        fprintf(stderr, "udp_client: %s\n", udp.error.text);
        return 3;
    }
    xf_udp_hal(&udp, &hal);
    xf_client_init(&client, &hal, NULL);

    xf_command_init(&cmd, XF_ORDER_EULER);
    xf_client_submit(&client, &cmd, NULL, NULL);
    xf_command_init(&cmd, XF_ORDER_ZOOM_TO);
    cmd.zoom = xf_zoom_to_rate_raw(5.0f);
    xf_client_submit(&client, &cmd, NULL, NULL);
    xf_client_set_angles(&client, 0.0f, -30.0f, 45.0f, xf_posix_now_ms());

    start = xf_posix_now_ms();
    while (xf_ms_since(xf_posix_now_ms(), start) < 2000u) {
        xf_posix_poll(clients, 1, sims, n_sims, 20);
    }
    {
        const xf_telemetry *t = xf_client_telemetry(&client);
        const xf_health *h = xf_client_health(&client);
        printf("pitch %.2f yaw %.2f zoom %.1fx; %u replies at %u Hz, %s\n", (double)xf_cdeg(t->cam_pitch),
               (double)xf_cdeg(t->cam_yaw), (double)xf_zoom_x(t->zoom_cam1), h->replies, h->reply_rate_hz,
               xf_link_state_name((xf_link_state)h->link));
    }
    xf_udp_close(&udp);
    return xf_client_link(&client) == XF_LINK_UP ? 0 : 3;
}
