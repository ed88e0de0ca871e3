/*
 * test_client_reorder.c - nothing taken for something else (docs/protocol.md
 * §7.4), against the simulator over an in-memory link on a fake clock
 * (client_test.h): the start-up rule, the guard after a command, clients one
 * after another on a link with late replies, links that reorder and
 * duplicate.
 */
#include "client_test.h"

/* ---- nothing mistaken: the start-up rule and links that reorder (docs/protocol.md §7.4) ---- */

/* A reply with the state of @p order, as a GCU sends it for an earlier command. */
static void nm_reply(ct_rig *r, uint8_t order, int with_state)
{
    xf_gcu_packet g;
    memset(&g, 0, sizeof(g));
    g.version = 1;
    g.order = order;
    if (with_state) {
        g.params[0] = XF_STATE_SUCCESS;
        g.params_len = 1;
    }
    ct_gcu_reply(r, &g);
}

/* A new client takes no reply for its command before a reply to one of its nulls: a late
 * "shutter ok" meant for a process that ran before it is not its own. */
static void test_start_waits_for_null_reply(void **state)
{
    xf_client_config cc;
    ct_rig *r;
    xf_host_packet last;
    uint32_t id;
    size_t i;
    (void)state;
    xf_client_config_init(&cc);
    cc.reorder_fixed = 1; /* replies out of step with the packets, by hand: no bound of the client's */
    r = ct_rig_new(&cc, NULL);
    r->sim_on = 0; /* the test is the GCU */
    id = ct_submit(r, XF_ORDER_SHUTTER);
    nm_reply(r, XF_ORDER_SHUTTER, 1); /* late, for someone else */
    ct_run(r, 100);
    assert_status(xf_client_command_status(&r->c, id, NULL), XF_CMD_QUEUED);
    assert_int_equal(xf_client_link(&r->c), XF_LINK_UP); /* a GCU answers: only the rule holds it */
    for (i = 0; i < r->log.n_sent; i++) {
        assert_int_equal(r->log.sent_order[i], XF_ORDER_NULL);
    }
    nm_reply(r, XF_ORDER_SHUTTER, 1); /* still not a null's reply */
    ct_run(r, 40);
    assert_status(xf_client_command_status(&r->c, id, NULL), XF_CMD_QUEUED);
    nm_reply(r, XF_ORDER_NULL, 0);
    (void)ct_drain_host(r, NULL);
    ct_run(r, 20); /* one packet period */
    assert_int_equal(ct_drain_host(r, &last), 1);
    assert_int_equal(last.order, XF_ORDER_SHUTTER); /* the next packet carries it */
    assert_status(xf_client_command_status(&r->c, id, NULL), XF_CMD_SENDING);
    nm_reply(r, XF_ORDER_SHUTTER, 1);
    ct_run(r, 5);
    assert_status(xf_client_command_status(&r->c, id, NULL), XF_CMD_OK);
    ct_rig_free(r);
}

/* A command that never gets to start ends after twice command_timeout_ms. */
static void test_unsynced_command_times_out(void **state)
{
    ct_rig *r = ct_rig_new(NULL, NULL);
    xf_cmd_result res;
    uint32_t id;
    (void)state;
    r->sim_on = 0;
    id = ct_submit(r, XF_ORDER_SHUTTER);
    ct_run(r, 1990);
    assert_status(xf_client_command_status(&r->c, id, NULL), XF_CMD_QUEUED);
    assert_status(ct_run_cmd(r, id, 100, &res), XF_CMD_LINK_LOST); /* nobody ever answered */
    assert_int_equal(res.packets, 0);
    assert_true(res.elapsed_ms >= 2000u && res.elapsed_ms <= 2002u);
    ct_rig_free(r);
}

/* A link for nm_shutters(): its faults, the client's bound, the simulator's seed. */
typedef struct nm_link {
    uint16_t jitter_ms, dup_permille;
    uint16_t reorder_ms;
    uint8_t reorder_fixed;
    uint32_t seed;
    uint32_t warm_ms;  /* nulls before the first command */
    unsigned commands; /* shutters, one after another */
} nm_link;

