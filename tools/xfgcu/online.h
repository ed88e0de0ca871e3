/*
 * online.h - what the commands that talk to a GCU share: opening the link
 * the link options name (linkopts.h: --link, --serial, --udp, --tcp or XFGCU_LINK), a client on it, the
 * wait for the first reply, running one command the protocol's way, and
 * the SIGINT/SIGTERM flag.
 *
 * Exit codes (cli.h): a missing link option is a usage error (2); a link
 * that cannot be opened or a GCU that does not answer within --timeout is
 * a link error (3), reported with the operating system's reason.
 */
#ifndef XFGCU_ONLINE_H
#define XFGCU_ONLINE_H

#include <stdint.h>
#include <stdio.h>

#include "cli.h"
#include "xfgcu/xf_client.h"
#include "xfgcu/posix/xf_link.h"
#include "xfgcu/posix/xf_posix.h"
#include "xfgcu/posix/xf_poll.h"
#include "xfgcu/posix/xf_simlink.h"
#include "tap.h"

#include <jansson.h>

/* ---- signals ----------------------------------------------------------------- */

/** Catch SIGINT and SIGTERM into a flag (sigaction, no work in the handler); SIGPIPE is ignored. */
void cli_signals_init(void);
/** Has SIGINT or SIGTERM arrived? */
int cli_stop_requested(void);

/* ---- small shared helpers ------------------------------------------------------ */

/** Milliseconds to seconds for humans: "1.25 s". */
double cli_seconds(uint32_t ms);
/** Wrap degrees into [-180, 180). */
double cli_wrap180(double deg);

/* ---- a client on the link of the options ---------------------------------------- */

/** Callbacks a command wants; all may be NULL. */
typedef struct online_hooks {
    xf_on_bytes_fn on_bytes; /**< every packet sent and received */
    xf_on_link_fn on_link;
    xf_tap_fn tap; /**< every chunk the link moved, both ways (record) */
    void *user;    /**< for on_bytes, on_link and tap */
} online_hooks;

typedef struct online {
    const cli_link *opt;
    const char *context; /* the command's name, for messages */
    char desc[320];      /* "tcp 127.0.0.1:2332": where, for messages and captures (xf_link_describe()) */
    char option[600];    /* "--tcp 127.0.0.1:2332": the option that named the link (linkopts_spec()) */
    xf_link link;        /* the link the options name, opened from their spec */
    xf_hal raw;          /* the link's own hal */
    xf_tap tap;
    xf_hal hal; /* what the client uses: raw, or tapped */
    xf_client client;
    uint32_t up_ms;         /* how long the first reply took */
    uint32_t t0_ms;         /* xf_posix_now_ms() when the link opened: --trace's and --json's times count from here */
    online_hooks hooks;     /* the command's callbacks, called after --trace's */
    int client_on;          /* the client was started: online_free() lets it settle first */
    unsigned submit_flags;  /* xf_client_submit_opt() flags: XF_SUBMIT_ANY_MODEL for send --force */
    uint32_t wait_ms;       /* set before online_open() (monitor --wait): 0, --timeout as usual; else how long the
                               link may take to open and the GCU to answer first, ONLINE_WAIT_FOREVER: until a signal */
    int wait_note;          /* print one note on stderr when the wait goes on past --timeout (a person is watching) */
    unsigned versions_sent; /* a bit per version byte the client has sent (1u << version): what a silence tried */
} online;

/** online.wait_ms: wait for the GCU until SIGINT or SIGTERM. */
#define ONLINE_WAIT_FOREVER UINT32_MAX

/**
 * Open the link, start a client on it (with --protocol, --rate, --timeout)
 * and wait for the first valid reply within --timeout. @p o must be zeroed
 * storage (online_new() gives one). Prints any error. @return an exit code.
 */
int online_open(online *o, const cli_link *opt, const char *context, const online_hooks *hooks);

/** Zeroed storage for a session (it is large); NULL when out of memory, after printing why. */
online *online_new(void);
/**
 * Let the client settle (xf_client_settled(): no reply to one of its commands still on the
 * link, where the next program could take it for its own), for at most twice --timeout plus
 * --reorder, with a note if it does not; then close the link and free @p o (may be NULL).
 */
void online_free(online *o);

/**
 * Switch the gimbal's mode with @p order, run as send runs it, with no control quantities (the
 * mode before would read them its own way); with @p json, print its result as one JSON line
 * (online_result_json() with "step": "mode" and "link"), whatever it is. @return an exit code
 * (a usage error only; the result is in *@p r)
 */
int online_run_mode(online *o, uint8_t order, int json, xf_cmd_result *r);

/** What point and rate do once the gimbal is in their mode. @return an exit code. */
typedef int (*online_mode_fn)(online *o, const void *args);

