/*
 * xf_posix.h - POSIX links behind the xf_hal interface: serial ports
 * (libserialport, with a termios path for pseudo-terminals), UDP, and TCP
 * as the client of the GCU's single-client server.
 *
 * Compiled code (src/xf_*.c, CMake target xfgcu::posix), not header-only.
 * Each link lives in storage the caller provides; open it, then get its
 * xf_hal with xf_*_hal(). A link is not thread-safe: drive it from one
 * thread (xf_hal's functions are meant for a single client loop).
 *
 * Open a link on zeroed or closed storage: opening an open link again
 * loses its descriptor (close it first).
 *
 * Errors carry the operating system's reason: after a failure,
 * link->error.text says what failed and why, in one line, e.g.
 * "open /dev/ttyUSB0: Permission denied".
 */
#ifndef XF_POSIX_H
#define XF_POSIX_H

#include <stddef.h>
#include <stdint.h>
#include <sys/socket.h>
#include "xf_error.h"
#include "xf_hal.h"

XF_BEGIN_DECLS

#define XF_GCU_DEFAULT_ADDRESS "192.168.144.108" /**< the vendor's default GCU address */
#define XF_GCU_TCP_PORT        2332u             /**< the GCU's TCP server */
#define XF_GCU_UDP_PORT        2337u             /**< the GCU's UDP port: host sends here, GCU sends from here */
#define XF_HOST_UDP_PORT       2338u             /**< the host's UDP port: GCU sends here */

/** Why the last operation of a link failed. */
typedef struct xf_os_error {
    int os_errno;   /**< errno, 0 when the failure is not the OS's */
    char text[192]; /**< one line: what, where, why */
} xf_os_error;

/** Counters of a link; they only increase. */
typedef struct xf_link_stats {
    uint32_t bytes_tx;
    uint32_t bytes_rx;
    uint32_t packets_tx;
    uint32_t opens;   /**< successful opens / connections, the first included */
    uint32_t losses;  /**< times the link was found lost (hang-up, peer closed, reset) */
    uint32_t foreign; /**< UDP datagrams dropped because they came from another source */
} xf_link_stats;

/** Monotonic milliseconds (CLOCK_MONOTONIC), wrapping at 2^32. */
uint32_t xf_posix_now_ms(void);

/* ---- serial ------------------------------------------------------------------ */

struct sp_port; /* libserialport's */

/** Baud rates the GCU speaks; anything else is XF_ERR_RANGE. */
int xf_serial_baud_ok(uint32_t baud);

typedef struct xf_serial {
    char path[256];
    uint32_t baud;
    int fd;                /**< -1 while closed */
    struct sp_port *port;  /**< set when opened through libserialport */
    uint8_t via_termios;   /**< opened with plain termios (pseudo-terminals) */
    uint8_t force_termios; /**< set before open to skip libserialport (tests, odd drivers) */
    uint32_t retry_at;     /**< after a hang-up: next reopen attempt */
    uint32_t backoff_ms;
    xf_link_stats stats;
    xf_os_error error;
} xf_serial;

/**
 * Open @p path at @p baud, 8N1, no flow control, non-blocking. Real ports go
 * through libserialport; a pseudo-terminal, which libserialport 0.1.1
 * refuses, goes through termios. After a hang-up, reads and writes return
 * XF_ERR_CLOSED and the link reopens the same path by itself (back-off
 * 50 ms doubling to 1 s), so a re-plugged adapter or a restarted pty
 * (behind a stable symlink) comes back.
 * @return XF_OK, XF_ERR_ARG, XF_ERR_RANGE (baud), XF_ERR_NOT_FOUND (no such
 *   device, or not a terminal), XF_ERR_PERMISSION, XF_ERR_BUSY, XF_ERR_IO.
 */
xf_err xf_serial_open(xf_serial *s, const char *path, uint32_t baud);
void xf_serial_close(xf_serial *s);
/** Fill @p hal with this link. Writes block at most 100 ms (a full driver buffer), else XF_ERR_IO. */
void xf_serial_hal(xf_serial *s, xf_hal *hal);
/** "libserialport", "termios" or "closed". */
const char *xf_serial_backend(const xf_serial *s);

/** A serial port found on the system. Strings are empty when unknown. */
typedef struct xf_serial_port_info {
    char path[128];
    char description[128];
    int usb_vid; /**< -1 when not a USB device */
    int usb_pid;
} xf_serial_port_info;

/** Call @p cb for each serial port libserialport finds. XF_ERR_IO if listing fails. */
xf_err xf_serial_list(void (*cb)(const xf_serial_port_info *info, void *user), void *user);

/* ---- UDP ---------------------------------------------------------------------- */

typedef struct xf_udp_config {
    const char *gcu_host;   /**< GCU address (or broadcast address with `broadcast`); default XF_GCU_DEFAULT_ADDRESS */
    uint16_t gcu_port;      /**< default 2337 */
    const char *local_host; /**< address to bind, default any */
    uint16_t local_port;    /**< default 2338; 0 = any free port */
    uint8_t accept_any;     /**< accept datagrams from any source (default: only gcu_host:gcu_port) */
    uint8_t broadcast;      /**< gcu_host is a broadcast address: send there, and take replies from any
                                 address whose source port is gcu_port */
} xf_udp_config;

typedef struct xf_udp {
    int fd;
    struct sockaddr_storage gcu;
    socklen_t gcu_len;
    uint8_t accept_any;
    uint8_t broadcast;
    uint16_t local_port; /**< the port bound (useful with local_port 0) */
    xf_link_stats stats;
    xf_os_error error;
} xf_udp;

