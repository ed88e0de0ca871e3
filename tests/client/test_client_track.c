/*
 * test_client_track.c - the external-track stream, against the simulator over
 * an in-memory link on a fake clock (client_test.h): streamed in every free
 * packet, paused for a command, stopped by an exit whose result is its own.
 */
#include "client_test.h"

/* ---- external track ----------------------------------------------------------------------- */

static void test_external_track_stream_and_stop(void **state)
{
    ct_rig *r = rig_up(NULL, NULL);
    const xf_telemetry *t = xf_client_telemetry(&r->c);
    uint32_t before, id, stop;
    size_t mark;
    xf_cmd_result res;
    (void)state;
    assert_xf(xf_client_external_track(&r->c, XF_CAM1, 512, -256), XF_OK);
    before = r->s.stats.executed[XF_ORDER_EXTERNAL_TRACK];
    ct_run(r, 500);
    /* every packet runs: exempt from the once-rule */
    assert_int_equal(r->s.stats.executed[XF_ORDER_EXTERNAL_TRACK] - before, 25);
    assert_int_equal(r->s.mode, XF_MODE_TRACK);
    assert_int_equal(t->gimbal_mode, XF_MODE_TRACK);
    assert_true((t->pod_status & XF_POD_TRACKING_OK) != 0u);
    assert_true(t->target_offset_x > 0 && t->target_offset_y < 0);
    /* new offsets go out at once */
    assert_xf(xf_client_external_track(&r->c, XF_CAM1, -100, 100), XF_OK);
    ct_run(r, 40);
    assert_true(t->target_offset_x < 0 && t->target_offset_y > 0);
    /* a command in the middle: the stream pauses for it and a null */
    mark = r->log.n_sent;
    id = ct_submit(r, XF_ORDER_SHUTTER);
    assert_status(ct_run_cmd(r, id, 1000, NULL), XF_CMD_OK);
    ct_run(r, 100);
    assert_int_equal(r->s.stats.photos, 1);
    assert_int_equal(sent_count(&r->log, XF_ORDER_SHUTTER, mark), 1);
    assert_true(sent_count(&r->log, XF_ORDER_EXTERNAL_TRACK, mark) >= 3u);
    /* stop: exit sent as a command, then no more streaming */
    assert_xf(xf_client_external_track_stop(&r->c, &stop), XF_OK);
    assert_status(ct_run_cmd(r, stop, 1000, &res), XF_CMD_OK);
    assert_int_equal(r->s.mode, XF_MODE_HEAD_LOCK);
    ct_run(r, 40);
    assert_int_equal(t->pod_status & XF_POD_TRACKING_OK, 0);
    before = r->s.stats.executed[XF_ORDER_EXTERNAL_TRACK];
    mark = r->log.n_sent;
    ct_run(r, 500);
    assert_int_equal(r->s.stats.executed[XF_ORDER_EXTERNAL_TRACK], before);
    assert_int_equal(sent_count(&r->log, XF_ORDER_NULL, mark), r->log.n_sent - mark);
    assert_xf(xf_client_external_track(NULL, 1, 0, 0), XF_ERR_ARG);
    assert_xf(xf_client_external_track_stop(NULL, NULL), XF_ERR_ARG);
    ct_rig_free(r);
}

/*
 * The stop's result is its own: with replies 200 ms late, the stream's
 * replies (order 0x1B, success) are still in flight when the stop starts.
 * The GCU fails the stop; the client must say so.
 */
static void test_external_track_stop_not_resolved_by_stream(void **state)
{
    xf_client_config cc;
    ct_rig *r;
    uint32_t stop;
    xf_cmd_result res;
    (void)state;
    xf_client_config_init(&cc);
    cc.command_timeout_ms = 3000;
    r = ct_rig_new(&cc, NULL);
    r->s.fault.delay_ms = 200;
    assert_true(ct_run_link(r, XF_LINK_UP, 1000));
    assert_xf(xf_client_external_track(&r->c, XF_CAM1, 10, 10), XF_OK);
    ct_run(r, 500);
    xf_sim_set_failure(&r->s, XF_ORDER_EXTERNAL_TRACK, XF_CAM1);
    assert_xf(xf_client_external_track_stop(&r->c, &stop), XF_OK);
    assert_status(ct_run_cmd(r, stop, 3000, &res), XF_CMD_FAILED);
    assert_int_equal(res.failed_cameras, XF_CAM1);
    ct_rig_free(r);
}

/*
 * Run until command @p id has a final status, at most @p max_ms, watching
 * what the simulator receives: *exits counts the external-track exits
 * (value 0), *cameras ORs their camera masks, *streamed counts the stream's
 * packets (value 2). Returns the status.
 */
static xf_cmd_status run_watch_exits(ct_rig *r, uint32_t id, uint32_t max_ms, size_t *exits, uint8_t *cameras,
                                     size_t *streamed)
{
    uint32_t i, seen = r->s.stats.packets_in;
    xf_cmd_status st = xf_client_command_status(&r->c, id, NULL);
    for (i = 0; i < max_ms && (st == XF_CMD_QUEUED || st == XF_CMD_SENDING || st == XF_CMD_OPERATING); i++) {
        ct_tick(r);
        /* The simulator keeps only the last host packet: look at each as it comes. */
        if (r->s.stats.packets_in != seen && r->s.host.order == XF_ORDER_EXTERNAL_TRACK) {
            xf_command got;
            assert_xf(xf_command_decode(r->s.host.order, r->s.host.params, r->s.host.params_len, r->s.host.version,
                                        &got, NULL),
                      XF_OK);
            if (got.value == 0u) {
                (*exits)++;
                *cameras |= got.cameras;
            } else {
                (*streamed)++;
            }
        }
        seen = r->s.stats.packets_in;
        st = xf_client_command_status(&r->c, id, NULL);
    }
    return st;
}

