/*
 * test_serial_lsp.c - the serial link's libserialport path, against a real pty.
 *
 * libserialport 0.1.1 will not open a pty: get_port_details() wants the
 * name to start with "/dev/" and a symlink at /sys/class/tty/<name without
 * "/dev/">, and sp_open() fails the modem-line ioctls with ENOTTY. So:
 *
 *   1. This program, started normally, enters a private mount namespace
 *      (unshare(CLONE_NEWNS), mounts made private so nothing leaks to the
 *      host) and re-executes itself with the test-only shim
 *      (pty_ioctl_shim.c, path in argv[1] or XFGCU_PTY_SHIM) in LD_PRELOAD.
 *   2. The re-executed program bind-mounts a temporary directory over
 *      /sys/class/tty holding shm/xfgcu-pty-<pid> -> ../../devices/virtual/...,
 *      and each test points /dev/shm/xfgcu-pty-<pid> at a fresh pty slave.
 *   3. xf_serial_open("/dev/shm/xfgcu-pty-<pid>") now succeeds through
 *      libserialport (xf_serial_backend() == "libserialport").
 *
 * If the namespace or the mount is not permitted (not root, no
 * CAP_SYS_ADMIN, a locked-down container), it prints why and exits with
 * 77, which CMake registers as SKIP_RETURN_CODE: reported as skipped, not
 * passed. The mounts vanish with the namespace; the temporary directory
 * and the /dev/shm symlink are removed on the way out.
 *
 * Sanitizers: with clang's default static ASan runtime the executable's
 * own ioctl interceptor forwards to the shim (RTLD_NEXT), which forwards
 * to libc. With a shared ASan runtime (gcc's libasan.so) the runtime must
 * come first in LD_PRELOAD; step 1 finds it in /proc/self/maps and puts it
 * there.
 */
#define _GNU_SOURCE /* unshare, RTLD_DEFAULT, posix_openpt, mkdtemp */
#include <dlfcn.h>
#include <errno.h>
#include <fcntl.h>
#include <dirent.h>
#include <sched.h>
#include <stdlib.h>
#include <sys/mount.h>
#include <sys/stat.h>
#include <unistd.h>

#include "hal_test.h"
#include "pty_util.h"

#define SKIP_CODE    77
#define INNER_ENV    "XFGCU_LSP_NAMESPACE"
#define SHIM_OFF_ENV "XFGCU_PTY_SHIM_OFF"
#define SYS_TTY      "/sys/class/tty"
#define FAKE_LISTED  "ttyXFT0" /* a fake listed port: no "virtual" in its target */

#ifndef XFGCU_PTY_SHIM
#define XFGCU_PTY_SHIM ""
#endif

static char g_sysdir[64]; /* mounted over /sys/class/tty */
static char g_port[128];  /* /dev/shm/xfgcu-pty-<pid>: the port's name for libserialport */
static int g_mounted;

/* ---- step 1: the namespace, then exec ourselves with the shim ------------------ */

static int skip_because(const char *why, int e)
{
    printf("SKIP: libserialport pty test not run: %s%s%s\n", why, e != 0 ? ": " : "", e != 0 ? strerror(e) : "");
    fflush(stdout);
    return SKIP_CODE;
}

/* The shared ASan runtime of this process, if any (it must come first in LD_PRELOAD). */
static int find_asan_runtime(char *out, size_t cap)
{
    char line[1024];
    FILE *maps = fopen("/proc/self/maps", "r");
    int found = 0;
    if (maps == NULL) {
        return 0;
    }
    while (!found && fgets(line, sizeof(line), maps) != NULL) {
        char *path = strchr(line, '/');
        if (path != NULL && (strstr(path, "/libasan.so") != NULL || strstr(path, "libclang_rt.asan") != NULL)) {
            path[strcspn(path, "\n")] = '\0';
            if (strlen(path) < cap) {
                snprintf(out, cap, "%s", path);
                found = 1;
            }
        }
    }
    fclose(maps);
    return found;
}

