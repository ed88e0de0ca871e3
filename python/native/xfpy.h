/*
 * xfpy.h - the flat C API of libxfgcu_py, the native library of the Python
 * package (python/xfgcu/_native.py loads it with ctypes).
 *
 * Only plain ints, doubles, byte buffers and JSON text cross it: no struct
 * of the library does, so the Python side never depends on a layout. The
 * JSON is the xfgcu program's own (tools/xfgcu/jsonpkt.c), and named
 * commands are parsed by the program's own code (tools/xfgcu/cmdargs.c),
 * so the package and the program cannot disagree.
 *
 * Threads: nothing here locks. The functions that can fail with a message
 * (xfpy_encode, xfpy_command, xfpy_client_submit) leave it in one
 * process-wide buffer (xfpy_error()), and command parsing uses getopt's
 * globals: the caller serialises them with one lock. A client or a
 * simulator handle is used by one thread at a time (the caller's lock);
 * xfpy_wait() touches no handle and needs no lock.
 */
#ifndef XFGCU_XFPY_H
#define XFGCU_XFPY_H

#include <stddef.h>
#include <stdint.h>

/* ---- messages ------------------------------------------------------------------- */

/** The last failure's one line (as the program prints it, without "xfgcu: "); "" when none. */
const char *xfpy_error(void);
/** Notes (warnings) since xfpy_clear(), one per line; "" when none. */
const char *xfpy_notes(void);
/** Forget the last failure and the notes. */
void xfpy_clear(void);
/** The library's version string. */
const char *xfpy_version(void);

/* ---- codec ----------------------------------------------------------------------- */

/**
 * One whole packet as `xfgcu decode --json` prints it (compact JSON, keys in order), with
 * pod_status read as @p pod says (0 auto, 1 le, 2 be).
 * @return 0; the codec's xf_err (< 0: XF_ERR_HEADER, _LENGTH, _CRC, _TRUNCATED); or the size
 *   needed (> 0) when @p cap is too small
 */
int xfpy_decode(const uint8_t *buf, size_t len, int pod, char *out, size_t cap);
/** The packet of a `xfgcu encode --json` object. @return an exit code (message: xfpy_error()). */
int xfpy_encode(const char *json, int version, uint8_t *out, size_t cap, size_t *len);
/** The packet of `xfgcu encode --protocol VERSION ARGV...` (argv[0] the command's name). @return an exit code. */
int xfpy_command(int argc, char **argv, int version, uint8_t *out, size_t cap, size_t *len);
/** The name of gimbal model @p code ("" when unknown). */
const char *xfpy_model_name(int code);
/** The command names, one per line. */
const char *xfpy_command_names(void);

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
/** Open the link @p spec and start the client. @return 0, or an xf_err (message: xfpy_error()). */
int xfpy_client_open(void *h, const char *spec);
/** Step the client; *fd receives the descriptor to wait on. @return ms until the next deadline. */
int xfpy_client_step(void *h, int *fd);
/** Replies (with new telemetry) received so far. */
uint32_t xfpy_client_replies(void *h);
/** 1 when no reply to a command can still be on the link (xf_client_settled()), or the link is down. */
int xfpy_client_settled(void *h);
/**
 * Telemetry JSON of reply number @p seq (1-based; 0: the latest) while among the last ones
 * kept: the keys of `xfgcu monitor --json` plus "units". @return 0, -1 (gone or none), or the
 * size needed.
 */
int xfpy_client_telemetry(void *h, uint32_t seq, char *out, size_t cap);
/** Health JSON. @return 0 or the size needed. */
int xfpy_client_health(void *h, char *out, size_t cap);
/**
 * Submit a named command (argv as for xfpy_command). @p force: even if the model lacks it.
 * @return an exit code (1: the model lacks it; 2: bad arguments); *id the command's id.
 */
int xfpy_client_submit(void *h, int argc, char **argv, int force, uint32_t *id);
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
/** Open the simulator's end: @p kind "tcp", "udp" or "pty"; @p where the address or the pty's link. */
int xfpy_sim_open(void *h, const char *kind, const char *where, int port);
/** The spec a client opens to reach it. */
const char *xfpy_sim_spec(void *h);
int xfpy_sim_step(void *h, int *fd);
/** Counters and state, JSON. @return 0 or the size needed. */
int xfpy_sim_stats(void *h, char *out, size_t cap);
void xfpy_sim_disconnect(void *h, long ms);
void xfpy_sim_free(void *h);

#endif /* XFGCU_XFPY_H */
