/*
 * multi_gimbal.c - several gimbals from one thread: N independent clients
 * (no shared state) driven by one poll loop. Here each talks to its own
 * simulated GCU over loopback UDP; with real gimbals, open one link each.
 *
 *   multi_gimbal [N]    (default 4, at most 64)
 */
#include <stdio.h>
#include <stdlib.h>

#include "xfgcu/xf_client.h"
#include "xfgcu/posix/xf_posix.h"
#include "xfgcu/posix/xf_simlink.h"
#include "xfgcu/posix/xf_poll.h"
#include "xfgcu/xf_sim.h"

#define MAX_GIMBALS 64

int main(int argc, char **argv)
{
    static xf_simlink gcu_links[MAX_GIMBALS];
    static xf_sim sims[MAX_GIMBALS];
    static xf_udp links[MAX_GIMBALS];
    static xf_client clients[MAX_GIMBALS];
    xf_client *cp[MAX_GIMBALS];
    xf_sim *sp[MAX_GIMBALS];
    long n = (argc > 1) ? strtol(argv[1], NULL, 10) : 4;
    int i, up = 0;
    uint32_t start;

    if (n < 1 || n > MAX_GIMBALS) {
        fprintf(stderr, "multi_gimbal: N must be in [1, %d]\n", MAX_GIMBALS);
        return 2;
    }
    for (i = 0; i < n; i++) {
        xf_udp_config uc;
        xf_hal h;
        xf_command cmd;
        if (xf_simlink_open_udp(&gcu_links[i], "127.0.0.1", 0) != XF_OK) {
            fprintf(stderr, "multi_gimbal: %s\n", gcu_links[i].error.text);
            return 3;
        }
        xf_simlink_hal(&gcu_links[i], &h);
        xf_sim_init(&sims[i], NULL);
        xf_sim_attach(&sims[i], &h);
        xf_udp_config_init(&uc);
        uc.gcu_host = "127.0.0.1";
        uc.gcu_port = gcu_links[i].port;
        uc.local_port = 0;
        if (xf_udp_open(&links[i], &uc) != XF_OK) {
            fprintf(stderr, "multi_gimbal: %s\n", links[i].error.text);
            return 3;
        }
        xf_udp_hal(&links[i], &h);
        xf_client_init(&clients[i], &h, NULL);
        xf_command_init(&cmd, XF_ORDER_EULER);
        xf_client_submit(&clients[i], &cmd, NULL, NULL);
        xf_client_set_angles(&clients[i], 0.0f, -10.0f * (float)(i % 9), 40.0f * (float)i, xf_posix_now_ms());
        cp[i] = &clients[i];
        sp[i] = &sims[i];
    }
    start = xf_posix_now_ms();
    while (xf_ms_since(xf_posix_now_ms(), start) < 2000u) {
        xf_posix_poll(cp, (size_t)n, sp, (size_t)n, 20);
    }
    for (i = 0; i < n; i++) {
        const xf_telemetry *t = xf_client_telemetry(&clients[i]);
        up += xf_client_link(&clients[i]) == XF_LINK_UP;
        printf("gimbal %2d: link %-5s pitch %7.2f yaw %7.2f, %u Hz\n", i,
               xf_link_state_name(xf_client_link(&clients[i])), (double)xf_cdeg(t->cam_pitch),
               (double)xf_cdeg(t->cam_yaw), xf_client_health(&clients[i])->reply_rate_hz);
    }
    printf("%d of %ld gimbals up\n", up, n);
    return up == n ? 0 : 3;
}
