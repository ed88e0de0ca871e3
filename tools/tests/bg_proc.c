/*
 * bg_proc.c - the program in the background (see bg_proc.h).
 */
#define _POSIX_C_SOURCE 200809L

#include "bg_proc.h"

#include <fcntl.h>
#include <poll.h>
#include <setjmp.h>
#include <signal.h>
#include <spawn.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>
#include <cmocka.h>

extern char **environ;

double now_s(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + (double)t.tv_nsec / 1e9;
}

void sleep_ms(long ms)
{
    struct timespec t;
    t.tv_sec = ms / 1000;
    t.tv_nsec = (ms % 1000) * 1000000L;
    nanosleep(&t, NULL);
}

/* Spawn with the arguments of @p ap. A file size limit is set in this process only around the
 * spawn (the child inherits it; the test's own files are not limited). */
static void bg_spawn(bg *b, const bg_opts *o, const char *tag, va_list ap)
{
    const char *args[40];
    char **argv;
    int argc = 0, rc;
    posix_spawn_file_actions_t fa;
    struct rlimit was, lim;
    const char *a;
    int err_end = -1;
    FILE *f;
    snprintf(b->out, sizeof(b->out), "/tmp/xfgcu-bg-%ld-%s.out", (long)getpid(), tag);
    snprintf(b->err, sizeof(b->err), "/tmp/xfgcu-bg-%ld-%s.err", (long)getpid(), tag);
    f = fopen(b->out, "w"); /* there for bg_finish() even when stdout goes elsewhere */
    assert_non_null(f);
    fclose(f);
    while ((a = va_arg(ap, const char *)) != NULL && argc < 38) {
        args[argc++] = a;
    }
    argv = spawn_argv(argc, args);
    assert_int_equal(posix_spawn_file_actions_init(&fa), 0);
    if (o->stdin_fd >= 0) {
        posix_spawn_file_actions_adddup2(&fa, o->stdin_fd, 0);
    } else {
        posix_spawn_file_actions_addopen(&fa, 0, "/dev/null", O_RDONLY, 0);
    }
    if (o->stdout_fd >= 0) {
        posix_spawn_file_actions_adddup2(&fa, o->stdout_fd, 1);
    } else {
        posix_spawn_file_actions_addopen(&fa, 1, b->out, O_WRONLY, 0);
    }
    b->err_fd = -1;
    if (o->max_file_bytes > 0) {
        int p[2];
        assert_int_equal(pipe(p), 0);
        assert_int_not_equal(fcntl(p[0], F_SETFD, FD_CLOEXEC), -1);
        assert_int_not_equal(fcntl(p[1], F_SETFD, FD_CLOEXEC), -1);
        posix_spawn_file_actions_adddup2(&fa, p[1], 2);
        b->err_fd = p[0];
        err_end = p[1];
    } else {
        posix_spawn_file_actions_addopen(&fa, 2, b->err, O_WRONLY | O_CREAT | O_TRUNC, 0600);
    }
    assert_int_equal(getrlimit(RLIMIT_FSIZE, &was), 0);
    lim = was;
    if (o->max_file_bytes > 0) {
        lim.rlim_cur = (rlim_t)o->max_file_bytes;
        assert_int_equal(setrlimit(RLIMIT_FSIZE, &lim), 0);
    }
    rc = posix_spawn(&b->pid, XFGCU_EXE, &fa, NULL, argv, environ);
    free(argv);
    assert_int_equal(setrlimit(RLIMIT_FSIZE, &was), 0);
    posix_spawn_file_actions_destroy(&fa);
    if (err_end >= 0) {
        close(err_end);
    }
    assert_int_equal(rc, 0);
}

void bg_start(bg *b, const char *tag, ...)
{
    static const bg_opts plain = {0, -1, -1};
    va_list ap;
    va_start(ap, tag);
    bg_spawn(b, &plain, tag, ap);
    va_end(ap);
}

void bg_start_with(bg *b, const bg_opts *o, const char *tag, ...)
{
    static const bg_opts plain = {0, -1, -1};
    va_list ap;
    va_start(ap, tag);
    bg_spawn(b, o != NULL ? o : &plain, tag, ap);
    va_end(ap);
}

char *slurp(const char *path)
{
    FILE *f = fopen(path, "rb");
    char *text = calloc(1, 1 << 20);
    size_t n;
    assert_non_null(f);
    assert_non_null(text);
    n = fread(text, 1, (1 << 20) - 1, f);
    text[n] = '\0';
    fclose(f);
    return text;
}

int bg_wait_output(const bg *b, const char *needle, unsigned count, double seconds)
{
    double end = now_s() + seconds;
    for (;;) {
        char *text = slurp(b->out);
        const char *at = text;
        unsigned n = 0;
        while ((at = strstr(at, needle)) != NULL) {
            n++;
            at++;
        }
        free(text);
        if (n >= count) {
            return 1;
        }
        if (now_s() >= end) {
            print_error("%s: no %u times \"%s\" within %.0f s (%u)\n", b->out, count, needle, seconds, n);
            fail();
            return 0;
        }
        sleep_ms(20);
    }
}

/* What is in the stderr pipe now (all of it once the program has ended), appended to @p text. */
static void drain_err(const bg *b, char **text, size_t *len, int wait_ms)
{
    struct pollfd p;
    char buf[4096];
    ssize_t got;
    p.fd = b->err_fd;
    p.events = POLLIN;
    while (poll(&p, 1, wait_ms) > 0 && (got = read(b->err_fd, buf, sizeof(buf))) > 0) {
        *text = realloc(*text, *len + (size_t)got + 1u);
        assert_non_null(*text);
        memcpy(*text + *len, buf, (size_t)got);
        *len += (size_t)got;
        (*text)[*len] = '\0';
    }
}

tool_result bg_finish(bg *b, long limit_ms)
{
    tool_result r;
    int wstatus = 0;
    double end = now_s() + (double)limit_ms / 1000.0;
    char *err = calloc(1, 1);
    size_t err_len = 0;
    pid_t got;
    assert_non_null(err);
    while ((got = waitpid(b->pid, &wstatus, WNOHANG)) == 0 && now_s() < end) {
        if (b->err_fd >= 0) {
            drain_err(b, &err, &err_len, 10);
        } else {
            sleep_ms(10);
        }
    }
    if (got == 0) {
        kill(b->pid, SIGKILL);
        waitpid(b->pid, &wstatus, 0);
        print_error("%s did not end in %ld ms\n", b->out, limit_ms);
    }
    if (b->err_fd >= 0) {
        drain_err(b, &err, &err_len, 1000); /* to the end: the writer has exited */
        close(b->err_fd);
        b->err_fd = -1;
    } else {
        free(err);
        err = slurp(b->err);
    }
    r.status = WIFEXITED(wstatus) ? WEXITSTATUS(wstatus) : 128 + WTERMSIG(wstatus);
    r.out = slurp(b->out);
    r.err = err;
    r.out_len = strlen(r.out);
    r.err_len = strlen(r.err);
    unlink(b->out);
    unlink(b->err);
    b->pid = 0;
    assert_int_not_equal(got, 0);
    return r;
}

void bg_stop(bg *b)
{
    tool_result r;
    kill(b->pid, SIGTERM);
    r = bg_finish(b, 5000);
    tool_result_free(&r);
}
