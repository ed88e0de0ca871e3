/*
 * test_cli_capture.c - capture keeps what it captured, always (issue 30): a write that fails (a
 * file size limit, RLIMIT_FSIZE, which fails a write with EFBIG as a full disk fails it with
 * ENOSPC, on any machine and without privileges) stops the capture at once, with exit 2, one
 * line naming the part file, the part file a valid capture cut at its last whole line or
 * record, and FILE as it was even with --force; a GCU killed during the capture (TCP, a pty,
 * UDP) ends it with exit 3, the same way. Text and pcap. And the other writers (issue 30's
 * audit): replay, sim's log and demo stop at once when their stdout cannot be written;
 * gen_field_tables never overwrites a file it did not make, nor leaves its own behind.
 */
#define _POSIX_C_SOURCE 200809L

#include <fcntl.h>
#include <glob.h>
#include <setjmp.h>
#include <signal.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>
#include <cmocka.h>

#include "bg_proc.h"
#include "run_tool.h"
#include "sim_proc.h"

#define LONG_S     "30"  /* a --duration the capture must not reach: it ends on the failure */
#define LONG_LIMIT 30.0  /* ... in seconds, for the time it says it captured */
#define WAIT_MS    20000 /* for the program to end: far more than it takes, far less than LONG_S */

/* ---- helpers ---------------------------------------------------------------------------- */

typedef struct place {
    char dir[64];
    char file[128]; /* FILE: in dir */
} place;

static void place_make(place *p, int existing)
{
    FILE *f;
    snprintf(p->dir, sizeof(p->dir), "/tmp/xfgcu-capture-XXXXXX");
    assert_non_null(mkdtemp(p->dir));
    snprintf(p->file, sizeof(p->file), "%s/run.cap", p->dir);
    if (existing) {
        f = fopen(p->file, "w");
        assert_non_null(f);
        fputs("precious\n", f);
        assert_int_equal(fclose(f), 0);
    }
}

static void place_remove(const place *p)
{
    char cmd[128];
    snprintf(cmd, sizeof(cmd), "rm -rf '%s'", p->dir); /* ours: made by place_make() */
    assert_int_equal(system(cmd), 0);
}

/* The one FILE.partXXXXXX there is, into @p part; 0 when there is none. */
static int part_of(const place *p, char *part, size_t cap)
{
    char pattern[160];
    glob_t g;
    int n;
    snprintf(pattern, sizeof(pattern), "%s.part*", p->file);
    if (glob(pattern, 0, NULL, &g) != 0) {
        return 0;
    }
    n = (int)g.gl_pathc;
    assert_int_equal(n, 1);
    snprintf(part, cap, "%s", g.gl_pathv[0]);
    globfree(&g);
    return 1;
}

static long file_size(const char *path)
{
    struct stat st;
    return stat(path, &st) == 0 ? (long)st.st_size : -1;
}

/* FILE as the test left it: "precious" (@p existing), or not there at all. */
static void assert_file_untouched(const place *p, int existing)
{
    if (existing) {
        char *text = slurp(p->file);
        assert_string_equal(text, "precious\n");
        free(text);
    } else {
        assert_int_equal(access(p->file, F_OK), -1);
    }
}

/*
 * The one failure line: exit @p status, nothing more on stderr, holding every needle, naming
 * the part file as where the capture is kept and saying it captured less than LONG_S seconds
 * (it stopped at the failure); FILE as it was. Returns the part file's path in @p part.
 */
