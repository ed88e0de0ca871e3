/*
 * sim_proc.c - `xfgcu sim` in the background (see sim_proc.h).
 */
#define _POSIX_C_SOURCE 200809L

#include "sim_proc.h"

#include <errno.h>
#include <fcntl.h>
#include <poll.h>
#include <setjmp.h>
#include <signal.h>
#include <spawn.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>
#include <cmocka.h>
#include <jansson.h>

extern char **environ;

#define MAX_SIMS     16
#define SIM_LIFETIME "40" /* seconds: no simulator outlives a crashed test by more */

static pid_t running[MAX_SIMS]; /* every simulator not reaped yet */
static int exit_hook;

static void kill_leftovers(void)
{
    int i;
    for (i = 0; i < MAX_SIMS; i++) {
        if (running[i] > 0) {
            kill(running[i], SIGKILL);
            waitpid(running[i], NULL, 0);
            running[i] = 0;
        }
    }
}

static void remember(pid_t pid, pid_t was)
{
    int i;
    for (i = 0; i < MAX_SIMS; i++) {
        if (running[i] == was) {
            running[i] = pid;
            return;
        }
    }
}

static long now_ms(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (long)ts.tv_sec * 1000L + ts.tv_nsec / 1000000L;
}

/* Read one line from @p fd within @p ms. */
static int read_line(int fd, char *buf, size_t cap, long ms)
{
    size_t n = 0;
    long end = now_ms() + ms;
    while (n + 1u < cap) {
        struct pollfd p = {fd, POLLIN, 0};
        long left = end - now_ms();
        char c;
        if (left <= 0 || poll(&p, 1, (int)left) <= 0 || read(fd, &c, 1) != 1) {
            break;
        }
        if (c == '\n') {
            buf[n] = '\0';
            return 0;
        }
        buf[n++] = c;
    }
    buf[n] = '\0';
    return -1;
}

static pid_t spawn_sim(int argc, const char *const *args, int out[2])
{
    posix_spawn_file_actions_t fa;
    char **argv = spawn_argv(argc, args);
    pid_t pid = 0;
    int rc;
    assert_int_equal(posix_spawn_file_actions_init(&fa), 0);
    posix_spawn_file_actions_addopen(&fa, 0, "/dev/null", O_RDONLY, 0);
    posix_spawn_file_actions_adddup2(&fa, out[1], 1);
    rc = posix_spawn(&pid, XFGCU_EXE, &fa, NULL, argv, environ);
    posix_spawn_file_actions_destroy(&fa);
    free(argv);
    assert_int_equal(rc, 0);
    return pid;
}

/* sim --json: the ready line is {"event": "listening", "port": N, ...} or {..., "path": PATH}. */
static void parse_ready_json(sim_proc *s)
{
    json_error_t e;
    json_t *o = json_loads(s->line, 0, &e);
    const char *event = json_string_value(json_object_get(o, "event"));
    if (event == NULL || strcmp(event, "listening") != 0) {
        print_error("unexpected ready line: \"%s\"\n", s->line);
        fail();
    }
    if (s->link == SIM_PTY) {
        snprintf(s->path, sizeof(s->path), "%s", json_string_value(json_object_get(o, "path")));
    } else {
        snprintf(s->port, sizeof(s->port), "%d", (int)json_integer_value(json_object_get(o, "port")));
    }
    json_decref(o);
}

static void parse_ready(sim_proc *s)
{
    const char *want = (s->link == SIM_TCP)   ? "xfgcu sim: listening on tcp 127.0.0.1:"
                       : (s->link == SIM_UDP) ? "xfgcu sim: listening on udp 127.0.0.1:"
                                              : "xfgcu sim: listening on pty ";
    if (s->line[0] == '{') {
        parse_ready_json(s);
        return;
    }
    if (strncmp(s->line, want, strlen(want)) != 0) {
        print_error("unexpected ready line: \"%s\"\n", s->line);
        fail();
    }
    if (s->link == SIM_PTY) {
        snprintf(s->path, sizeof(s->path), "%s", s->line + strlen(want));
        s->path[strcspn(s->path, " ")] = '\0';
    } else {
        snprintf(s->port, sizeof(s->port), "%s", s->line + strlen(want));
    }
}

