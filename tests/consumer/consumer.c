/*
 * consumer.c - an application outside the xfgcu tree: a client against a
 * simulated GCU over loopback UDP for half a second. Exits 0 when the link
 * came up and a command succeeded (proves headers, libraries and the
 * libserialport dependency all resolve for a consumer).
 */
#include <stdio.h>

#include "xfgcu/xf_client.h"
#include "xfgcu/xf_posix.h"
#include "xfgcu/xf_sim.h"
#include "xfgcu/xf_version.h"

int main(void)
{
    static xf_simlink gcu;
    static xf_sim sim;
    static xf_udp udp;
    static xf_client client;
    xf_client *cp[1] = {&client};
    xf_sim *sp[1] = {&sim};
    xf_udp_config uc;
    xf_hal h;
    xf_command cmd;
    uint32_t id = 0, start;
    if (xf_simlink_open_udp(&gcu, "127.0.0.1", 0) != XF_OK) {
        return 3;
    }
    xf_simlink_hal(&gcu, &h);
    xf_sim_init(&sim, NULL);
    xf_sim_attach(&sim, &h);
    xf_udp_config_init(&uc);
    uc.gcu_host = "127.0.0.1";
    uc.gcu_port = gcu.port;
    uc.local_port = 0;
    if (xf_udp_open(&udp, &uc) != XF_OK) {
        return 3;
    }
    xf_udp_hal(&udp, &h);
    xf_client_init(&client, &h, NULL);
    xf_command_init(&cmd, XF_ORDER_SHUTTER);
    xf_client_submit(&client, &cmd, &id, NULL);
    start = xf_posix_now_ms();
    while (xf_ms_since(xf_posix_now_ms(), start) < 500u) {
        xf_posix_poll(cp, 1, sp, 1, 10);
    }
    printf("consumer: xfgcu %s, link %s, shutter %s\n", XF_VERSION_STRING, xf_link_state_name(xf_client_link(&client)),
           xf_cmd_status_name(xf_client_command_status(&client, id, NULL)));
    return xf_client_command_status(&client, id, NULL) == XF_CMD_OK ? 0 : 1;
}
