/**
 * @file
 * @brief POSIX links behind the xf_hal interface: serial ports
 * (libserialport, with a termios path for pseudo-terminals), UDP, and TCP
 * as the client of the GCU's single-client server.
 *
 * Compiled code (src/xf_serial.c, xf_udp.c, xf_tcp.c, xf_posix_common.c;
 * CMake target xfgcu::links): it needs the codec and the HAL only.
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
 *
 * Blocking: the links are non-blocking. Their xf_hal read never waits;
 * their write waits at most a bounded time for a full buffer (serial and
 * TCP: 100 ms; UDP: never). Opening a link may block briefly in the
 * operating system (opening a device, resolving a host name with DNS: pass
 * a numeric address to avoid that). xf_tcp_wait() blocks
 * by design, up to the time they are given. Each function below says so.
 *
 * Cost: each function says what it costs in system calls and whether it allocates. Reads,
 * writes and closes never allocate; opening a network link resolves its host with
 * getaddrinfo(), which allocates (and frees before it returns), and a serial port opened through
 * libserialport holds a structure libserialport allocated until it is closed. Measured
 * latencies: docs/performance.md.
 */
#ifndef XF_POSIX_H
#define XF_POSIX_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <sys/socket.h>
#include "../xf_error.h"
#include "../xf_hal.h"

XF_BEGIN_DECLS

#define XF_GCU_DEFAULT_ADDRESS "192.168.144.108" /**< the vendor's default GCU address */
#define XF_GCU_TCP_PORT        2332u             /**< the GCU's TCP server */
#define XF_GCU_UDP_PORT        2337u             /**< the GCU's UDP port: host sends here, GCU sends from here */
#define XF_HOST_UDP_PORT       2338u             /**< the host's UDP port: GCU sends here */

/** Why the last operation of a link failed (every link has one, as its `error` member). */
typedef struct xf_os_error {
    int os_errno;   /**< errno, 0 when the failure is not the OS's */
    char text[192]; /**< one line: what, where, why */
} xf_os_error;

/** Counters of a link; they only increase. */
typedef struct xf_link_stats {
    uint32_t bytes_tx;   /**< bytes written */
    uint32_t bytes_rx;   /**< bytes read */
    uint32_t packets_tx; /**< writes (packets) that succeeded */
    uint32_t opens;      /**< successful opens / connections, the first included */
    uint32_t losses;     /**< times the link was found lost (hang-up, peer closed, reset) */
    uint32_t foreign;    /**< UDP datagrams dropped because they came from another source */
} xf_link_stats;

/**
 * Monotonic milliseconds (CLOCK_MONOTONIC), wrapping at 2^32: a clock for
 * xf_client_step(), the setters, xf_sim_step() and a tap (the links have no
 * clock; the POSIX ones time their own reconnects with this). Never blocks.
 * Cost: one clock_gettime() (on Linux usually a vDSO call, no system call); never allocates.
 * @return the time, ms
 */
uint32_t xf_posix_now_ms(void);

/* ---- serial ------------------------------------------------------------------ */

struct sp_port; /* libserialport's */

/**
 * Baud rates the GCU speaks; anything else is XF_ERR_RANGE.
 * @param baud  the rate
 * @return true for 115200, 250000, 500000 and 1000000; false otherwise
 *   (which xf_serial_open() refuses with ::XF_ERR_RANGE)
 */
bool xf_serial_baud_ok(uint32_t baud);

/** A serial link's state: zero it (or close it) before xf_serial_open(). */
typedef struct xf_serial {
    char path[256];        /**< the device opened (and reopened after a hang-up); empty when closed */
    uint32_t baud;         /**< the baud rate */
    int fd;                /**< -1 while closed */
    struct sp_port *port;  /**< set when opened through libserialport */
    uint8_t via_termios;   /**< opened with plain termios (pseudo-terminals) */
    uint8_t force_termios; /**< set before open to skip libserialport (tests, odd drivers) */
    uint32_t retry_at;     /**< after a hang-up: next reopen attempt */
    uint32_t backoff_ms;   /**< after a hang-up: current delay between reopen attempts */
    xf_link_stats stats;   /**< counters */
    xf_os_error error;     /**< why the last operation failed */
} xf_serial;