/* What nm_shutters() saw. */
typedef struct nm_seen {
    unsigned false_ok;    /* an ok before the simulator had run that many shutters */
    unsigned extra;       /* executions beyond one per command (fewer when oks were false) */
    uint32_t elapsed_ms;  /* from the first submit to the last result */
    uint32_t packets;     /* packets that carried the commands */
    uint32_t out_of_turn; /* xf_health's, at the end */
    uint16_t reorder_ms;  /* the bound in force at the end */
} nm_seen;

/*
 * The red team's case: shutters in a row over a link with 0..jitter_ms of jitter each way and
 * dup_permille of packets duplicated (60 ms and 30 % in the red team's run).
 */
static void nm_shutters_on(const nm_link *l, nm_seen *out)
{
    xf_client_config cc;
    xf_sim_config sc;
    ct_rig *r;
    unsigned k, ok = 0;
    uint32_t t0;
    memset(out, 0, sizeof(*out));
    xf_client_config_init(&cc);
    cc.reorder_ms = l->reorder_ms;
    cc.reorder_fixed = l->reorder_fixed;
    xf_sim_config_init(&sc);
    sc.seed = l->seed;
    r = ct_rig_new(&cc, &sc);
    r->s.fault.jitter_ms = l->jitter_ms;
    r->s.fault.dup_permille = l->dup_permille;
    ct_run(r, l->warm_ms);
    t0 = r->now;
    for (k = 0; k < l->commands; k++) {
        xf_cmd_result res;
        uint32_t id = ct_submit(r, XF_ORDER_SHUTTER);
        xf_cmd_status st = ct_run_cmd(r, id, 5000, &res);
        assert_status(st, XF_CMD_OK);
        ok++;
        out->packets += res.packets;
        if (r->s.stats.photos < ok) {
            out->false_ok++; /* the reply it took was an earlier command's */
        }
    }
    out->elapsed_ms = r->now - t0;
    ct_run(r, 500);
    out->extra = (r->s.stats.photos > ok) ? r->s.stats.photos - ok : 0u;
    out->out_of_turn = xf_client_health(&r->c)->out_of_turn;
    out->reorder_ms = xf_client_health(&r->c)->reorder_ms;
    ct_rig_free(r);
}

/* The red team's link, 60 shutters after 200 ms of nulls, with the client's bound @p reorder_ms
 * (fixed: the client applies none of its own); returns the false oks, the extra runs in *extra. */
static unsigned nm_shutters(uint16_t reorder_ms, unsigned *extra)
{
    nm_link l = {60, 300, 0, 1, 1, 200, 60};
    nm_seen seen;
    l.reorder_ms = reorder_ms;
    nm_shutters_on(&l, &seen);
    *extra = seen.extra;
    return seen.false_ok;
}

/*
 * The red team's other case: every reply 1.5 s late, and one client after another on the same
 * link, as `xfgcu send shutter` run again and again. Each client settles before it goes
 * (xf_client_settled(): its command's replies are in) when @p settle; returns the "ok"s taken
 * sooner than the command's own reply could have come (an earlier client's late reply).
 */
static unsigned nm_sequence_at(uint32_t delay_ms, int settle, uint32_t timeout_ms, unsigned *oks);

static unsigned nm_sequence(int settle, uint32_t timeout_ms, unsigned *oks)
{
    return nm_sequence_at(1500, settle, timeout_ms, oks);
}