void xf_udp_config_init(xf_udp_config *cfg);
/** @return XF_OK, XF_ERR_ARG, XF_ERR_NOT_FOUND (address does not resolve), XF_ERR_BUSY (port in use),
 * XF_ERR_PERMISSION, XF_ERR_IO. */
xf_err xf_udp_open(xf_udp *u, const xf_udp_config *cfg);
void xf_udp_close(xf_udp *u);
/** Fill @p hal. Each write is one datagram; reads return whole datagrams from the GCU only. */
void xf_udp_hal(xf_udp *u, xf_hal *hal);

/* ---- TCP ---------------------------------------------------------------------- */

typedef struct xf_tcp_config {
    const char *host;            /**< default XF_GCU_DEFAULT_ADDRESS */
    uint16_t port;               /**< default 2332 */
    uint32_t connect_timeout_ms; /**< one attempt, default 1000 */
    uint32_t retry_min_ms;       /**< back-off after a loss or a failed attempt, default 50 */
    uint32_t retry_max_ms;       /**< doubling up to this, default 500 */
} xf_tcp_config;

typedef enum xf_tcp_state { XF_TCP_DOWN = 0, XF_TCP_CONNECTING = 1, XF_TCP_UP = 2 } xf_tcp_state;

typedef struct xf_tcp {
    int fd;
    xf_tcp_state state;
    struct sockaddr_storage addr;
    socklen_t addr_len;
    xf_tcp_config cfg;
    char host[128];
    uint32_t started_at; /**< of the current connection attempt */
    uint32_t retry_at;
    uint32_t backoff_ms;
    xf_link_stats stats;
    xf_os_error error;
} xf_tcp;

void xf_tcp_config_init(xf_tcp_config *cfg);
/**
 * Resolve the GCU's address and start connecting (non-blocking). The link
 * connects, and reconnects after a loss, by itself whenever it is read or
 * written. @return XF_OK, XF_ERR_ARG, XF_ERR_NOT_FOUND (does not resolve).
 */
xf_err xf_tcp_open(xf_tcp *t, const xf_tcp_config *cfg);
/** Block up to @p timeout_ms until connected: XF_OK, or XF_ERR_TIMEOUT / XF_ERR_CLOSED with error.text. */
xf_err xf_tcp_wait(xf_tcp *t, uint32_t timeout_ms);
void xf_tcp_close(xf_tcp *t);
/** Fill @p hal. Writes block at most 100 ms for a full socket buffer, else the connection is dropped. */
void xf_tcp_hal(xf_tcp *t, xf_hal *hal);

/* ---- the GCU side: links for the simulator ----------------------------------- */

typedef enum xf_simlink_kind { XF_SIMLINK_PTY = 0, XF_SIMLINK_UDP = 1, XF_SIMLINK_TCP = 2 } xf_simlink_kind;

/**
 * A simulated GCU's end of a link: a pseudo-terminal's master (the host
 * opens the slave path), a UDP socket on the GCU's port answering whoever
 * sent the last packet, or a TCP server accepting one client at a time (a
 * second client is refused, like the real GCU).
 */
typedef struct xf_simlink {
    xf_simlink_kind kind;
    int fd;              /**< pty master, UDP socket or TCP listener; -1 when closed */
    int slave_fd;        /**< pty: a slave descriptor held open so the master never reads EIO */
    int client_fd;       /**< TCP: the connected host, -1 if none */
    char pty_path[64];   /**< pty: the slave's path */
    char link_path[256]; /**< pty: a stable symlink to the slave ("" if none) */
    char bind_host[64];
    uint16_t port; /**< UDP / TCP: the port bound */
    struct sockaddr_storage peer;
    socklen_t peer_len; /**< UDP: 0 until a packet arrived */
    uint8_t down;       /**< disconnected by xf_simlink_disconnect */
    uint32_t up_at;
    xf_link_stats stats;
    xf_os_error error;
} xf_simlink;

/** A new pty; its slave path is in l->pty_path, and @p symlink_path (may be NULL) points to it. */
xf_err xf_simlink_open_pty(xf_simlink *l, const char *symlink_path);
/** Listen for UDP on @p host (NULL: 127.0.0.1) : @p port (0: any free, then l->port). */
xf_err xf_simlink_open_udp(xf_simlink *l, const char *host, uint16_t port);
/** TCP server on @p host (NULL: 127.0.0.1) : @p port (0: any free). */
xf_err xf_simlink_open_tcp(xf_simlink *l, const char *host, uint16_t port);
void xf_simlink_hal(xf_simlink *l, xf_hal *hal);
/**
 * Fault injection: drop the host now and come back after @p ms: the pty
 * hangs up (its symlink removed meanwhile, then a new pty behind it), the
 * TCP connection is closed and new ones refused meanwhile, UDP goes silent.
 * What the host sends meanwhile is lost, as with a GCU that is gone: it is
 * never answered (or executed) when the link comes back.
 */
void xf_simlink_disconnect(xf_simlink *l, uint32_t ms);
void xf_simlink_close(xf_simlink *l);

/* ---- many clients, one thread --------------------------------------------------- */

struct xf_client;
struct xf_sim;

/**
 * One round of a poll loop: wait (at most @p max_wait_ms; negative: no
 * limit of the caller's) until a link of any client or simulator is
 * readable or a client's next packet is due (with simulators, at most
 * 5 ms), then step every client and simulator. Call it in a loop; the clients
 * stay independent (no shared state). Returns XF_OK or XF_ERR_IO (poll).
 */
xf_err xf_posix_poll(struct xf_client *const *clients, size_t n_clients, struct xf_sim *const *sims, size_t n_sims,
                     int max_wait_ms);

XF_END_DECLS

#endif /* XF_POSIX_H */
