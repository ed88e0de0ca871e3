/* xf_posix_loop.c - drive any number of clients and simulators from one thread with poll(). */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <poll.h>

#include "xfgcu/xf_client.h"
#include "xfgcu/posix/xf_posix.h"
#include "xfgcu/posix/xf_poll.h"
#include "xfgcu/xf_sim.h"

#define XF_POLL_MAX 256

xf_err xf_posix_poll(struct xf_client *const *clients, size_t n_clients, struct xf_sim *const *sims, size_t n_sims,
                     int max_wait_ms)
{
    struct pollfd pfd[XF_POLL_MAX];
    nfds_t n = 0;
    size_t i;
    uint32_t now = xf_posix_now_ms();
    int wait = max_wait_ms; /* < 0: no limit of the caller's; deadlines still bound it */
    for (i = 0; i < n_clients; i++) {
        /* Wake for the earliest packet due. */
        int32_t due = (int32_t)(xf_client_next_deadline(clients[i]) - now);
        int fd = xf_hal_fd(&clients[i]->hal);
        if (wait < 0 || due < wait) {
            wait = (due < 0) ? 0 : (int)due;
        }
        if (fd >= 0 && n < XF_POLL_MAX) {
            pfd[n].fd = fd;
            pfd[n].events = POLLIN;
            pfd[n].revents = 0;
            n++;
        }
    }
    for (i = 0; i < n_sims; i++) {
        int fd = xf_hal_fd(&sims[i]->hal);
        if (fd >= 0 && n < XF_POLL_MAX) {
            pfd[n].fd = fd;
            pfd[n].events = POLLIN;
            pfd[n].revents = 0;
            n++;
        }
    }
    if (n_sims > 0u && (wait < 0 || wait > 5)) {
        wait = 5; /* simulators move their gimbal between packets, and TCP servers accept */
    }
    if (poll(pfd, n, wait) < 0 && errno != EINTR) {
        return XF_ERR_IO;
    }
    now = xf_posix_now_ms();
    for (i = 0; i < n_sims; i++) {
        xf_sim_step(sims[i], now);
    }
    for (i = 0; i < n_clients; i++) {
        xf_client_step(clients[i], now);
    }
    return XF_OK;
}
