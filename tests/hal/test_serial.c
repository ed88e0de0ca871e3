/*
 * test_serial.c - the serial link on real pseudo-terminals (termios path).
 *
 * Outside a prepared namespace libserialport 0.1.1 refuses a pty (no
 * /sys/class/tty entry, ENOTTY on the modem-line ioctls), so xf_serial_open
 * takes its termios path here; test_serial_lsp.c covers the libserialport
 * path. The pty master plays the GCU.
 */
#define _GNU_SOURCE /* posix_openpt, mkdtemp, setgroups */
#include <errno.h>
#include <fcntl.h>
#include <grp.h>
#include <signal.h>
#include <stdlib.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include "hal_test.h"
#include "pty_util.h"

typedef struct fixture {
    ht_pty pty;
    char dir[64];   /* mkdtemp */
    char link[128]; /* dir/gcu -> the pty slave */
    xf_serial s;
    xf_hal hal;
} fixture;

static int setup(void **state)
{
    fixture *f = calloc(1, sizeof(*f));
    if (f == NULL) {
        return -1;
    }
    f->pty.master = -1;
    f->s.fd = -1;
    snprintf(f->dir, sizeof(f->dir), "/tmp/xfgcu-serial-XXXXXX");
    if (mkdtemp(f->dir) == NULL || ht_pty_open(&f->pty) != 0) {
        free(f);
        return -1;
    }
    snprintf(f->link, sizeof(f->link), "%s/gcu", f->dir);
    if (symlink(f->pty.slave, f->link) != 0) {
        ht_pty_close(&f->pty);
        rmdir(f->dir);
        free(f);
        return -1;
    }
    *state = f;
    return 0;
}

static int teardown(void **state)
{
    fixture *f = *state;
    char path[192];
    xf_serial_close(&f->s);
    ht_pty_close(&f->pty);
    unlink(f->link);
    snprintf(path, sizeof(path), "%s/plain", f->dir);
    unlink(path);
    rmdir(f->dir);
    free(f);
    return 0;
}

/* Open the link on the fixture's pty through @p path. */
static void open_link(fixture *f, const char *path)
{
    assert_xf(xf_serial_open(&f->s, path, 115200), XF_OK);
    xf_serial_hal(&f->s, &f->hal);
    assert_xf(xf_hal_check(&f->hal), XF_OK);
    assert_true(xf_hal_fd(&f->hal) >= 0);
}

/* Every byte value, both ways: the line is raw (no CR/LF mapping, no
 * XON/XOFF, no signals, no echo). */
static void check_bytes_both_ways(fixture *f)
{
    uint8_t all[256], got[256];
    size_t n;
    ht_all_bytes(all);

    assert_int_equal(ht_write_all(f->pty.master, all, sizeof(all)), 0);
    memset(got, 0, sizeof(got));
    n = ht_hal_read_until(&f->hal, got, sizeof(got), 1000, NULL);
    assert_int_equal(n, sizeof(all));
    assert_memory_equal(got, all, sizeof(all));

    assert_xf(f->hal.write(f->hal.ctx, all, sizeof(all)), XF_OK);
    memset(got, 0, sizeof(got));
    n = ht_read_fd_until(f->pty.master, got, sizeof(got), 5000);
    assert_int_equal(n, sizeof(all));
    assert_memory_equal(got, all, sizeof(all));
    /* no echo of what the master sent */
    assert_false(ht_wait_readable(f->pty.master, 20));
}

static void test_open_termios_bytes_both_ways(void **state)
{
    fixture *f = *state;
    open_link(f, f->pty.slave);
    assert_string_equal(xf_serial_backend(&f->s), "termios");
    assert_int_equal(f->s.stats.opens, 1);
    check_bytes_both_ways(f);
    assert_int_equal(f->s.stats.bytes_rx, 256);
    assert_int_equal(f->s.stats.bytes_tx, 256);
    assert_int_equal(f->s.stats.packets_tx, 1);
    assert_int_equal(f->s.stats.losses, 0);
}

static void test_force_termios(void **state)
{
    fixture *f = *state;
    f->s.force_termios = 1; /* kept across xf_serial_open */
    open_link(f, f->link);
    assert_int_equal(f->s.force_termios, 1);
    assert_string_equal(xf_serial_backend(&f->s), "termios");
    check_bytes_both_ways(f);
}