static void assert_kept(const tool_result *r, int status, const place *p, int existing, char *part, size_t cap, ...)
{
    char named[256] = "";
    double took = -1.0;
    const char *at = strstr(r->err, "what was captured (");
    va_list ap;
    const char *needle;
    if (r->status != status || count_lines(r->err) != 1u || strncmp(r->err, "xfgcu: capture: ", 16) != 0 ||
        at == NULL) {
        print_error("status %d (want %d)\nstdout: %s\nstderr: %s\n", r->status, status, r->out, r->err);
        fail();
    }
    va_start(ap, cap);
    while ((needle = va_arg(ap, const char *)) != NULL) {
        if (strstr(r->err, needle) == NULL) {
            print_error("stderr lacks \"%s\": %s", needle, r->err);
            fail();
        }
    }
    va_end(ap);
    assert_non_null(strstr(r->err, existing ? "run.cap is as it was\n" : "run.cap is not written\n"));
    assert_int_equal(sscanf(at, "what was captured (%lf s, ", &took), 1);
    assert_true(took >= 0.0 && took < LONG_LIMIT);
    at = strstr(at, " is kept as ");
    assert_non_null(at);
    assert_int_equal(sscanf(at, " is kept as %255[^;]", named), 1);
    assert_true(part_of(p, part, cap));
    assert_string_equal(named, part);
    assert_file_untouched(p, existing);
}

/* The part file is a whole capture: replay reads it to its end, and it holds packets both
 * ways; a text one ends with a whole line. */
static void assert_valid_capture(const char *part, int pcap)
{
    tool_result r = run_tool(NULL, "replay", part, "--brief", NULL);
    unsigned host = 0, gcu = 0;
    const char *sum;
    if (r.status != 0 || r.err_len != 0u) {
        print_error("replay %s: status %d\nstderr: %s\n", part, r.status, r.err);
        fail();
    }
    sum = strstr(r.out, " packets: ");
    assert_non_null(sum);
    assert_int_equal(sscanf(sum, " packets: %u host to GCU, %u GCU to host", &host, &gcu), 2);
    assert_true(host >= 1u && gcu >= 1u);
    tool_result_free(&r);
    if (!pcap) {
        char *text = slurp(part);
        size_t n = strlen(text);
        assert_true(n > 0u && text[n - 1u] == '\n');
        free(text);
    }
}

/* The link options of @p s, then "capture", [--pcap], [--force] */
static int capture_args(const sim_proc *s, int pcap, int force, const char **args)
{
    int n = sim_link_args(s, args);
    args[n++] = "capture";
    if (pcap) {
        args[n++] = "--pcap";
    }
    if (force) {
        args[n++] = "--force";
    }
    return n;
}

/* bg_start_with() a file size limit (0: none), the link options of @p s, "capture" and its arguments. */
static void start_capture(bg *b, long limit, const sim_proc *s, int pcap, int force, const char *file, const char *a1,
                          const char *a2)
{
    const char *args[16];
    bg_opts o = {0, -1, -1};
    int n = capture_args(s, pcap, force, args);
    o.max_file_bytes = limit;
    assert_true(n <= 9);
    args[n++] = file;
    args[n++] = a1;
    args[n++] = a2;
    while (n < 12) {
        args[n++] = NULL;
    }
    bg_start_with(b, &o, "capture", args[0], args[1], args[2], args[3], args[4], args[5], args[6], args[7], args[8],
                  args[9], args[10], args[11], NULL);
}

/* ---- a write that fails ----------------------------------------------------------------- */

#define LIMIT 4096L /* bytes: a few dozen chunks */

/* Capture (--force over an existing FILE when @p existing) into a file that may not grow past
 * @p limit bytes, with the arguments @p a1 and @p a2 (may be NULL): exit 2, the one line naming
 * the part file (into @p part), FILE as it was. */
static tool_result capture_limited(sim_proc *s, int pcap, int existing, long limit, const char *a1, const char *a2,
                                   place *p, char *part, size_t cap)
{
    bg b;
    tool_result r;
    place_make(p, existing);
    start_capture(&b, limit, s, pcap, existing, p->file, a1, a2);
    r = bg_finish(&b, WAIT_MS);
    assert_kept(&r, 2, p, existing, part, cap, "capture: cannot write ", "File too large", NULL);
    return r;
}

