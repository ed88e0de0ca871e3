/**
 * @file
 * @brief Any link from one string: `tcp:HOST[:PORT]`, `udp:HOST[:PORT][,local=PORT]` or
 * `serial:PATH[,baud=N]`, opened behind the xf_hal interface (CMake target xfgcu::linkspec, above
 * the links alone: neither the client nor the simulator).
 *
 * A program that takes "which gimbal" from its user (a command-line argument, a configuration
 * file) reads one string, validates it with xf_link_spec_parse() and opens it with
 * xf_link_open(); an xf_link holds whichever of xf_serial, xf_udp and xf_tcp the string names.
 *
 * The grammar, with the GCU's documented defaults for what is left out:
 *
 * | spec                           | link                                                         |
 * |--------------------------------|--------------------------------------------------------------|
 * | `tcp:HOST[:PORT]`              | a TCP client of the GCU's server at PORT (2332)              |
 * | `udp:HOST[:PORT][,local=PORT]` | UDP to the GCU's PORT (2337), listening on `local` (2338; 0: any free port) |
 * | `serial:PATH[,baud=N]`         | a serial port or a pty; N: 115200 (default), 250000, 500000, 1000000 |
 *
 * HOST is a name or an address: an IPv6 address with a port goes in brackets
 * (`tcp:[fe80::1%eth0]:2332`); a bare IPv6 address (two colons or more) has no port. Ports are
 * decimal, 1..65535 (`local` also 0). The link kind and option names are lower case; options
 * follow the first comma, so a serial PATH cannot contain one. A spec is at most
 * ::XF_LINK_SPEC_MAX bytes, with no control characters.
 *
 * Errors are an ::xf_err and a one-line reason that quotes the spec (its first 64 bytes, control
 * characters shown as '?') and says what is wrong, e.g.
 * "serial:/dev/ttyUSB0,baud=9600: baud must be 115200, 250000, 500000 or 1000000". Malformed
 * text is ::XF_ERR_ARG; a number or a length outside its range is ::XF_ERR_RANGE. No input
 * crashes a function here: NULL, empty, huge or garbage strings are refused with a reason.
 *
 * Blocking: parsing and describing never block. Opening may block in the operating system:
 * resolving a host name (DNS; a numeric address does not), opening a device. xf_link_wait()
 * blocks by design. Like the links it holds, an xf_link is not thread-safe.
 */
#ifndef XF_LINK_H
#define XF_LINK_H

#include <stddef.h>
#include <stdint.h>
#include "../xf_error.h"
#include "../xf_hal.h"
#include "xf_posix.h"

XF_BEGIN_DECLS

#define XF_LINK_SPEC_MAX 512u /**< the longest spec accepted, in bytes (the terminating NUL not counted) */

/** Which link a spec names (xf_link_spec.kind). */
typedef enum xf_link_kind {
    XF_LINK_KIND_NONE = 0,   /**< none: a spec not parsed, or that failed to parse */
    XF_LINK_KIND_SERIAL = 1, /**< `serial:`: an xf_serial */
    XF_LINK_KIND_UDP = 2,    /**< `udp:`: an xf_udp */
    XF_LINK_KIND_TCP = 3     /**< `tcp:`: an xf_tcp */
} xf_link_kind;

/**
 * A parsed spec: what xf_link_open_spec() opens. xf_link_spec_parse() fills it from a string;
 * xf_link_spec_init() fills it from its parts (a program's own options), after which members
 * may be changed before opening.
 */
typedef struct xf_link_spec {
    xf_link_kind kind;           /**< which link */
    char host[128];              /**< tcp, udp: the GCU's host name or address (IPv6 without brackets) */
    char path[256];              /**< serial: the device, such as /dev/ttyUSB0 */
    uint16_t port;               /**< tcp: the GCU's TCP port (default 2332); udp: its UDP port (default 2337) */
    uint16_t local_port;         /**< udp: the port the host listens on (default 2338; 0: any free port) */
    uint32_t baud;               /**< serial: the baud rate (default 115200) */
    uint32_t connect_timeout_ms; /**< tcp: how long one connection attempt may take; 0 (as parsed): 1000 */
    uint8_t port_given;          /**< tcp, udp: 1 when the spec named the port, 0 when it is the default */
    xf_os_error error;           /**< after a failure: why, in one line */
} xf_link_spec;