/**
 * Open @p path at @p baud, 8N1, no flow control, non-blocking. Real ports go
 * through libserialport; a pseudo-terminal, which libserialport 0.1.1
 * refuses, goes through termios. After a hang-up, reads and writes return
 * XF_ERR_CLOSED and the link reopens the same path by itself (back-off
 * 50 ms doubling to 1 s), so a re-plugged adapter or a restarted pty
 * (behind a stable symlink) comes back.
 *
 * Open on zeroed or closed storage (force_termios, set beforehand, is
 * kept). May block briefly in the operating system while the device is
 * opened and configured; never waits for the peer. On failure the link is
 * closed and s->error says why.
 *
 * Cost: a few system calls (open, ioctl, tcsetattr). The termios path allocates nothing;
 * libserialport allocates its port structure (kept until xf_serial_close()) and reads the
 * port's details from the system.
 * @param s     the link's storage
 * @param path  the device, such as /dev/ttyUSB0 (shorter than 256 bytes)
 * @param baud  115200, 250000, 500000 or 1000000 (xf_serial_baud_ok())
 * @return XF_OK, XF_ERR_ARG, XF_ERR_RANGE (baud), XF_ERR_NOT_FOUND (no such
 *   device, or not a terminal), XF_ERR_PERMISSION, XF_ERR_BUSY, XF_ERR_IO.
 *   (::XF_ERR_ARG: NULL @p s or @p path, or @p path too long. Rarely another
 *   code mapped from the OS's errno, such as ::XF_ERR_CLOSED for EIO.)
 */
xf_err xf_serial_open(xf_serial *s, const char *path, uint32_t baud);
/**
 * Close the link; it no longer reopens by itself. Safe on a closed link;
 * does nothing for a NULL @p s. Never blocks. Cost: one close() (and libserialport's
 * free of its port structure); never allocates.
 * @param s  the link
 */
void xf_serial_close(xf_serial *s);
/**
 * Fill @p hal with this link. Writes block at most 100 ms (a full driver buffer), else XF_ERR_IO.
 *
 * The link must stay where it is while @p hal is in use. Its read never
 * waits; after a hang-up, read and write return ::XF_ERR_CLOSED and try to
 * reopen the device (back-off 50 ms doubling to 1 s). Write returns
 * ::XF_OK, ::XF_ERR_CLOSED or ::XF_ERR_IO (never ::XF_ERR_AGAIN); read
 * returns ::XF_OK, ::XF_ERR_CLOSED or ::XF_ERR_IO. Does nothing for a NULL
 * @p hal.
 *
 * Cost per call: read, one poll() and at most one read(); write, write() calls until every
 * byte is taken (poll() between them). Neither allocates, except that a reopen after a
 * hang-up costs what xf_serial_open() does.
 * @param s    the link
 * @param hal  receives the link's functions
 */
void xf_serial_hal(xf_serial *s, xf_hal *hal);
/**
 * Which way the link was opened.
 * @param s  the link (may be NULL)
 * @return "libserialport", "termios" or "closed" (NULL, never opened,
 *   closed, or hung up and not reopened yet)
 */
const char *xf_serial_backend(const xf_serial *s);

/** A serial port found on the system. Strings are empty when unknown. */
typedef struct xf_serial_port_info {
    char path[128];        /**< the device path, such as /dev/ttyUSB0 */
    char description[128]; /**< libserialport's description of the port */
    int usb_vid;           /**< -1 when not a USB device */
    int usb_pid;           /**< USB product id; -1 when not a USB device */
} xf_serial_port_info;

/**
 * Call @p cb for each serial port libserialport finds. XF_ERR_IO if listing fails.
 * Blocks while the system is asked for its ports (no device is opened).
 * Allocates: libserialport builds the list on the heap, freed before this returns.
 * @param cb    called once per port, with the port's description (valid
 *   during the call only) and @p user
 * @param user  passed to @p cb
 * @return ::XF_OK, ::XF_ERR_ARG (NULL @p cb), ::XF_ERR_IO (listing failed)
 */
xf_err xf_serial_list(void (*cb)(const xf_serial_port_info *info, void *user), void *user);

/* ---- UDP ---------------------------------------------------------------------- */

