/* xf_posix_loop.c - drive any number of clients and simulators from one thread with poll(). */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <limits.h>
#include <poll.h>
#include <string.h>

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

/* ---- one command to its result ----------------------------------------------------- */

static int xf__running(xf_cmd_status st)
{
    return st == XF_CMD_QUEUED || st == XF_CMD_SENDING || st == XF_CMD_OPERATING;
}

xf_err xf_posix_wait(struct xf_client *c, uint32_t id, uint32_t timeout_ms, xf_cmd_result *result,
                     struct xf_sim *const *sims, size_t n_sims)
{
    uint32_t start = xf_posix_now_ms();
    if (c == NULL || (sims == NULL && n_sims != 0u)) {
        return XF_ERR_ARG;
    }
    if (c->busy) {
        return XF_ERR_BUSY; /* from a callback: its step could never run */
    }
    for (;;) {
        xf_cmd_result r;
        xf_cmd_status st;
        uint32_t elapsed;
        xf_err err;
        memset(&r, 0, sizeof(r));
        st = xf_client_command_status(c, id, &r);
        if (st == XF_CMD_UNKNOWN) {
            return XF_ERR_NOT_FOUND; /* never given, or its result already replaced by newer ones */
        }
        if (!xf__running(st)) {
            if (result != NULL) {
                *result = r;
            }
            return XF_OK;
        }
        elapsed = xf_ms_since(xf_posix_now_ms(), start);
        if (elapsed >= timeout_ms) {
            if (result != NULL) {
                memset(result, 0, sizeof(*result));
                result->id = id;
                result->status = st;
            }
            return XF_ERR_TIMEOUT;
        }
        /* poll() wakes for the reply (or the next packet due): the step after it resolves the command */
        err = xf_posix_poll(&c, 1, sims, n_sims,
                            (timeout_ms - elapsed > (uint32_t)INT_MAX) ? INT_MAX : (int)(timeout_ms - elapsed));
        if (err != XF_OK) {
            return err;
        }
    }
}

xf_err xf_posix_run(struct xf_client *c, const xf_command *cmd, uint32_t timeout_ms, xf_cmd_result *result)
{
    uint32_t id = 0;
    xf_err err;
    if (result != NULL) {
        memset(result, 0, sizeof(*result));
        result->order = (cmd != NULL) ? cmd->order : 0u;
    }
    if (c == NULL || cmd == NULL) {
        return XF_ERR_ARG;
    }
    if (c->busy) {
        return XF_ERR_BUSY; /* from a callback: nothing submitted */
    }
    err = xf_client_submit(c, cmd, &id, NULL);
    if (err != XF_OK) {
        return err;
    }
    err = xf_posix_wait(c, id, timeout_ms, result, NULL, 0);
    if (err == XF_ERR_TIMEOUT && result != NULL) {
        result->order = cmd->order;
    }
    return err;
}
