/*
 * test_cli_demo.c - `xfgcu demo`: the simulator and a client in one
 * process over loopback TCP; every step of the tour must behave, in a
 * bounded time, and say what happened.
 */
#define _POSIX_C_SOURCE 200809L

#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>
#include <time.h>
#include <cmocka.h>

#include "run_tool.h"

static void test_demo(void **state)
{
    static const char *const needles[] = {
        "simulated GCU  Z-9B_V4(T) (code 58) on tcp 127.0.0.1:",
        "[ 1] connect",
        "< first reply after ",
        "Z-9B_V4(T) (code 58), hardware 3.1, firmware 5.0, mode ", /* models and versions one way */
        "head_lock: ok",
        "yaw rate +30 deg/s",
        "arrived after ",
        "distance 240.0 m",
        "mode orthoview, pitch -90.00 deg",
        "zoom of camera 1: 1.0x -> 5.0x",
        "zoom_stop: ok",
        "the packets sent: shutter x1, null x",
        "the simulated camera took 2 photos",
        "mode track, tracking ok",
        "palette: failed cameras 0x02",
        "calibration: operating...",
        "calibration: ok",
        "link up: ",
        "Every step behaved",
    };
    struct timespec t0, t1;
    double seconds;
    size_t i;
    tool_result r;
    (void)state;
    clock_gettime(CLOCK_MONOTONIC, &t0);
    r = run_tool(NULL, "demo", NULL);
    clock_gettime(CLOCK_MONOTONIC, &t1);
    seconds = (double)(t1.tv_sec - t0.tv_sec) + (double)(t1.tv_nsec - t0.tv_nsec) / 1e9;
    if (r.status != 0 || r.err_len != 0) {
        print_error("status %d\nstdout: %s\nstderr: %s\n", r.status, r.out, r.err);
        fail();
    }
    for (i = 0; i < sizeof(needles) / sizeof(needles[0]); i++) {
        if (strstr(r.out, needles[i]) == NULL) {
            print_error("the demo does not say \"%s\":\n%s\n", needles[i], r.out);
            fail();
        }
    }
    assert_null(strstr(r.out, "!!"));
    assert_true(seconds < 20.0);
    tool_result_free(&r);
}

static void test_demo_arguments(void **state)
{
    tool_result r = run_tool(NULL, "demo", "--fast", NULL);
    (void)state;
    assert_failure(&r, 2, "demo: unknown option '--fast'", NULL);
    tool_result_free(&r);
    r = run_tool(NULL, "demo", "--help", NULL);
    assert_int_equal(r.status, 0);
    assert_non_null(strstr(r.out, "usage: xfgcu demo"));
    tool_result_free(&r);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_demo_arguments),
        cmocka_unit_test(test_demo),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