/** Where a UDP link sends and listens; start from xf_udp_config_init(). */
typedef struct xf_udp_config {
    const char *gcu_host;   /**< GCU address (or broadcast address with `broadcast`); default XF_GCU_DEFAULT_ADDRESS */
    uint16_t gcu_port;      /**< default 2337 */
    const char *local_host; /**< address to bind, default any */
    uint16_t local_port;    /**< default 2338; 0 = any free port */
    uint8_t accept_any;     /**< accept datagrams from any source (default: only gcu_host:gcu_port) */
    uint8_t broadcast;      /**< gcu_host is a broadcast address: send there, and take replies from any
                                 address whose source port is gcu_port */
} xf_udp_config;

/** A UDP link's state. */
typedef struct xf_udp {
    int fd;                      /**< the socket; -1 while closed */
    struct sockaddr_storage gcu; /**< where packets go */
    socklen_t gcu_len;           /**< length of gcu */
    uint8_t accept_any;          /**< as xf_udp_config.accept_any */
    uint8_t broadcast;           /**< as xf_udp_config.broadcast */
    uint16_t local_port;         /**< the port bound (useful with local_port 0) */
    xf_link_stats stats;         /**< counters */
    xf_os_error error;           /**< why the last operation failed */
} xf_udp;

/**
 * Fill @p cfg with the defaults documented at each member. Does nothing for
 * a NULL @p cfg.
 * @param cfg  the configuration to fill
 */
void xf_udp_config_init(xf_udp_config *cfg);
/**
 * Open a UDP link: resolve the GCU's address, bind the local port,
 * non-blocking socket. Unlike TCP there is no connection: the link is usable
 * at once. May block while a host name resolves (DNS); a numeric address
 * does not. On failure the link is closed and u->error says why.
 *
 * Cost: getaddrinfo() (which allocates, freed before this returns, and may ask DNS), then
 * socket(), bind() and a few setsockopt() calls.
 * @param u    the link's storage
 * @param cfg  where to send and listen; NULL means xf_udp_config_init()'s
 *   defaults (a zero gcu_port is not replaced by the default)
 * @return XF_OK, XF_ERR_ARG, XF_ERR_NOT_FOUND (address does not resolve), XF_ERR_BUSY (port in use),
 * XF_ERR_PERMISSION, XF_ERR_IO.
 */
xf_err xf_udp_open(xf_udp *u, const xf_udp_config *cfg);
/**
 * Close the link. Safe on a closed link; does nothing for a NULL @p u.
 * Cost: one close(); never allocates.
 * @param u  the link
 */
void xf_udp_close(xf_udp *u);
/**
 * Fill @p hal. Each write is one datagram; reads return whole datagrams from the GCU only.
 *
 * The link must stay where it is while @p hal is in use. Neither function
 * waits. Write returns ::XF_OK (also when an earlier datagram was refused
 * by ICMP: UDP cannot tell), ::XF_ERR_AGAIN (socket buffer full),
 * ::XF_ERR_CLOSED (closed) or ::XF_ERR_IO. Read takes up to 64 datagrams
 * while a whole packet still fits in the buffer, dropping (and counting)
 * those from other sources; it returns ::XF_OK, ::XF_ERR_CLOSED (closed) or
 * ::XF_ERR_IO. Does nothing for a NULL @p hal.
 *
 * Cost per call: write, one sendto(); read, recvfrom() until the socket is empty or the
 * buffer full (at most 64 calls), O(bytes). Neither allocates.
 * @param u    the link
 * @param hal  receives the link's functions
 */
void xf_udp_hal(xf_udp *u, xf_hal *hal);

/* ---- TCP ---------------------------------------------------------------------- */

/** Where a TCP link connects; start from xf_tcp_config_init(). */
typedef struct xf_tcp_config {
    const char *host;            /**< default XF_GCU_DEFAULT_ADDRESS */
    uint16_t port;               /**< default 2332 */
    uint32_t connect_timeout_ms; /**< one attempt, default 1000 */
    uint32_t retry_min_ms;       /**< back-off after a loss or a failed attempt, default 50 */
    uint32_t retry_max_ms;       /**< doubling up to this, default 500 */
} xf_tcp_config;

/** Where a TCP link's connection is (xf_tcp.state). */
typedef enum xf_tcp_state { XF_TCP_DOWN = 0, XF_TCP_CONNECTING = 1, XF_TCP_UP = 2 } xf_tcp_state;
/** @var XF_TCP_DOWN
 *  no connection: waiting for the next attempt (or closed) */
