/*
 * test_client_many.c - many clients and many simulators in one thread with
 * xf_posix_poll: nine independent pairs (three over ptys, three over UDP,
 * three over TCP) all get their own replies, results and data; and the
 * poll loop's waiting rules.
 */
#define _XOPEN_SOURCE 700 /* mkdtemp, sigaction, setitimer */
#include <poll.h>
#include <signal.h>
#include <sys/time.h>
#include <unistd.h>

#include "client_links.h"

#define N_PAIRS 9

static tx *pairs_open(void)
{
    static const xf_simlink_kind kinds[3] = {XF_SIMLINK_PTY, XF_SIMLINK_UDP, XF_SIMLINK_TCP};
    tx *t = (tx *)calloc(N_PAIRS, sizeof(*t));
    size_t i;
    assert_non_null(t);
    for (i = 0; i < N_PAIRS; i++) {
        xf_client_config cc;
        xf_client_config_init(&cc);
        cc.command_timeout_ms = 500;
        /* the carrier is set once; under qemu-user (the bigendian stage) a round can take longer
         * than the default 200 ms age, and what is tested here is that each carrier arrives */
        cc.carrier_max_age_ms = 10000;
        assert_int_equal(tx_open(&t[i], kinds[i % 3u], NULL, &cc), 0);
    }
    return t;
}

static void pairs_close(tx *t)
{
    size_t i;
    for (i = 0; i < N_PAIRS; i++) {
        tx_close(&t[i]);
    }
    free(t);
}

static void pairs_round(tx *t, int max_wait)
{
    xf_client *cs[N_PAIRS];
    xf_sim *ss[N_PAIRS];
    size_t i;
    for (i = 0; i < N_PAIRS; i++) {
        cs[i] = &t[i].c;
        ss[i] = &t[i].sim;
    }
    assert_xf(xf_posix_poll(cs, N_PAIRS, ss, N_PAIRS, max_wait), XF_OK);
}

static int all_up(const tx *t)
{
    size_t i;
    for (i = 0; i < N_PAIRS; i++) {
        if (xf_client_link(&t[i].c) != XF_LINK_UP) {
            return 0;
        }
    }
    return 1;
}

static void test_many_clients_one_thread(void **state)
{
    tx *t = pairs_open();
    uint32_t shot[N_PAIRS], zoom[N_PAIRS], t0;
    size_t i, done;
    (void)state;
    t0 = now();
    while (!all_up(t) && xf_ms_since(now(), t0) < 5000u) {
        pairs_round(t, 20);
    }
    assert_true(all_up(t));
    for (i = 0; i < N_PAIRS; i++) {
        xf_command cmd;
        xf_carrier k;
        /* each its own failure, its own carrier */
        if (i % 2u == 1u) {
            xf_sim_set_failure(&t[i].sim, XF_ORDER_ZOOM_IN, XF_CAM2);
        }
        memset(&k, 0, sizeof(k));
        k.yaw_deg = (float)(10u * i);
        xf_client_set_carrier(&t[i].c, &k, now());
        xf_command_init(&cmd, XF_ORDER_SHUTTER);
        assert_xf(xf_client_submit(&t[i].c, &cmd, &shot[i], NULL), XF_OK);
        xf_command_init(&cmd, XF_ORDER_ZOOM_IN);
        cmd.cameras = XF_CAM1 | XF_CAM2;
        assert_xf(xf_client_submit(&t[i].c, &cmd, &zoom[i], NULL), XF_OK);
    }
    t0 = now();
    do {
        pairs_round(t, 20);
        for (i = 0, done = 0; i < N_PAIRS; i++) {
            done += (xf_client_pending(&t[i].c) == 0u);
        }
    } while (done < N_PAIRS && xf_ms_since(now(), t0) < 5000u);
    for (i = 0; i < N_PAIRS; i++) {
        xf_cmd_result res;
        assert_status(xf_client_command_status(&t[i].c, shot[i], NULL), XF_CMD_OK);
        if (i % 2u == 1u) {
            assert_status(xf_client_command_status(&t[i].c, zoom[i], &res), XF_CMD_FAILED);
            assert_int_equal(res.failed_cameras, XF_CAM2);
        } else {
            assert_status(xf_client_command_status(&t[i].c, zoom[i], NULL), XF_CMD_OK);
        }
        assert_int_equal(t[i].sim.stats.photos, 1);
        assert_int_equal(t[i].sim.stats.executed[XF_ORDER_ZOOM_IN], 1);
        assert_int_equal(t[i].sim.host.main.carrier_yaw, 1000u * i);
    }
    /* two seconds of steady traffic, both ways: every pair answered, never faster than its rate (a late
     * step sends one packet, not a burst); how near 50 Hz depends on the machine's load, which a test
     * cannot bound (the rate itself is tested on the fake clock) */
    t0 = now();
    while (xf_ms_since(now(), t0) < 2100u) {
        pairs_round(t, 20);
    }
    for (i = 0; i < N_PAIRS; i++) {
        const xf_health *h = xf_client_health(&t[i].c);
        if (h->reply_rate_hz < 1u || h->reply_rate_hz > 55u) {
            print_error("pair %u (%s): %u replies/s\n", (unsigned)i, kind_name(t[i].kind), h->reply_rate_hz);
            fail();
        }
        assert_true(h->replies_missing <= h->packets_sent - h->replies);
        assert_true(t[i].sim.stats.packets_in >= h->replies);
        assert_true(t[i].sim.stats.packets_in <= h->packets_sent);
        assert_int_equal(xf_client_parser_stats(&t[i].c)->crc_errors, 0);
    }
    pairs_close(t);
}