/**
 * Open the link (online_open()), switch the gimbal's mode with @p order, run
 * as send runs it, with no control quantities until the mode reads them,
 * then @p then(o, @p args); close the link. Catches SIGINT and SIGTERM.
 * @p what names the order in the messages. With @p json, the mode's result is
 * printed first as one JSON line (online_result_json() with "step": "mode" and
 * "link"), whatever it is. @return an exit code.
 */
int online_run_in_mode(const cli_link *opt, const char *context, uint8_t order, const char *what, int json,
                       online_mode_fn then, const void *args);

/** One round of the loop: wait at most @p max_wait_ms for the link or the next packet, then step the client. */
void online_poll(online *o, int max_wait_ms);

/** Keep the loop going (null packets, or whatever control is set) until @p packets more were sent. */
void online_linger(online *o, uint32_t packets);

/* ---- JSON lines (--json of send, point, rate, monitor, probe) ------------------------ */

/**
 * Add the two times every --json object carries: "time_mono", seconds on the monotonic clock
 * (CLOCK_MONOTONIC: for intervals, never steps), and "time_utc", the wall clock as ISO 8601
 * with milliseconds ("2026-11-26T10:00:00.123Z"). @return @p obj
 */
json_t *cli_json_times(json_t *obj);
/** A field of the GCU's telemetry (@p name, its wire integer @p raw) as JSON: in engineering units, or
 *  the wire integer with --raw (the unit rule: jsonpkt_value()). */
json_t *online_field_json(const online *o, const char *name, int64_t raw);
/** Print @p obj (taken: it is freed) on one line of stdout, flushed. @return 0, or -1 if out of memory. */
int cli_json_line(json_t *obj);
/** A command's result as JSON: status ("ok", "failed", "timeout", "link_lost", "cancelled",
 *  "operating"), order, order_name, state, failed_cameras, packets, elapsed_ms, and the times. */
json_t *online_result_json(const xf_cmd_result *r);

/** Prints progress of a command (operating) as it runs; NULL for none. */
typedef void (*online_progress_fn)(void *user, const xf_cmd_result *r, uint32_t operating_ms);

/**
 * Run @p cmd the protocol's way: submit it (an osd parsed from --show or
 * --hide gets the value of the GCU's version, cmdargs_for_version(); an
 * order the GCU's model lacks is refused unless submit_flags insists), keep
 * the loop going until its
 * result is final (ok, failed, timeout, link lost) or a signal arrives
 * (status XF_CMD_CANCELLED). @p progress is called when the GCU says
 * "operating", then about every 5 s while it still is.
 * @return XFGCU_EXIT_OK with *result set, or a usage error (the command
 *   does not fit the protocol version).
 */
int online_run(online *o, const xf_command *cmd, xf_cmd_result *result, online_progress_fn progress, void *user);

/** The result as one word or phrase for stdout: "ok", "failed cameras 0x02", "failed", "timeout", "link lost". */
void online_result_text(const xf_cmd_result *r, char *buf, size_t cap);
/**
 * The exit code of a finished command, printing the one stderr line of a
 * failure ("send zoom-in: the GCU answered failed cameras 0x02 on tcp ...").
 */
int online_result_exit(const online *o, const char *what, const xf_cmd_result *r);

/* ---- what the user sees of the client's health --------------------------------------- */

/**
 * The client's judgement of the link and the version the GCU answers, as JSON: version_setting
 * ("auto", 1 or 2: --protocol), version_sent, version_answered (null before an answer),
 * gcu_version (the version byte of its replies), in_order, out_of_turn, reorder_ms (the bound in
 * force), reorder_fixed (--reorder given), replies, given_up (frames the receive parser gave up).
 * NULL if out of memory.
 */
json_t *online_health_json(const online *o);
/** The same as one line of text: "protocol version 2 answered (auto), link in order, reorder bound 0 ms, ...". */
void online_health_text(const online *o, char *buf, size_t cap);

/**
 * Send one packet on the client's link, outside the client (a probe's question): its bytes as
 * given, traced with --trace. The client is not stepped meanwhile. @return the link's error
 */
xf_err online_raw_send(online *o, const uint8_t *data, size_t len);
/**
 * Read the link outside the client for @p ms milliseconds (the client is not stepped): each valid
 * GCU packet goes to @p got (traced with --trace); other bytes are dropped. @return the number of
 * GCU packets read
 */
unsigned online_raw_read(online *o, uint32_t ms, void (*got)(void *user, const uint8_t *data, size_t len), void *user);

/** The telemetry's attitude as "roll 0.00 pitch -30.00 yaw 45.00 deg". */
void online_attitude_text(const xf_telemetry *t, char *buf, size_t cap);

#endif /* XFGCU_ONLINE_H */
