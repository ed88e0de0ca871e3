/*
 * test_cli_questions.c - point uses what the GCU has, and probe asks the open questions
 * (issue 29 items 1 and 3), against `xfgcu sim` in the background:
 *
 * - point in Euler angle control 0x14 where the GCU takes it; where it answers euler with failure
 *   (sim --fail euler=1: V2.0.6's support list has no model without it), in angle control 0x10,
 *   with yaw relative to the carrier (V0.2) or every axis relative (V0.1), said in the text and
 *   the JSON;
 * - probe asks the questions of docs/protocol.md section 12 it safely can, and gets each of the
 *   simulator's readings: every version answered or one (--answer-only), the execution state in
 *   every reply to a repeated order or only the first (--state-once), a two-byte parameter failed
 *   (the strict reading, which the simulator's log names); the others are listed with why not.
 */
#define _POSIX_C_SOURCE 200809L

#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>
#include <jansson.h>

#include "run_tool.h"
#include "sim_proc.h"

/* ---- point ------------------------------------------------------------------------------- */

static void test_point_euler(void **state)
{
    sim_proc *s = (sim_proc *)*state;
    tool_result r = sim_run_on(s, "point", "--pitch", "-20", "--yaw", "30", NULL);
    assert_int_equal(r.status, 0);
    assert_true(strncmp(r.out, "reached roll 0.00 pitch -20.00 yaw 30.00 deg in ", 48) == 0);
    assert_non_null(strstr(r.out, " s, Euler angle control 0x14\n"));
    tool_result_free(&r);
    r = sim_run_on(s, "point", "--pitch", "-10", "--yaw", "20", "--json", NULL);
    assert_int_equal(r.status, 0);
    assert_int_equal(count_lines(r.out), 2); /* the mode, the motion */
    {
        json_t *o = parse_line(strchr(r.out, '\n') + 1);
        assert_string_equal(str_key(o, "status"), "reached");
        assert_int_equal(int_key(o, "mode_order"), 0x14);
        assert_string_equal(str_key(o, "mode_order_name"), "euler");
        assert_true(json_is_false(json_object_get(o, "yaw_relative")));
        assert_true(json_is_null(json_object_get(o, "fallback")));
        json_decref(o);
    }
    tool_result_free(&r);
}

/* A GCU that answers euler with failure, in V0.2: angle control, yaw relative to the carrier. */
static void test_point_falls_back_v2(void **state)
{
    sim_proc *s = (sim_proc *)*state;
    tool_result r;
    json_t *o;
    const char *line;
    sim_start(s, SIM_TCP, "--protocol", "2", "--fail", "euler=1", NULL);
    r = sim_run_on(s, "point", "--pitch", "-30", "--yaw", "45", NULL);
    assert_int_equal(r.status, 0);
    assert_int_equal(r.err_len, 0);
    assert_true(strncmp(r.out, "reached roll 0.00 pitch -30.00 relative yaw 45.00 deg in ", 57) == 0);
    assert_non_null(strstr(r.out, "angle control 0x10: yaw relative to the carrier; the GCU answered euler (0x14) "
                                  "with failure\n"));
    tool_result_free(&r);
    r = sim_run_on(s, "point", "--pitch", "-20", "--yaw", "-45", "--json", NULL);
    assert_int_equal(r.status, 0);
    assert_int_equal(count_lines(r.out), 3); /* euler failed, angle control ok, the motion */
    o = parse_line(r.out);
    assert_string_equal(str_key(o, "step"), "mode");
    assert_string_equal(str_key(o, "order_name"), "euler");
    assert_string_equal(str_key(o, "status"), "failed");
    json_decref(o);
    line = strchr(r.out, '\n') + 1;
    o = parse_line(line);
    assert_string_equal(str_key(o, "order_name"), "angle_control");
    assert_string_equal(str_key(o, "status"), "ok");
    json_decref(o);
    o = parse_line(strchr(line, '\n') + 1);
    assert_string_equal(str_key(o, "status"), "reached");
    assert_int_equal(int_key(o, "mode_order"), 0x10);
    assert_true(json_is_true(json_object_get(o, "yaw_relative")));
    assert_non_null(strstr(str_key(o, "fallback"), "euler (0x14) with failure"));
    assert_true(fabs(num_key(o, "rel_angle_z") + 45.0) <= 0.5);
    assert_true(fabs(num_key(o, "pitch") + 20.0) <= 0.5);
    json_decref(o);
    tool_result_free(&r);
}

/* In V0.1 angle control 0x10 (V2.0.4's "FPV") reads every axis relative to the carrier. */
static void test_point_falls_back_v1(void **state)
{
    sim_proc *s = (sim_proc *)*state;
    tool_result r;
    sim_start(s, SIM_TCP, "--fail", "euler=1", NULL);
    r = sim_run_on(s, "point", "--pitch", "-30", "--yaw", "45", "--roll", "5", NULL);
    assert_int_equal(r.status, 0);
    assert_true(strncmp(r.out, "reached roll 5.00 pitch -30.00 relative yaw 45.00 deg in ", 57) == 0);
    assert_non_null(strstr(r.out, "angle control 0x10: roll, pitch and yaw relative to the carrier (V0.1)"));
    tool_result_free(&r);
    /* both refused: the one line of the second refusal, exit 1 */
    assert_int_equal(sim_stop(s), 0);
    sim_start(s, SIM_TCP, "--fail", "euler=1", "--fail", "angle-control=1", NULL);
    r = sim_run_on(s, "point", "--pitch", "-30", "--yaw", "45", NULL);
    assert_failure(&r, 1, "point: angle-control (angle control): the GCU answered failed", NULL);
    tool_result_free(&r);
}