static int enter_namespace_and_reexec(char **argv, const char *shim)
{
    char preload[2048], asan[512];
    const char *old = getenv("LD_PRELOAD");
    if (shim[0] == '\0' || access(shim, R_OK) != 0) {
        fprintf(stderr, "FAIL: the pty ioctl shim \"%s\" is missing (pass its path as argv[1])\n", shim);
        return 1;
    }
    if (access(SYS_TTY, F_OK) != 0) {
        return skip_because("no " SYS_TTY " (sysfs not mounted)", errno);
    }
    if (access("/dev/shm", W_OK) != 0) {
        return skip_because("/dev/shm is not writable", errno);
    }
    if (unshare(CLONE_NEWNS) != 0) {
        return skip_because("cannot create a private mount namespace (unshare(CLONE_NEWNS); needs root or "
                            "CAP_SYS_ADMIN)",
                            errno);
    }
    if (mount(NULL, "/", NULL, MS_REC | MS_PRIVATE, NULL) != 0) {
        return skip_because("cannot make the mounts of the namespace private", errno);
    }
    preload[0] = '\0';
    if (find_asan_runtime(asan, sizeof(asan))) {
        snprintf(preload, sizeof(preload), "%s:", asan);
    }
    snprintf(preload + strlen(preload), sizeof(preload) - strlen(preload), "%s%s%s", shim,
             (old != NULL && old[0] != '\0') ? ":" : "", (old != NULL) ? old : "");
    if (setenv("LD_PRELOAD", preload, 1) != 0 || setenv(INNER_ENV, "1", 1) != 0) {
        perror("setenv");
        return 1;
    }
    execv("/proc/self/exe", argv);
    fprintf(stderr, "FAIL: re-executing /proc/self/exe: %s\n", strerror(errno));
    return 1;
}

/* ---- step 2: inside, the fake /sys/class/tty -------------------------------------- */

static void remove_fake_sysfs(void)
{
    char p[256];
    if (g_mounted) {
        (void)umount2(SYS_TTY, MNT_DETACH);
        g_mounted = 0;
    }
    if (g_sysdir[0] != '\0') {
        snprintf(p, sizeof(p), "%s/%s", g_sysdir, g_port + 5);
        (void)unlink(p);
        snprintf(p, sizeof(p), "%s/shm", g_sysdir);
        (void)rmdir(p);
        snprintf(p, sizeof(p), "%s/" FAKE_LISTED, g_sysdir);
        (void)unlink(p);
        (void)rmdir(g_sysdir);
        g_sysdir[0] = '\0';
    }
    if (g_port[0] != '\0') {
        (void)unlink(g_port);
    }
}

/* 0, or a skip/fail exit code. */
static int make_fake_sysfs(void)
{
    char p[256];
    snprintf(g_port, sizeof(g_port), "/dev/shm/xfgcu-pty-%ld", (long)getpid());
    snprintf(g_sysdir, sizeof(g_sysdir), "/tmp/xfgcu-sysfs-XXXXXX");
    if (mkdtemp(g_sysdir) == NULL) {
        g_sysdir[0] = '\0';
        return skip_because("mkdtemp", errno);
    }
    snprintf(p, sizeof(p), "%s/shm", g_sysdir);
    if (mkdir(p, 0755) != 0) {
        return skip_because("mkdir", errno);
    }
    /* readlink("/sys/class/tty/shm/xfgcu-pty-<pid>") must succeed; a target
     * naming neither "usb" nor "bluetooth" makes it a native port. */
    snprintf(p, sizeof(p), "%s/%s", g_sysdir, g_port + 5);
    if (symlink("../../devices/virtual/tty/xfgcu-pty", p) != 0) {
        return skip_because("symlink", errno);
    }
    /* For sp_list_ports: a top-level entry whose target is not "virtual". */
    snprintf(p, sizeof(p), "%s/" FAKE_LISTED, g_sysdir);
    if (symlink("../../devices/platform/serial-xftest/tty/" FAKE_LISTED, p) != 0) {
        return skip_because("symlink", errno);
    }
    if (mount(g_sysdir, SYS_TTY, NULL, MS_BIND, NULL) != 0) {
        return skip_because("cannot bind-mount a directory over " SYS_TTY, errno);
    }
    g_mounted = 1;
    return 0;
}

/* ---- step 3: the tests ---------------------------------------------------------- */

typedef struct fixture {
    ht_pty pty;
    xf_serial s;
    xf_hal hal;
} fixture;

static int setup(void **state)
{
    fixture *f = calloc(1, sizeof(*f));
    if (f == NULL) {
        return -1;
    }
    f->s.fd = -1;
    if (ht_pty_open(&f->pty) != 0 || ht_repoint(g_port, f->pty.slave) != 0) {
        ht_pty_close(&f->pty);
        free(f);
        return -1;
    }
    *state = f;
    return 0;
}

static int teardown(void **state)
{
    fixture *f = *state;
    xf_serial_close(&f->s);
    ht_pty_close(&f->pty);
    (void)unlink(g_port);
    (void)unsetenv(SHIM_OFF_ENV);
    free(f);
    return 0;
}

