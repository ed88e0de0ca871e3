/*
 * test_link.c - links from spec strings (xfgcu/posix/xf_link.h) and the blocking run helper
 * (xf_posix_run, xf_posix_wait in xfgcu/posix/xf_poll.h).
 *
 *   parsing      good specs and their defaults; bad ones, each with its code and a one-line
 *                reason; NULL, empty, huge and random input
 *   opening      tcp, udp and serial (a pty) against the simulator's links, a command run on
 *                each; failures with the operating system's reason
 *   running      xf_posix_run against a simulated GCU in another process: it returns in the step
 *                that resolves the command; the timeout path; the arguments it refuses
 *
 * Timing checks leave room for a loaded machine and sanitizers.
 */
#define _XOPEN_SOURCE 700 /* mkdtemp, kill */
#include <fcntl.h>
#include <signal.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include "client_test.h"
#include "xfgcu/posix/xf_link.h"
#include "xfgcu/posix/xf_poll.h"
#include "xfgcu/posix/xf_simlink.h"

#include "../loopback.h" /* after cmocka.h, which client_test.h includes */

/* ---- parsing ----------------------------------------------------------------------------- */

typedef struct good_spec {
    const char *spec;
    xf_link_kind kind;
    const char *where; /* host or path */
    unsigned port, local_port, baud, port_given;
    const char *describe;
} good_spec;

static const good_spec goods[] = {
    {"tcp:192.168.144.108", XF_LINK_KIND_TCP, "192.168.144.108", 2332, 2338, 115200, 0, "tcp 192.168.144.108:2332"},
    {"tcp:gimbal.local:2000", XF_LINK_KIND_TCP, "gimbal.local", 2000, 2338, 115200, 1, "tcp gimbal.local:2000"},
    {"tcp:h:065535", XF_LINK_KIND_TCP, "h", 65535, 2338, 115200, 1, "tcp h:65535"},
    {"tcp:[::1]:2332", XF_LINK_KIND_TCP, "::1", 2332, 2338, 115200, 1, "tcp [::1]:2332"},
    {"tcp:[fe80::1%eth0]", XF_LINK_KIND_TCP, "fe80::1%eth0", 2332, 2338, 115200, 0, "tcp [fe80::1%eth0]:2332"},
    {"tcp:fe80::1", XF_LINK_KIND_TCP, "fe80::1", 2332, 2338, 115200, 0, "tcp [fe80::1]:2332"},
    {"tcp:[gimbal]", XF_LINK_KIND_TCP, "gimbal", 2332, 2338, 115200, 0, "tcp gimbal:2332"},
    {"udp:10.0.0.5", XF_LINK_KIND_UDP, "10.0.0.5", 2337, 2338, 115200, 0, "udp 10.0.0.5:2337"},
    {"udp:10.0.0.5:4000,local=0", XF_LINK_KIND_UDP, "10.0.0.5", 4000, 0, 115200, 1, "udp 10.0.0.5:4000"},
    {"udp:[::1]:2337,local=40000", XF_LINK_KIND_UDP, "::1", 2337, 40000, 115200, 1, "udp [::1]:2337"},
    {"udp:gcu,local=65535", XF_LINK_KIND_UDP, "gcu", 2337, 65535, 115200, 0, "udp gcu:2337"},
    {"serial:/dev/ttyUSB0", XF_LINK_KIND_SERIAL, "/dev/ttyUSB0", 2337, 2338, 115200, 0,
     "serial /dev/ttyUSB0 at 115200 baud"},
    {"serial:/dev/ttyUSB0,baud=1000000", XF_LINK_KIND_SERIAL, "/dev/ttyUSB0", 2337, 2338, 1000000, 0,
     "serial /dev/ttyUSB0 at 1000000 baud"},
    {"serial:ttyS1:x,baud=250000", XF_LINK_KIND_SERIAL, "ttyS1:x", 2337, 2338, 250000, 0,
     "serial ttyS1:x at 250000 baud"},
};

static void test_parse_good(void **state)
{
    size_t i;
    (void)state;
    for (i = 0; i < sizeof(goods) / sizeof(goods[0]); i++) {
        const good_spec *g = &goods[i];
        xf_link l;
        char text[128];
        memset(&l, 0, sizeof(l));
        assert_xf(xf_link_spec_parse(g->spec, &l.spec), XF_OK);
        assert_int_equal(l.spec.kind, g->kind);
        assert_string_equal(g->kind == XF_LINK_KIND_SERIAL ? l.spec.path : l.spec.host, g->where);
        if (g->kind == XF_LINK_KIND_SERIAL) {
            assert_int_equal(l.spec.baud, g->baud);
        } else {
            assert_int_equal(l.spec.port, g->port);
            assert_int_equal(l.spec.port_given, g->port_given);
        }
        if (g->kind == XF_LINK_KIND_UDP) {
            assert_int_equal(l.spec.local_port, g->local_port);
        }
        assert_int_equal(l.spec.connect_timeout_ms, 0);
        assert_string_equal(l.spec.error.text, "");
        assert_int_equal(xf_link_describe(&l, text, sizeof(text)), strlen(g->describe));
        assert_string_equal(text, g->describe);
    }
}

