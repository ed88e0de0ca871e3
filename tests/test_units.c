/*
 * test_units.c - xf_units.h: physical units <-> raw wire integers
 * (rounding, saturation at both ends, NaN, wrapping angles), GNSS time and
 * the camera-axis transform of vendor appendix 3.
 *
 * Expected values are worked out by hand from the spec's resolutions; the
 * GNSS times are computed here from the calendar, independently of the
 * codec's constants.
 */
#include <math.h>
#include "test_util.h"

#define EPS 1e-4

/* ---- rounding and wrapping helpers ---------------------------------------- */

static void test_round_and_wrap(void **state)
{
    (void)state;
    /* half away from zero */
    assert_sint_equal(xf_units_round(2.5, -10, 10), 3);
    assert_sint_equal(xf_units_round(-2.5, -10, 10), -3);
    assert_sint_equal(xf_units_round(2.4999, -10, 10), 2);
    assert_sint_equal(xf_units_round(-2.4999, -10, 10), -2);
    /* clamped */
    assert_sint_equal(xf_units_round(1e300, 0, 10), 10);
    assert_sint_equal(xf_units_round(-1e300, 0, 10), 0);
    assert_sint_equal(xf_units_round((double)INFINITY, -5, 5), 5);
    assert_sint_equal(xf_units_round(-(double)INFINITY, -5, 5), -5);
    /* NaN: 0, or the bound nearest 0 when 0 is outside */
    assert_sint_equal(xf_units_round((double)NAN, -10, 10), 0);
    assert_sint_equal(xf_units_round((double)NAN, 5, 10), 5);
    assert_sint_equal(xf_units_round((double)NAN, -10, -5), -5);

    assert_near(xf_units_wrap360(370.0, 0.0), 10.0, EPS);
    assert_near(xf_units_wrap360(-10.0, 0.0), 350.0, EPS);
    assert_near(xf_units_wrap360(720.0, 0.0), 0.0, EPS);
    assert_near(xf_units_wrap360(-720.25, 0.0), 359.75, EPS);
    assert_near(xf_units_wrap360(180.0, -180.0), -180.0, EPS);
    assert_near(xf_units_wrap360(-180.0, -180.0), -180.0, EPS);
    assert_near(xf_units_wrap360(190.0, -180.0), -170.0, EPS);
    assert_near(xf_units_wrap360(1e6 + 0.5, 0.0), 280.5, EPS); /* 1e6 = 2777 turns + 280 */
    {
        double w = xf_units_wrap360((double)NAN, 0.0);
        assert_true(w >= 0.0 && w < 360.0);
    }
}

/* ---- host main frame -------------------------------------------------------- */

static void test_carrier_roll(void **state)
{
    (void)state;
    /* 0.01 deg, wrapped into [-180, 180) (docs/protocol.md §3: [-18000, 18000)) */
    assert_sint_equal(xf_carrier_roll_raw(0.0f), 0);
    assert_sint_equal(xf_carrier_roll_raw(-11.3213f), -1132); /* appendix 1 */
    assert_sint_equal(xf_carrier_roll_raw(190.0f), -17000);
    assert_sint_equal(xf_carrier_roll_raw(-190.0f), 17000);
    assert_sint_equal(xf_carrier_roll_raw(180.0f), -18000);
    assert_sint_equal(xf_carrier_roll_raw(-180.0f), -18000);
    assert_sint_equal(xf_carrier_roll_raw(179.99f), 17999);
    assert_sint_equal(xf_carrier_roll_raw(179.999f), -18000); /* rounds to 180.00 = -180.00 */
    assert_sint_equal(xf_carrier_roll_raw(540.0f), -18000);
    assert_sint_equal(xf_carrier_roll_raw(370.5f), 1050);
    assert_sint_equal(xf_carrier_roll_raw(NAN), 0);
    assert_in_range(xf_carrier_roll_raw(INFINITY) + 18000, 0, 35999);
    assert_in_range(xf_carrier_roll_raw(-1e30f) + 18000, 0, 35999);
}