static void open_lsp(fixture *f)
{
    xf_err err = xf_serial_open(&f->s, g_port, 115200);
    if (err != XF_OK) {
        print_error("xf_serial_open(%s): %s\n", g_port, f->s.error.text);
    }
    assert_xf(err, XF_OK);
    assert_string_equal(xf_serial_backend(&f->s), "libserialport");
    assert_non_null(f->s.port);
    assert_int_equal(f->s.via_termios, 0);
    xf_serial_hal(&f->s, &f->hal);
    assert_true(xf_hal_fd(&f->hal) >= 0);
}

static void test_lsp_bytes_both_ways(void **state)
{
    fixture *f = *state;
    uint8_t all[256], got[2 * XF_PACKET_LIMIT];
    size_t n;
    ssize_t r;
    open_lsp(f);
    ht_all_bytes(all);

    /* every byte value: libserialport left the line raw */
    assert_int_equal(ht_write_all(f->pty.master, all, sizeof(all)), 0);
    n = ht_hal_read_until(&f->hal, got, sizeof(all), 1000, NULL);
    assert_int_equal(n, sizeof(all));
    assert_memory_equal(got, all, sizeof(all));
    assert_xf(f->hal.write(f->hal.ctx, all, sizeof(all)), XF_OK);
    n = ht_read_fd_until(f->pty.master, got, sizeof(all), 5000);
    assert_int_equal(n, sizeof(all));
    assert_memory_equal(got, all, sizeof(all));

    /* a host packet through sp_blocking_write arrives in one piece */
    n = ht_host_packet(all, sizeof(all), 321);
    assert_xf(f->hal.write(f->hal.ctx, all, n), XF_OK);
    assert_true(ht_wait_readable(f->pty.master, 1000));
    r = read(f->pty.master, got, sizeof(got));
    assert_int_equal(r, (ssize_t)n);
    assert_memory_equal(got, all, n);
    assert_int_equal(f->s.stats.packets_tx, 2);
    assert_int_equal(f->s.stats.bytes_tx, 256 + n);
    assert_int_equal(f->s.stats.bytes_rx, 256);
}

/* A GCU packet in three fragments, read between them, parses whole. */
static void test_lsp_fragmented_gcu_packet(void **state)
{
    fixture *f = *state;
    uint8_t pkt[XF_PACKET_LIMIT], buf[XF_PACKET_LIMIT];
    size_t len = ht_gcu_packet(pkt, sizeof(pkt), 4242), cuts[3], off = 0, i;
    ht_sink sink;
    ht_sink_init(&sink, XF_DIR_GCU);
    open_lsp(f);
    cuts[0] = 3;
    cuts[1] = 40;
    cuts[2] = len - 43;
    for (i = 0; i < 3; i++) {
        size_t n;
        assert_int_equal(ht_write_all(f->pty.master, pkt + off, cuts[i]), 0);
        off += cuts[i];
        n = ht_hal_read_until(&f->hal, buf, cuts[i], 1000, NULL);
        assert_int_equal(n, cuts[i]);
        ht_sink_feed(&sink, buf, n);
        assert_int_equal(sink.frames, i == 2 ? 1u : 0u);
    }
    ht_assert_frame(&sink, 0, pkt, len);
}

/* Hang-up and reopen, both through libserialport. */
static void test_lsp_hangup_and_reopen(void **state)
{
    fixture *f = *state;
    uint8_t buf[XF_PACKET_LIMIT], pkt[XF_PACKET_LIMIT];
    size_t n, len;
    uint32_t t0;
    xf_err err = XF_OK;
    open_lsp(f);

    ht_pty_close(&f->pty);
    t0 = ht_now();
    while (ht_since(t0) < 5000u) { /* until the hang-up shows */
        n = 0;
        err = f->hal.read(f->hal.ctx, buf, sizeof(buf), &n);
        if (err != XF_OK) {
            break;
        }
        ht_sleep_ms(2);
    }
    assert_xf(err, XF_ERR_CLOSED);
    assert_int_equal(f->s.stats.losses, 1);
    assert_contains(f->s.error.text, "hung up");
    assert_null(f->s.port);
    assert_string_equal(xf_serial_backend(&f->s), "closed");

    assert_int_equal(ht_pty_open(&f->pty), 0);
    assert_int_equal(ht_repoint(g_port, f->pty.slave), 0);
    t0 = ht_now();
    while (f->s.stats.opens < 2 && ht_since(t0) < 5000u) { /* a back-off or two; more on a loaded machine */
        err = f->hal.read(f->hal.ctx, buf, sizeof(buf), &n);
        assert_true(err == XF_OK || err == XF_ERR_CLOSED);
        ht_sleep_ms(5);
    }
    assert_int_equal(f->s.stats.opens, 2);
    assert_string_equal(xf_serial_backend(&f->s), "libserialport");

    len = ht_gcu_packet(pkt, sizeof(pkt), 9);
    assert_int_equal(ht_write_all(f->pty.master, pkt, len), 0);
    n = ht_hal_read_until(&f->hal, buf, len, 1000, &err);
    assert_xf(err, XF_OK);
    assert_int_equal(n, len);
    assert_memory_equal(buf, pkt, len);
}