typedef struct bad_spec {
    const char *spec;
    xf_err code;
    const char *reason; /* a fragment of the error text */
} bad_spec;

static const bad_spec bads[] = {
    {"", XF_ERR_ARG, "no link spec: give tcp:HOST[:PORT], udp:HOST[:PORT][,local=PORT] or serial:PATH[,baud=N]"},
    {"192.168.144.108", XF_ERR_ARG, "192.168.144.108: no link kind"},
    {"ftp:host", XF_ERR_ARG, "ftp:host: unknown link kind 'ftp'"},
    {"TCP:host", XF_ERR_ARG, "unknown link kind 'TCP'"},
    {":host", XF_ERR_ARG, "unknown link kind ''"},
    {"tcp:", XF_ERR_ARG, "tcp:: no host"},
    {"tcp::2332", XF_ERR_ARG, "no host"},
    {"tcp:host:", XF_ERR_ARG, "port is empty"},
    {"tcp:host:0", XF_ERR_RANGE, "tcp:host:0: port 0 is out of range 1..65535"},
    {"tcp:host:65536", XF_ERR_RANGE, "port 65536 is out of range"},
    {"tcp:host:99999999999999999999", XF_ERR_RANGE, "out of range 1..65535"},
    {"tcp:host:-1", XF_ERR_ARG, "port '-1' is not a decimal number"},
    {"tcp:host:0x10", XF_ERR_ARG, "not a decimal number"},
    {"tcp:host:+5", XF_ERR_ARG, "not a decimal number"},
    {"tcp:host: 5", XF_ERR_ARG, "not a decimal number"},
    {"tcp:[::1", XF_ERR_ARG, "'[' without ']'"},
    {"tcp:[]:2332", XF_ERR_ARG, "no host between '[' and ']'"},
    {"tcp:[::1]2332", XF_ERR_ARG, "after ']' comes ':PORT' or nothing"},
    {"tcp:[::1]:", XF_ERR_ARG, "port is empty"},
    {"tcp:[::1]:70000", XF_ERR_RANGE, "out of range"},
    {"tcp:ho st", XF_ERR_ARG, "' ' has no place in a host name"},
    {"tcp:host/x:1", XF_ERR_ARG, "'/' has no place"},
    {"tcp:[a]b]", XF_ERR_ARG, "after ']'"},
    {"tcp:host,local=1", XF_ERR_ARG, "unknown option 'local' (tcp takes none)"},
    {"tcp:host,", XF_ERR_ARG, "empty option"},
    {"udp:host,local=65536", XF_ERR_RANGE, "local 65536 is out of range 0..65535"},
    {"udp:host,local=", XF_ERR_ARG, "local is empty"},
    {"udp:host,local", XF_ERR_ARG, "option 'local' has no '=' and value (udp takes local=PORT)"},
    {"udp:host,local=1,local=2", XF_ERR_ARG, "local given twice"},
    {"udp:host,,local=1", XF_ERR_ARG, "empty option"},
    {"udp:host,baud=115200", XF_ERR_ARG, "unknown option 'baud' (udp takes local=PORT)"},
    {"udp:,local=1", XF_ERR_ARG, "no host"},
    {"udp:host:0", XF_ERR_RANGE, "port 0"},
    {"serial:", XF_ERR_ARG, "no device path"},
    {"serial:,baud=115200", XF_ERR_ARG, "no device path"},
    {"serial:/dev/ttyUSB0,baud=9600", XF_ERR_RANGE,
     "serial:/dev/ttyUSB0,baud=9600: baud must be 115200, 250000, 500000 or 1000000"},
    {"serial:/dev/ttyUSB0,baud=99999999999", XF_ERR_RANGE, "baud must be"},
    {"serial:/dev/ttyUSB0,baud=fast", XF_ERR_ARG, "baud 'fast' is not a decimal number"},
    {"serial:/dev/ttyUSB0,baud=115200,baud=250000", XF_ERR_ARG, "baud given twice"},
    {"serial:/dev/x,speed=1", XF_ERR_ARG, "unknown option 'speed' (serial takes baud=N)"},
    {"serial:/dev/x,local=1", XF_ERR_ARG, "unknown option 'local'"},
    {"tcp:host\n", XF_ERR_ARG, "tcp:host?: control character at byte 8"},
    {"serial:/dev/\x7f", XF_ERR_ARG, "control character"},
};