/* ---- probe's questions ------------------------------------------------------------------------- */

/* probe --json on @p s: its "questions", checked for their shape (the caller frees the report). */
static json_t *probe_questions(const sim_proc *s, json_t **report)
{
    tool_result r = sim_run_on(s, "probe", "--json", "--window", "0.2", NULL);
    json_t *q, *item;
    size_t i;
    if (r.status != 0) {
        print_error("probe: status %d\n%s\n", r.status, r.err);
        fail();
    }
    *report = parse_line(r.out);
    tool_result_free(&r);
    q = json_object_get(*report, "questions");
    assert_true(json_is_array(q));
    assert_int_equal(json_array_size(q), 14); /* the rows of docs/protocol.md section 12 */
    json_array_foreach(q, i, item)
    {
        assert_int_equal(int_key(item, "question"), (json_int_t)i + 1);
        (void)str_key(item, "title");
        (void)str_key(item, json_is_true(json_object_get(item, "asked")) ? "answer" : "why");
    }
    return q;
}

static const json_t *question(const json_t *q, size_t number)
{
    const json_t *item = json_array_get(q, number - 1u);
    assert_true(json_is_true(json_object_get(item, "asked")));
    return json_object_get(item, "detail");
}

/* The default simulator: answers both versions, repeats the state, 72-byte null replies; a
 * two-byte parameter failed, which its log names. The questions that would move the gimbal or
 * change a setting are not asked. */
static void test_probe_default_readings(void **state)
{
    sim_proc *s = (sim_proc *)*state;
    static const size_t never[] = {2, 3, 4, 5, 6, 10, 11, 12, 14};
    json_t *report, *q = NULL;
    const json_t *d;
    char line[512];
    size_t i;
    sim_start(s, SIM_TCP, NULL);
    q = probe_questions(s, &report);
    d = question(q, 7);
    assert_true(json_is_true(json_object_get(d, "answers_version_1")));
    assert_true(json_is_true(json_object_get(d, "answers_version_2")));
    d = question(q, 8);
    assert_int_equal(int_key(d, "replies"), 3);
    assert_int_equal(int_key(d, "with_state"), 3);
    d = question(q, 9);
    assert_true(int_key(d, "bytes_72") > 0);
    assert_int_equal(int_key(d, "bytes_73"), 0);
    d = question(q, 1);
    assert_int_equal(int_key(d, "state"), 1);
    d = question(q, 13);
    (void)str_key(d, "pod_status_order");
    for (i = 0; i < sizeof(never) / sizeof(never[0]); i++) {
        const json_t *item = json_array_get(q, never[i] - 1u);
        assert_true(json_is_false(json_object_get(item, "asked")));
    }
    assert_string_equal(str_key(json_array_get(q, 2), "why"), "record starts or stops a video");
    assert_int_equal(int_key(json_object_get(report, "gimbal"), "version_answered"), 1);
    assert_string_equal(str_key(json_object_get(report, "link"), "protocol_setting"), "auto");
    (void)int_key(json_object_get(report, "health"), "out_of_turn");
    json_decref(report);
    assert_int_equal(
        sim_log_line(s, "note: open question 1: zoom_stop (0x24) with 2 parameter bytes", 3000, line, sizeof(line)), 0);
}

/* A GCU that answers version 2 only and sends the state once: both answers differ. */
static void test_probe_other_readings(void **state)
{
    sim_proc *s = (sim_proc *)*state;
    json_t *report, *q;
    const json_t *d;
    tool_result r;
    sim_start(s, SIM_TCP, "--answer-only", "2", "--state-once", NULL);
    q = probe_questions(s, &report);
    d = question(q, 7);
    assert_false(json_is_true(json_object_get(d, "answers_version_1")));
    assert_true(json_is_true(json_object_get(d, "answers_version_2")));
    assert_non_null(strstr(str_key(json_array_get(q, 6), "answer"), "no: it answers version 2 only"));
    d = question(q, 8);
    assert_int_equal(int_key(d, "replies"), 3);
    assert_int_equal(int_key(d, "with_state"), 1);
    assert_int_equal(int_key(json_object_get(report, "gimbal"), "version_answered"), 2);
    json_decref(report);
    /* the text report lists them too */
    r = sim_run_on(s, "probe", "--window", "0.2", NULL);
    assert_int_equal(r.status, 0);
    assert_non_null(strstr(r.out, "\nopen questions (docs/protocol.md section 12):\n"));
    assert_non_null(strstr(r.out, "no: 1 of 3 replies to zoom_stop sent 3 times in a row carried it"));
    assert_non_null(strstr(r.out, "not asked: record starts or stops a video\n"));
    assert_non_null(strstr(r.out, "\nversion      it answered packets of version 2 (--protocol auto)\n"));
    tool_result_free(&r);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup_teardown(test_point_euler, sim_setup_tcp, sim_teardown),
        cmocka_unit_test_setup_teardown(test_point_falls_back_v2, sim_setup_none, sim_teardown),
        cmocka_unit_test_setup_teardown(test_point_falls_back_v1, sim_setup_none, sim_teardown),
        cmocka_unit_test_setup_teardown(test_probe_default_readings, sim_setup_none, sim_teardown),
        cmocka_unit_test_setup_teardown(test_probe_other_readings, sim_setup_none, sim_teardown),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
