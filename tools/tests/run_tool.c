/*
 * run_tool.c - posix_spawn the program with three pipes and pump them
 * with poll(), so that neither side blocks however much either writes.
 */
#define _POSIX_C_SOURCE 200809L

#include "run_tool.h"

#include <errno.h>
#include <fcntl.h>
#include <poll.h>
#include <setjmp.h>
#include <signal.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>
#include <spawn.h>
#include <cmocka.h>

#include "../../tests/loopback.h"

#include "xfgcu/xfgcu.h"

extern char **environ;

const uint8_t appendix1[72] = {0xA8, 0xE5, 0x48, 0x00, 0x01, 0x00, 0x00, 0x64, 0x00, 0x9C, 0xFF, 0x05, 0x94, 0xFB, 0x65,
                               0x00, 0xC0, 0x5D, 0x70, 0x00, 0x90, 0xFF, 0x70, 0x00, 0x40, 0x80, 0xC0, 0xF7, 0x40, 0x80,
                               0x01, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x01, 0x24, 0xF2, 0xDF, 0x65, 0x16, 0xEE, 0xAA,
                               0x16, 0xA3, 0xA0, 0x00, 0x00, 0x13, 0xB0, 0x0C, 0x06, 0x15, 0xE6, 0x08, 0x58, 0x2F, 0x00,
                               0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0xE9, 0xD4};

typedef struct sink {
    char *data;
    size_t len, cap;
} sink;

static void sink_add(sink *s, const char *bytes, size_t n)
{
    if (s->len + n + 1u > s->cap) {
        s->cap = (s->len + n + 1u) * 2u;
        s->data = realloc(s->data, s->cap);
        assert_non_null(s->data);
    }
    memcpy(s->data + s->len, bytes, n);
    s->len += n;
    s->data[s->len] = '\0';
}

/* Read what is there; returns 0 at end of file. */
static int drain(int fd, sink *s)
{
    char buf[4096];
    ssize_t n = read(fd, buf, sizeof(buf));
    if (n > 0) {
        sink_add(s, buf, (size_t)n);
        return 1;
    }
    return (n < 0 && (errno == EINTR || errno == EAGAIN)) ? 1 : 0;
}

static void make_pipe(int fds[2])
{
    assert_int_equal(pipe(fds), 0);
    assert_int_not_equal(fcntl(fds[0], F_SETFD, FD_CLOEXEC), -1);
    assert_int_not_equal(fcntl(fds[1], F_SETFD, FD_CLOEXEC), -1);
}

char **spawn_argv(int argc, const char *const *args)
{
    size_t bytes = ((size_t)argc + 2u) * sizeof(char *) + sizeof(XFGCU_EXE);
    char **argv;
    char *text;
    int i;
    for (i = 0; i < argc; i++) {
        bytes += strlen(args[i]) + 1u;
    }
    argv = malloc(bytes);
    assert_non_null(argv);
    text = (char *)(argv + argc + 2);
    argv[0] = strcpy(text, XFGCU_EXE);
    text += sizeof(XFGCU_EXE);
    for (i = 0; i < argc; i++) {
        argv[i + 1] = strcpy(text, args[i]);
        text += strlen(args[i]) + 1u;
    }
    argv[argc + 1] = NULL;
    return argv;
}

static pid_t spawn(int argc, const char *const *args, int in[2], int out[2], int err[2])
{
    posix_spawn_file_actions_t fa;
    char **argv = spawn_argv(argc, args);
    pid_t pid = 0;
    assert_int_equal(posix_spawn_file_actions_init(&fa), 0);
    posix_spawn_file_actions_adddup2(&fa, in[0], 0);
    posix_spawn_file_actions_adddup2(&fa, out[1], 1);
    posix_spawn_file_actions_adddup2(&fa, err[1], 2);
    assert_int_equal(posix_spawn(&pid, XFGCU_EXE, &fa, NULL, argv, environ), 0);
    posix_spawn_file_actions_destroy(&fa);
    free(argv);
    return pid;
}

/* Write stdin while reading stdout and stderr, until both outputs end. */
static void pump(int in_fd, const char *input, size_t len, int out_fd, int err_fd, sink *out, sink *err)
{
    size_t sent = 0;
    int open_out = 1, open_err = 1;
    if (len == 0u) {
        close(in_fd);
        in_fd = -1;
    } else {
        assert_int_not_equal(fcntl(in_fd, F_SETFL, O_NONBLOCK), -1);
    }
    while (open_out || open_err) {
        struct pollfd p[3] = {{out_fd, POLLIN, 0}, {err_fd, POLLIN, 0}, {in_fd, POLLOUT, 0}};
        assert_true(poll(p, in_fd >= 0 ? 3 : 2, 20000) > 0); /* 20 s: a hung program fails the test */
        if (open_out && (p[0].revents & (POLLIN | POLLHUP)) != 0) {
            open_out = drain(out_fd, out);
        }
        if (open_err && (p[1].revents & (POLLIN | POLLHUP)) != 0) {
            open_err = drain(err_fd, err);
        }
        if (in_fd >= 0 && (p[2].revents & (POLLOUT | POLLERR | POLLHUP)) != 0) {
            ssize_t n = write(in_fd, input + sent, len - sent);
            if (n > 0) {
                sent += (size_t)n;
            }
            if ((n < 0 && errno != EAGAIN && errno != EINTR) || sent == len) {
                close(in_fd); /* done, or the program stopped reading */
                in_fd = -1;
            }
        }
    }
    if (in_fd >= 0) {
        close(in_fd);
    }
}