/* A failure as the header promises it: the code, no kind, one line that says why. */
static void assert_refused(const xf_link_spec *s, xf_err got, xf_err want, const char *reason)
{
    if (got != want || strstr(s->error.text, reason) == NULL) {
        print_error("got %d (%s) \"%s\"; expected %d (%s) with \"%s\"\n", (int)got, xf_strerror(got), s->error.text,
                    (int)want, xf_strerror(want), reason);
        fail();
    }
    assert_int_equal(s->kind, XF_LINK_KIND_NONE);
    assert_int_equal(s->error.os_errno, 0);
    assert_null(strchr(s->error.text, '\n'));
    assert_true(strlen(s->error.text) > 0u && strlen(s->error.text) < sizeof(s->error.text) - 1u);
}

static void test_parse_bad(void **state)
{
    size_t i;
    xf_link_spec s;
    (void)state;
    for (i = 0; i < sizeof(bads) / sizeof(bads[0]); i++) {
        assert_refused(&s, xf_link_spec_parse(bads[i].spec, &s), bads[i].code, bads[i].reason);
    }
    assert_refused(&s, xf_link_spec_parse(NULL, &s), XF_ERR_ARG, "no link spec");
    assert_xf(xf_link_spec_parse("tcp:host", NULL), XF_ERR_ARG);
}

static void test_parse_lengths(void **state)
{
    static char big[1u << 20];
    char host[200], spec[400];
    xf_link_spec s;
    (void)state;
    /* a host of 127 bytes fits xf_tcp's; 128 does not */
    memset(host, 'h', 127);
    host[127] = '\0';
    snprintf(spec, sizeof(spec), "tcp:%s:1", host);
    assert_xf(xf_link_spec_parse(spec, &s), XF_OK);
    assert_string_equal(s.host, host);
    snprintf(spec, sizeof(spec), "udp:%sh", host);
    assert_refused(&s, xf_link_spec_parse(spec, &s), XF_ERR_RANGE, "host longer than 127 bytes");
    /* a path of 255 bytes fits xf_serial's; 256 does not */
    memset(spec, 0, sizeof(spec));
    memcpy(spec, "serial:/", 8);
    memset(spec + 8, 'p', 254);
    assert_xf(xf_link_spec_parse(spec, &s), XF_OK);
    assert_int_equal(strlen(s.path), 255);
    spec[8 + 254] = 'p';
    assert_refused(&s, xf_link_spec_parse(spec, &s), XF_ERR_RANGE, "device path longer than 255 bytes");
    /* the longest spec, and one byte more; then a megabyte: the error quotes only its start */
    memset(big, 'x', sizeof(big) - 1u);
    memcpy(big, "serial:", 7);
    big[XF_LINK_SPEC_MAX + 1u] = '\0';
    assert_refused(&s, xf_link_spec_parse(big, &s), XF_ERR_RANGE, "longer than 512 bytes");
    big[XF_LINK_SPEC_MAX + 1u] = 'x';
    big[sizeof(big) - 1u] = '\0';
    assert_refused(&s, xf_link_spec_parse(big, &s), XF_ERR_RANGE, "serial:xxx");
    assert_contains(s.error.text, "...: longer than 512 bytes");
    assert_true(strlen(s.error.text) < 100u);
    memcpy(big, "tcp:xxx", 7);
    big[4 + 100] = '\0'; /* a 100-byte host: the quote is cut, the reason is whole */
    assert_xf(xf_link_spec_parse(big, &s), XF_OK);
    big[4 + 100] = ':';
    big[4 + 101] = 'z';
    big[4 + 102] = '\0';
    assert_refused(&s, xf_link_spec_parse(big, &s), XF_ERR_ARG, "...: port 'z' is not a decimal number");
}

/* Random bytes, and random text of the grammar's own characters: never a crash, always a verdict. */
static void test_parse_garbage(void **state)
{
    static const char alphabet[] = "tcpudpserial:::,,==[]local=baud=0123456789./%- \x01";
    uint32_t seed = 12345u;
    char spec[700];
    int round;
    (void)state;
    for (round = 0; round < 20000; round++) {
        size_t n, i;
        xf_link l;
        xf_err err;
        char text[64];
        seed = seed * 1103515245u + 12345u;
        n = (seed >> 8) % (round < 10000 ? 40u : sizeof(spec));
        for (i = 0; i < n; i++) {
            seed = seed * 1103515245u + 12345u;
            spec[i] = (round % 2 == 0) ? alphabet[(seed >> 16) % (sizeof(alphabet) - 1u)] : (char)(seed >> 16);
            if (spec[i] == '\0') {
                spec[i] = '?';
            }
        }
        spec[n] = '\0';
        if (round % 3 == 0 && n > 6u) {
            memcpy(spec, round % 6 == 0 ? "tcp:" : "udp:", 4);
        }
        memset(&l, 0, sizeof(l));
        err = xf_link_spec_parse(spec, &l.spec);
        assert_true(err == XF_OK || err == XF_ERR_ARG || err == XF_ERR_RANGE);
        assert_true((err == XF_OK) == (l.spec.kind != XF_LINK_KIND_NONE));
        assert_true((err == XF_OK) == (l.spec.error.text[0] == '\0'));
        assert_null(strchr(l.spec.error.text, '\n'));
        (void)xf_link_describe(&l, text, sizeof(text));
        assert_true(strlen(text) < sizeof(text));
    }
}

