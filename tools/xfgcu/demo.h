/*
 * demo.h - the harness of `xfgcu demo`: a simulated GCU and a client in
 * one process, over a real TCP connection on loopback, driven by one
 * poll loop; and the helpers the tour's steps print and check with.
 */
#ifndef XFGCU_DEMO_H
#define XFGCU_DEMO_H

#include <stdint.h>

#include "cli.h"
#include "xfgcu/xf_client.h"
#include "xfgcu/posix/xf_link.h"
#include "xfgcu/posix/xf_posix.h"
#include "xfgcu/posix/xf_poll.h"
#include "xfgcu/posix/xf_simlink.h"
#include "xfgcu/xf_sim.h"

#define DEMO_LOG_MAX 24 /* runs of orders sent, for showing a step's packets */

typedef struct demo {
    xf_simlink gcu_link; /* the simulator's end: a TCP server on 127.0.0.1 */
    xf_sim sim;
    xf_link link; /* the client's end: a TCP link, from the spec that reaches the simulator */
    xf_client client;
    uint32_t t0;   /* start of the tour */
    uint32_t mark; /* start of what a step times */
    int step;
    /* what the client sends in every packet, refreshed by the loop */
    int rates_on;
    float rate_pitch, rate_yaw;
    xf_gnss gnss;
    double target_pitch, target_yaw, target_zoom; /* what a step waits for */
    /* orders of the host packets sent since demo_log_start: runs of one order */
    uint8_t log_order[DEMO_LOG_MAX];
    uint16_t log_count[DEMO_LOG_MAX];
    int log_n, logging;
    char failure[200]; /* the first thing that did not behave */
} demo;

/** Start the simulator on a free loopback port and connect a client to it. Prints any error. @return an exit code. */
int demo_start(demo *d);
void demo_stop(demo *d);

/** Run the loop for @p ms (rates and GNSS refreshed); returns 0 early on SIGINT/SIGTERM. */
int demo_pump(demo *d, uint32_t ms);
/** Run the loop until @p done(d) or @p ms pass; returns the ms it took, or -1 when it did not happen. */
long demo_pump_until(demo *d, uint32_t ms, int (*done)(const demo *d));

/**
 * Run one command the protocol's way and print it: "> what" then
 * "< name: result after N packets (T ms)". Checks that the result is
 * @p want (XF_CMD_OK, XF_CMD_FAILED). @return the result's status.
 */
xf_cmd_status demo_command(demo *d, const xf_command *cmd, const char *what, xf_cmd_status want, xf_cmd_result *out);

/** Set the rates sent in every packet (deg/s) and keep them fresh; demo_rates_off() sends zero rates. */
void demo_rates(demo *d, float pitch_dps, float yaw_dps);
void demo_rates_off(demo *d);

/** Start recording the orders of the host packets sent; demo_log_text() describes them ("shutter x2, null x1"). */
void demo_log_start(demo *d);
void demo_log_text(demo *d, char *buf, size_t cap);

const xf_telemetry *demo_tele(const demo *d);
/** Seconds since demo_mark(). */
double demo_since(const demo *d);
void demo_mark(demo *d);

/* ---- printing and checking -------------------------------------------------------- */

void demo_step(demo *d, const char *fmt, ...) CLI_PRINTF(2, 3);
/** One line: @p prefix, then the message. */
void demo_line(const char *prefix, const char *fmt, ...) CLI_PRINTF(2, 3);
/** "     > ..." what the library sends */
#define demo_sent(...) demo_line("     > ", __VA_ARGS__)
/** "     < ..." what the gimbal reports */
#define demo_got(...) demo_line("     < ", __VA_ARGS__)
/** "       ..." an explanation */
#define demo_say(...) demo_line("       ", __VA_ARGS__)
/** When @p ok is 0: print "     !! ..." and keep the first such reason. @return ok. */
int demo_check(demo *d, int ok, const char *fmt, ...) CLI_PRINTF(3, 4);

#endif /* XFGCU_DEMO_H */
