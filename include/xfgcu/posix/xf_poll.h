/**
 * @file
 * @brief Many clients and simulators from one thread: a poll(2) loop that
 * sleeps until a link is readable or a packet is due (CMake target
 * xfgcu::posix, above the links, the client and the simulator).
 */
#ifndef XF_POLL_H
#define XF_POLL_H

#include "../xf_client.h"
#include "../xf_sim.h"
#include "xf_posix.h"

XF_BEGIN_DECLS

/* ---- many clients, one thread --------------------------------------------------- */

/**
 * One round of a poll loop: wait (at most @p max_wait_ms; negative: no
 * limit of the caller's) until a link of any client or simulator is
 * readable or a client's next packet is due (with simulators, at most
 * 5 ms), then step every client and simulator. Call it in a loop; the clients
 * stay independent (no shared state). Returns XF_OK or XF_ERR_IO (poll).
 *
 * Blocks in poll() by design. The clients' callbacks run from here; they
 * must not call xf_posix_poll(). The steps' own errors are not returned
 * (see each client's xf_health). At most 256 descriptors are watched; with
 * no client, no simulator and a negative @p max_wait_ms it waits forever.
 * @param clients      the clients (none NULL; may be NULL when @p n_clients is 0)
 * @param n_clients    how many
 * @param sims         the simulators (none NULL; may be NULL when @p n_sims is 0)
 * @param n_sims       how many
 * @param max_wait_ms  longest wait, ms; negative: only the clients' deadlines bound it
 * @return ::XF_OK, ::XF_ERR_IO (poll() failed other than by a signal)
 */
xf_err xf_posix_poll(struct xf_client *const *clients, size_t n_clients, struct xf_sim *const *sims, size_t n_sims,
                     int max_wait_ms);

XF_END_DECLS

#endif /* XF_POLL_H */
