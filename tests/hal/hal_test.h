/*
 * hal_test.h - helpers shared by the tests of the POSIX links (tests/hal).
 *
 * The links are tested against real kernel objects: pseudo-terminals and
 * loopback sockets. Every wait here is bounded by a deadline, so a broken
 * link fails a test instead of hanging it.
 *
 * Include it after the feature-test macros (_GNU_SOURCE); it includes
 * cmocka itself, with the headers cmocka needs before it.
 */
#ifndef XFGCU_HAL_TEST_H
#define XFGCU_HAL_TEST_H

#include <errno.h>
#include <poll.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>
#include <signal.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>
#include <cmocka.h>

#include "xfgcu/posix/xf_posix.h"
#include "xfgcu/xfgcu.h"
#include "../xf_test_assert.h"

static inline uint32_t ht_now(void) { return xf_posix_now_ms(); }

static inline uint32_t ht_since(uint32_t t0) { return xf_ms_since(xf_posix_now_ms(), t0); }

/* Sleep for @p ms milliseconds (short waits between polls of a link). */
static inline void ht_sleep_ms(unsigned ms) { (void)poll(NULL, 0, (int)ms); }

/* Wait until @p fd is readable, at most @p ms: 1 readable (or hung up), 0 not. */
/* Wait for the child @p pid, at most 5 s (then kill it and fail the test); its exit status. */
static inline int ht_wait_child(pid_t pid)
{
    int status = 0;
    uint32_t t0 = ht_now();
    while (waitpid(pid, &status, WNOHANG) == 0) {
        if (ht_since(t0) > 5000u) {
            kill(pid, SIGKILL);
            (void)waitpid(pid, &status, 0);
            fail_msg("the child did not finish");
        }
        ht_sleep_ms(2);
    }
    assert_true(WIFEXITED(status));
    return WEXITSTATUS(status);
}

/* Run @p fn in a forked child (which must not outlive 5 s) and return its exit status:
 * for checks that need their own namespace or credentials. */
static inline int ht_run_child(int (*fn)(void))
{
    pid_t pid;
    fflush(NULL);
    pid = fork();
    assert_true(pid >= 0);
    if (pid == 0) {
        alarm(5);
        _exit(fn());
    }
    return ht_wait_child(pid);
}

static inline int ht_wait_readable(int fd, int ms)
{
    struct pollfd pfd;
    int r;
    pfd.fd = fd;
    pfd.events = POLLIN;
    pfd.revents = 0;
    do {
        r = poll(&pfd, 1, ms);
    } while (r < 0 && errno == EINTR);
    return r > 0;
}

/* Write all of @p len bytes to a (possibly non-blocking) fd within 2 s; 0 or -1. */
static inline int ht_write_all(int fd, const uint8_t *data, size_t len)
{
    uint32_t t0 = ht_now();
    size_t done = 0;
    while (done < len) {
        ssize_t w = write(fd, data + done, len - done);
        if (w > 0) {
            done += (size_t)w;
            continue;
        }
        if (w < 0 && errno != EAGAIN && errno != EWOULDBLOCK && errno != EINTR) {
            return -1;
        }
        if (ht_since(t0) > 5000u) {
            return -1;
        }
        ht_sleep_ms(1);
    }
    return 0;
}

/* Read from a raw fd until @p want bytes are in @p buf or @p ms pass; bytes read. */
static inline size_t ht_read_fd_until(int fd, uint8_t *buf, size_t want, uint32_t ms)
{
    uint32_t t0 = ht_now();
    size_t got = 0;
    while (got < want && ht_since(t0) < ms) {
        ssize_t r;
        if (!ht_wait_readable(fd, 10)) {
            continue;
        }
        r = read(fd, buf + got, want - got);
        if (r > 0) {
            got += (size_t)r;
        } else if (r == 0 || (errno != EAGAIN && errno != EWOULDBLOCK && errno != EINTR)) {
            break;
        }
    }
    return got;
}

/*
 * Read a link through its xf_hal until @p want bytes are in @p buf or @p ms
 * pass, waiting on the link's fd between reads. Returns the bytes read;
 * *last (may be NULL) gets the last result of hal->read.
 */
