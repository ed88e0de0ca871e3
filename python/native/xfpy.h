/*
 * xfpy.h - the flat C API of libxfgcu_py, the native library of the Python
 * package (python/xfgcu/_native.py loads it with ctypes).
 *
 * Only plain ints, doubles, byte buffers, strings and JSON text cross it: no struct
 * of the library does, so the Python side never depends on a layout. The
 * JSON and the named commands are the text layer's (xfgcu::text, tools/text), the one the xfgcu
 * program uses, so the package and the program cannot disagree. A command's arguments are named
 * pairs (names[i], values[i]; a NULL value for a switch), as the text layer takes them.
 *
 * Messages: a function that can fail writes its messages into the caller's buffer @p msgs
 * (capacity @p msgs_cap), one per line: "note: ..." for each note (a warning), then
 * "error: ..." for the failure, worded for any caller (no command-line hint).
 *
 * Threads: there is no process-wide state, so the codec functions need no lock. A client or a
 * simulator handle is used by one thread at a time (the caller's lock); xfpy_wait() touches no
 * handle and needs no lock.
 */
#ifndef XFGCU_XFPY_H
#define XFGCU_XFPY_H

#include <stddef.h>
#include <stdint.h>

/** The library's version string. */
const char *xfpy_version(void);

/* ---- codec ----------------------------------------------------------------------- */

/**
 * One whole packet as `xfgcu decode --json` prints it (compact JSON, keys in order), with
 * pod_status read as @p pod says (0 auto, 1 le, 2 be), the fields in engineering units or, with
 * @p raw, as wire integers (decode --raw).
 * @return 0; the codec's xf_err (< 0: XF_ERR_HEADER, _LENGTH, _CRC, _TRUNCATED); or the size
 *   needed (> 0) when @p cap is too small
 */
int xfpy_decode(const uint8_t *buf, size_t len, int pod, int raw, char *out, size_t cap);
/** The packet of a `xfgcu encode --json` object (wire integers with @p raw). @return 0, or 2 (messages). */
int xfpy_encode(const char *json, int version, int raw, uint8_t *out, size_t cap, size_t *len, char *msgs,
                size_t msgs_cap);
/**
 * The packet of `xfgcu encode --protocol VERSION NAME --NAME1 VALUE1 ...`: the command @p name with
 * @p n named arguments. @return 0, or 2 (messages).
 */
int xfpy_command(const char *name, int n, const char *const *names, const char *const *values, int version,
                 uint8_t *out, size_t cap, size_t *len, char *msgs, size_t msgs_cap);
/** The name of gimbal model @p code ("" when unknown). */
const char *xfpy_model_name(int code);
/** The command names, one per line, into @p out. @return 0, or the size needed. */
int xfpy_command_names(char *out, size_t cap);

/* ---- stream parser ------------------------------------------------------------- */

/** A parser of both directions; NULL when out of memory. */
void *xfpy_parser_new(void);
void xfpy_parser_free(void *p);
/**
 * Feed bytes. Each frame found goes to @p out as a record: its end in the stream (4 bytes,
 * little-endian), its direction (0 host, 1 GCU), its length (1 byte), its bytes. @p cap must
 * hold 2 * (len / 72 + 2) * (XF_PACKET_MAX_LEN + 6) bytes. @return the bytes written, or -1.
 */
long xfpy_parser_feed(void *p, const uint8_t *data, size_t len, uint8_t *out, size_t cap);

/** Wait up to @p ms for @p fd to become readable (fd < 0: sleep). Holds no handle. */
void xfpy_wait(int fd, int ms);

/* ---- client ------------------------------------------------------------------------ */

/** A client handle with the default configuration; NULL when out of memory. */
void *xfpy_client_new(void);
/** Set configuration @p name (an xf_client_config member) before open. @return 0, or -1 (unknown name). */
int xfpy_client_config(void *h, const char *name, long value);
/** Why the configuration set so far cannot work (xf_client_config_problem()), or NULL. */
const char *xfpy_client_config_problem(void *h);
/** Open the link @p spec and start the client. @return 0, or an xf_err (messages). */
int xfpy_client_open(void *h, const char *spec, char *msgs, size_t msgs_cap);
/** Step the client; *fd receives the descriptor to wait on. @return ms until the next deadline. */
int xfpy_client_step(void *h, int *fd);
/** Replies (with new telemetry) received so far. */
uint32_t xfpy_client_replies(void *h);
/** 1 when no reply to a command can still be on the link (xf_client_settled()), or the link is down. */
int xfpy_client_settled(void *h);
/**
 * Telemetry JSON of reply number @p seq (1-based; 0: the latest) while among the last ones
 * kept: the keys of `xfgcu monitor --json` (wire integers with @p raw, as monitor --raw) plus
 * "units". @return 0, -1 (gone or none), or the size needed.
 */
int xfpy_client_telemetry(void *h, uint32_t seq, int raw, char *out, size_t cap);
/** Health JSON. @return 0 or the size needed. */
int xfpy_client_health(void *h, char *out, size_t cap);
/**
 * Submit a named command (@p name and its named arguments, as for xfpy_command), built for the
 * version the GCU speaks. @p force: even if the model lacks it.
 * @return 0, 1 (the model lacks it) or 2 (bad arguments), with the messages; *id the command's id.
 */
int xfpy_client_submit(void *h, const char *name, int n, const char *const *names, const char *const *values, int force,
                       uint32_t *id, char *msgs, size_t msgs_cap);
/** A command's status (xf_cmd_status) and its result's figures. */
int xfpy_client_result(void *h, uint32_t id, int *failed_cameras, int *packets, long *elapsed_ms, int *state);
/** Cancel every queued command. */
void xfpy_client_cancel_all(void *h);
/** @return the control status (xf_ctrl_status). */
int xfpy_client_set_rates(void *h, double roll, double pitch, double yaw);
int xfpy_client_set_angles(void *h, double roll, double pitch, double yaw);
void xfpy_client_clear_control(void *h);
void xfpy_client_set_carrier(void *h, const double *values9);
/** GNSS in degrees and metres; @p week < 0: the time now. */
void xfpy_client_set_gnss(void *h, double lat, double lon, double alt_m, int satellites, int week, long ms_of_week,
                          double relative_height_m);
/** Where the link goes ("tcp 127.0.0.1:2332"). */
const char *xfpy_client_describe(void *h);
void xfpy_client_free(void *h);

/* ---- simulator --------------------------------------------------------------------- */

void *xfpy_sim_new(void);
/** Set configuration @p name before open (version, model, ...). @return 0 or -1. */
int xfpy_sim_config(void *h, const char *name, long value);
/** Set a fault (drop_next, drop_permille, corrupt_next, corrupt_permille, delay_ms, silent). @return 0 or -1. */
int xfpy_sim_fault(void *h, const char *name, long value);
/** Executions of @p order answer @p state. */
void xfpy_sim_fail(void *h, int order, int state);
/** Open the simulator's end: @p kind "tcp", "udp" or "pty"; @p where the address or the pty's link.
 *  @return 0, or an xf_err (messages). */
int xfpy_sim_open(void *h, const char *kind, const char *where, int port, char *msgs, size_t msgs_cap);
/** The spec a client opens to reach it. */
const char *xfpy_sim_spec(void *h);
int xfpy_sim_step(void *h, int *fd);
/** Counters and state, JSON. @return 0 or the size needed. */
int xfpy_sim_stats(void *h, char *out, size_t cap);
void xfpy_sim_disconnect(void *h, long ms);
void xfpy_sim_free(void *h);

#endif /* XFGCU_XFPY_H */