static void test_spec_init(void **state)
{
    char path[300];
    xf_link_spec s;
    (void)state;
    assert_xf(xf_link_spec_init(&s, XF_LINK_KIND_UDP, "10.0.0.5"), XF_OK);
    assert_int_equal(s.kind, XF_LINK_KIND_UDP);
    assert_string_equal(s.host, "10.0.0.5");
    assert_int_equal(s.port, 2337);
    assert_int_equal(s.local_port, 2338);
    assert_xf(xf_link_spec_init(&s, XF_LINK_KIND_TCP, "::1"), XF_OK);
    assert_int_equal(s.port, 2332);
    assert_int_equal(s.port_given, 0);
    assert_xf(xf_link_spec_init(&s, XF_LINK_KIND_SERIAL, "/dev/odd,name"), XF_OK); /* any path: no options here */
    assert_string_equal(s.path, "/dev/odd,name");
    assert_int_equal(s.baud, 115200);
    assert_refused(&s, xf_link_spec_init(&s, XF_LINK_KIND_NONE, "x"), XF_ERR_ARG, "link kind 0");
    assert_refused(&s, xf_link_spec_init(&s, (xf_link_kind)99, "x"), XF_ERR_ARG, "link kind 99");
    assert_refused(&s, xf_link_spec_init(&s, XF_LINK_KIND_TCP, NULL), XF_ERR_ARG, "no host");
    assert_refused(&s, xf_link_spec_init(&s, XF_LINK_KIND_SERIAL, ""), XF_ERR_ARG, "no device path");
    assert_refused(&s, xf_link_spec_init(&s, XF_LINK_KIND_UDP, "a host"), XF_ERR_ARG, "' ' has no place");
    memset(path, 'p', sizeof(path) - 1u);
    path[sizeof(path) - 1u] = '\0';
    assert_refused(&s, xf_link_spec_init(&s, XF_LINK_KIND_SERIAL, path), XF_ERR_RANGE, "longer than 255 bytes");
    path[128] = '\0';
    assert_refused(&s, xf_link_spec_init(&s, XF_LINK_KIND_TCP, path), XF_ERR_RANGE, "longer than 127 bytes");
    assert_xf(xf_link_spec_init(NULL, XF_LINK_KIND_TCP, "x"), XF_ERR_ARG);
}

/* Serial lines and TCP streams keep order and never duplicate; UDP may not: only the first two
 * let a client skip judging the link. */
static void test_keeps_order(void **state)
{
    static const struct {
        const char *spec;
        int keeps;
    } kinds[] = {{"serial:/dev/ttyUSB0", 1},
                 {"tcp:10.0.0.5", 1},
                 {"tcp:10.0.0.5:2332", 1},
                 {"udp:10.0.0.5", 0},
                 {"udp:127.0.0.1:2337,local=0", 0}};
    xf_link_spec s;
    size_t i;
    (void)state;
    for (i = 0; i < sizeof(kinds) / sizeof(kinds[0]); i++) {
        assert_xf(xf_link_spec_parse(kinds[i].spec, &s), XF_OK);
        assert_int_equal(xf_link_keeps_order(&s), kinds[i].keeps);
    }
    memset(&s, 0, sizeof(s));
    assert_int_equal(xf_link_keeps_order(&s), 0); /* no kind */
    assert_int_equal(xf_link_keeps_order(NULL), 0);
}

static void test_describe(void **state)
{
    xf_link l;
    char text[64];
    (void)state;
    assert_int_equal(xf_link_describe(NULL, text, sizeof(text)), 4);
    assert_string_equal(text, "none");
    memset(&l, 0, sizeof(l));
    assert_int_equal(xf_link_describe(&l, text, sizeof(text)), 4);
    assert_string_equal(text, "none");
    assert_xf(xf_link_spec_parse("tcp:192.168.144.108", &l.spec), XF_OK);
    assert_int_equal(xf_link_describe(&l, NULL, 0), strlen("tcp 192.168.144.108:2332"));
    assert_int_equal(xf_link_describe(&l, text, 8), strlen("tcp 192.168.144.108:2332")); /* cut, like snprintf */
    assert_string_equal(text, "tcp 192");
    memset(l.spec.host, 'h', sizeof(l.spec.host)); /* not NUL-terminated: not read past */
    assert_int_equal(xf_link_describe(&l, text, sizeof(text)), 4);
    assert_string_equal(text, "none");
}

/* ---- the xf_link's own arguments -------------------------------------------------------- */