/* A GCU packet written by the master in fragments, read between them,
 * comes out of the parser whole, once, and only after its last byte. */
static void test_fragmented_gcu_packet(void **state)
{
    static const size_t cuts[] = {1, 2, 5, 17, 30}; /* then the rest */
    fixture *f = *state;
    uint8_t pkt[XF_PACKET_LIMIT], buf[XF_PACKET_LIMIT];
    size_t len = ht_gcu_packet(pkt, sizeof(pkt), 1234), off = 0, i, reads = 0;
    ht_sink sink;
    assert_int_equal(len, XF_PACKET_MIN_LEN);
    ht_sink_init(&sink, XF_DIR_GCU);
    open_link(f, f->link);

    for (i = 0; i <= sizeof(cuts) / sizeof(cuts[0]); i++) {
        size_t piece = (i < sizeof(cuts) / sizeof(cuts[0])) ? cuts[i] : len - off;
        size_t n;
        assert_int_equal(ht_write_all(f->pty.master, pkt + off, piece), 0);
        off += piece;
        n = ht_hal_read_until(&f->hal, buf, piece, 1000, NULL);
        assert_int_equal(n, piece);
        reads++;
        ht_sink_feed(&sink, buf, n);
        assert_int_equal(sink.frames, off == len ? 1u : 0u);
    }
    assert_int_equal(off, len);
    assert_true(reads >= 6);
    ht_assert_frame(&sink, 0, pkt, len);
    assert_int_equal(sink.parser.stats.crc_errors, 0);
    assert_int_equal(sink.parser.stats.bytes_skipped, 0);
}

/* A host packet written through the HAL reaches the master byte-exact, in one piece. */
static void test_host_packet_in_one_piece(void **state)
{
    fixture *f = *state;
    uint8_t pkt[XF_PACKET_LIMIT], got[2 * XF_PACKET_LIMIT];
    size_t len = ht_host_packet(pkt, sizeof(pkt), -1234);
    ssize_t n;
    assert_true(len > XF_PACKET_MIN_LEN);
    open_link(f, f->link);
    assert_xf(f->hal.write(f->hal.ctx, pkt, len), XF_OK);
    assert_true(ht_wait_readable(f->pty.master, 1000));
    n = read(f->pty.master, got, sizeof(got));
    assert_int_equal(n, (ssize_t)len);
    assert_memory_equal(got, pkt, len);
    assert_xf(xf_packet_check(got, (size_t)n, XF_DIR_HOST), XF_OK);
    assert_int_equal(f->s.stats.packets_tx, 1);
    assert_int_equal(f->s.stats.bytes_tx, len);
}

/* Nobody reads the other end: once the pty's buffer is full, a write gives
 * up after its bound (100 ms) with XF_ERR_IO, as xf_posix.h promises. */
static void test_write_full_buffer(void **state)
{
    fixture *f = *state;
    uint8_t pkt[XF_PACKET_LIMIT];
    size_t len = ht_host_packet(pkt, sizeof(pkt), 5), i;
    xf_err err = XF_OK;
    uint32_t t0 = ht_now(), took = 0;
    open_link(f, f->link);
    for (i = 0; i < 100000u && ht_since(t0) < 5000u; i++) {
        uint32_t w0 = ht_now();
        err = f->hal.write(f->hal.ctx, pkt, len);
        took = ht_since(w0);
        if (err != XF_OK) {
            break;
        }
    }
    assert_xf(err, XF_ERR_IO);
    assert_true(took >= 90u);
    assert_true(took < 3000u); /* 100 ms, and whatever a loaded machine adds: not a wait for ever */
    assert_contains(f->s.error.text, f->link);
    assert_contains(f->s.error.text, "buffer full");
    assert_int_equal(f->s.stats.losses, 0); /* a full buffer is not a hang-up */
    assert_string_equal(xf_serial_backend(&f->s), "termios");
}

/* Read the link until it reports XF_ERR_CLOSED, at most @p ms; the time taken or -1. */
static long read_until_closed(fixture *f, uint32_t ms)
{
    uint32_t t0 = ht_now();
    while (ht_since(t0) < ms) {
        uint8_t buf[64];
        size_t n = 99;
        xf_err err = f->hal.read(f->hal.ctx, buf, sizeof(buf), &n);
        if (err == XF_ERR_CLOSED) {
            assert_int_equal(n, 0);
            return (long)ht_since(t0);
        }
        assert_xf(err, XF_OK);
        ht_sleep_ms(2);
    }
    return -1;
}