/** @var XF_TCP_CONNECTING
 *  an attempt is in progress */
/** @var XF_TCP_UP
 *  connected */

/** A TCP link's state. */
typedef struct xf_tcp {
    int fd;                       /**< the socket; -1 while there is none */
    xf_tcp_state state;           /**< where the connection is */
    struct sockaddr_storage addr; /**< the GCU's address, resolved at open */
    socklen_t addr_len;           /**< length of addr */
    xf_tcp_config cfg;            /**< the configuration (a copy, zero values replaced by defaults) */
    char host[128];               /**< the host name; empty once closed (no reconnecting) */
    uint32_t started_at;          /**< of the current connection attempt */
    uint32_t retry_at;            /**< when the next attempt may start */
    uint32_t backoff_ms;          /**< current delay between attempts */
    xf_link_stats stats;          /**< counters */
    xf_os_error error;            /**< why the last operation or attempt failed */
} xf_tcp;

/**
 * Fill @p cfg with the defaults documented at each member. Does nothing for
 * a NULL @p cfg.
 * @param cfg  the configuration to fill
 */
void xf_tcp_config_init(xf_tcp_config *cfg);
/**
 * Resolve the GCU's address and start connecting (non-blocking). The link
 * connects, and reconnects after a loss, by itself whenever it is read or
 * written.
 *
 * May block while a host name resolves (DNS); a numeric address does not.
 * Never waits for the connection: xf_tcp_wait() does.
 *
 * Cost: getaddrinfo() (which allocates, freed before this returns, and may ask DNS), then
 * socket() and a non-blocking connect(). Reconnects reuse the address: they never resolve or
 * allocate.
 * @param t    the link's storage
 * @param cfg  where to connect; NULL means xf_tcp_config_init()'s defaults.
 *   A NULL host, a zero connect_timeout_ms and a zero retry_min_ms are
 *   replaced by the defaults (a zero port is not); retry_max_ms is raised to
 *   retry_min_ms if below it
 * @return ::XF_OK, ::XF_ERR_ARG (NULL @p t, or a host name of 128 bytes or
 *   more), ::XF_ERR_NOT_FOUND (does not resolve; t->error says why)
 */
xf_err xf_tcp_open(xf_tcp *t, const xf_tcp_config *cfg);
/**
 * Block up to @p timeout_ms until connected: XF_OK, or XF_ERR_TIMEOUT / XF_ERR_CLOSED with error.text.
 * Blocks (polling every 5 ms at most) by design: for start-up, before the
 * client loop runs. Cost: one poll() per 5 ms waited; never allocates.
 * @param t           the link, opened
 * @param timeout_ms  how long to wait at most
 * @return ::XF_OK (connected), ::XF_ERR_ARG (NULL @p t, or not opened),
 *   ::XF_ERR_TIMEOUT (an attempt still in progress), ::XF_ERR_CLOSED (not
 *   connected: refused or failed, t->error says why)
 */
xf_err xf_tcp_wait(xf_tcp *t, uint32_t timeout_ms);
/**
 * Close the link; it no longer reconnects. Safe on a closed link; does
 * nothing for a NULL @p t. Cost: one close(); never allocates.
 * @param t  the link
 */
void xf_tcp_close(xf_tcp *t);
/**
 * Fill @p hal. Writes block at most 100 ms for a full socket buffer, else the connection is dropped.
 *
 * The link must stay where it is while @p hal is in use. Read never waits.
 * Each read or write first moves the connection on (starts an attempt when
 * the back-off has passed, checks one in progress); while not connected
 * they return ::XF_ERR_CLOSED. A failed or closed connection returns
 * ::XF_ERR_CLOSED and reconnects after the back-off. Write returns ::XF_OK or
 * ::XF_ERR_CLOSED; read ::XF_OK or ::XF_ERR_CLOSED. The fd function gives -1
 * unless connected. Does nothing for a NULL @p hal.
 *
 * Cost per call: read, one recv(); write, send() calls until every byte is taken (poll()
 * between them); while not connected, one poll() on the attempt, or socket() and connect()
 * once the back-off has passed. Neither allocates.
 * @param t    the link
 * @param hal  receives the link's functions
 */
void xf_tcp_hal(xf_tcp *t, xf_hal *hal);

XF_END_DECLS

#endif /* XF_POSIX_H */