static void test_carrier_pitch(void **state)
{
    (void)state;
    /* 0.01 deg, clamped to [-90, 90] */
    assert_sint_equal(xf_carrier_pitch_raw(1.01f), 101); /* appendix 1 */
    assert_sint_equal(xf_carrier_pitch_raw(-45.5f), -4550);
    assert_sint_equal(xf_carrier_pitch_raw(0.125f), 13); /* 12.5 -> 13 */
    assert_sint_equal(xf_carrier_pitch_raw(-0.125f), -13);
    assert_sint_equal(xf_carrier_pitch_raw(90.0f), 9000);
    assert_sint_equal(xf_carrier_pitch_raw(100.0f), 9000);
    assert_sint_equal(xf_carrier_pitch_raw(-100.0f), -9000);
    assert_sint_equal(xf_carrier_pitch_raw(INFINITY), 9000);
    assert_sint_equal(xf_carrier_pitch_raw(-INFINITY), -9000);
    assert_sint_equal(xf_carrier_pitch_raw(NAN), 0);
}

static void test_carrier_yaw(void **state)
{
    (void)state;
    /* 0.01 deg, wrapped into [0, 360) (docs/protocol.md §3: [0, 36000)) */
    assert_int_equal(xf_carrier_yaw_raw(240.0f), 24000); /* appendix 1 */
    assert_int_equal(xf_carrier_yaw_raw(-10.0f), 35000);
    assert_int_equal(xf_carrier_yaw_raw(359.999f), 0);
    assert_int_equal(xf_carrier_yaw_raw(359.99f), 35999);
    assert_int_equal(xf_carrier_yaw_raw(360.0f), 0);
    assert_int_equal(xf_carrier_yaw_raw(720.5f), 50);
    assert_int_equal(xf_carrier_yaw_raw(-370.0f), 35000);
    assert_int_equal(xf_carrier_yaw_raw(NAN), 0);
    assert_in_range(xf_carrier_yaw_raw(INFINITY), 0, 35999);
    assert_in_range(xf_carrier_yaw_raw(-INFINITY), 0, 35999);
}

static void test_accel_velocity(void **state)
{
    (void)state;
    /* 0.01 m/s^2 and 0.01 m/s (docs/protocol.md §9.1), clamped to S16 */
    assert_sint_equal(xf_accel_raw(1.123f), 112); /* appendix 1 */
    assert_sint_equal(xf_accel_raw(-1.123f), -112);
    assert_sint_equal(xf_accel_raw(327.67f), 32767);
    assert_sint_equal(xf_accel_raw(327.68f), 32767);
    assert_sint_equal(xf_accel_raw(-327.68f), -32768);
    assert_sint_equal(xf_accel_raw(1000.0f), 32767);
    assert_sint_equal(xf_accel_raw(-1000.0f), -32768);
    assert_sint_equal(xf_accel_raw(INFINITY), 32767);
    assert_sint_equal(xf_accel_raw(-INFINITY), -32768);
    assert_sint_equal(xf_accel_raw(NAN), 0);

    assert_sint_equal(xf_velocity_raw(21.123f), 2112); /* appendix 1, the intended value */
    assert_sint_equal(xf_velocity_raw(-21.123f), -2112);
    assert_sint_equal(xf_velocity_raw(400.0f), 32767);
    assert_sint_equal(xf_velocity_raw(-400.0f), -32768);
    assert_sint_equal(xf_velocity_raw(NAN), 0);
}

static void test_ctrl_angle_rate(void **state)
{
    (void)state;
    /* desired angles: 0.01 deg, [-18000, 18000] */
    assert_sint_equal(xf_ctrl_angle_raw(-45.0f), -4500); /* appendix 4: pitch -45 */
    assert_sint_equal(xf_ctrl_angle_raw(1.0f), 100);
    assert_sint_equal(xf_ctrl_angle_raw(180.0f), 18000);
    assert_sint_equal(xf_ctrl_angle_raw(200.0f), 18000);
    assert_sint_equal(xf_ctrl_angle_raw(-200.0f), -18000);
    assert_sint_equal(xf_ctrl_angle_raw(NAN), 0);

    /* desired rates: one unit is 0.1 deg/s divided by the zoom, so
     * raw = dps * 10 * zoom, [-1500, 1500]; zoom below 1 counts as 1 */
    assert_sint_equal(xf_ctrl_rate_raw(10.0f, 1.0f), 100);
    assert_sint_equal(xf_ctrl_rate_raw(10.0f, 2.0f), 200);
    assert_sint_equal(xf_ctrl_rate_raw(1.5f, 30.0f), 450);
    assert_sint_equal(xf_ctrl_rate_raw(-2.5f, 4.0f), -100);
    assert_sint_equal(xf_ctrl_rate_raw(10.0f, 0.5f), 100);
    assert_sint_equal(xf_ctrl_rate_raw(10.0f, 0.0f), 100);
    assert_sint_equal(xf_ctrl_rate_raw(10.0f, -3.0f), 100);
    assert_sint_equal(xf_ctrl_rate_raw(10.0f, NAN), 100);
    assert_sint_equal(xf_ctrl_rate_raw(150.0f, 1.0f), 1500);
    assert_sint_equal(xf_ctrl_rate_raw(200.0f, 1.0f), 1500);
    assert_sint_equal(xf_ctrl_rate_raw(-200.0f, 1.0f), -1500);
    assert_sint_equal(xf_ctrl_rate_raw(100.0f, 2.0f), 1500);
    assert_sint_equal(xf_ctrl_rate_raw(NAN, 1.0f), 0);
    assert_sint_equal(xf_ctrl_rate_raw(INFINITY, 1.0f), 1500);
}