/* Hang-up (the master closes), then a new pty behind the same symlink: the
 * link notices, reports it, and reopens the path by itself. */
static void test_hangup_and_reopen(void **state)
{
    fixture *f = *state;
    uint8_t pkt[XF_PACKET_LIMIT], buf[XF_PACKET_LIMIT];
    char gone[192];
    size_t len, n;
    uint32_t t0;
    long took;
    xf_err err;
    open_link(f, f->link);
    assert_int_equal(f->s.stats.opens, 1);

    ht_pty_close(&f->pty);
    took = read_until_closed(f, 5000);
    assert_true(took >= 0);
    assert_int_equal(f->s.stats.losses, 1);
    assert_contains(f->s.error.text, "hung up");
    assert_contains(f->s.error.text, f->link);
    assert_string_equal(xf_serial_backend(&f->s), "closed");
    assert_int_equal(xf_hal_fd(&f->hal), -1);
    assert_xf(f->hal.write(f->hal.ctx, buf, 8), XF_ERR_CLOSED);
    /* still down while nothing is behind the path (past two back-offs):
     * every call says closed, no second loss, no open */
    snprintf(gone, sizeof(gone), "%s/gone", f->dir);
    assert_int_equal(ht_repoint(f->link, gone), 0);
    t0 = ht_now();
    while (ht_since(t0) < 180u) {
        n = 99;
        assert_xf(f->hal.read(f->hal.ctx, buf, sizeof(buf), &n), XF_ERR_CLOSED);
        assert_int_equal(n, 0);
        ht_sleep_ms(5);
    }
    assert_int_equal(f->s.stats.losses, 1);
    assert_int_equal(f->s.stats.opens, 1);
    assert_contains(f->s.error.text, "hung up"); /* the failed retries keep the reason */

    /* the "GCU" comes back on a new pty, behind the same symlink */
    assert_int_equal(ht_pty_open(&f->pty), 0);
    assert_int_equal(ht_repoint(f->link, f->pty.slave), 0);
    t0 = ht_now();
    while (f->s.stats.opens < 2 && ht_since(t0) < 5000u) { /* a back-off or two; more on a loaded machine */
        n = 0;
        err = f->hal.read(f->hal.ctx, buf, sizeof(buf), &n);
        assert_true(err == XF_OK || err == XF_ERR_CLOSED);
        ht_sleep_ms(5);
    }
    assert_int_equal(f->s.stats.opens, 2);
    print_message("reopened %u ms after the new pty appeared\n", (unsigned)ht_since(t0));
    assert_int_equal(f->s.stats.losses, 1);
    assert_string_equal(xf_serial_backend(&f->s), "termios");
    assert_true(xf_hal_fd(&f->hal) >= 0);

    /* data flows again, both ways */
    len = ht_gcu_packet(pkt, sizeof(pkt), 7);
    assert_int_equal(ht_write_all(f->pty.master, pkt, len), 0);
    n = ht_hal_read_until(&f->hal, buf, len, 1000, &err);
    assert_xf(err, XF_OK);
    assert_int_equal(n, len);
    assert_memory_equal(buf, pkt, len);
    len = ht_host_packet(pkt, sizeof(pkt), 99);
    assert_xf(f->hal.write(f->hal.ctx, pkt, len), XF_OK);
    n = ht_read_fd_until(f->pty.master, buf, len, 5000);
    assert_int_equal(n, len);
    assert_memory_equal(buf, pkt, len);
}

/* Closed by the application: no reopen, even with a live pty behind the path. */
static void test_close_stays_closed(void **state)
{
    fixture *f = *state;
    uint8_t buf[16];
    size_t n = 5;
    open_link(f, f->link);
    xf_serial_close(&f->s);
    assert_string_equal(xf_serial_backend(&f->s), "closed");
    ht_sleep_ms(60); /* past the first back-off */
    assert_xf(f->hal.read(f->hal.ctx, buf, sizeof(buf), &n), XF_ERR_CLOSED);
    assert_int_equal(n, 0);
    assert_xf(f->hal.write(f->hal.ctx, buf, sizeof(buf)), XF_ERR_CLOSED);
    assert_int_equal(f->s.stats.opens, 1);
    xf_serial_close(&f->s); /* twice is harmless */
}