static void test_link_arguments(void **state)
{
    xf_link l;
    xf_link_spec s;
    xf_hal hal;
    int fd0_open;
    (void)state;
    memset(&l, 0, sizeof(l));
    memset(&s, 0, sizeof(s));
    assert_xf(xf_link_open(NULL, "tcp:127.0.0.1"), XF_ERR_ARG);
    assert_xf(xf_link_open_spec(NULL, &s), XF_ERR_ARG);
    assert_xf(xf_link_open(&l, NULL), XF_ERR_ARG);
    assert_contains(xf_link_error(&l)->text, "no link spec");
    assert_xf(xf_link_open(&l, "serial:/dev/ttyUSB0,baud=9600"), XF_ERR_RANGE);
    assert_string_equal(l.error.text, "serial:/dev/ttyUSB0,baud=9600: baud must be 115200, 250000, 500000 or 1000000");
    assert_int_equal(l.is_open, 0);
    assert_xf(xf_link_open_spec(&l, NULL), XF_ERR_ARG);
    assert_contains(l.error.text, "no link spec");
    /* a spec filled by hand is checked again */
    assert_xf(xf_link_spec_init(&s, XF_LINK_KIND_TCP, "127.0.0.1"), XF_OK);
    s.port = 0;
    assert_xf(xf_link_open_spec(&l, &s), XF_ERR_RANGE);
    assert_contains(l.error.text, "port 0");
    assert_xf(xf_link_spec_init(&s, XF_LINK_KIND_SERIAL, "/dev/null"), XF_OK);
    s.baud = 9600;
    assert_xf(xf_link_open_spec(&l, &s), XF_ERR_RANGE);
    assert_contains(l.error.text, "baud 9600");
    memset(s.path, 'p', sizeof(s.path));
    s.baud = 115200;
    assert_xf(xf_link_open_spec(&l, &s), XF_ERR_ARG);
    s.kind = (xf_link_kind)7;
    assert_xf(xf_link_open_spec(&l, &s), XF_ERR_ARG);
    assert_contains(l.error.text, "link kind 7");
    /* not open: refused, nothing crashes */
    memset(&l, 0, sizeof(l));
    assert_xf(xf_link_hal(&l, &hal), XF_ERR_CLOSED);
    assert_xf(xf_link_hal(NULL, &hal), XF_ERR_ARG);
    assert_xf(xf_link_hal(&l, NULL), XF_ERR_ARG);
    assert_xf(xf_link_wait(&l, 10), XF_ERR_CLOSED);
    assert_xf(xf_link_wait(NULL, 10), XF_ERR_ARG);
    assert_null(xf_link_error(NULL));
    assert_string_equal(xf_link_error(&l)->text, "");
    xf_link_close(NULL);
    fd0_open = fcntl(0, F_GETFD) != -1;
    xf_link_close(&l); /* zeroed: descriptor 0 is not closed */
    assert_int_equal(fcntl(0, F_GETFD) != -1, fd0_open);
    assert_int_equal(xf_simlink_host_spec(NULL, NULL, 0), 0);
}

static void test_open_failures(void **state)
{
    char spec[64], text[64];
    uint16_t port = 0;
    int fd;
    xf_link l;
    (void)state;
    memset(&l, 0, sizeof(l));
    assert_xf(xf_link_open(&l, "serial:/dev/xfgcu-no-such-device"), XF_ERR_NOT_FOUND);
    assert_contains(l.error.text, "/dev/xfgcu-no-such-device");
    assert_contains(xf_link_error(&l)->text, "No such file or directory");
    assert_int_equal(l.is_open, 0);
    assert_int_equal(xf_link_describe(&l, text, sizeof(text)),
                     strlen("serial /dev/xfgcu-no-such-device at 115200 baud"));
    xf_link_close(&l);
    /* a local UDP port in use */
    fd = test_loopback_socket(SOCK_DGRAM, &port);
    snprintf(spec, sizeof(spec), "udp:127.0.0.1:9,local=%u", (unsigned)port);
    assert_xf(xf_link_open(&l, spec), XF_ERR_BUSY);
    assert_true(l.error.os_errno != 0);
    assert_true(l.error.text[0] != '\0');
    close(fd);
    /* a TCP port that refuses: the open succeeds (it connects by itself), the wait says why not */
    fd = test_loopback_socket(SOCK_STREAM, &port); /* bound, not listening */
    snprintf(spec, sizeof(spec), "tcp:127.0.0.1:%u", (unsigned)port);
    assert_xf(xf_link_open(&l, spec), XF_OK);
    assert_xf(xf_link_wait(&l, 2000), XF_ERR_CLOSED);
    assert_contains(xf_link_error(&l)->text, "connect to 127.0.0.1:");
    xf_link_close(&l);
    assert_xf(xf_link_wait(&l, 10), XF_ERR_CLOSED);
    close(fd);
}

/* ---- open against the simulator's links, and run a command ------------------------------ */

typedef struct rig {
    char dir[64];
    char spec[300];
    xf_simlink gcu;
    xf_sim sim;
    xf_link link;
    xf_hal hal;
    xf_client c;
    ct_log log;
} rig;