/* Capture for LONG_S seconds into a file that may not grow past LIMIT: it stops at the first
 * failed write, exit 2, the part kept with what fit, FILE as it was (@p existing, with --force). */
static void full_case(sim_proc *s, int pcap, int existing)
{
    place p;
    char part[256];
    tool_result r = capture_limited(s, pcap, existing, LIMIT, "--duration", LONG_S, &p, part, sizeof(part));
    assert_int_equal(r.out_len, 0u);
    assert_true(file_size(part) <= LIMIT && file_size(part) >= LIMIT / 2); /* what fit is there */
    assert_valid_capture(part, pcap);
    tool_result_free(&r);
    place_remove(&p);
}

static void test_full_text(void **state)
{
    sim_proc *s = (sim_proc *)*state;
    full_case(s, 0, 1);
    full_case(s, 0, 0);
}

static void test_full_pcap(void **state)
{
    sim_proc *s = (sim_proc *)*state;
    full_case(s, 1, 1);
    full_case(s, 1, 0);
}

/* Not even the file's header can be written: the same (libpcap closes the stream it cannot write
 * its header to, which once made a pcap capture free it twice). */
static void test_full_at_once(void **state)
{
    int pcap;
    for (pcap = 0; pcap < 2; pcap++) {
        place p;
        char part[256];
        tool_result r = capture_limited((sim_proc *)*state, pcap, 1, 10, "--duration", LONG_S, &p, part, sizeof(part));
        assert_int_equal(file_size(part), 0); /* no partial header */
        tool_result_free(&r);
        place_remove(&p);
    }
}

/* The write fails while COMMAND runs: the command, sent, is let finish and its result printed;
 * then the capture ends the same way. */
static void test_full_during_command(void **state)
{
    static const long limits[2] = {600L, 300L}; /* text, pcap: a header and a chunk or two */
    int pcap;
    for (pcap = 0; pcap < 2; pcap++) {
        place p;
        char part[256];
        tool_result r =
            capture_limited((sim_proc *)*state, pcap, 1, limits[pcap], "shutter", NULL, &p, part, sizeof(part));
        assert_string_equal(r.out, "ok\n");
        assert_true(file_size(part) <= limits[pcap] && file_size(part) > 0);
        tool_result_free(&r);
        place_remove(&p);
    }
}

/* ---- a GCU that dies ---------------------------------------------------------------------- */

/* Wait until the capture has written @p bytes to its part file (it is running, with chunks). */
static void wait_for_part(const place *p, long bytes)
{
    char part[256];
    double end = now_s() + 10.0;
    while (now_s() < end) {
        if (part_of(p, part, sizeof(part)) && file_size(part) >= bytes) {
            return;
        }
        sleep_ms(20);
    }
    fail_msg("the capture wrote no %ld bytes to %s.part* within 10 s", bytes, p->file);
}

/* Start a simulator on @p link, capture it for LONG_S seconds (--force over an existing FILE), kill
 * the simulator once chunks are in the file: exit 3, the part kept, FILE as it was. */
static void killed_case(sim_proc *s, sim_link link, int pcap, const char *why)
{
    place p;
    char part[256];
    bg b;
    tool_result r;
    place_make(&p, 1);
    sim_start(s, link, NULL);
    start_capture(&b, 0, s, pcap, 1, p.file, "--duration", LONG_S);
    wait_for_part(&p, 1000);
    assert_int_equal(kill(s->pid, SIGKILL), 0);
    (void)sim_stop(s); /* reaps it */
    r = bg_finish(&b, WAIT_MS);
    assert_kept(&r, 3, &p, 1, part, sizeof(part), "capture: link lost on ", why, NULL);
    assert_int_equal(r.out_len, 0u);
    assert_valid_capture(part, pcap);
    tool_result_free(&r);
    place_remove(&p);
}