static void test_no_device(void **state)
{
    fixture *f = *state;
    char path[192];
    snprintf(path, sizeof(path), "%s/ttyUSB9", f->dir);
    assert_xf(xf_serial_open(&f->s, path, 115200), XF_ERR_NOT_FOUND);
    assert_int_equal(f->s.error.os_errno, ENOENT);
    assert_contains(f->s.error.text, path);
    assert_contains(f->s.error.text, "No such file");
    assert_string_equal(xf_serial_backend(&f->s), "closed");
    assert_int_equal(f->s.stats.opens, 0);
}

/* A link whose open failed is closed: its HAL says so and never opens the
 * path by itself, even once the path works (or at a refused baud rate). */
static void test_failed_open_stays_closed(void **state)
{
    fixture *f = *state;
    char path[192];
    uint8_t buf[16];
    size_t n = 7;
    uint32_t t0;

    assert_xf(xf_serial_open(&f->s, f->link, 9600), XF_ERR_RANGE);
    xf_serial_hal(&f->s, &f->hal);
    t0 = ht_now();
    while (ht_since(t0) < 80u) {
        assert_xf(f->hal.read(f->hal.ctx, buf, sizeof(buf), &n), XF_ERR_CLOSED);
        assert_int_equal(n, 0);
        ht_sleep_ms(5);
    }
    assert_xf(f->hal.write(f->hal.ctx, buf, sizeof(buf)), XF_ERR_CLOSED);
    assert_int_equal(f->s.stats.opens, 0);
    assert_int_equal(xf_hal_fd(&f->hal), -1);
    assert_contains(f->s.error.text, "9600");

    /* not there at open time, there later: still closed until opened again */
    snprintf(path, sizeof(path), "%s/later", f->dir);
    assert_xf(xf_serial_open(&f->s, path, 115200), XF_ERR_NOT_FOUND);
    assert_int_equal(symlink(f->pty.slave, path), 0);
    t0 = ht_now();
    while (ht_since(t0) < 80u) {
        assert_xf(f->hal.read(f->hal.ctx, buf, sizeof(buf), &n), XF_ERR_CLOSED);
        ht_sleep_ms(5);
    }
    assert_int_equal(f->s.stats.opens, 0);
    assert_contains(f->s.error.text, "No such file");
    assert_xf(xf_serial_open(&f->s, path, 115200), XF_OK);
    assert_int_equal(f->s.stats.opens, 1);
    unlink(path);
}

static void test_not_a_terminal(void **state)
{
    fixture *f = *state;
    char path[192];
    int fd;
    snprintf(path, sizeof(path), "%s/plain", f->dir);
    fd = open(path, O_CREAT | O_WRONLY | O_TRUNC, 0600);
    assert_true(fd >= 0);
    assert_int_equal(write(fd, "x", 1), 1);
    close(fd);
    assert_xf(xf_serial_open(&f->s, path, 115200), XF_ERR_NOT_FOUND);
    assert_contains(f->s.error.text, path);
    assert_contains(f->s.error.text, "not a serial port");
    assert_string_equal(xf_serial_backend(&f->s), "closed");
}

static void test_bad_baud_and_args(void **state)
{
    static const uint32_t good[] = {115200u, 250000u, 500000u, 1000000u};
    fixture *f = *state;
    char longpath[400];
    size_t i;
    assert_xf(xf_serial_open(&f->s, f->pty.slave, 9600), XF_ERR_RANGE);
    assert_contains(f->s.error.text, "9600");
    assert_int_equal(f->s.fd, -1);
    assert_false(xf_serial_baud_ok(9600));
    assert_false(xf_serial_baud_ok(0));
    assert_false(xf_serial_baud_ok(230400));
    for (i = 0; i < sizeof(good) / sizeof(good[0]); i++) {
        assert_true(xf_serial_baud_ok(good[i]));
    }
    /* every supported rate opens a pty (250000 has no Bxxx constant) */
    for (i = 0; i < sizeof(good) / sizeof(good[0]); i++) {
        assert_xf(xf_serial_open(&f->s, f->link, good[i]), XF_OK);
        xf_serial_close(&f->s);
    }
    assert_xf(xf_serial_open(NULL, f->link, 115200), XF_ERR_ARG);
    assert_xf(xf_serial_open(&f->s, NULL, 115200), XF_ERR_ARG);
    memset(longpath, 'a', sizeof(longpath) - 1);
    longpath[sizeof(longpath) - 1] = '\0';
    assert_xf(xf_serial_open(&f->s, longpath, 115200), XF_ERR_ARG);
}