/* A simulated GCU on a new link of @p kind, and an xf_link opened on the spec that reaches it. */
static void rig_open(rig *r, xf_simlink_kind kind, uint16_t rate_hz)
{
    xf_client_config cc;
    xf_hal sim_hal;
    char link[128];
    memset(r, 0, sizeof(*r));
    if (kind == XF_SIMLINK_PTY) {
        snprintf(r->dir, sizeof(r->dir), "/tmp/xfgcu-link-XXXXXX");
        assert_non_null(mkdtemp(r->dir));
        snprintf(link, sizeof(link), "%s/gcu", r->dir);
        assert_xf(xf_simlink_open_pty(&r->gcu, link), XF_OK);
    } else if (kind == XF_SIMLINK_UDP) {
        assert_xf(xf_simlink_open_udp(&r->gcu, "127.0.0.1", 0), XF_OK);
    } else {
        assert_xf(xf_simlink_open_tcp(&r->gcu, "127.0.0.1", 0), XF_OK);
    }
    xf_simlink_hal(&r->gcu, &sim_hal);
    assert_xf(xf_sim_init(&r->sim, NULL), XF_OK);
    assert_xf(xf_sim_attach(&r->sim, &sim_hal), XF_OK);
    assert_true(xf_simlink_host_spec(&r->gcu, r->spec, sizeof(r->spec)) < sizeof(r->spec));
    if (xf_link_open(&r->link, r->spec) != XF_OK) {
        print_error("%s: %s\n", r->spec, r->link.error.text);
        fail();
    }
    assert_int_equal(r->link.is_open, 1);
    assert_xf(xf_link_wait(&r->link, 2000), XF_OK);
    assert_xf(xf_link_hal(&r->link, &r->hal), XF_OK);
    xf_client_config_init(&cc);
    cc.rate_hz = rate_hz;
    ct_log_hook(&r->log, &cc);
    assert_true(xf_client_init(&r->c, &r->hal, &cc) >= XF_OK);
}

static void rig_close(rig *r)
{
    xf_link_close(&r->link);
    assert_int_equal(r->link.is_open, 0);
    xf_simlink_close(&r->gcu);
    if (r->dir[0] != '\0') {
        (void)rmdir(r->dir);
    }
}

/* Submit @p order and wait for it with the simulator stepped in the same loop. */
static void run_in_process(rig *r, uint8_t order)
{
    xf_sim *sims[1];
    xf_command cmd;
    xf_cmd_result res;
    uint32_t id = 0;
    sims[0] = &r->sim;
    xf_command_init(&cmd, order);
    assert_xf(xf_client_submit(&r->c, &cmd, &id, NULL), XF_OK);
    assert_xf(xf_posix_wait(&r->c, id, 3000, &res, sims, 1), XF_OK);
    assert_status(res.status, XF_CMD_OK);
    assert_int_equal(res.id, id);
    assert_int_equal(res.order, order);
    assert_status(xf_client_command_status(&r->c, id, NULL), XF_CMD_OK);
}

static void test_open_tcp(void **state)
{
    rig *r = calloc(1, sizeof(*r));
    char want[64], text[64];
    (void)state;
    assert_non_null(r);
    rig_open(r, XF_SIMLINK_TCP, 50);
    snprintf(want, sizeof(want), "tcp:127.0.0.1:%u", (unsigned)r->gcu.port);
    assert_string_equal(r->spec, want);
    snprintf(want, sizeof(want), "tcp 127.0.0.1:%u", (unsigned)r->gcu.port);
    assert_int_equal(xf_link_describe(&r->link, text, sizeof(text)), strlen(want));
    assert_string_equal(text, want);
    run_in_process(r, XF_ORDER_HEAD_LOCK);
    run_in_process(r, XF_ORDER_SHUTTER);
    assert_true(r->link.as.tcp.stats.bytes_rx > 0u);
    assert_string_equal(xf_link_error(&r->link)->text, "");
    rig_close(r);
    assert_int_equal(xf_link_describe(&r->link, text, sizeof(text)), strlen(want)); /* the spec outlives the close */
    assert_string_equal(text, want);
    free(r);
}

static void test_open_udp(void **state)
{
    rig *r = calloc(1, sizeof(*r));
    char want[64];
    (void)state;
    assert_non_null(r);
    rig_open(r, XF_SIMLINK_UDP, 50);
    snprintf(want, sizeof(want), "udp:127.0.0.1:%u,local=0", (unsigned)r->gcu.port);
    assert_string_equal(r->spec, want);
    assert_int_equal(r->link.spec.local_port, 0);
    assert_true(r->link.as.udp.local_port != 0u); /* any free port was bound */
    run_in_process(r, XF_ORDER_EULER);
    rig_close(r);
    free(r);
}