/** The link an xf_link holds, as xf_link_spec.kind says (xf_link.as). */
typedef union xf_link_any {
    xf_serial serial; /**< ::XF_LINK_KIND_SERIAL */
    xf_udp udp;       /**< ::XF_LINK_KIND_UDP */
    xf_tcp tcp;       /**< ::XF_LINK_KIND_TCP */
} xf_link_any;

/**
 * Any link, opened from a spec. Zero it (or close it) before opening; keep it where it is while
 * its xf_hal is in use. Its members may be read (the link's counters: `as.tcp.stats`); change
 * them only through the functions.
 */
typedef struct xf_link {
    xf_link_spec spec; /**< what was opened, or tried (kept after a failure and a close, for messages) */
    xf_link_any as;    /**< the open link, as spec.kind says */
    uint8_t is_open;   /**< 1 from a successful open to xf_link_close() */
    xf_os_error error; /**< why the last open failed; once open, see xf_link_error() */
} xf_link;

/**
 * Parse @p spec into @p out without opening anything (to validate a user's input early, or to
 * change members before xf_link_open_spec()). Never blocks; touches no file or network.
 * Cost: O(length of @p spec), no system call; never allocates.
 * @param spec  the text, such as "tcp:192.168.144.108" (may be NULL: refused)
 * @param out   receives the parsed spec, with the defaults of what @p spec leaves out; on failure
 *   its kind is ::XF_LINK_KIND_NONE and out->error.text says why
 * @return ::XF_OK; ::XF_ERR_ARG (NULL @p out, when nothing is written; NULL or empty @p spec,
 *   unknown link kind, missing host or path, a character that has no place there, text after
 *   `]`, an unknown, repeated or empty option, a number that is not decimal); ::XF_ERR_RANGE (a
 *   port outside 1..65535, `local` outside 0..65535, a baud rate the GCU does not speak, a host of
 *   128 bytes or more, a path of 256 bytes or more, a spec longer than ::XF_LINK_SPEC_MAX)
 */
xf_err xf_link_spec_parse(const char *spec, xf_link_spec *out);

/**
 * Fill @p out from its parts: @p kind, its host (tcp, udp) or device path (serial), and the
 * defaults of the grammar for the rest (ports 2332, 2337 and 2338; 115200 baud); change ports,
 * baud or connect_timeout_ms afterwards as needed. For programs with their own options (the
 * xfgcu program's --udp HOST --gcu-port N). Never blocks.
 * @param out    receives the spec; on failure its kind is ::XF_LINK_KIND_NONE and out->error
 *   says why
 * @param kind   ::XF_LINK_KIND_SERIAL, ::XF_LINK_KIND_UDP or ::XF_LINK_KIND_TCP
 * @param where  the host name or address (IPv6 without brackets), or the device path
 * @return ::XF_OK; ::XF_ERR_ARG (NULL @p out, when nothing is written; NULL or empty @p where, a
 *   bad @p kind, a character that has no place in a host name); ::XF_ERR_RANGE (a host of 128
 *   bytes or more, a path of 256 bytes or more)
 */
xf_err xf_link_spec_init(xf_link_spec *out, xf_link_kind kind, const char *where);

/**
 * Parse @p spec (xf_link_spec_parse()) and open the link it names (xf_link_open_spec()).
 *
 * May block while a host name resolves (DNS; a numeric address does not) or a device opens;
 * never waits for the GCU, nor for a TCP connection: the TCP link connects, and reconnects, by
 * itself as it is used (xf_link_wait() waits for it). Open on zeroed or closed storage (opening
 * an open link loses its descriptor). On failure the link is closed, l->spec holds what was
 * parsed, and l->error.text says why, in one line.
 *
 * Cost: O(length of @p spec) to parse, then what the link's own open costs: getaddrinfo() for
 * `tcp:` and `udp:` (it allocates, and frees before this returns), libserialport for a real
 * serial port (it allocates a structure kept until xf_link_close()), termios for a pty (no
 * allocation) (xf_serial_open(), xf_udp_open(), xf_tcp_open()).
 * @param l     the link's storage
 * @param spec  the text, such as "tcp:192.168.144.108:2332" or "serial:/dev/ttyUSB0,baud=115200"
 *   (read during the call only)
 * @return ::XF_OK; ::XF_ERR_ARG (NULL @p l, when nothing is written); what xf_link_spec_parse()
 *   returns for a bad @p spec; what xf_serial_open(), xf_udp_open() or xf_tcp_open() return
 *   (::XF_ERR_NOT_FOUND: no such device or host; ::XF_ERR_BUSY: port in use;
 *   ::XF_ERR_PERMISSION, ::XF_ERR_IO)
 */