static unsigned nm_sequence_at(uint32_t delay_ms, int settle, uint32_t timeout_ms, unsigned *oks)
{
    xf_client_config cc;
    ct_rig *r;
    unsigned k, false_ok = 0;
    xf_client_config_init(&cc);
    cc.command_timeout_ms = timeout_ms;
    r = ct_rig_new(&cc, NULL);
    *oks = 0;
    r->s.fault.delay_ms = delay_ms;
    for (k = 0; k < 4u; k++) {
        xf_client_config keep = r->c.cfg;
        xf_cmd_result res;
        uint32_t id, i;
        assert_xf(xf_client_init(&r->c, &r->host_hal, &keep), XF_OK); /* a new process, same link */
        id = ct_submit(r, XF_ORDER_SHUTTER);
        if (ct_run_cmd(r, id, 10000, &res) == XF_CMD_OK) {
            (*oks)++;
            false_ok += (res.elapsed_ms < delay_ms) ? 1u : 0u; /* before its own reply could have come */
        }
        for (i = 0; settle && i < 3u * delay_ms + 2000u && !xf_client_settled(&r->c); i++) {
            ct_tick(r);
        }
        assert_true(!settle || xf_client_settled(&r->c));
    }
    ct_rig_free(r);
    return false_ok;
}

static void test_late_replies_not_taken(void **state)
{
    unsigned oks = 0, false_ok;
    (void)state;
    false_ok = nm_sequence(1, 1000, &oks); /* the red team's: the timeout is shorter than the delay */
    print_message("settled clients, 1 s timeout: %u ok of 4, %u false\n", oks, false_ok);
    assert_int_equal(false_ok, 0);
    false_ok = nm_sequence(1, 4000, &oks); /* a timeout long enough: every one genuinely ok */
    print_message("settled clients, 4 s timeout: %u ok of 4, %u false\n", oks, false_ok);
    assert_int_equal(false_ok, 0);
    assert_int_equal(oks, 4);
    /* without settling, the next client can take the last one's late "ok": the check can fail */
    false_ok = nm_sequence(0, 1000, &oks);
    print_message("unsettled clients, 1 s timeout: %u ok of 4, %u false\n", oks, false_ok);
    assert_true(false_ok > 0u);
}

/* The simulator's delay queue full of late replies never costs a host packet: the GCU still runs
 * what it receives (replies 3 s late at 50 Hz: more than the queue holds). And what is held when
 * the host goes away is not delivered to the next one. */
static void test_sim_delay_queue_keeps_commands(void **state)
{
    ct_rig *r = ct_rig_new(NULL, NULL);
    (void)state;
    r->s.fault.delay_ms = 3000;
    ct_run(r, 2900); /* the queue fills with replies */
    assert_int_equal(r->s.n_delayed, XF_SIM_DELAY_QUEUE);
    r->sim_on = 0;
    {
        xf_host_packet p;
        uint8_t buf[XF_PACKET_MAX_LEN];
        size_t len = 0;
        xf_host_packet_init(&p, 1);
        p.order = XF_ORDER_SHUTTER;
        assert_xf(xf_host_pack(&p, buf, sizeof(buf), &len), XF_OK);
        ct_fifo_put(&r->h2g, buf, len);
    }
    (void)xf_sim_step(&r->s, r->now + 1u);
    assert_int_equal(r->s.stats.executed[XF_ORDER_SHUTTER], 1); /* run at once, not dropped behind the replies */
    r->gcu.closed = 1;                                          /* the host goes away */
    (void)xf_sim_step(&r->s, r->now + 2u);
    assert_int_equal(r->s.n_delayed, 0);
    ct_rig_free(r);
}

/* The review's cases (2026-11-26): each ended with a false "ok" or a command that never ran. */

/* Two commands of different orders time out with their replies still on the way (1.5 s late):
 * the second's guard must not drop the first's, or a third of the first's order takes its late ok. */
static void test_guard_two_orders(void **state)
{
    ct_rig *r = ct_rig_new(NULL, NULL);
    xf_cmd_result res;
    (void)state;
    r->s.fault.delay_ms = 1500;
    ct_run(r, 3000);
    assert_status(ct_run_cmd(r, ct_submit(r, XF_ORDER_SHUTTER), 5000, &res), XF_CMD_TIMEOUT);
    assert_status(ct_run_cmd(r, ct_submit(r, XF_ORDER_RECORD), 5000, &res), XF_CMD_TIMEOUT);
    if (ct_run_cmd(r, ct_submit(r, XF_ORDER_SHUTTER), 5000, &res) == XF_CMD_OK) {
        assert_true(res.elapsed_ms >= 1500u); /* its own reply, never the first shutter's */
    }
    ct_rig_free(r);
}

