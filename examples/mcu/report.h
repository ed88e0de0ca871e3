/*
 * report.h - the firmware's report for bring-up: what the client sees (link
 * state and rates, packets sent and received, the parser's errors, command
 * results, the INS), as text lines on the board's report UART, in the words
 * the xfgcu program prints on Linux. Portable: the board gives it a clock
 * and a UART (report_init()). Call everything from the main loop (the
 * client's callbacks run there too); nothing waits.
 */
#ifndef REPORT_H
#define REPORT_H

#include "xfgcu/xf_client.h"

#ifndef REPORT_RING
#define REPORT_RING 512u /* bytes of text waiting for the UART, a power of two */
#endif
#if (REPORT_RING & (REPORT_RING - 1u)) != 0u || REPORT_RING < 512u
#error "REPORT_RING must be a power of two, at least 512"
#endif

/* The clock the lines are stamped with (the client's), and the UART: put() sends one byte if
 * the UART can take it now (1) or returns 0, never waiting. Starts the report afresh. */
void report_init(uint32_t (*now_ms)(void), int (*put)(uint8_t byte));
/* The first line: the board, the gimbal link's speed, the photo period. */
void report_start(const char *board, uint32_t baud, uint32_t photo_ms);
/* Its own line, e.g. when the client cannot start. */
void report_text(const char *text);
/* xf_client_config.on_link and .on_result: a line per change and per result. */
void report_link(void *user, xf_link_state state);
void report_result(void *user, const xf_cmd_result *result);
/* A line when the INS's data becomes valid or stops being so. */
void report_ins(int valid);
/* The health line: the client's xf_client_health() and parser counters, the command
 * results so far, and the UART driver's receive overruns. */
void report_health(const xf_client *c, uint32_t rx_overruns);
/* Hand waiting text to the UART as far as it takes it now; call on every wake-up. */
void report_poll(void);

#endif