xf_err xf_link_open(xf_link *l, const char *spec);

/**
 * Open the link @p spec names (as filled by xf_link_spec_parse() or xf_link_spec_init(), and
 * perhaps changed). Blocks as xf_link_open() does; @p spec is copied to l->spec and checked
 * again first (a kind, a host or path that is not empty and ends within its array, a GCU port
 * not 0, a baud rate the GCU speaks). @p spec may be &l->spec. Cost: as xf_link_open(), less
 * the parsing.
 * @param l     the link's storage (zeroed or closed)
 * @param spec  what to open
 * @return as xf_link_open(); ::XF_ERR_ARG also for a NULL @p spec
 */
xf_err xf_link_open_spec(xf_link *l, const xf_link_spec *spec);

/**
 * Wait until the link can carry packets: for TCP, block up to @p timeout_ms until connected
 * (xf_tcp_wait(), polling every 5 ms at most); UDP and serial links have no connection, and
 * return at once. Blocks by design: for start-up, before the client loop runs. Cost: one
 * poll() per 5 ms waited; never allocates.
 * @param l           the link, open
 * @param timeout_ms  how long to wait at most
 * @return ::XF_OK (ready); ::XF_ERR_ARG (NULL @p l); ::XF_ERR_CLOSED (not open; or TCP refused or
 *   failed: xf_link_error() says why); ::XF_ERR_TIMEOUT (a TCP attempt still in progress)
 */
xf_err xf_link_wait(xf_link *l, uint32_t timeout_ms);

/**
 * Fill @p hal with the open link's functions (xf_serial_hal(), xf_udp_hal() or xf_tcp_hal():
 * what each says about blocking and errors holds). The link must stay where it is while @p hal
 * is in use. Never blocks.
 * @param l    the link
 * @param hal  receives the link's functions
 * @return ::XF_OK; ::XF_ERR_ARG (NULL @p l or @p hal); ::XF_ERR_CLOSED (@p l is not open:
 *   @p hal is left alone)
 */
xf_err xf_link_hal(xf_link *l, xf_hal *hal);

/**
 * Whether a link of this kind delivers bytes in the order they were sent and never twice: a
 * serial line and a TCP stream do, UDP does not (a radio, a VPN or Wi-Fi may reorder or duplicate
 * datagrams). A client on such a link need not judge it: set xf_client_config.reorder_fixed from
 * this, unless the user gave a reorder bound (docs/protocol.md §7.4). Never blocks.
 * @param spec  a parsed spec (xf_link.spec)
 * @return 1 for `serial:` and `tcp:`, 0 for `udp:` and anything else (NULL included)
 */
int xf_link_keeps_order(const xf_link_spec *spec);

/**
 * Close the link; it no longer reconnects or reopens by itself. l->spec is kept (for
 * xf_link_describe()). Safe on a closed or never-opened (zeroed) link; does nothing for a NULL
 * @p l. Never blocks. Cost: the link's close (one close(), and libserialport's free for a
 * serial port it opened); never allocates.
 * @param l  the link
 */
void xf_link_close(xf_link *l);

/**
 * One line that says which link @p l is, from l->spec: "tcp 192.168.144.108:2332",
 * "tcp [::1]:2332", "udp 192.168.144.108:2337", "serial /dev/ttyUSB0 at 115200 baud", or "none"
 * (a NULL @p l, or no spec). Like snprintf(): writes at most @p cap bytes, NUL-terminated when
 * @p cap is not 0. Never blocks.
 * @param l    the link (open, closed, or after a failed open)
 * @param buf  receives the text (may be NULL when @p cap is 0)
 * @param cap  the size of @p buf
 * @return the length of the whole description (not counting the NUL): @p buf holds all of it
 *   when this is below @p cap
 */
size_t xf_link_describe(const xf_link *l, char *buf, size_t cap);

/**
 * Why the link's last operation failed: once open, the error of the link it holds (which its
 * xf_hal's reads and writes update: a lost TCP connection, a hung-up serial port); otherwise
 * l->error (why the open failed). Never blocks.
 * @param l  the link
 * @return the error (its text is empty when nothing failed), or NULL for a NULL @p l
 */
const xf_os_error *xf_link_error(const xf_link *l);

XF_END_DECLS

#endif /* XF_LINK_H */
