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
/** The code of order @p name ("zoom_to" or "zoom-to", xf_order_from_name()), or -1 when there is none. */
int xfpy_order_code(const char *name);
/** The name of gimbal model @p code ("" when unknown). */
const char *xfpy_model_name(int code);
/** The command names, one per line, into @p out. @return 0, or the size needed. */
int xfpy_command_names(char *out, size_t cap);
/**
 * Argument @p i of command @p name, as the text layer takes it (cmdargs_option_info()): its name,
 * how many values (0: a switch), whether a real number, its words, whether the cameras, each
 * value's range, the xf_command member it sets and a line of help.
 * @return 1; 0 past the last; -1 for a command that does not exist
 */
int xfpy_command_option(const char *name, size_t i, const char **arg, unsigned *values, int *real, const char **words,
                        int *cameras, double *lo, double *hi, const char **field, const char **help);
/**
 * Row @p i of a group of the field table (xf_wire_fields(); xf_wire_group @p group): its name,
 * unit, one line of meaning, kind (xf_wire_kind) and the first version that has it.
 * @return 1, or 0 past the last
 */
int xfpy_field_at(int group, size_t i, const char **name, const char **unit, const char **meaning, int *kind,
                  int *since);

/* ---- what the package checks arguments against ------------------------------------- */

/**
 * Setting @p i of a table (0: the client's configuration, xf_client_config; 1: the simulator's,
 * xf_sim_config; 2: the simulator's faults, xf_sim_faults): its name and the range it takes.
 * The setters below take exactly these names and ranges. @return 1, or 0 past the last.
 */
int xfpy_setting_at(int table, size_t i, const char **name, long long *lo, long long *hi);
/**
 * Limit @p i of the arguments of the setters ("set_angles.pitch", "set_gnss.week", ...): the
 * range in which the library's conversion is exact (beyond it, it would clamp or wrap), and
 * whether the value goes round (1: an angle wrapped into its range by the library, accepted
 * over one turn either way). @return 1, or 0 past the last.
 */
int xfpy_limit_at(size_t i, const char **name, double *lo, double *hi, int *wraps);

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
/** Set configuration @p name (setting table 0) before open. @return 0, or -1 (unknown name, out of range). */
int xfpy_client_config(void *h, const char *name, long long value);
/** Configuration @p name as it is set (setting table 0). @return it, or -1 (unknown name). */
long long xfpy_client_config_get(void *h, const char *name);
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
 * kept: the object of `xfgcu monitor --json` (engineering units; wire integers with @p raw, as
 * monitor --raw). @return 0, -1 (gone or none), or the size needed.
 */
int xfpy_client_telemetry(void *h, uint32_t seq, int raw, char *out, size_t cap);
/** Health JSON (xf_health, the parser's counters, the versions). @return 0 or the size needed. */
int xfpy_client_health(void *h, char *out, size_t cap);
/** The last packet the link accepted (on_bytes) into @p out. @return its length, 0 before the first. */
int xfpy_client_last_sent(void *h, uint8_t *out, size_t cap);
/** The largest rate, deg/s, that set_rates() carries unclamped at the main camera's zoom now. */
double xfpy_client_rate_limit(void *h);
/** The camera on the GCU's main screen, whose zoom scales the rates: 1 or 2 (xf_client_set_main_camera()). */
void xfpy_client_set_main_camera(void *h, int camera);
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
/** GNSS in degrees and metres, within the limits of xfpy_limit_at(); @p week < 0: the time now. */
void xfpy_client_set_gnss(void *h, double lat, double lon, double alt_m, int satellites, int week, long ms_of_week,
                          double relative_height_m);
/** Where the link goes ("tcp 127.0.0.1:2332"). */
const char *xfpy_client_describe(void *h);
void xfpy_client_free(void *h);

/* ---- simulator --------------------------------------------------------------------- */

void *xfpy_sim_new(void);
/** Set configuration @p name (setting table 1) before open. @return 0 or -1 (unknown name, out of range). */
int xfpy_sim_config(void *h, const char *name, long long value);
/** Configuration @p name as it is set. @return it, or -1 (unknown name). */
long long xfpy_sim_config_get(void *h, const char *name);
/** Set a fault (setting table 2) at any time after open. @return 0 or -1 (unknown name, out of range). */
int xfpy_sim_fault(void *h, const char *name, long long value);
/** Fault @p name as it is set. @return it, or -1 (unknown name). */
long long xfpy_sim_fault_get(void *h, const char *name);
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
/**
 * What the simulator read strictly where V2.0.6 leaves a GCU's behaviour open (xf_sim_config.on_note),
 * the last ones kept, oldest first: a JSON array of one-line texts. @return 0 or the size needed.
 */
int xfpy_sim_notes(void *h, char *out, size_t cap);
void xfpy_sim_disconnect(void *h, long ms);
void xfpy_sim_free(void *h);

#endif /* XFGCU_XFPY_H */