static void test_open_serial_pty(void **state)
{
    rig *r = calloc(1, sizeof(*r));
    char want[300], text[300];
    (void)state;
    assert_non_null(r);
    rig_open(r, XF_SIMLINK_PTY, 50);
    snprintf(want, sizeof(want), "serial:%s", r->gcu.link_path);
    assert_string_equal(r->spec, want);
    snprintf(want, sizeof(want), "serial %s at 115200 baud", r->gcu.link_path);
    (void)xf_link_describe(&r->link, text, sizeof(text));
    assert_string_equal(text, want);
    assert_string_not_equal(xf_serial_backend(&r->link.as.serial), "closed");
    run_in_process(r, XF_ORDER_HEAD_LOCK);
    rig_close(r);
    free(r);
}

/* ---- xf_posix_run against a simulated GCU in another process ---------------------------- */

/* The simulator's loop, in a child: until killed, or 20 s at most (never outlives a crashed test). */
static pid_t sim_child(rig *r)
{
    pid_t pid = fork();
    assert_true(pid >= 0);
    if (pid == 0) {
        xf_sim *sims[1];
        uint32_t t0 = xf_posix_now_ms();
        sims[0] = &r->sim;
        while (xf_ms_since(xf_posix_now_ms(), t0) < 20000u && getppid() != 1) {
            (void)xf_posix_poll(NULL, 0, sims, 1, 5);
        }
        _exit(0);
    }
    return pid;
}

static void sim_child_stop(pid_t pid)
{
    int status = 0;
    assert_int_equal(kill(pid, SIGKILL), 0);
    assert_int_equal(waitpid(pid, &status, 0), pid);
}

static void test_run_to_result(void **state)
{
    rig *r = calloc(1, sizeof(*r));
    xf_command cmd;
    xf_cmd_result res;
    uint32_t t0, took;
    pid_t pid;
    (void)state;
    assert_non_null(r);
    /* 5 packets a second: a helper that waited for one packet more than needed would take 200 ms more */
    rig_open(r, XF_SIMLINK_TCP, 5);
    pid = sim_child(r);
    xf_command_init(&cmd, XF_ORDER_HEAD_LOCK);
    t0 = xf_posix_now_ms();
    assert_xf(xf_posix_run(&r->c, &cmd, 3000, &res), XF_OK);
    took = xf_ms_since(xf_posix_now_ms(), t0);
    assert_status(res.status, XF_CMD_OK);
    assert_int_equal(res.order, XF_ORDER_HEAD_LOCK);
    assert_true(res.id != 0u);
    assert_int_equal(res.packets, 1);
    /* a null first (a new client sends nulls until a reply to one is back), then the command;
     * returned in the step that read the command's reply: no packet went out after it (a helper
     * that waited for one packet more would have sent one, 200 ms later) */
    assert_true(r->log.n_sent >= 2u);
    assert_int_equal(r->log.sent_order[0], XF_ORDER_NULL);
    assert_int_equal(r->log.sent_order[r->log.n_sent - 1u], XF_ORDER_HEAD_LOCK);
    assert_int_equal(r->log.n_sent, xf_client_health(&r->c)->packets_sent);
    print_message("xf_posix_run: %u ms, %u packets\n", (unsigned)took, (unsigned)r->log.n_sent);
    assert_int_equal(xf_client_pending(&r->c), 0);
    /* the next, of another order, after the null that follows (the protocol's way) */
    xf_command_init(&cmd, XF_ORDER_SHUTTER);
    assert_xf(xf_posix_run(&r->c, &cmd, 3000, &res), XF_OK);
    assert_status(res.status, XF_CMD_OK);
    assert_int_equal(res.order, XF_ORDER_SHUTTER);
    /* a command queued before runs first, and is reported as usual */
    {
        uint32_t first = 0;
        xf_cmd_result fr;
        xf_command_init(&cmd, XF_ORDER_ZOOM_IN);
        assert_xf(xf_client_submit(&r->c, &cmd, &first, NULL), XF_OK);
        xf_command_init(&cmd, XF_ORDER_ZOOM_STOP);
        assert_xf(xf_posix_run(&r->c, &cmd, 5000, &res), XF_OK);
        assert_status(res.status, XF_CMD_OK);
        assert_status(xf_client_command_status(&r->c, first, &fr), XF_CMD_OK);
        assert_true(fr.id < res.id);
    }
    sim_child_stop(pid);
    rig_close(r);
    free(r);
}

static void test_run_timeout(void **state)
{
    rig *r = calloc(1, sizeof(*r));
    xf_command cmd;
    xf_cmd_result res;
    uint32_t t0, took;
    (void)state;
    assert_non_null(r);
    rig_open(r, XF_SIMLINK_UDP, 50); /* the simulator is never stepped: nobody answers */
    xf_command_init(&cmd, XF_ORDER_SHUTTER);
    t0 = xf_posix_now_ms();
    assert_xf(xf_posix_run(&r->c, &cmd, 150, &res), XF_ERR_TIMEOUT);
    took = xf_ms_since(xf_posix_now_ms(), t0);
    assert_true(took >= 150u);                /* at its deadline (later only on a loaded machine), not the command's */
    assert_status(res.status, XF_CMD_QUEUED); /* never sent: no reply to a null came back */
    assert_int_equal(res.order, XF_ORDER_SHUTTER);
    assert_true(res.id != 0u);
    /* the command stays: it ends by the client's own timeout (the link never came up: link lost) */
    assert_status(xf_client_command_status(&r->c, res.id, NULL), XF_CMD_QUEUED);
    assert_xf(xf_posix_wait(&r->c, res.id, 0, &res, NULL, 0), XF_ERR_TIMEOUT);
    assert_xf(xf_posix_wait(&r->c, res.id, 3000, &res, NULL, 0), XF_OK);
    assert_status(res.status, XF_CMD_LINK_LOST);
    rig_close(r);
    free(r);
}

