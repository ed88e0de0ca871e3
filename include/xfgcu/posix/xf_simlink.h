/**
 * @file
 * @brief The GCU side of a link, for the simulator: a pseudo-terminal, a
 * UDP port or a TCP server that a simulated GCU answers on, behind the
 * xf_hal interface (CMake target xfgcu::simlink, above the links).
 */
#ifndef XF_SIMLINK_H
#define XF_SIMLINK_H

#include "xf_posix.h"

XF_BEGIN_DECLS

/* ---- the GCU side: links for the simulator ----------------------------------- */

/** Which kind of link an xf_simlink is. */
typedef enum xf_simlink_kind { XF_SIMLINK_PTY = 0, XF_SIMLINK_UDP = 1, XF_SIMLINK_TCP = 2 } xf_simlink_kind;
/** @var XF_SIMLINK_PTY
 *  a pseudo-terminal; the host opens its slave as a serial port */
/** @var XF_SIMLINK_UDP
 *  a UDP socket on the GCU's port */
/** @var XF_SIMLINK_TCP
 *  a TCP server serving one client at a time */

/**
 * A simulated GCU's end of a link: a pseudo-terminal's master (the host
 * opens the slave path), a UDP socket on the GCU's port answering whoever
 * sent the last packet, or a TCP server accepting one client at a time (a
 * second client is refused, like the real GCU).
 */
typedef struct xf_simlink {
    xf_simlink_kind kind;         /**< which kind of link */
    int fd;                       /**< pty master, UDP socket or TCP listener; -1 when closed */
    int slave_fd;                 /**< pty: a slave descriptor held open so the master never reads EIO */
    int client_fd;                /**< TCP: the connected host, -1 if none */
    char pty_path[64];            /**< pty: the slave's path */
    char link_path[256];          /**< pty: a stable symlink to the slave ("" if none) */
    char bind_host[64];           /**< UDP / TCP: the address bound */
    uint16_t port;                /**< UDP / TCP: the port bound */
    struct sockaddr_storage peer; /**< UDP: who sent the last packet (replies go there) */
    socklen_t peer_len;           /**< UDP: 0 until a packet arrived */
    uint8_t fixed_peer;           /**< UDP: replies go to peer whoever asks (xf_simlink_udp_reply_to()) */
    uint8_t asked;                /**< UDP: a packet has arrived (replies may go) */
    uint8_t down;                 /**< disconnected by xf_simlink_disconnect */
    uint8_t link_made;            /**< pty: link_path is a link this simlink made (and may remove) */
    uint32_t up_at;               /**< after xf_simlink_disconnect(): when the link comes back */
    xf_link_stats stats;          /**< counters */
    xf_os_error error;            /**< why the last operation failed */
} xf_simlink;

/**
 * A new pty; its slave path is in l->pty_path, and @p symlink_path (may be NULL) points to it.
 * Nothing that exists at @p symlink_path is replaced (a file, another
 * simulator's link): that is an error (::XF_ERR_BUSY). The link is removed
 * at close, and while disconnected, only if it is still the one made here
 * to this pty. When it cannot be made,
 * the error is returned but the pty stays open: call xf_simlink_close()
 * after any failure. Never waits. Cost: a few system calls (posix_openpt(), open(),
 * tcsetattr(), symlink()); never allocates.
 * @param l             the link's storage
 * @param symlink_path  a stable path for the host to open (shorter than 256 bytes), or NULL
 * @return ::XF_OK, ::XF_ERR_ARG (NULL @p l, or @p symlink_path too long), or
 *   a code mapped from the OS's errno (l->error says why)
 */
xf_err xf_simlink_open_pty(xf_simlink *l, const char *symlink_path);
/**
 * Listen for UDP on @p host (NULL: 127.0.0.1) : @p port (0: any free, then l->port).
 * Replies go to whoever sent the last packet. May block while a host name
 * resolves (DNS). Cost: getaddrinfo() (which allocates, freed before this
 * returns), socket() and bind().
 * @param l     the link's storage
 * @param host  address to bind, or NULL for 127.0.0.1
 * @param port  port to bind, 0 for any free one
 * @return ::XF_OK, ::XF_ERR_ARG (NULL @p l), ::XF_ERR_NOT_FOUND (does not
 *   resolve), or a code mapped from the OS's errno (::XF_ERR_BUSY: port in
 *   use; l->error says why)
 */
xf_err xf_simlink_open_udp(xf_simlink *l, const char *host, uint16_t port);
/**
 * TCP server on @p host (NULL: 127.0.0.1) : @p port (0: any free).
 * Serves one host at a time and refuses others, like the real GCU. May
 * block while a host name resolves (DNS). Cost: getaddrinfo() (which
 * allocates, freed before this returns), socket(), bind() and listen().
 * @param l     the link's storage
 * @param host  address to bind, or NULL for 127.0.0.1
 * @param port  port to bind, 0 for any free one (then l->port)
 * @return ::XF_OK, ::XF_ERR_ARG (NULL @p l), ::XF_ERR_NOT_FOUND (does not
 *   resolve), or a code mapped from the OS's errno (::XF_ERR_BUSY: port in
 *   use; l->error says why)
 */