tool_result run_tool_bytes(int argc, const char *const *args, const char *input, size_t input_len)
{
    int in[2], out[2], err[2], wstatus = 0;
    sink so = {NULL, 0, 0}, se = {NULL, 0, 0};
    tool_result r;
    pid_t pid;
    signal(SIGPIPE, SIG_IGN);
    make_pipe(in);
    make_pipe(out);
    make_pipe(err);
    pid = spawn(argc, args, in, out, err);
    close(in[0]);
    close(out[1]);
    close(err[1]);
    sink_add(&so, "", 0);
    sink_add(&se, "", 0);
    pump(in[1], input, input_len, out[0], err[0], &so, &se);
    close(out[0]);
    close(err[0]);
    assert_int_equal(waitpid(pid, &wstatus, 0), pid);
    r.status = WIFEXITED(wstatus) ? WEXITSTATUS(wstatus) : 128 + WTERMSIG(wstatus);
    r.out = so.data;
    r.out_len = so.len;
    r.err = se.data;
    r.err_len = se.len;
    return r;
}

tool_result run_tool_argv(int argc, const char *const *args, const char *input)
{
    return run_tool_bytes(argc, args, input, input != NULL ? strlen(input) : 0u);
}

tool_result run_tool(const char *input, ...)
{
    const char *args[64];
    int n = 0;
    va_list ap;
    va_start(ap, input);
    for (;;) {
        const char *a = va_arg(ap, const char *);
        if (a == NULL) {
            break;
        }
        assert_true(n < 64);
        args[n++] = a;
    }
    va_end(ap);
    return run_tool_argv(n, args, input);
}

void tool_result_free(tool_result *r)
{
    free(r->out);
    free(r->err);
    r->out = r->err = NULL;
}

size_t count_lines(const char *text)
{
    size_t n = 0;
    for (; *text != '\0'; text++) {
        n += (*text == '\n');
    }
    return n;
}

void assert_failure(const tool_result *r, int status, ...)
{
    va_list ap;
    if (r->status != status || r->out_len != 0u || count_lines(r->err) != 1u || strncmp(r->err, "xfgcu: ", 7) != 0) {
        print_error("status %d (want %d)\nstdout: %s\nstderr: %s\n", r->status, status, r->out, r->err);
        fail();
    }
    va_start(ap, status);
    for (;;) {
        const char *needle = va_arg(ap, const char *);
        if (needle == NULL) {
            break;
        }
        if (strstr(r->err, needle) == NULL) {
            print_error("stderr lacks \"%s\": %s", needle, r->err);
            fail();
        }
    }
    va_end(ap);
}

void hex_line(const uint8_t *bytes, size_t n, char *buf)
{
    size_t i;
    for (i = 0; i < n; i++) {
        sprintf(buf + 3u * i, i + 1u < n ? "%02X " : "%02X\n", bytes[i]);
    }
    if (n == 0u) {
        buf[0] = '\0';
    }
}

void seal_packet(uint8_t *bytes, size_t len)
{
    uint16_t crc;
    xf_put_u16le(bytes + XF_OFF_LENGTH, (uint16_t)len);
    crc = xf_crc16(bytes, len - 2u);
    bytes[len - 2u] = (uint8_t)(crc >> 8);
    bytes[len - 1u] = (uint8_t)(crc & 0xFFu);
}

json_t *cut_summary(tool_result *r)
{
    char *last;
    json_t *obj, *summary;
    if (r->out_len == 0u || r->out[r->out_len - 1u] != '\n') {
        print_error("no summary line: %s\n", r->out);
        fail();
    }
    r->out[r->out_len - 1u] = '\0';
    last = strrchr(r->out, '\n');
    last = (last != NULL) ? last + 1 : r->out;
    obj = parse_line(last);
    summary = json_object_get(obj, "summary");
    if (!json_is_object(summary) || json_object_get(obj, "direction") != NULL) {
        print_error("the last line is no summary: %s\n", last);
        fail();
    }
    json_incref(summary);
    json_decref(obj);
    *last = '\0';
    r->out_len = (size_t)(last - r->out);
    return summary;
}

size_t count_packet_lines(const char *text)
{
    size_t n = 0;
    const char *p = text;
    while (*p != '\0') {
        size_t len = strcspn(p, "\n");
        json_t *obj = parse_line(p);
        n += json_object_get(obj, "direction") != NULL;
        json_decref(obj);
        p += len + (p[len] == '\n');
    }
    return n;
}

json_t *parse_line(const char *text)
{
    json_error_t e;
    json_t *obj = json_loadb(text, strcspn(text, "\n"), 0, &e);
    if (obj == NULL) {
        print_error("not JSON (%s): %s\n", e.text, text);
        fail();
    }
    return obj;
}

json_int_t int_key(const json_t *obj, const char *key)
{
    json_t *v = json_object_get(obj, key);
    if (!json_is_integer(v)) {
        print_error("key %s is missing or not an integer\n", key);
        fail();
    }
    return json_integer_value(v);
}

double num_key(const json_t *obj, const char *key)
{
    json_t *v = json_object_get(obj, key);
    if (!json_is_number(v)) {
        print_error("key %s is missing or not a number\n", key);
        fail();
    }
    return json_number_value(v);
}

const char *str_key(const json_t *obj, const char *key)
{
    json_t *v = json_object_get(obj, key);
    if (!json_is_string(v)) {
        print_error("key %s is missing or not a string\n", key);
        fail();
    }
    return json_string_value(v);
}

int hold_port(int type, char *port, size_t cap)
{
    uint16_t p = 0;
    int fd = test_loopback_socket(type, &p);
    snprintf(port, cap, "%u", (unsigned)p);
    return fd;
}