static int busy_rc = 0;

static void call_run_from_callback(void *user, const xf_telemetry *t)
{
    xf_command cmd;
    (void)t;
    xf_command_init(&cmd, XF_ORDER_SHUTTER);
    busy_rc = (int)xf_posix_run((xf_client *)user, &cmd, 100, NULL);
}

static void test_run_refusals(void **state)
{
    rig *r = calloc(1, sizeof(*r));
    xf_command cmd;
    xf_cmd_result res;
    xf_sim *sims[1];
    xf_client_config cc;
    int i;
    (void)state;
    assert_non_null(r);
    rig_open(r, XF_SIMLINK_TCP, 50);
    sims[0] = &r->sim;
    xf_command_init(&cmd, XF_ORDER_ZOOM_TO);
    assert_xf(xf_posix_run(NULL, &cmd, 100, &res), XF_ERR_ARG);
    assert_int_equal(res.order, XF_ORDER_ZOOM_TO);
    assert_xf(xf_posix_run(&r->c, NULL, 100, &res), XF_ERR_ARG);
    cmd.zoom = 0; /* out of range: not submitted */
    assert_xf(xf_posix_run(&r->c, &cmd, 100, &res), XF_ERR_RANGE);
    assert_int_equal(res.id, 0);
    cmd.order = 0xEE; /* no such order: not submitted */
    assert_xf(xf_posix_run(&r->c, &cmd, 100, &res), XF_ERR_NOT_FOUND);
    assert_int_equal(res.order, 0xEE);
    assert_int_equal(xf_client_pending(&r->c), 0);
    assert_xf(xf_posix_wait(NULL, 1, 100, &res, NULL, 0), XF_ERR_ARG);
    assert_xf(xf_posix_wait(&r->c, 12345, 100, &res, NULL, 0), XF_ERR_NOT_FOUND); /* never given */
    assert_xf(xf_posix_wait(&r->c, 0, 100, &res, NULL, 0), XF_ERR_NOT_FOUND);
    assert_xf(xf_posix_wait(&r->c, 1, 100, &res, NULL, 1), XF_ERR_ARG);
    /* a full queue */
    xf_command_init(&cmd, XF_ORDER_SHUTTER);
    for (i = 0; i < XF_CLIENT_QUEUE; i++) {
        assert_xf(xf_client_submit(&r->c, &cmd, NULL, NULL), XF_OK);
    }
    assert_xf(xf_posix_run(&r->c, &cmd, 100, &res), XF_ERR_BUSY);
    xf_client_cancel_all(&r->c);
    /* from a callback: refused at once, nothing submitted */
    xf_client_config_init(&cc);
    cc.on_telemetry = call_run_from_callback;
    cc.user = &r->c;
    assert_xf(xf_client_init(&r->c, &r->hal, &cc), XF_OK);
    busy_rc = 0;
    xf_command_init(&cmd, XF_ORDER_HEAD_LOCK);
    assert_xf(xf_client_submit(&r->c, &cmd, NULL, NULL), XF_OK);
    {
        uint32_t id = 0;
        xf_command_init(&cmd, XF_ORDER_EULER);
        assert_xf(xf_client_submit(&r->c, &cmd, &id, NULL), XF_OK);
        assert_xf(xf_posix_wait(&r->c, id, 3000, &res, sims, 1), XF_OK);
    }
    assert_xf(busy_rc, XF_ERR_BUSY);
    assert_int_equal(xf_client_pending(&r->c), 0);
    rig_close(r);
    free(r);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_parse_good),    cmocka_unit_test(test_parse_bad),
        cmocka_unit_test(test_parse_lengths), cmocka_unit_test(test_parse_garbage),
        cmocka_unit_test(test_spec_init),     cmocka_unit_test(test_keeps_order),
        cmocka_unit_test(test_describe),      cmocka_unit_test(test_link_arguments),
        cmocka_unit_test(test_open_failures), cmocka_unit_test(test_open_tcp),
        cmocka_unit_test(test_open_udp),      cmocka_unit_test(test_open_serial_pty),
        cmocka_unit_test(test_run_to_result), cmocka_unit_test(test_run_timeout),
        cmocka_unit_test(test_run_refusals),
    };
    signal(SIGPIPE, SIG_IGN);
    return cmocka_run_group_tests(tests, NULL, NULL);
}