static void test_killed_tcp(void **state)
{
    sim_proc *s = (sim_proc *)*state;
    /* closed, or reset when the simulator died with bytes unread: the link's own words either way */
    killed_case(s, SIM_TCP, 0, ": receive from 127.0.0.1:");
    killed_case(s, SIM_TCP, 1, ": receive from 127.0.0.1:");
}

static void test_killed_pty(void **state)
{
    sim_proc *s = (sim_proc *)*state;
    killed_case(s, SIM_PTY, 0, "hung up");
    killed_case(s, SIM_PTY, 1, "hung up");
}

/* UDP has no connection: a GCU gone is a GCU that stopped answering (the client's link down). */
static void test_killed_udp(void **state) { killed_case((sim_proc *)*state, SIM_UDP, 0, "the GCU stopped answering"); }

/* A pipe whose ends the program does not inherit (but the one made its stdin or stdout). */
static void make_pipe(int fds[2])
{
    assert_int_equal(pipe(fds), 0);
    assert_int_not_equal(fcntl(fds[0], F_SETFD, FD_CLOEXEC), -1);
    assert_int_not_equal(fcntl(fds[1], F_SETFD, FD_CLOEXEC), -1);
}

/* ---- the other writers: stdout ---------------------------------------------------------- */

/* replay into a stdout that cannot be written stops at once, exit 2 and one line, without reading
 * the rest of its input: its stdin is kept open, so it must end on its own. */
static void test_replay_full_stdout(void **state)
{
    bg_opts o = {0, -1, -1};
    char line[16 + sizeof(APPENDIX1_HEX)];
    int in[2], full = open("/dev/full", O_WRONLY), i;
    bg b;
    tool_result r;
    (void)state;
    signal(SIGPIPE, SIG_IGN); /* it may stop reading before we stop writing */
    assert_true(full >= 0);
    make_pipe(in);
    o.stdin_fd = in[0];
    o.stdout_fd = full;
    bg_start_with(&b, &o, "replay", "replay", "-", NULL);
    close(in[0]);
    close(full);
    assert_true(write(in[1], "# xfgcu capture 1\n", 18) == 18);
    for (i = 0; i < 100; i++) { /* a table of some 2 kB each: far more than a stdio buffer */
        int n = snprintf(line, sizeof(line), "%d.%03d > %s\n", i / 50, (i % 50) * 20, APPENDIX1_HEX);
        if (write(in[1], line, (size_t)n) != n) {
            break; /* it has stopped reading: fine */
        }
    }
    r = bg_finish(&b, WAIT_MS);
    close(in[1]);
    assert_failure(&r, 2, "cannot write to stdout", NULL);
    tool_result_free(&r);
}

/* sim --verbose whose log cannot be written any more (its reader went away) stops at once, exit 2
 * and one line, rather than serving on with its log lost. */
static void test_sim_log_lost(void **state)
{
    bg_opts o = {0, -1, -1};
    char ready[256] = "", link[64];
    int out[2];
    size_t n = 0;
    bg b;
    tool_result r;
    (void)state;
    make_pipe(out);
    o.stdout_fd = out[1];
    bg_start_with(&b, &o, "sim", "sim", "--tcp", "0", "--verbose", "--duration", LONG_S, NULL);
    close(out[1]);
    while (n + 1u < sizeof(ready) && strchr(ready, '\n') == NULL && read(out[0], ready + n, 1) == 1) {
        ready[++n] = '\0';
    }
    close(out[0]); /* the reader goes away */
    assert_int_equal(sscanf(ready, "xfgcu sim: listening on tcp %63s", link), 1);
    r = run_tool(NULL, "--tcp", link, "send", "shutter", NULL); /* the sim's log line for it fails */
    assert_int_equal(r.status, 0);
    tool_result_free(&r);
    r = bg_finish(&b, WAIT_MS);
    assert_failure(&r, 2, "cannot write to stdout", NULL);
    tool_result_free(&r);
}