/* ---- the poll loop's waiting rules -------------------------------------------------------- */

static volatile sig_atomic_t alarms;

static void on_alarm(int sig)
{
    (void)sig;
    alarms++;
}

/* A watchdog for a call that might block: SIGALRM after @p ms interrupts poll (no SA_RESTART). */
static void arm_alarm(unsigned ms)
{
    struct sigaction sa;
    struct itimerval it;
    memset(&sa, 0, sizeof(sa));
    sa.sa_handler = on_alarm;
    sigemptyset(&sa.sa_mask);
    sa.sa_flags = 0;
    assert_int_equal(sigaction(SIGALRM, &sa, NULL), 0);
    memset(&it, 0, sizeof(it));
    it.it_value.tv_sec = (time_t)(ms / 1000u);
    it.it_value.tv_usec = (suseconds_t)((ms % 1000u) * 1000u);
    assert_int_equal(setitimer(ITIMER_REAL, &it, NULL), 0);
}

static void disarm_alarm(void)
{
    struct itimerval it;
    memset(&it, 0, sizeof(it));
    (void)setitimer(ITIMER_REAL, &it, NULL);
}

/* The shortest of ten xf_posix_poll() calls, ms. */
static uint32_t quickest_poll(xf_client **cs, size_t nc, xf_sim **ss, size_t ns, int max_wait_ms)
{
    uint32_t best = UINT32_MAX;
    int i;
    for (i = 0; i < 10; i++) {
        uint32_t t0 = now(), took;
        assert_xf(xf_posix_poll(cs, nc, ss, ns, max_wait_ms), XF_OK);
        took = xf_ms_since(now(), t0);
        best = (took < best) ? took : best;
    }
    return best;
}

/*
 * A client whose GCU never answers: nothing is ever readable, so only the
 * client's own deadline can wake the loop. With max_wait_ms < 0 (no limit
 * of the caller's), xf_posix_poll must still wake for the next packet.
 */
static void test_poll_wakes_for_deadline(void **state)
{
    tx t;
    xf_client *cs[1];
    uint32_t t0, took, sent;
    int k;
    (void)state;
    assert_int_equal(tx_open(&t, XF_SIMLINK_UDP, NULL, NULL), 0);
    t.sim.fault.silent = 1;
    cs[0] = &t.c;
    assert_xf(xf_posix_poll(cs, 1, NULL, 0, 0), XF_OK); /* the first packet goes at once */
    sent = t.c.health.packets_sent;
    assert_int_equal(sent, 1);
    for (k = 0; k < 2; k++) {
        static const int waits[2] = {-1, 10000};
        alarms = 0;
        arm_alarm(1500);
        t0 = now();
        assert_xf(xf_posix_poll(cs, 1, NULL, 0, waits[k]), XF_OK);
        took = xf_ms_since(now(), t0);
        disarm_alarm();
        if (alarms != 0) { /* waited for the caller's max_wait (10 s, or for ever), not the packet's 20 ms */
            print_error("xf_posix_poll(max_wait %d) took %u ms: woken by the test's alarm\n", waits[k], (unsigned)took);
            fail();
        }
        assert_int_equal(t.c.health.packets_sent, sent + 1u);
        sent = t.c.health.packets_sent;
    }
    /* 0: no wait at all. One call can be late on a loaded machine; the quickest of ten is not,
     * unless each of them waited (for the next packet, 20 ms away). */
    assert_true(quickest_poll(cs, 1, NULL, 0, 0) < 10u);
    {
        /* with simulators it wakes every 5 ms at most, whatever the caller allows */
        xf_sim *ss[1];
        ss[0] = &t.sim;
        alarms = 0;
        arm_alarm(1500);
        took = quickest_poll(cs, 0, ss, 1, -1);
        disarm_alarm();
        assert_int_equal(alarms, 0);
        assert_true(took <= 50u);
    }
    tx_close(&t);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_many_clients_one_thread),
        cmocka_unit_test(test_poll_wakes_for_deadline),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