/* ---- sub frames and gaze_geo ----------------------------------------------- */

static void test_deg7_mm(void **state)
{
    (void)state;
    assert_sint_equal(xf_deg7_raw(170.917533212), 1709175332); /* appendix 1 */
    assert_sint_equal(xf_deg7_raw(38.030082231), 380300822);
    assert_sint_equal(xf_deg7_raw(-38.030082231), -380300822);
    assert_sint_equal(xf_deg7_raw(180.0), 1800000000);
    assert_sint_equal(xf_deg7_raw(200.0), 1800000000);
    assert_sint_equal(xf_deg7_raw(-200.0), -1800000000);
    assert_sint_equal(xf_deg7_raw((double)NAN), 0);
    assert_near(xf_deg7(1709175332), 170.9175332, 1e-9);
    assert_near(xf_deg7(-380300822), -38.0300822, 1e-9);

    assert_sint_equal(xf_mm_raw(41.1231), 41123); /* appendix 1 */
    assert_sint_equal(xf_mm_raw(12.12), 12120);
    assert_sint_equal(xf_mm_raw(-3.5), -3500);
    assert_sint_equal(xf_mm_raw(1e10), INT32_MAX);
    assert_sint_equal(xf_mm_raw(-1e10), INT32_MIN);
    assert_sint_equal(xf_mm_raw((double)NAN), 0);
}

/* ---- GCU frames --------------------------------------------------------------- */

static void test_gcu_units(void **state)
{
    float m = 123.0f;
    (void)state;
    assert_near(xf_cdeg(24000), 240.0, EPS);
    assert_near(xf_cdeg(-1132), -11.32, EPS);

    /* rates: 0.01 deg/s in V0.1, 0.1 deg/s in V0.2 (docs/protocol.md §10) */
    assert_near(xf_gcu_rate_dps(100, XF_PROTOCOL_V1), 1.0, EPS);
    assert_near(xf_gcu_rate_dps(100, XF_PROTOCOL_V2), 10.0, EPS);
    assert_near(xf_gcu_rate_dps(-5, XF_PROTOCOL_V2), -0.5, EPS);
    assert_near(xf_gcu_rate_dps(-32768, XF_PROTOCOL_V1), -327.68, EPS);
    assert_sint_equal(xf_gcu_rate_raw(1.0f, XF_PROTOCOL_V1), 100);
    assert_sint_equal(xf_gcu_rate_raw(1.0f, XF_PROTOCOL_V2), 10);
    assert_sint_equal(xf_gcu_rate_raw(-2.5f, XF_PROTOCOL_V2), -25);
    assert_sint_equal(xf_gcu_rate_raw(400.0f, XF_PROTOCOL_V1), 32767);
    assert_sint_equal(xf_gcu_rate_raw(400.0f, XF_PROTOCOL_V2), 4000);
    assert_sint_equal(xf_gcu_rate_raw(4000.0f, XF_PROTOCOL_V2), 32767);
    assert_sint_equal(xf_gcu_rate_raw(-1e6f, XF_PROTOCOL_V1), -32768);
    assert_sint_equal(xf_gcu_rate_raw(-1e6f, XF_PROTOCOL_V2), -32768);
    assert_sint_equal(xf_gcu_rate_raw(NAN, XF_PROTOCOL_V2), 0);

    /* zoom: 0.1 x */
    assert_near(xf_zoom_x(55), 5.5, EPS);
    assert_near(xf_zoom_x(65535), 6553.5, EPS);
    assert_int_equal(xf_zoom_raw(5.5f), 55);
    assert_int_equal(xf_zoom_raw(30.0f), 300);
    assert_int_equal(xf_zoom_raw(-1.0f), 0);
    assert_int_equal(xf_zoom_raw(1e6f), 65535);
    assert_int_equal(xf_zoom_raw(NAN), 0);

    /* target_distance: 0.1 m; -1 m (raw -10) and 0 mean no measurement */
    assert_false(xf_distance_m(-10, &m));
    assert_near(m, 123.0, EPS); /* untouched */
    assert_false(xf_distance_m(0, &m));
    assert_false(xf_distance_m(-1, &m));
    assert_near(m, 123.0, EPS);
    assert_true(xf_distance_m(1234, &m));
    assert_near(m, 123.4, EPS);
    assert_true(xf_distance_m(1, &m));
    assert_near(m, 0.1, EPS);
    assert_true(xf_distance_m(1234, NULL));
    assert_false(xf_distance_m(-10, NULL));
}

