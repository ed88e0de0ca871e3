/*
 * udp_client.c - a gimbal over UDP: the host listens on 2338 and sends to
 * the GCU's 2337. Zooms to 5x, points with Euler angles, prints telemetry.
 *
 *   udp_client [SPEC]                    default: a built-in simulator on 127.0.0.1
 *   udp_client udp:192.168.144.108       a real GCU (ports 2337 and 2338)
 *   udp_client udp:127.0.0.1:2337,local=0   e.g. `xfgcu sim --udp`, from any free local port
 */
#include <stdio.h>

#include "xfgcu/xf_client.h"
#include "xfgcu/posix/xf_link.h"
#include "xfgcu/posix/xf_posix.h"
#include "xfgcu/posix/xf_simlink.h"
#include "xfgcu/posix/xf_poll.h"
#include "xfgcu/xf_sim.h"
#include "example_links.h"

int main(int argc, char **argv)
{
    static xf_simlink gcu_link; /* only used without a SPEC */
    static xf_sim sim;
    static xf_link link; /* a UDP link here; any link the spec names */
    static xf_client client;
    xf_client *clients[1] = {&client};
    xf_sim *sims[1] = {&sim};
    size_t n_sims = (argc > 1) ? 0u : 1u; /* a SPEC, or a simulated GCU to step */
    /* the simulator's spec is "udp:127.0.0.1:PORT,local=0": any free local port, leaving 2338 to a real setup */
    const char *spec = example_spec("udp_client", argc > 1 ? argv[1] : NULL, XF_SIMLINK_UDP, &gcu_link, &sim);
    xf_hal hal;
    xf_command cmd;
    xf_cmd_result res;
    uint32_t zoom = 0, start;

    if (example_link_open("udp_client", &link, spec, &hal) != 0) {
        return 3;
    }
    xf_client_init(&client, &hal, NULL);

    start = xf_posix_now_ms();
    xf_command_init(&cmd, XF_ORDER_EULER);
    xf_client_submit(&client, &cmd, NULL, NULL);
    xf_command_init(&cmd, XF_ORDER_ZOOM_TO);
    cmd.zoom = xf_zoom_to_rate_raw(5.0f);
    xf_client_submit(&client, &cmd, &zoom, NULL);
    xf_client_set_angles(&client, 0.0f, -30.0f, 45.0f, xf_posix_now_ms());

    /* block until both have run (in order: euler, then zoom_to), stepping the simulator too */
    if (xf_posix_wait(&client, zoom, 2000, &res, sims, n_sims) == XF_OK) {
        printf("euler, then zoom_to: %s, %u ms after start\n", xf_cmd_status_name(res.status),
               (unsigned)xf_ms_since(xf_posix_now_ms(), start));
    }
    while (xf_ms_since(xf_posix_now_ms(), start) < 2000u) {
        xf_posix_poll(clients, 1, sims, n_sims, 20);
    }
    {
        const xf_telemetry *t = xf_client_telemetry(&client);
        const xf_health *h = xf_client_health(&client);
        printf("pitch %.2f yaw %.2f zoom %.1fx; %u replies at %u Hz, %s\n", (double)xf_cdeg(t->cam_pitch),
               (double)xf_cdeg(t->cam_yaw), (double)xf_zoom_x(t->zoom_cam1), h->replies, h->reply_rate_hz,
               xf_link_state_name(h->link));
    }
    xf_link_close(&link);
    return xf_client_link(&client) == XF_LINK_UP ? 0 : 3;
}