/*
 * A stop refused with XF_ERR_BUSY (queue full) changes nothing: the stream
 * stays on, nothing is queued, the client is byte for byte as before. The
 * application's retry, once a command has finished, then sends the exit to
 * the stream's camera (2 here), not to camera 1, the camera of a stop with
 * no stream on.
 */
static void test_external_track_stop_busy_changes_nothing(void **state)
{
    ct_rig *r = rig_up(NULL, NULL);
    xf_client *before = (xf_client *)malloc(sizeof(xf_client));
    uint32_t id[XF_CLIENT_QUEUE], stop = 0;
    size_t i, exits = 0, streamed = 0;
    uint8_t cameras = 0;
    (void)state;
    assert_non_null(before);
    assert_xf(xf_client_external_track(&r->c, XF_CAM2, 300, -200), XF_OK);
    ct_run(r, 100);
    assert_int_equal(r->s.mode, XF_MODE_TRACK);
    for (i = 0; i < XF_CLIENT_QUEUE; i++) {
        id[i] = ct_submit(r, XF_ORDER_SHUTTER);
    }
    memcpy(before, &r->c, sizeof(xf_client));
    assert_xf(xf_client_external_track_stop(&r->c, &stop), XF_ERR_BUSY);
    assert_int_equal(stop, 0); /* no id given */
    assert_int_equal(r->c.stream_on, 1);
    assert_int_equal(r->c.stream[0], XF_CAM2);
    assert_int_equal(xf_client_pending(&r->c), XF_CLIENT_QUEUE);
    assert_int_equal(r->c.guard_order, before->guard_order);
    assert_int_equal(r->c.guard_open, before->guard_open);
    assert_memory_equal(&r->c, before, sizeof(xf_client));
    free(before);
    /* the first command done, there is room: the retry queues the stream's exit */
    assert_status(ct_run_cmd(r, id[0], 1000, NULL), XF_CMD_OK);
    assert_xf(xf_client_external_track_stop(&r->c, &stop), XF_OK);
    assert_true(stop != 0u);
    assert_int_equal(r->c.stream_on, 0);
    assert_status(run_watch_exits(r, stop, 5000, &exits, &cameras, &streamed), XF_CMD_OK);
    assert_int_equal(r->s.stats.photos, XF_CLIENT_QUEUE); /* the commands ahead of it all ran */
    assert_true(exits >= 1u);
    assert_int_equal(cameras, XF_CAM2); /* every exit went to camera 2, none to camera 1 */
    assert_int_equal(streamed, 0);      /* the stream stopped with the accepted stop */
    assert_int_equal(r->s.mode, XF_MODE_HEAD_LOCK);
    ct_rig_free(r);
}

/* A stop accepted at once: the stream ends, the exit goes to the stream's
 * camera, waits behind the stream's replies, and its result is its own. */
static void test_external_track_stop_success(void **state)
{
    ct_rig *r = rig_up(NULL, NULL);
    uint32_t stop = 0, before;
    size_t mark, exits = 0, streamed = 0;
    uint8_t cameras = 0;
    xf_cmd_result res;
    (void)state;
    assert_xf(xf_client_external_track(&r->c, XF_CAM2, -300, 200), XF_OK);
    ct_run(r, 100);
    assert_int_equal(r->s.mode, XF_MODE_TRACK);
    assert_xf(xf_client_external_track_stop(&r->c, &stop), XF_OK);
    assert_true(stop != 0u);
    assert_int_equal(r->c.stream_on, 0);
    assert_int_equal(xf_client_pending(&r->c), 1);
    /* the stream's late replies may still come: the exit waits for another order's */
    assert_int_equal(r->c.guard_order, XF_ORDER_EXTERNAL_TRACK);
    assert_int_equal(r->c.guard_open, 1);
    assert_status(run_watch_exits(r, stop, 1000, &exits, &cameras, &streamed), XF_CMD_OK);
    assert_status(xf_client_command_status(&r->c, stop, &res), XF_CMD_OK);
    assert_int_equal(res.order, XF_ORDER_EXTERNAL_TRACK);
    assert_true(exits >= 1u);
    assert_int_equal(cameras, XF_CAM2);
    assert_int_equal(streamed, 0);
    assert_int_equal(r->s.mode, XF_MODE_HEAD_LOCK);
    /* and no more streaming */
    before = r->s.stats.executed[XF_ORDER_EXTERNAL_TRACK];
    mark = r->log.n_sent;
    ct_run(r, 300);
    assert_int_equal(r->s.stats.executed[XF_ORDER_EXTERNAL_TRACK], before);
    assert_int_equal(sent_count(&r->log, XF_ORDER_EXTERNAL_TRACK, mark), 0);
    ct_rig_free(r);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_external_track_stream_and_stop),
        cmocka_unit_test(test_external_track_stop_not_resolved_by_stream),
        cmocka_unit_test(test_external_track_stop_busy_changes_nothing),
        cmocka_unit_test(test_external_track_stop_success),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