void sim_start(sim_proc *s, sim_link link, ...)
{
    const char *argv[40];
    int argc = 0, out[2];
    va_list ap;
    const char *a;
    if (!exit_hook) {
        exit_hook = 1;
        atexit(kill_leftovers);
        signal(SIGPIPE, SIG_IGN);
    }
    memset(s, 0, sizeof(*s));
    s->link = link;
    argv[argc++] = "sim";
    argv[argc++] = link == SIM_TCP ? "--tcp" : link == SIM_UDP ? "--udp" : "--pty";
    if (link != SIM_PTY) {
        argv[argc++] = "0";
    }
    argv[argc++] = "--duration";
    argv[argc++] = SIM_LIFETIME;
    va_start(ap, link);
    while ((a = va_arg(ap, const char *)) != NULL && argc < 38) {
        argv[argc++] = a;
    }
    va_end(ap);
    assert_int_equal(pipe(out), 0);
    fcntl(out[0], F_SETFD, FD_CLOEXEC);
    fcntl(out[1], F_SETFD, FD_CLOEXEC);
    s->pid = spawn_sim(argc, argv, out);
    remember(s->pid, 0);
    close(out[1]);
    s->out_fd = out[0];
    if (read_line(s->out_fd, s->line, sizeof(s->line), 20000) != 0) { /* far more than it takes, on any load */
        print_error("xfgcu sim printed no ready line within 20 s (got \"%s\")\n", s->line);
        fail();
    }
    parse_ready(s);
}

int sim_stop(sim_proc *s)
{
    int wstatus = 0;
    long end;
    pid_t r = 0;
    if (s->pid <= 0) {
        return -1;
    }
    kill(s->pid, SIGTERM);
    end = now_ms() + 20000;
    while ((r = waitpid(s->pid, &wstatus, WNOHANG)) == 0 && now_ms() < end) {
        struct timespec ten_ms = {0, 10000000L};
        nanosleep(&ten_ms, NULL);
    }
    if (r == 0) {
        kill(s->pid, SIGKILL);
        waitpid(s->pid, &wstatus, 0);
    }
    remember(0, s->pid);
    s->pid = 0;
    close(s->out_fd);
    return WIFEXITED(wstatus) ? WEXITSTATUS(wstatus) : 128 + WTERMSIG(wstatus);
}

void sim_read_log(const sim_proc *s, char *log, size_t cap, size_t *len, sim_log_enough_fn enough, const void *user)
{
    struct pollfd p;
    long end = now_ms() + 20000;
    p.fd = s->out_fd;
    p.events = POLLIN;
    log[*len] = '\0';
    while (*len + 1u < cap) {
        long wait = enough(log, user) ? 300 : end - now_ms();
        ssize_t got;
        if (wait <= 0 || poll(&p, 1, (int)wait) <= 0 || (got = read(s->out_fd, log + *len, cap - 1u - *len)) <= 0) {
            break;
        }
        *len += (size_t)got;
        log[*len] = '\0';
    }
}

int sim_log_line(sim_proc *s, const char *needle, long ms, char *buf, size_t cap)
{
    long end = now_ms() + ms;
    while (now_ms() < end) {
        if (read_line(s->out_fd, buf, cap, end - now_ms()) != 0) {
            break;
        }
        if (strstr(buf, needle) != NULL) {
            return 0;
        }
    }
    return -1;
}

int sim_link_args(const sim_proc *s, const char **args)
{
    static char tcp[64];
    switch (s->link) {
    case SIM_TCP:
        snprintf(tcp, sizeof(tcp), "127.0.0.1:%s", s->port);
        args[0] = "--tcp";
        args[1] = tcp;
        return 2;
    case SIM_UDP:
        args[0] = "--udp";
        args[1] = "127.0.0.1";
        args[2] = "--gcu-port";
        args[3] = s->port;
        args[4] = "--local-port";
        args[5] = "0";
        return 6;
    default:
        args[0] = "--serial";
        args[1] = s->path;
        return 2;
    }
}

static int setup(void **state, int link)
{
    sim_proc *s = calloc(1, sizeof(*s));
    if (s == NULL) {
        return -1;
    }
    *state = s;
    if (link >= 0) {
        sim_start(s, (sim_link)link, NULL);
    }
    return 0;
}

int sim_setup_tcp(void **state) { return setup(state, SIM_TCP); }
int sim_setup_udp(void **state) { return setup(state, SIM_UDP); }
int sim_setup_pty(void **state) { return setup(state, SIM_PTY); }
int sim_setup_none(void **state) { return setup(state, -1); }

int sim_teardown(void **state)
{
    sim_proc *s = (sim_proc *)*state;
    int status = 0;
    if (s != NULL && s->pid > 0) {
        status = sim_stop(s);
    }
    free(s);
    *state = NULL;
    if (status != 0) {
        print_error("xfgcu sim ended with status %d, not 0\n", status);
    }
    return status == 0 ? 0 : -1;
}

tool_result sim_run_on(const sim_proc *s, ...)
{
    const char *args[48];
    int n = sim_link_args(s, args);
    va_list ap;
    const char *a;
    va_start(ap, s);
    while ((a = va_arg(ap, const char *)) != NULL) {
        assert_true(n < 48);
        args[n++] = a;
    }
    va_end(ap);
    return run_tool_argv(n, args, NULL);
}
