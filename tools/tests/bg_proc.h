/*
 * bg_proc.h - the program in the background for the tests that act while it runs (stop a
 * simulator under it, watch what it writes): started with posix_spawn, stdout and stderr to
 * files, waited for with a limit; and the clock and sleep those tests use.
 */
#ifndef XFGCU_BG_PROC_H
#define XFGCU_BG_PROC_H

#include <stddef.h>
#include <sys/types.h>

#include "run_tool.h"

/** A program in the background, its stdout and stderr to files (stderr through a pipe when the
 *  size of its files is limited: the limit would cut its messages short too). */
typedef struct bg {
    pid_t pid;
    char out[96], err[96];
    int err_fd; /* the pipe's end to read, or -1 */
} bg;

/** Start xfgcu with the arguments (NULL-terminated); @p tag names its output files. */
void bg_start(bg *b, const char *tag, ...);

/** What bg_start_with() changes. */
typedef struct bg_opts {
    long max_file_bytes; /**< > 0: a limit on the size of the files it writes (RLIMIT_FSIZE): a write beyond
                              it fails with EFBIG, as on a full disk with ENOSPC, on any machine and without
                              privileges */
    int stdin_fd;        /**< >= 0: its stdin (else /dev/null) */
    int stdout_fd;       /**< >= 0: its stdout, such as a pipe or /dev/full (else a file bg_finish() reads) */
} bg_opts;

/** bg_start() with @p o (NULL: as bg_start()). */
void bg_start_with(bg *b, const bg_opts *o, const char *tag, ...);
/** Wait for it (SIGKILL after @p limit_ms, which fails the test), read what it wrote, remove the files. */
tool_result bg_finish(bg *b, long limit_ms);
/** SIGTERM, then bg_finish() with 5 s; its output is dropped. */
void bg_stop(bg *b);

/**
 * Wait until the program's stdout (its file) holds @p needle at least @p count times, for at most
 * @p seconds: the tests act on what a program has done, not on how long it usually takes.
 * @return 1, or 0 when it did not come in time (which fails the test).
 */
int bg_wait_output(const bg *b, const char *needle, unsigned count, double seconds);

/** The whole file at @p path (at most 1 MiB), NUL-terminated; free() it. */
char *slurp(const char *path);
/** Seconds on the monotonic clock. */
double now_s(void);
void sleep_ms(long ms);

#endif /* XFGCU_BG_PROC_H */