/* Permission denied: a 0600 root-owned pty slave opened by another user. As
 * root the check is bypassed, so a child drops to nobody (65534) first and
 * reports through its exit status. */
enum { CHILD_OK = 0, CHILD_WRONG_CODE = 1, CHILD_WRONG_TEXT = 2, CHILD_NO_DROP = 3 };

static void test_permission_denied(void **state)
{
    fixture *f = *state;
    pid_t pid;
    int status = 0;
    if (geteuid() != 0) {
        /* not root: our own slave, with no permission bits, does it */
        assert_int_equal(chmod(f->pty.slave, 0), 0);
        assert_xf(xf_serial_open(&f->s, f->pty.slave, 115200), XF_ERR_PERMISSION);
        assert_int_equal(f->s.error.os_errno, EACCES);
        assert_contains(f->s.error.text, "Permission denied");
        assert_contains(f->s.error.text, f->pty.slave);
        return;
    }
    assert_int_equal(chown(f->pty.slave, 0, 0), 0);
    assert_int_equal(chmod(f->pty.slave, 0600), 0);
    fflush(NULL);
    pid = fork();
    assert_true(pid >= 0);
    if (pid == 0) {
        xf_serial s;
        xf_err err;
        alarm(5);
        if (setgroups(0, NULL) != 0 || setgid(65534) != 0 || setuid(65534) != 0 || geteuid() != 65534) {
            _exit(CHILD_NO_DROP);
        }
        memset(&s, 0, sizeof(s));
        err = xf_serial_open(&s, f->pty.slave, 115200);
        if (err != XF_ERR_PERMISSION) {
            fprintf(stderr, "child: xf_serial_open: %d (%s): %s\n", (int)err, xf_strerror(err), s.error.text);
            _exit(CHILD_WRONG_CODE);
        }
        if (s.error.os_errno != EACCES || strstr(s.error.text, "Permission denied") == NULL ||
            strstr(s.error.text, f->pty.slave) == NULL) {
            fprintf(stderr, "child: error text: %s\n", s.error.text);
            _exit(CHILD_WRONG_TEXT);
        }
        _exit(CHILD_OK);
    }
    status = ht_wait_child(pid);
    if (status == CHILD_NO_DROP) {
        skip(); /* a container that forbids setuid: nothing to test */
    }
    assert_int_equal(status, CHILD_OK);
}

static int list_count;
static int list_bad;

static void list_cb(const xf_serial_port_info *info, void *user)
{
    (void)user;
    list_count++;
    if (info == NULL || info->path[0] == '\0' || (info->usb_vid < -1) || (info->usb_pid < -1)) {
        list_bad++;
    }
}

/* Listing works whatever ports the machine has (maybe none). */
static void test_list(void **state)
{
    int marker = 0;
    (void)state;
    list_count = 0;
    list_bad = 0;
    assert_xf(xf_serial_list(list_cb, &marker), XF_OK);
    assert_int_equal(list_bad, 0);
    assert_xf(xf_serial_list(NULL, NULL), XF_ERR_ARG);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup_teardown(test_open_termios_bytes_both_ways, setup, teardown),
        cmocka_unit_test_setup_teardown(test_force_termios, setup, teardown),
        cmocka_unit_test_setup_teardown(test_fragmented_gcu_packet, setup, teardown),
        cmocka_unit_test_setup_teardown(test_host_packet_in_one_piece, setup, teardown),
        cmocka_unit_test_setup_teardown(test_write_full_buffer, setup, teardown),
        cmocka_unit_test_setup_teardown(test_hangup_and_reopen, setup, teardown),
        cmocka_unit_test_setup_teardown(test_close_stays_closed, setup, teardown),
        cmocka_unit_test_setup_teardown(test_no_device, setup, teardown),
        cmocka_unit_test_setup_teardown(test_failed_open_stays_closed, setup, teardown),
        cmocka_unit_test_setup_teardown(test_not_a_terminal, setup, teardown),
        cmocka_unit_test_setup_teardown(test_bad_baud_and_args, setup, teardown),
        cmocka_unit_test_setup_teardown(test_permission_denied, setup, teardown),
        cmocka_unit_test(test_list),
    };
    return cmocka_run_group_tests_name("serial (pty, termios)", tests, NULL, NULL);
}