xf_err xf_simlink_open_tcp(xf_simlink *l, const char *host, uint16_t port);
/**
 * UDP: send every reply to @p host : @p port instead of to whoever sent the
 * last packet. The vendor's GCU sends to the LAN's broadcast address, port
 * 2338 (::XF_HOST_UDP_PORT): give that address (e.g. 192.168.144.255, or
 * 255.255.255.255) to behave so; broadcast is allowed on the socket. Call
 * after xf_simlink_open_udp(). Replies start once a host has sent a
 * packet, as before. May block while a host name resolves (DNS).
 * @param l     a UDP link
 * @param host  the address replies go to (a broadcast address, or a host)
 * @param port  its port, e.g. ::XF_HOST_UDP_PORT
 * @return ::XF_OK, ::XF_ERR_ARG (NULL @p l or @p host, not a UDP link),
 *   ::XF_ERR_NOT_FOUND (does not resolve), or a code mapped from the OS's
 *   errno (l->error says why)
 */
xf_err xf_simlink_udp_reply_to(xf_simlink *l, const char *host, uint16_t port);
/**
 * Fill @p hal with the GCU's end of this link, for xf_sim_attach(). The link
 * must stay where it is while @p hal is in use. Read never waits (a TCP
 * server accepts a waiting host there) and returns ::XF_ERR_CLOSED while no
 * host is connected or the link is disconnected; write waits at most
 * 100 ms for a full buffer (pty, TCP). Does nothing for a NULL @p hal.
 * Cost per call: read, accept() until none waits (TCP) and one read(),
 * recvfrom() or recv(); write, one sendto() (UDP) or write() and send()
 * calls until every byte is taken. Neither allocates.
 * @param l    the link
 * @param hal  receives the link's functions
 */
void xf_simlink_hal(xf_simlink *l, xf_hal *hal);
/**
 * Fault injection: drop the host now and come back after @p ms: the pty
 * hangs up (its symlink removed meanwhile, then a new pty behind it), the
 * TCP connection is closed and new ones refused meanwhile, UDP goes silent.
 * What the host sends meanwhile is lost, as with a GCU that is gone: it is
 * never answered (or executed) when the link comes back.
 * Does nothing for a NULL @p l. Never waits.
 * @param l   the link
 * @param ms  how long the link stays down
 */
void xf_simlink_disconnect(xf_simlink *l, uint32_t ms);
/**
 * Faults on the wire, for testing a host's receiver (its parser, its link
 * health): random bytes added to what the simulator sends (line noise) and
 * bytes of it lost. It wraps any link, a serial port included
 * (xf_simlink_wire_init()); what the host sends is passed on untouched.
 * Fill it with xf_simlink_wire_init(), then set the two shares at any time.
 */
typedef struct xf_simlink_wire {
    xf_hal inner;            /**< the wrapped link (a copy) */
    uint16_t noise_permille; /**< after each byte sent, a random byte more with this chance, 0..1000 */
    uint16_t drop_permille;  /**< each byte to send is lost with this chance, 0..1000 */
    uint32_t rng;            /**< the faults' random state (xorshift32, never 0) */
    uint32_t noise_bytes;    /**< random bytes added so far (in writes the link took) */
    uint32_t dropped_bytes;  /**< bytes lost so far (in writes the link took) */
} xf_simlink_wire;

/**
 * Wrap @p inner (copied) with wire faults, none yet; @p out becomes the
 * faulty link, for xf_sim_attach(). Its write hands each packet, with the
 * faults applied, to the inner link in one write (a packet longer than
 * 256 bytes in several): an inner ::XF_ERR_AGAIN still means nothing was
 * sent. Its read and fd are the inner link's. @p w must outlive @p out.
 * Does nothing if any pointer is NULL.
 * @param w      the wrapper's storage
 * @param inner  the link to wrap
 * @param seed   starts the random faults (0 is taken as 1): the same seed, the same faults
 * @param out    receives the faulty link
 */
void xf_simlink_wire_init(xf_simlink_wire *w, const xf_hal *inner, uint32_t seed, xf_hal *out);
/**
 * Close the link and remove its symlink. Safe on a closed link; does
 * nothing for a NULL @p l. Cost: readlink() and unlink() for the symlink,
 * one close() per descriptor; never allocates.
 * @param l  the link
 */
void xf_simlink_close(xf_simlink *l);

/**
 * The spec a host opens (xf_link_open() of posix/xf_link.h) to reach the simulator's end of a
 * link @p gcu (for tests, demonstrations and examples with a built-in simulated GCU):
 * "tcp:127.0.0.1:PORT", "udp:127.0.0.1:PORT,local=0" (any free local port) or "serial:PATH"
 * (the pty's symlink when it has one, else its slave). A TCP or UDP link bound to any address
 * (0.0.0.0, ::) is reached on the loopback address. Like snprintf(): writes at most @p cap
 * bytes, NUL-terminated when @p cap is not 0. Never blocks.
 * @param gcu  the simulator's link, open
 * @param buf  receives the spec (may be NULL when @p cap is 0)
 * @param cap  the size of @p buf
 * @return the length of the whole spec (not counting the NUL); 0, with an empty @p buf, for a
 *   NULL @p gcu or one never opened
 */
size_t xf_simlink_host_spec(const xf_simlink *gcu, char *buf, size_t cap);

XF_END_DECLS

#endif /* XF_SIMLINK_H */