/* A guard that gave up waiting no longer holds commands back, but the client is not settled:
 * nothing says the late replies have come (replies 2.5 s late, 1 s timeout). */
static void test_settled_needs_evidence(void **state)
{
    unsigned oks = 0;
    (void)state;
    assert_int_equal(nm_sequence_at(2500, 1, 1000, &oks), 0);
}

/* With the external-track stream on, a command that waits (for the start-up rule or a guard)
 * gets null packets, not the stream: else no null's reply ever comes and it never runs. */
static void test_stream_and_waiting_commands(void **state)
{
    ct_rig *r = ct_rig_new(NULL, NULL);
    xf_cmd_result res;
    uint32_t id;
    (void)state;
    assert_xf(xf_client_external_track(&r->c, 1, 10, 10), XF_OK); /* before the first step */
    ct_run(r, 500);
    assert_status(ct_run_cmd(r, ct_submit(r, XF_ORDER_ZOOM_STOP), 3000, &res), XF_CMD_OK);
    ct_run(r, 500);
    assert_xf(xf_client_external_track_stop(&r->c, &id), XF_OK);
    assert_xf(xf_client_external_track(&r->c, 1, 20, 20), XF_OK); /* a new target at once */
    assert_status(ct_run_cmd(r, id, 3000, &res), XF_CMD_OK);
    ct_rig_free(r);
}

/* 0x1B submitted as a command while the stream runs: the stream's replies carry that order's
 * state, so the command waits for them to pass (replies 100 ms late). */
static void test_track_command_while_streaming(void **state)
{
    ct_rig *r = ct_rig_new(NULL, NULL);
    xf_cmd_result res;
    xf_command cmd;
    (void)state;
    ct_run(r, 500);
    r->s.fault.delay_ms = 100;
    assert_xf(xf_client_external_track(&r->c, 1, 10, 10), XF_OK);
    ct_run(r, 500);
    xf_command_init(&cmd, XF_ORDER_EXTERNAL_TRACK);
    assert_status(ct_run_cmd(r, ct_submit_cmd(r, &cmd), 5000, &res), XF_CMD_OK);
    assert_true(res.elapsed_ms >= 100u); /* its own reply */
    ct_rig_free(r);
}

/* A link that stalls 1.3 s and then delivers what it held: the lost command's late "ok" is not
 * the retry's, even though the link went down in between. */
static void test_retry_after_stall(void **state)
{
    ct_rig *r = ct_rig_new(NULL, NULL);
    xf_cmd_result res;
    (void)state;
    ct_run(r, 500);
    r->s.fault.delay_ms = 1300;
    assert_status(ct_run_cmd(r, ct_submit(r, XF_ORDER_SHUTTER), 5000, &res), XF_CMD_LINK_LOST);
    r->s.fault.delay_ms = 0;
    assert_status(ct_run_cmd(r, ct_submit(r, XF_ORDER_SHUTTER), 5000, &res), XF_CMD_OK);
    assert_int_equal(r->s.stats.photos, 2); /* the retry ran before its ok */
    ct_rig_free(r);
}

/* A command submitted after the application has not stepped for a while waits from the next
 * step, not from the old step's time. */
static void test_submit_after_a_pause(void **state)
{
    xf_client_config cc;
    ct_rig *r;
    uint32_t id, i;
    (void)state;
    xf_client_config_init(&cc);
    cc.down_ms = 5000; /* the pause is not a lost link */
    r = ct_rig_new(&cc, NULL);
    ct_run(r, 500);
    for (i = 0; i < 2100u; i++) { /* the simulator runs on; the client is not stepped */
        r->now++;
        (void)xf_sim_step(&r->s, r->now);
    }
    id = ct_submit(r, XF_ORDER_SHUTTER);
    (void)xf_client_step(&r->c, r->now);
    assert_true(xf_client_command_status(&r->c, id, NULL) != XF_CMD_TIMEOUT);
    assert_status(ct_run_cmd(r, id, 1000, NULL), XF_CMD_OK);
    ct_rig_free(r);
}

