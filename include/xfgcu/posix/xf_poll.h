/**
 * @file
 * @brief Many clients and simulators from one thread: a poll(2) loop that
 * sleeps until a link is readable or a packet is due (CMake target
 * xfgcu::poll, above the links, the client and the simulator).
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
 *
 * Cost: one poll() over the links' descriptors, then one xf_sim_step() per simulator and one
 * xf_client_step() per client (what those cost, O(@p n_clients + @p n_sims) besides); stack: an
 * array of 256 struct pollfd. Never allocates.
 * @param clients      the clients (none NULL; may be NULL when @p n_clients is 0)
 * @param n_clients    how many
 * @param sims         the simulators (none NULL; may be NULL when @p n_sims is 0)
 * @param n_sims       how many
 * @param max_wait_ms  longest wait, ms; negative: only the clients' deadlines bound it
 * @return ::XF_OK, ::XF_ERR_IO (poll() failed other than by a signal)
 */
xf_err xf_posix_poll(struct xf_client *const *clients, size_t n_clients, struct xf_sim *const *sims, size_t n_sims,
                     int max_wait_ms);

/* ---- one command to its result ---------------------------------------------------- */

/**
 * Run @p cmd to its result: submit it to @p c, then drive @p c with the poll loop
 * (xf_posix_wait()) until the result is known, and return at once when it is: in the step that
 * handles the reply carrying the command's final state, with no packet waited for beyond what
 * the client itself needs. For start-up and simple programs; a program with work of its own
 * between packets submits and polls itself (xf_client_submit(), xf_posix_poll()).
 *
 * Blocks, by design, up to @p timeout_ms (the command itself ends by the client's own timeouts:
 * command_timeout_ms, or operating_timeout_ms after "operating"). Only @p c is stepped meanwhile:
 * other clients and simulators of the program are not (xf_posix_wait() steps simulators too).
 * Commands queued before @p cmd run first, as always, and the wait includes their time; their
 * results, and those of commands that callbacks submit meanwhile, come as usual (on_result,
 * xf_client_command_status()); nothing is cancelled. Signals do not end the wait (call with a
 * short timeout in a loop to react to them). Must not be called from one of @p c's callbacks.
 * Cost: one xf_client_submit() and then what xf_posix_wait() costs; never allocates.
 * @param c           the client, started (xf_client_init())
 * @param cmd         the command (copied)
 * @param timeout_ms  how long to wait at most, ms
 * @param result      receives the outcome (may be NULL): on ::XF_OK the final result (ok, failed,
 *   timeout, link lost, cancelled); on ::XF_ERR_TIMEOUT its id, order and where it is (queued,
 *   sending, operating); otherwise zeros but its order
 * @return ::XF_OK (the result is known: see result->status, which may be a failure);
 *   ::XF_ERR_TIMEOUT (@p timeout_ms passed first: the command stays queued or running, and its
 *   result comes later as any command's, by result->id; xf_client_cancel_all() drops it and every
 *   other); ::XF_ERR_ARG (NULL @p c or @p cmd); what xf_client_submit() refuses a command with
 *   (::XF_ERR_RANGE: a member out of range, which xf_command_check() names;
 *   ::XF_ERR_NOT_FOUND: an order the protocol does not define); ::XF_ERR_BUSY (queue full, or
 *   called from one of @p c's callbacks: nothing submitted); ::XF_ERR_IO (poll() failed)
 */
xf_err xf_posix_run(struct xf_client *c, const xf_command *cmd, uint32_t timeout_ms, xf_cmd_result *result);

/**
 * Drive @p c (and the simulators @p sims, stepped in the same loop: an in-process simulated GCU)
 * with xf_posix_poll() until command @p id has finished, or @p timeout_ms has passed. Returns as
 * soon as the step that finishes it has run. What xf_posix_run() does after submitting, for a
 * command submitted already (xf_client_submit()), or to wait in slices (a loop that calls it
 * with a short timeout and checks a signal flag between calls, as the xfgcu program does).
 *
 * Blocks, by design, up to @p timeout_ms; a @p timeout_ms of 0 only looks at the status. Other
 * clients are not stepped meanwhile; no command is cancelled. Must not be called from one of
 * @p c's callbacks. Cost: one xf_posix_poll() round per wake-up (a reply, a packet due, or 5 ms
 * with simulators) and an O(1) status look-up after each; never allocates.
 * @param c           the client
 * @param id          the command's id (from xf_client_submit())
 * @param timeout_ms  how long to wait at most, ms
 * @param result      receives the outcome (may be NULL): on ::XF_OK the final result; on
 *   ::XF_ERR_TIMEOUT its id and where it is (queued, sending, operating), order 0; left alone
 *   otherwise
 * @param sims        simulators to step too (none NULL; may be NULL when @p n_sims is 0)
 * @param n_sims      how many
 * @return ::XF_OK (finished: see result->status); ::XF_ERR_TIMEOUT (not finished within
 *   @p timeout_ms); ::XF_ERR_ARG (NULL @p c, or NULL @p sims with @p n_sims not 0);
 *   ::XF_ERR_NOT_FOUND (an @p id the client does not know: never given, or finished so long ago
 *   that ::XF_CLIENT_RESULTS newer results replaced its own); ::XF_ERR_BUSY (called from one of
 *   @p c's callbacks); ::XF_ERR_IO (poll() failed)
 */
xf_err xf_posix_wait(struct xf_client *c, uint32_t id, uint32_t timeout_ms, xf_cmd_result *result,
                     struct xf_sim *const *sims, size_t n_sims);

XF_END_DECLS

#endif /* XF_POLL_H */