static void test_zoom_to_rate(void **state)
{
    (void)state;
    /* ZZ = -(rate x 10), rate clamped to [1.0, 3276.8] (docs/protocol.md §7) */
    assert_sint_equal(xf_zoom_to_rate_raw(5.5f), -55);
    assert_sint_equal(xf_zoom_to_rate_raw(1.0f), -10);
    assert_sint_equal(xf_zoom_to_rate_raw(15.0f), -150);
    assert_sint_equal(xf_zoom_to_rate_raw(30.0f), -300);
    assert_sint_equal(xf_zoom_to_rate_raw(0.5f), -10);
    assert_sint_equal(xf_zoom_to_rate_raw(0.0f), -10);
    assert_sint_equal(xf_zoom_to_rate_raw(-3.0f), -10);
    assert_sint_equal(xf_zoom_to_rate_raw(3276.8f), -32768);
    assert_sint_equal(xf_zoom_to_rate_raw(5000.0f), -32768);
    assert_sint_equal(xf_zoom_to_rate_raw(INFINITY), -32768);
    assert_sint_equal(xf_zoom_to_rate_raw(NAN), -10);
    /* always a valid zoom_to rate */
    {
        xf_command c;
        xf_command_init(&c, XF_ORDER_ZOOM_TO);
        c.zoom = xf_zoom_to_rate_raw(0.25f);
        assert_err(xf_command_check(&c, 1, NULL), XF_OK);
    }
}

/* ---- GNSS time -------------------------------------------------------------- */

static int is_leap(int y) { return (y % 4 == 0 && y % 100 != 0) || y % 400 == 0; }

/* Days from 1970-01-01 to y-m-d, counted the long way. */
static int64_t unix_days(int y, int m, int d)
{
    static const int mdays[12] = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
    int64_t days = 0;
    int k;
    for (k = 1970; k < y; k++) {
        days += is_leap(k) ? 366 : 365;
    }
    for (k = 1; k < m; k++) {
        days += mdays[k - 1] + ((k == 2 && is_leap(y)) ? 1 : 0);
    }
    return days + d - 1;
}