static void test_reorder_no_false_ok(void **state)
{
    unsigned extra = 0, false_ok;
    (void)state;
    false_ok = nm_shutters(100, &extra); /* the bound covers the 60 ms of jitter */
    assert_int_equal(false_ok, 0);
    assert_int_equal(extra, 0); /* and the GCU ran each command once */
    /* the same link without the bound, and without the client's own: the check above can fail */
    false_ok = nm_shutters(0, &extra);
    print_message("reorder_ms 0, fixed, on a reordering link: %u false ok, %u extra executions of 60\n", false_ok,
                  extra);
    assert_true(false_ok > 0u || extra > 0u);
}

/* The sum of nm_shutters_on() over @p seeds seeds from 1 on; out_of_turn and reorder_ms count runs:
 * those that saw replies out of turn, those that ended under the client's own bound. */
static void nm_seeds(nm_link *l, uint32_t seeds, nm_seen *sum)
{
    uint32_t seed;
    memset(sum, 0, sizeof(*sum));
    for (seed = 1; seed <= seeds; seed++) {
        nm_seen one;
        l->seed = seed;
        nm_shutters_on(l, &one);
        sum->false_ok += one.false_ok;
        sum->extra += one.extra;
        sum->elapsed_ms += one.elapsed_ms;
        sum->packets += one.packets;
        sum->out_of_turn += (one.out_of_turn > 0u);
        sum->reorder_ms = (uint16_t)(sum->reorder_ms + (one.reorder_ms > 0u));
    }
}

/* The measurement of docs/protocol.md §7.4: each case of the reordering-link test, on a fixed set
 * of seeds (deterministic on the fake clock), with the default settings and with the bound fixed
 * at 0. */
typedef struct nm_case {
    uint16_t jitter_ms, dup_permille;
    uint32_t warm_ms; /* nulls before the first command */
    unsigned commands;
    uint32_t seeds, seeds_full; /* in the test; with XF_REORDER_FULL set (the figures of §7.4) */
    const char *what;
} nm_case;

static const nm_case nm_cases[] = {
    {60, 300, 200, 60, 16, 200, "jitter and duplicates, 60 shutters after 200 ms"},
    {60, 0, 200, 60, 16, 200, "jitter only, 60 shutters after 200 ms"},
    {0, 300, 200, 60, 16, 200, "duplicates only, 60 shutters after 200 ms"},
    {60, 300, 0, 1, 200, 1000, "jitter and duplicates, a new client's one shutter at once"},
    {60, 0, 0, 1, 200, 1000, "jitter only, a new client's one shutter at once"},
    {0, 300, 0, 1, 200, 1000, "duplicates only, a new client's one shutter at once"},
};

/*
 * Safety wins by default: on every case, with the default settings, no command is taken for
 * another's and none runs twice. A link that reorders rarely answers the first six packets each
 * before the next, alike (the fast verdict), so a new client's first command runs under the
 * client's bound there; the start-up nulls show the faults before a later one. With the bound
 * fixed at 0 the same links give false oks and double runs: the check can fail. The test runs a
 * fixed set of seeds in about a second (a few under the sanitizers); XF_REORDER_FULL=1 in the
 * environment runs the larger sets the published figures come from (200 runs of 60 shutters and
 * 1000 new clients per link; about a minute).
 */