static inline size_t ht_hal_read_until(const xf_hal *hal, uint8_t *buf, size_t want, uint32_t ms, xf_err *last)
{
    uint32_t t0 = ht_now();
    size_t got = 0;
    xf_err err = XF_OK;
    while (got < want && ht_since(t0) < ms) {
        size_t n = 0;
        int fd = xf_hal_fd(hal);
        if (fd >= 0) {
            (void)ht_wait_readable(fd, 10);
        } else {
            ht_sleep_ms(5);
        }
        err = hal->read(hal->ctx, buf + got, want - got, &n);
        if (err != XF_OK && err != XF_ERR_CLOSED) {
            break;
        }
        got += n;
    }
    if (last != NULL) {
        *last = err;
    }
    return got;
}

/* ---- packets ------------------------------------------------------------------ */

/*
 * A GCU packet whose fields carry @p seed, so that each one differs, and
 * the bytes a terminal in cooked mode would mangle (CR, LF, XON, XOFF,
 * ^C, ^D, DEL), so that a link that is not raw is caught.
 */
static inline size_t ht_gcu_packet(uint8_t *buf, size_t cap, uint16_t seed)
{
    xf_gcu_packet pkt;
    size_t len = 0;
    memset(&pkt, 0, sizeof(pkt));
    pkt.version = XF_PROTOCOL_V2;
    pkt.main.gimbal_mode = 0x03;
    pkt.main.pod_status = 0x1311;      /* XOFF, XON */
    pkt.main.target_offset_x = 0x0A0D; /* LF, CR */
    pkt.main.target_offset_y = 0x0403; /* ^D, ^C */
    pkt.main.rel_angle_x = 0x7F1A;     /* DEL, ^Z */
    pkt.main.cam_yaw = seed;
    pkt.sub.sub_header = XF_SUB_HEADER;
    pkt.sub.fw_version = 0x0D;
    pkt.sub.target_distance = (int32_t)seed * 10;
    if (xf_gcu_pack(&pkt, buf, cap, &len) != XF_OK) {
        return 0;
    }
    return len;
}

/* A host packet (what the link writes toward the GCU). */
static inline size_t ht_host_packet(uint8_t *buf, size_t cap, int16_t yaw)
{
    xf_host_packet pkt;
    size_t len = 0;
    xf_host_packet_init(&pkt, XF_PROTOCOL_V2);
    pkt.main.yaw_ctrl = yaw;
    pkt.main.pitch_ctrl = 0x0D0A;
    pkt.main.status = XF_STATUS_CTRL_VALID;
    pkt.params_len = 2;
    pkt.params[0] = 0x11;
    pkt.params[1] = 0x13;
    if (xf_host_pack(&pkt, buf, cap, &len) != XF_OK) {
        return 0;
    }
    return len;
}

/* Frames parsed out of a stream, kept for comparison. */
#define HT_MAX_FRAMES 8
typedef struct ht_sink {
    xf_parser parser;
    size_t frames;
    uint8_t frame[HT_MAX_FRAMES][XF_PACKET_LIMIT];
    size_t frame_len[HT_MAX_FRAMES];
} ht_sink;

static inline void ht_sink_init(ht_sink *s, xf_direction dir)
{
    memset(s, 0, sizeof(*s));
    (void)xf_parser_init(&s->parser, dir);
}

static inline void ht_sink_feed(ht_sink *s, const uint8_t *data, size_t len)
{
    size_t used = 0;
    xf_frame f;
    for (;;) {
        xf_parse_status r = xf_parser_feed(&s->parser, data, len, &used, &f);
        if (r != XF_PARSE_FRAME) {
            break;
        }
        if (s->frames < HT_MAX_FRAMES && f.len <= XF_PACKET_LIMIT) {
            memcpy(s->frame[s->frames], f.data, f.len);
            s->frame_len[s->frames] = f.len;
        }
        s->frames++;
        data += used;
        len -= used;
    }
}

/* Frame @p i of the sink equals @p want (len bytes)? Fails the test if not. */
static inline void ht_assert_frame(const ht_sink *s, size_t i, const uint8_t *want, size_t len)
{
    assert_true(i < s->frames);
    assert_true(i < HT_MAX_FRAMES);
    assert_int_equal(s->frame_len[i], len);
    assert_memory_equal(s->frame[i], want, len);
}

/* Every byte value, in an order that starts with the dangerous ones. */
static inline void ht_all_bytes(uint8_t out[256])
{
    size_t i;
    for (i = 0; i < 256u; i++) {
        out[i] = (uint8_t)(255u - i);
    }
    out[0] = 0x0D;
    out[255 - 0x0D] = 0xFF;
}

#endif /* XFGCU_HAL_TEST_H */
