/*
 * multi_gimbal.c - several gimbals from one thread: N independent clients
 * (no shared state) driven by one poll loop, one link each. With a number
 * N, each talks to its own simulated GCU over loopback UDP; with specs, to
 * the gimbals they name.
 *
 *   multi_gimbal [N]              N simulated gimbals (default 4, at most 64)
 *   multi_gimbal SPEC [SPEC...]   e.g. tcp:192.168.144.108 tcp:192.168.144.109
 */
#include <stdio.h>
#include <stdlib.h>

#include "xfgcu/xf_client.h"
#include "xfgcu/posix/xf_link.h"
#include "xfgcu/posix/xf_posix.h"
#include "xfgcu/posix/xf_simlink.h"
#include "xfgcu/posix/xf_poll.h"
#include "xfgcu/xf_sim.h"
#include "example_links.h"

#define MAX_GIMBALS 64

int main(int argc, char **argv)
{
    static xf_simlink gcu_links[MAX_GIMBALS];
    static xf_sim sims[MAX_GIMBALS];
    static xf_link links[MAX_GIMBALS];
    static xf_client clients[MAX_GIMBALS];
    xf_client *cp[MAX_GIMBALS];
    xf_sim *sp[MAX_GIMBALS];
    char *end = NULL;
    long n = (argc > 1) ? strtol(argv[1], &end, 10) : 4;
    int specs = (argc > 1 && (end == argv[1] || *end != '\0')); /* not a number: specs */
    size_t n_sims = specs ? 0u : (size_t)n;
    int i, up = 0;
    uint32_t start;

    if (specs) {
        n = argc - 1;
    }
    if (n < 1 || n > MAX_GIMBALS) {
        fprintf(stderr, "multi_gimbal: give N in [1, %d], or at most %d specs\n", MAX_GIMBALS, MAX_GIMBALS);
        return 2;
    }
    for (i = 0; i < n; i++) {
        const char *spec =
            example_spec("multi_gimbal", specs ? argv[i + 1] : NULL, XF_SIMLINK_UDP, &gcu_links[i], &sims[i]);
        xf_hal h;
        xf_command cmd;
        if (example_link_open("multi_gimbal", &links[i], spec, &h) != 0) {
            return 3;
        }
        xf_client_init(&clients[i], &h, NULL);
        xf_command_init(&cmd, XF_ORDER_EULER);
        xf_client_submit(&clients[i], &cmd, NULL, NULL);
        xf_client_set_angles(&clients[i], 0.0f, -10.0f * (float)(i % 9), 40.0f * (float)i, xf_posix_now_ms());
        cp[i] = &clients[i];
        sp[i] = &sims[i];
    }
    start = xf_posix_now_ms();
    while (xf_ms_since(xf_posix_now_ms(), start) < 2000u) {
        xf_posix_poll(cp, (size_t)n, sp, n_sims, 20);
    }
    for (i = 0; i < n; i++) {
        const xf_telemetry *t = xf_client_telemetry(&clients[i]);
        char where[300];
        (void)xf_link_describe(&links[i], where, sizeof(where));
        up += xf_client_link(&clients[i]) == XF_LINK_UP;
        printf("gimbal %2d: link %-5s pitch %7.2f yaw %7.2f, %u Hz  (%s)\n", i,
               xf_link_state_name(xf_client_link(&clients[i])), (double)xf_cdeg(t->cam_pitch),
               (double)xf_cdeg(t->cam_yaw), xf_client_health(&clients[i])->reply_rate_hz, where);
        xf_link_close(&links[i]);
    }
    printf("%d of %ld gimbals up\n", up, n);
    return up == n ? 0 : 3;
}