static void test_reorder_safe_by_default(void **state)
{
    size_t i;
    int full = getenv("XF_REORDER_FULL") != NULL;
    (void)state;
    for (i = 0; i < sizeof(nm_cases) / sizeof(nm_cases[0]); i++) {
        const nm_case *k = &nm_cases[i];
        uint32_t seeds = full ? k->seeds_full : k->seeds;
        nm_link l = {0, 0, 0, 0, 0, 0, 0};
        nm_seen dflt, fixed;
        l.jitter_ms = k->jitter_ms;
        l.dup_permille = k->dup_permille;
        l.warm_ms = k->warm_ms;
        l.commands = k->commands;
        nm_seeds(&l, seeds, &dflt);
        l.reorder_fixed = 1;
        nm_seeds(&l, seeds, &fixed);
        print_message("%s, %u seeds: defaults %u false ok, %u run twice, %.1f ms a command; bound fixed at 0: "
                      "%u false ok, %u run twice, %.1f ms\n",
                      k->what, (unsigned)seeds, dflt.false_ok, dflt.extra,
                      (double)dflt.elapsed_ms / (double)(seeds * k->commands), fixed.false_ok, fixed.extra,
                      (double)fixed.elapsed_ms / (double)(seeds * k->commands));
        assert_int_equal(dflt.false_ok, 0);
        assert_int_equal(dflt.extra, 0);
        if (k->warm_ms > 0u) { /* the start-up nulls showed the faults in every run */
            assert_int_equal(dflt.out_of_turn, seeds);
            assert_int_equal(dflt.reorder_ms, seeds);
        }
        if (k->jitter_ms > 0u) {
            assert_true(fixed.false_ok + fixed.extra > 0u);
        }
    }
}

/*
 * A clean link: the first six packets answered before the next, alike, show it in order, and
 * the client's commands then run exactly as with the bound fixed at 0 (the same packets at the
 * same times): one packet and one period a shutter. What safety costs there: a new client's first
 * command waits for those six periods (it would go in the second packet with the bound fixed).
 */
static void test_clean_link_keeps_speed(void **state)
{
    nm_link l = {0, 0, 0, 0, 1, 200, 60};
    nm_seen fixed, dflt;
    ct_rig *r;
    (void)state;
    nm_shutters_on(&l, &fixed);
    l.reorder_fixed = 0;
    nm_shutters_on(&l, &dflt);
    print_message("clean link, defaults: %.1f ms and %.2f packets a shutter (bound fixed at 0: %.1f ms, %.2f)\n",
                  (double)dflt.elapsed_ms / 60.0, (double)dflt.packets / 60.0, (double)fixed.elapsed_ms / 60.0,
                  (double)fixed.packets / 60.0);
    assert_int_equal(dflt.out_of_turn, 0);
    assert_int_equal(dflt.reorder_ms, 0);
    assert_int_equal(dflt.elapsed_ms, fixed.elapsed_ms);
    assert_int_equal(dflt.packets, 60);
    assert_int_equal(dflt.elapsed_ms, 2u + 59u * 40u); /* a null and the command a shutter; the first at once */
    {
        static const uint32_t want_ms[2] = {122, 22}, want_sent[2] = {7, 2};
        uint32_t done[2];
        int k;
        for (k = 0; k < 2; k++) {
            xf_client_config cc;
            xf_client_config_init(&cc);
            cc.reorder_fixed = (uint8_t)k;
            r = ct_rig_new(&cc, NULL);
            assert_status(ct_run_cmd(r, ct_submit(r, XF_ORDER_SHUTTER), 1000, NULL), XF_CMD_OK);
            done[k] = r->now - 1000u;
            assert_int_equal(done[k], want_ms[k]);
            assert_int_equal(r->log.n_sent, want_sent[k]); /* six nulls answered alike, then the command */
            assert_int_equal(xf_client_health(&r->c)->in_order, k == 0);
            ct_rig_free(r);
        }
        print_message("clean link, a new client's first shutter: ok after %u ms (bound fixed at 0: %u ms)\n",
                      (unsigned)done[0], (unsigned)done[1]);
    }
    /* replies late by a steady 150 ms (in order): the client's bound until 25 periods in a row have
     * had one reply each, then none; nothing out of turn */
    r = ct_rig_new(NULL, NULL);
    r->s.fault.delay_ms = 150;
    assert_true(ct_run_link(r, XF_LINK_UP, 1000));
    assert_int_equal(xf_client_health(&r->c)->in_order, 0);
    assert_int_equal(xf_client_health(&r->c)->reorder_ms, 114);
    assert_status(ct_run_cmd(r, ct_submit(r, XF_ORDER_SHUTTER), 2000, NULL), XF_CMD_OK);
    ct_run(r, 1000);
    assert_int_equal(xf_client_health(&r->c)->out_of_turn, 0);
    assert_int_equal(xf_client_health(&r->c)->in_order, 1);
    assert_int_equal(xf_client_health(&r->c)->reorder_ms, 0);
    ct_rig_free(r);
}