static void test_gnss_time(void **state)
{
    int64_t gps_epoch_ms = unix_days(1980, 1, 6) * 86400 * 1000;
    int64_t week_ms = 7LL * 86400 * 1000;
    int64_t want, got = 0;
    int16_t wk = 0;
    uint32_t ms = 0;
    (void)state;
    assert_true(gps_epoch_ms == 315964800000LL);
    assert_true(XF_GPS_EPOCH_UNIX == 315964800LL);

    /* appendix 1: week 2278, 352718000 ms of week, 18 leap seconds
     * = 2023-09-07 01:58:20 UTC (GPS week 2278 began Sunday 2023-09-03;
     * 352718 s is 4 days 01:58:38 GPS time, minus 18 s) */
    want = gps_epoch_ms + 2278 * week_ms + 352718000LL - 18000LL;
    assert_true(want == (unix_days(2023, 9, 7) * 86400 + 1 * 3600 + 58 * 60 + 20) * 1000);
    assert_err(xf_gnss_to_unix_ms(2278, 352718000u, XF_LEAP_SECONDS_2017, &got), XF_OK);
    assert_sint_equal(got, want);
    assert_err(xf_unix_ms_to_gnss(want, 18, &wk, &ms), XF_OK);
    assert_sint_equal(wk, 2278);
    assert_int_equal(ms, 352718000u);

    /* leap seconds are an explicit parameter */
    assert_err(xf_gnss_to_unix_ms(2278, 352718000u, 0, &got), XF_OK);
    assert_sint_equal(got, want + 18000);
    /* the epoch itself */
    assert_err(xf_gnss_to_unix_ms(0, 0, 0, &got), XF_OK);
    assert_sint_equal(got, gps_epoch_ms);
    assert_err(xf_unix_ms_to_gnss(gps_epoch_ms - 18000, 18, &wk, &ms), XF_OK);
    assert_sint_equal(wk, 0);
    assert_int_equal(ms, 0);
    /* last millisecond of a week, first of the next */
    assert_err(xf_gnss_to_unix_ms(10, 604799999u, 0, &got), XF_OK);
    assert_sint_equal(got, gps_epoch_ms + 11 * week_ms - 1);
    assert_err(xf_unix_ms_to_gnss(gps_epoch_ms + 11 * week_ms, 0, &wk, &ms), XF_OK);
    assert_sint_equal(wk, 11);
    assert_int_equal(ms, 0);

    /* round trips */
    {
        test_rng r;
        int k;
        rng_seed(&r, 0x6E55);
        for (k = 0; k < 2000; k++) {
            int16_t w0 = (int16_t)rng_below(&r, 32768), w1 = -1;
            uint32_t m0 = rng_below(&r, 604800000u), m1 = 0;
            int leap = (int)rng_below(&r, 40);
            int64_t u = 0;
            assert_err(xf_gnss_to_unix_ms(w0, m0, leap, &u), XF_OK);
            assert_sint_equal(u, gps_epoch_ms + (int64_t)w0 * week_ms + m0 - leap * 1000LL);
            assert_err(xf_unix_ms_to_gnss(u, leap, &w1, &m1), XF_OK);
            assert_sint_equal(w1, w0);
            assert_int_equal(m1, m0);
        }
    }

    /* range errors */
    got = 42;
    assert_err(xf_gnss_to_unix_ms(-1, 0, 18, &got), XF_ERR_RANGE);
    assert_err(xf_gnss_to_unix_ms(-32768, 0, 18, &got), XF_ERR_RANGE);
    assert_err(xf_gnss_to_unix_ms(2278, 604800000u, 18, &got), XF_ERR_RANGE);
    assert_err(xf_gnss_to_unix_ms(2278, 0xFFFFFFFFu, 18, &got), XF_ERR_RANGE);
    assert_err(xf_gnss_to_unix_ms(2278, 604799999u, 18, &got), XF_OK);
    assert_err(xf_unix_ms_to_gnss(0, 18, &wk, &ms), XF_ERR_RANGE);                        /* 1970 */
    assert_err(xf_unix_ms_to_gnss(gps_epoch_ms - 18000 - 1, 18, &wk, &ms), XF_ERR_RANGE); /* just before */
    assert_err(xf_unix_ms_to_gnss(gps_epoch_ms + 32767 * week_ms + 604799999LL, 0, &wk, &ms), XF_OK);
    assert_sint_equal(wk, 32767);
    assert_err(xf_unix_ms_to_gnss(gps_epoch_ms + 32768 * week_ms, 0, &wk, &ms), XF_ERR_RANGE);
    assert_err(xf_unix_ms_to_gnss(INT64_MAX / 2, 0, &wk, &ms), XF_ERR_RANGE);
    /* NULL */
    assert_err(xf_gnss_to_unix_ms(2278, 0, 18, NULL), XF_ERR_ARG);
    assert_err(xf_unix_ms_to_gnss(want, 18, NULL, &ms), XF_ERR_ARG);
    assert_err(xf_unix_ms_to_gnss(want, 18, &wk, NULL), XF_ERR_ARG);
}

/* Absurd times must give XF_ERR_RANGE, not arithmetic overflow. Run under
 * UBSan (XFGCU_SANITIZE=ON) for this to bite: without it the overflow wraps
 * silently and happens to land on RANGE. */
static void test_gnss_extreme_inputs(void **state)
{
    int16_t wk = 0;
    uint32_t ms = 0;
    int64_t u = 0;
    (void)state;
    assert_err(xf_unix_ms_to_gnss(INT64_MAX, 18, &wk, &ms), XF_ERR_RANGE);
    assert_err(xf_unix_ms_to_gnss(INT64_MAX, -2000000000, &wk, &ms), XF_ERR_RANGE);
    assert_err(xf_gnss_to_unix_ms(32767, 604799999u, -2000000000, &u), XF_OK);
    assert_err(xf_gnss_to_unix_ms(0, 0, 2000000000, &u), XF_OK);
    assert_err(xf_unix_ms_to_gnss(-1000000000000LL, 18, &wk, &ms), XF_ERR_RANGE);
    /* the most negative time: `unix_ms - epoch_ms` overflows int64 */
    assert_err(xf_unix_ms_to_gnss(INT64_MIN, 18, &wk, &ms), XF_ERR_RANGE);
}