/* Nobody reads the other end: sp_blocking_write gives up after 100 ms, XF_ERR_IO. */
static void test_lsp_write_full_buffer(void **state)
{
    fixture *f = *state;
    uint8_t pkt[XF_PACKET_LIMIT];
    size_t len = ht_host_packet(pkt, sizeof(pkt), 5), i;
    xf_err err = XF_OK;
    uint32_t t0 = ht_now(), took = 0;
    open_lsp(f);
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
    assert_contains(f->s.error.text, "buffer full");
    assert_int_equal(f->s.stats.losses, 0);
    assert_string_equal(xf_serial_backend(&f->s), "libserialport");
}

static int count_fds(void)
{
    DIR *d = opendir("/proc/self/fd");
    struct dirent *e;
    int n = 0;
    if (d == NULL) {
        return -1;
    }
    while ((e = readdir(d)) != NULL) {
        n += (e->d_name[0] != '.');
    }
    closedir(d);
    return n;
}

/* Without the shim libserialport refuses the pty (ENOTTY): the link falls
 * back to termios, leaking nothing. This also shows that the shim is what
 * made the other tests take the libserialport path. */
static void test_lsp_refused_falls_back_to_termios(void **state)
{
    fixture *f = *state;
    uint8_t b = 0x5A, got = 0;
    int before = count_fds();
    assert_true(before > 0);
    assert_int_equal(setenv(SHIM_OFF_ENV, "1", 1), 0);
    assert_xf(xf_serial_open(&f->s, g_port, 115200), XF_OK);
    assert_string_equal(xf_serial_backend(&f->s), "termios");
    assert_null(f->s.port);
    xf_serial_hal(&f->s, &f->hal);
    assert_xf(f->hal.write(f->hal.ctx, &b, 1), XF_OK);
    assert_int_equal(ht_read_fd_until(f->pty.master, &got, 1, 5000), 1);
    assert_int_equal(got, 0x5A);
    assert_int_equal(count_fds(), before + 1);
    xf_serial_close(&f->s);
    assert_int_equal(count_fds(), before);
}

static int g_listed;

static void list_cb(const xf_serial_port_info *info, void *user)
{
    (void)user;
    if (strcmp(info->path, "/dev/" FAKE_LISTED) == 0 && strcmp(info->description, FAKE_LISTED) == 0 &&
        info->usb_vid == -1 && info->usb_pid == -1) {
        g_listed++;
    }
}

/* xf_serial_list reports what libserialport finds under /sys/class/tty. */
static void test_lsp_list(void **state)
{
    (void)state;
    g_listed = 0;
    assert_xf(xf_serial_list(list_cb, NULL), XF_OK);
    assert_int_equal(g_listed, 1);
}

static int run_lsp_tests(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup_teardown(test_lsp_bytes_both_ways, setup, teardown),
        cmocka_unit_test_setup_teardown(test_lsp_fragmented_gcu_packet, setup, teardown),
        cmocka_unit_test_setup_teardown(test_lsp_write_full_buffer, setup, teardown),
        cmocka_unit_test_setup_teardown(test_lsp_hangup_and_reopen, setup, teardown),
        cmocka_unit_test_setup_teardown(test_lsp_refused_falls_back_to_termios, setup, teardown),
        cmocka_unit_test(test_lsp_list),
    };
    return cmocka_run_group_tests_name("serial (pty, libserialport in a mount namespace)", tests, NULL, NULL);
}

int main(int argc, char **argv)
{
    int rc;
    if (getenv(INNER_ENV) == NULL) {
        return enter_namespace_and_reexec(argv, argc > 1 ? argv[1] : XFGCU_PTY_SHIM);
    }
    (void)unsetenv(INNER_ENV);
    if (dlsym(RTLD_DEFAULT, "xfgcu_pty_shim_marker") == NULL) {
        fprintf(stderr, "FAIL: LD_PRELOAD did not load the pty ioctl shim (LD_PRELOAD=%s)\n",
                getenv("LD_PRELOAD") != NULL ? getenv("LD_PRELOAD") : "");
        return 1;
    }
    rc = make_fake_sysfs();
    if (rc != 0) {
        remove_fake_sysfs();
        return rc;
    }
    rc = run_lsp_tests();
    remove_fake_sysfs();
    return rc;
}