/* demo into a stdout that cannot be written stops after its first step (the whole tour takes
 * seconds of waiting, more on a loaded machine: it does not reach the second step's), exit 2. */
static void test_demo_full_stdout(void **state)
{
    bg_opts o = {0, -1, -1};
    int full = open("/dev/full", O_WRONLY);
    double t0 = now_s();
    bg b;
    tool_result r;
    (void)state;
    assert_true(full >= 0);
    o.stdout_fd = full;
    bg_start_with(&b, &o, "demo", "demo", NULL);
    close(full);
    r = bg_finish(&b, WAIT_MS);
    assert_failure(&r, 2, "cannot write to stdout", NULL);
    assert_true(now_s() - t0 < 5.0);
    tool_result_free(&r);
}

/* ---- the documentation generator ----------------------------------------------------------- */

/* Run `sh -c SCRIPT` (with "$1" the generator, "$2" the file); its exit status. */
static int sh_run(const char *script, const char *file)
{
    char cmd[1024];
    int st;
    snprintf(cmd, sizeof(cmd), "sh -c '%s' sh '%s' '%s' 2>/dev/null", script, GEN_FIELD_TABLES, file);
    st = system(cmd);
    return WIFEXITED(st) ? WEXITSTATUS(st) : -1;
}

/* gen_field_tables replaces FILE through a new file of its own: one that is there under any name
 * it might pick is never overwritten, a failed write leaves FILE as it was and nothing behind. */
static void test_gen_field_tables_writes(void **state)
{
    place p;
    char tmp[160], cmd[400], *orig, *now;
    FILE *f;
    (void)state;
    place_make(&p, 0);
    snprintf(cmd, sizeof(cmd), "cp '%s' '%s'", PROTOCOL_MD, p.file);
    assert_int_equal(system(cmd), 0);
    snprintf(tmp, sizeof(tmp), "%s.tmp", p.file); /* the name it used to write through */
    f = fopen(tmp, "w");
    assert_non_null(f);
    fputs("precious\n", f);
    assert_int_equal(fclose(f), 0);
    assert_int_equal(sh_run("exec \"$1\" \"$2\"", p.file), 0);
    orig = slurp(PROTOCOL_MD);
    now = slurp(p.file);
    assert_string_equal(now, orig); /* rewritten: the same tables */
    free(now);
    now = slurp(tmp);
    assert_string_equal(now, "precious\n");
    free(now);
    /* a write that fails (1 kB at most: ulimit -f counts 512- or 1024-byte blocks) */
    assert_int_equal(sh_run("trap \"\" XFSZ; ulimit -f 1 && exec \"$1\" \"$2\"", p.file), 1);
    now = slurp(p.file);
    assert_string_equal(now, orig);
    free(now);
    free(orig);
    snprintf(cmd, sizeof(cmd), "test $(ls '%s' | wc -l) -eq 2", p.dir); /* run.cap and run.cap.tmp: nothing left */
    assert_int_equal(system(cmd), 0);
    place_remove(&p);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup_teardown(test_full_text, sim_setup_tcp, sim_teardown),
        cmocka_unit_test_setup_teardown(test_full_pcap, sim_setup_udp, sim_teardown),
        cmocka_unit_test_setup_teardown(test_full_at_once, sim_setup_pty, sim_teardown),
        cmocka_unit_test_setup_teardown(test_full_during_command, sim_setup_tcp, sim_teardown),
        cmocka_unit_test_setup_teardown(test_killed_tcp, sim_setup_none, sim_teardown),
        cmocka_unit_test_setup_teardown(test_killed_pty, sim_setup_none, sim_teardown),
        cmocka_unit_test_setup_teardown(test_killed_udp, sim_setup_none, sim_teardown),
        cmocka_unit_test(test_replay_full_stdout),
        cmocka_unit_test(test_sim_log_lost),
        cmocka_unit_test(test_demo_full_stdout),
        cmocka_unit_test(test_gen_field_tables_writes),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
