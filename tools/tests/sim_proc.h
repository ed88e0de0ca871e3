/*
 * sim_proc.h - `xfgcu sim` as a background process for the tests of the
 * online commands: started with posix_spawn, its ready line read from a
 * pipe, stopped with SIGTERM (then SIGKILL) and reaped. Every simulator
 * started is also remembered, and killed at exit if a test left it, and
 * each runs with --duration so that none outlives a crashed test.
 */
#ifndef XFGCU_SIM_PROC_H
#define XFGCU_SIM_PROC_H

#include <stddef.h>
#include <sys/types.h>

#include "run_tool.h"

typedef enum sim_link { SIM_TCP, SIM_UDP, SIM_PTY } sim_link;

typedef struct sim_proc {
    pid_t pid;  /* 0: not running */
    int out_fd; /* its stdout (kept open: it may print with --verbose) */
    sim_link link;
    char line[256]; /* the ready line */
    char port[8];   /* TCP / UDP */
    char path[128]; /* pty */
} sim_proc;

/**
 * Start `xfgcu sim` on @p link (port 0: any free one) with @p extra
 * arguments (NULL-terminated list, may be empty) and wait for its ready
 * line, text or --json's (20 s at most: far more than it takes on any load; a failure fails the test).
 */
void sim_start(sim_proc *s, sim_link link, ...);

/** Stop it (SIGTERM, then SIGKILL after 20 s) and reap it; returns its exit status (128 + signal if killed). */
int sim_stop(sim_proc *s);

/** A test of what the simulator's output (--verbose) holds so far: 1 when it holds all it should. */
typedef int (*sim_log_enough_fn)(const char *log, const void *user);

/**
 * Read the simulator's stdout into @p log (@p *len bytes there already; NUL-terminated after)
 * until @p enough says it holds all it should (20 s at most: a simulator slowed down by the
 * machine's load prints late, not never), then on until it has been quiet for 300 ms, so that
 * one more line, which would be one too many, shows.
 */
void sim_read_log(const sim_proc *s, char *log, size_t cap, size_t *len, sim_log_enough_fn enough, const void *user);

/**
 * Read the simulator's log (its stdout after the ready line) until a line holding @p needle, for
 * at most @p ms; the line goes to @p buf. @return 0 when found, -1 when not within the time
 */
int sim_log_line(sim_proc *s, const char *needle, long ms, char *buf, size_t cap);

/** The link options that reach it: "--tcp 127.0.0.1:PORT", UDP with --gcu-port and --local-port 0, or --serial PATH. */
int sim_link_args(const sim_proc *s, const char **args);

/** Run xfgcu with the link options of @p s, then the arguments (NULL-terminated, at most 40). */
tool_result sim_run_on(const sim_proc *s, ...);

/** cmocka setup/teardown: state is a zeroed sim_proc, started on TCP, UDP, a pty, or not at all. */
int sim_setup_tcp(void **state);
int sim_setup_udp(void **state);
int sim_setup_pty(void **state);
int sim_setup_none(void **state);
int sim_teardown(void **state);

#endif /* XFGCU_SIM_PROC_H */