/* ---- camera axes (vendor appendix 3, docs/protocol.md §8) ------------------------------ */

static void test_axes_to_euler(void **state)
{
    float roll = 0, pitch = 0, yaw = 0, ax = 0, ay = 0, az = 0;
    (void)state;
    /* AngleZ += 90, wrapped into [0, 360); roll = +Y; pitch = -X; yaw = +Z */
    xf_axes_to_euler(10.0f, 20.0f, 30.0f, &roll, &pitch, &yaw);
    assert_near(roll, 20.0, EPS);
    assert_near(pitch, -10.0, EPS);
    assert_near(yaw, 120.0, EPS);
    xf_axes_to_euler(-45.0f, -5.0f, 0.0f, &roll, &pitch, &yaw);
    assert_near(roll, -5.0, EPS);
    assert_near(pitch, 45.0, EPS);
    assert_near(yaw, 90.0, EPS);
    xf_axes_to_euler(0.0f, 0.0f, 270.0f, &roll, &pitch, &yaw);
    assert_near(yaw, 0.0, EPS);
    xf_axes_to_euler(0.0f, 0.0f, 300.0f, &roll, &pitch, &yaw);
    assert_near(yaw, 30.0, EPS);
    xf_axes_to_euler(0.0f, 0.0f, -90.0f, &roll, &pitch, &yaw);
    assert_near(yaw, 0.0, EPS);
    xf_axes_to_euler(0.0f, 0.0f, -180.0f, &roll, &pitch, &yaw);
    assert_near(yaw, 270.0, EPS);
    xf_axes_to_euler(0.0f, 0.0f, 269.5f, &roll, &pitch, &yaw);
    assert_near(yaw, 359.5, EPS);
    xf_axes_to_euler(1.0f, 2.0f, 3.0f, NULL, NULL, NULL); /* outputs are optional */

    /* the inverse; az in [-180, 180) */
    xf_euler_to_axes(20.0f, -10.0f, 120.0f, &ax, &ay, &az);
    assert_near(ax, 10.0, EPS);
    assert_near(ay, 20.0, EPS);
    assert_near(az, 30.0, EPS);
    xf_euler_to_axes(0.0f, 0.0f, 0.0f, &ax, &ay, &az);
    assert_near(az, -90.0, EPS);
    xf_euler_to_axes(0.0f, 0.0f, 90.0f, &ax, &ay, &az);
    assert_near(az, 0.0, EPS);
    xf_euler_to_axes(0.0f, 0.0f, 270.0f, &ax, &ay, &az);
    assert_near(az, -180.0, EPS);
    xf_euler_to_axes(0.0f, 0.0f, 359.0f, &ax, &ay, &az);
    assert_near(az, -91.0, EPS);
    xf_euler_to_axes(0.0f, 0.0f, 269.0f, &ax, &ay, &az);
    assert_near(az, 179.0, EPS);
    xf_euler_to_axes(1.0f, 2.0f, 3.0f, NULL, NULL, NULL);

    /* round trip over a grid */
    {
        int x, z;
        for (x = -90; x <= 90; x += 15) {
            for (z = -180; z < 180; z += 5) {
                float r2, p2, y2, x3, y3, z3;
                xf_axes_to_euler((float)x, (float)(x / 2), (float)z + 0.25f, &r2, &p2, &y2);
                assert_true(y2 >= 0.0f && y2 < 360.0f);
                xf_euler_to_axes(r2, p2, y2, &x3, &y3, &z3);
                assert_near(x3, (double)x, EPS);
                assert_near(y3, (double)(x / 2), EPS);
                assert_near(z3, (double)z + 0.25, EPS);
            }
        }
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_round_and_wrap),
        cmocka_unit_test(test_carrier_roll),
        cmocka_unit_test(test_carrier_pitch),
        cmocka_unit_test(test_carrier_yaw),
        cmocka_unit_test(test_accel_velocity),
        cmocka_unit_test(test_ctrl_angle_rate),
        cmocka_unit_test(test_deg7_mm),
        cmocka_unit_test(test_gcu_units),
        cmocka_unit_test(test_zoom_to_rate),
        cmocka_unit_test(test_gnss_time),
        cmocka_unit_test(test_axes_to_euler),
        /* last: under UBSan its overflow aborts the binary */
        cmocka_unit_test(test_gnss_extreme_inputs),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