/*
 * Each sign of a bad link, made by hand (the test is the GCU): two replies in one packet period;
 * a reply of the command's order after a null's reply that followed one of its own; more
 * replies of the command than its packets. Each is counted and applies the bound, unless the
 * application fixed it.
 */
static void test_out_of_turn_signs(void **state)
{
    int kind;
    unsigned i;
    (void)state;
    for (kind = 0; kind < 4; kind++) {
        xf_client_config cc;
        ct_rig *r;
        const xf_health *h;
        uint32_t id;
        xf_client_config_init(&cc);
        cc.reorder_fixed = (kind == 3);
        r = ct_rig_new(&cc, NULL);
        h = xf_client_health(&r->c);
        r->sim_on = 0;
        ct_run(r, 1);
        for (i = 0; i < 7u; i++) { /* the first packets answered alike, each before the next: in order */
            nm_reply(r, XF_ORDER_NULL, 0);
            ct_run(r, (i < 6u) ? 20u : 15u);
        }
        assert_int_equal(h->out_of_turn, 0);
        assert_int_equal(h->in_order, 1); /* judged, also when the bound is fixed */
        id = ct_submit(r, XF_ORDER_SHUTTER);
        ct_run(r, 5); /* the command's first packet */
        assert_status(xf_client_command_status(&r->c, id, NULL), XF_CMD_SENDING);
        if (kind == 0 || kind == 3) {
            nm_reply(r, XF_ORDER_NULL, 0);
            nm_reply(r, XF_ORDER_NULL, 0); /* two replies before the next packet */
            ct_run(r, 20);
        } else if (kind == 1) {
            ct_run(r, 20); /* its second packet */
            nm_reply(r, XF_ORDER_SHUTTER, 0);
            nm_reply(r, XF_ORDER_NULL, 0); /* a null's reply between two of the shutter's */
            ct_run(r, 5);
            nm_reply(r, XF_ORDER_SHUTTER, 1);
            ct_run(r, 5);
        } else {
            nm_reply(r, XF_ORDER_SHUTTER, 0); /* one packet of the shutter, two replies (without its state) */
            nm_reply(r, XF_ORDER_SHUTTER, 0);
            ct_run(r, 1);
        }
        assert_int_equal(h->out_of_turn, 1);
        assert_int_equal(h->reorder_ms, kind == 3 ? 0 : 114);
        assert_int_equal(h->in_order, 0); /* the link's verdict, whatever the bound */
        ct_rig_free(r);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_start_waits_for_null_reply),
        cmocka_unit_test(test_unsynced_command_times_out),
        cmocka_unit_test(test_reorder_no_false_ok),
        cmocka_unit_test(test_reorder_safe_by_default),
        cmocka_unit_test(test_clean_link_keeps_speed),
        cmocka_unit_test(test_out_of_turn_signs),
        cmocka_unit_test(test_late_replies_not_taken),
        cmocka_unit_test(test_guard_two_orders),
        cmocka_unit_test(test_sim_delay_queue_keeps_commands),
        cmocka_unit_test(test_settled_needs_evidence),
        cmocka_unit_test(test_stream_and_waiting_commands),
        cmocka_unit_test(test_track_command_while_streaming),
        cmocka_unit_test(test_retry_after_stall),
        cmocka_unit_test(test_submit_after_a_pause),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
