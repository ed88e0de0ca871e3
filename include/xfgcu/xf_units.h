/**
 * @file
 * @brief Physical units to and from raw wire integers, GNSS time, and the
 * vendor's camera-axis transform (docs/protocol.md §8).
 *
 * Saturation policy: every conversion to a raw value returns the nearest
 * value inside the field's documented range (rounding half away from zero);
 * NaN becomes 0. Angles that wrap (roll, yaw) are wrapped instead of
 * clamped. Conversions from raw never fail. No libm is needed. The
 * functions keep no state and never block.
 */
#ifndef XF_UNITS_H
#define XF_UNITS_H

#include <stdbool.h>
#include <stdint.h>
#include "xf_config.h"
#include "xf_error.h"
#include "xf_protocol.h"

XF_BEGIN_DECLS

#define XF_GPS_EPOCH_UNIX    315964800LL /**< 1980-01-06T00:00:00Z in Unix seconds */
#define XF_WEEK_MS           604800000UL /**< milliseconds in a GNSS week */
#define XF_LEAP_SECONDS_2017 18          /**< GPS - UTC since 2017-01-01 (pass what is current) */

/**
 * Round to the nearest integer (half away from zero), clamped to [lo, hi].
 * @param v   the value; NaN counts as 0
 * @param lo  lowest result
 * @param hi  highest result (>= @p lo)
 * @return the rounded value in [lo, hi]: 0 for NaN (or the bound nearest 0
 *   when 0 is outside [lo, hi])
 */
XF_API int32_t xf_units_round(double v, int32_t lo, int32_t hi);
/**
 * An angle wrapped into [lo, lo + 360).
 * @param deg  the angle, deg
 * @param lo   start of the range, deg
 * @return the angle in [lo, lo + 360); for NaN or a magnitude above 1e12,
 *   0 when @p lo < 0 and @p lo otherwise
 */
XF_API double xf_units_wrap360(double deg, double lo);
/**
 * Single-precision xf_units_round() (for int16-range fields): an MCU's FPU
 * does these in hardware, and the conversions of attitude, accelerations and
 * velocities use only these.
 * @param v   the value; NaN counts as 0
 * @param lo  lowest result
 * @param hi  highest result (>= @p lo)
 * @return the rounded value in [lo, hi]
 */
XF_API int32_t xf_units_roundf(float v, int32_t lo, int32_t hi);
/**
 * Single-precision xf_units_wrap360().
 * @param deg  the angle, deg
 * @param lo   start of the range, deg
 * @return the angle in [lo, lo + 360); for NaN or a magnitude above 1e7,
 *   0 when @p lo < 0 and @p lo otherwise
 */
XF_API float xf_units_wrap360f(float deg, float lo);

/* host main frame */
/**
 * Carrier roll for xf_host_main.carrier_roll.
 * @param deg  roll, deg (any value: wrapped into [-180, 180))
 * @return 0.01 deg, in [-18000, 17999]
 */
XF_API int16_t xf_carrier_roll_raw(float deg);
/**
 * Carrier pitch for xf_host_main.carrier_pitch.
 * @param deg  pitch, deg (clamped to [-90, 90])
 * @return 0.01 deg, in [-9000, 9000]
 */
XF_API int16_t xf_carrier_pitch_raw(float deg);
/**
 * Carrier yaw for xf_host_main.carrier_yaw.
 * @param deg  yaw, deg (any value: wrapped into [0, 360))
 * @return 0.01 deg, in [0, 35999]
 */
XF_API uint16_t xf_carrier_yaw_raw(float deg);
/**
 * Carrier acceleration (gravity excluded) for xf_host_main.accel_north and
 * the like.
 * @param mps2  acceleration, m/s^2
 * @return 0.01 m/s^2, clamped to int16
 */
XF_API int16_t xf_accel_raw(float mps2);
/**
 * Carrier velocity for xf_host_main.vel_north and the like.
 * @param mps  velocity, m/s
 * @return 0.01 m/s, clamped to int16
 */
XF_API int16_t xf_velocity_raw(float mps);
/**
 * Control angle (Euler or relative to the carrier) for the control
 * quantities of xf_host_main.
 * @param deg  angle, deg (clamped to [-180, 180]; not wrapped)
 * @return 0.01 deg, in [-18000, 18000]
 */
XF_API int16_t xf_ctrl_angle_raw(float deg);
/**
 * Control rate for the control quantities of xf_host_main: one raw unit is
 * 0.1 deg/s divided by the main screen's zoom, so the raw value is
 * dps x 10 x zoom.
 * @param dps   desired angular velocity, deg/s
 * @param zoom  the main screen's zoom, x (below 1, NaN included, counts as 1)
 * @return the raw rate, clamped to [-1500, 1500]
 */
XF_API int16_t xf_ctrl_rate_raw(float dps, float zoom);

/* host sub frame and gaze_geo */
/**
 * Latitude or longitude for the host sub frame and gaze_geo.
 * @param deg  degrees
 * @return 1e-7 deg, clamped to [-180, 180] deg
 */
XF_API int32_t xf_deg7_raw(double deg);
/**
 * Altitude or height for the host sub frame and gaze_geo.
 * @param m  metres
 * @return millimetres, clamped to int32
 */
XF_API int32_t xf_mm_raw(double m);

/* GCU frames */
/**
 * Angle from 0.01 deg (cam_roll, rel_angle_x, ...) to degrees.
 * @param raw  0.01 deg
 * @return degrees
 */
XF_API float xf_cdeg(int32_t raw);
/**
 * GCU angular velocity (xf_gcu_main.rate_x and the like) in deg/s.
 * @param raw      the wire value
 * @param version  the packet's protocol version: V0.1 sends 0.01 deg/s,
 *   V0.2 (any version >= 2) 0.1 deg/s
 * @return deg/s
 */
XF_API float xf_gcu_rate_dps(int16_t raw, uint8_t version);
/**
 * Inverse of xf_gcu_rate_dps() (GCU side: the simulator).
 * @param dps      deg/s
 * @param version  protocol version of the packet, as for xf_gcu_rate_dps()
 * @return the wire value, clamped to int16
 */
XF_API int16_t xf_gcu_rate_raw(float dps, uint8_t version);
/**
 * Zoom from 0.1 x (zoom_cam1, zoom_cam2) to x.
 * @param raw  0.1 x
 * @return zoom factor, x
 */
XF_API float xf_zoom_x(uint16_t raw);
/**
 * Zoom factor to 0.1 x.
 * @param x  zoom factor, x
 * @return 0.1 x, clamped to [0, 65535]
 */
XF_API uint16_t xf_zoom_raw(float x);
/**
 * Latitude or longitude from 1e-7 deg to degrees.
 * @param raw  1e-7 deg
 * @return degrees
 */
XF_API double xf_deg7(int32_t raw);
/**
 * Laser range (xf_gcu_sub.target_distance) in metres.
 * @param raw  0.1 m; <= 0 (-10, 0) means no valid measurement
 * @param m    receives the distance in metres when valid (may be NULL);
 *   left alone otherwise
 * @return true when the measurement is valid, false when not
 */
XF_API bool xf_distance_m(int32_t raw, float *m);
/**
 * zoom_to's ZZ (xf_command.zoom) for a desired zoom rate: -(rate x 10).
 * @param rate  zoom rate, x (clamped to [1.0, 3276.8])
 * @return ZZ, in [-32768, -10]
 */
XF_API int16_t xf_zoom_to_rate_raw(float rate);

/**
 * GNSS week and milliseconds of week to Unix time in ms.
 * @param week          GNSS week number (>= 0)
 * @param ms            milliseconds of the week (< ::XF_WEEK_MS)
 * @param leap_seconds  GPS - UTC in seconds: 18 since 2017 (::XF_LEAP_SECONDS_2017); pass what is current
 * @param unix_ms       receives milliseconds since 1970-01-01T00:00:00Z (UTC)
 * @return ::XF_OK, ::XF_ERR_ARG (NULL @p unix_ms), ::XF_ERR_RANGE (week < 0
 *   or ms >= a week)
 */
XF_API xf_err xf_gnss_to_unix_ms(int16_t week, uint32_t ms, int leap_seconds, int64_t *unix_ms);
/**
 * Unix time in ms to GNSS week and milliseconds of week (for the host sub
 * frame); the inverse of xf_gnss_to_unix_ms().
 * @param unix_ms       milliseconds since 1970-01-01T00:00:00Z (UTC)
 * @param leap_seconds  GPS - UTC in seconds (18 since 2017)
 * @param week          receives the GNSS week number
 * @param ms            receives the milliseconds of the week
 * @return ::XF_OK, ::XF_ERR_ARG (NULL @p week or @p ms), ::XF_ERR_RANGE
 *   (before the GPS epoch or past week 32767); the outputs are written only
 *   on success
 */
XF_API xf_err xf_unix_ms_to_gnss(int64_t unix_ms, int leap_seconds, int16_t *week, uint32_t *ms);

/**
 * The vendor's camera-axis rule (appendix 3 of V2.0.4, appendix 4 of
 * V2.0.6; docs/protocol.md §8): the camera's absolute X/Y/Z-axis angles
 * (deg, rotation order Z-Y-X) to the Euler angles the GCU reports:
 * roll = Y, pitch = -X, yaw = Z + 90 wrapped into [0, 360).
 *
 * The input is in no packet. The GCU reports the absolute Euler angles
 * themselves (xf_gcu_main.cam_roll, cam_pitch, cam_yaw) and the camera's
 * axis angles relative to the carrier (rel_angle_x, rel_angle_y,
 * rel_angle_z); the relative angles are not absolute axis angles and are
 * not this function's input. Absolute axis angles come from outside the
 * protocol: an attitude sensor fixed to the camera, or the carrier's
 * attitude (its INS) combined with the relative angles in the frames, the
 * mounting and the Z-Y-X order of docs/protocol.md §8, a rotation the
 * library does not compute; or a model of a gimbal that states what its
 * GCU would report.
 * @param ax     X-axis angle, deg
 * @param ay     Y-axis angle, deg
 * @param az     Z-axis angle, deg
 * @param roll   receives the roll, deg (may be NULL)
 * @param pitch  receives the pitch, deg (may be NULL)
 * @param yaw    receives the yaw, deg, in [0, 360) (may be NULL)
 */
XF_API void xf_axes_to_euler(float ax, float ay, float az, float *roll, float *pitch, float *yaw);
/**
 * Inverse of xf_axes_to_euler(): from the Euler angles the GCU reports
 * (cam_roll, cam_pitch, cam_yaw, converted with xf_cdeg()) to the camera's
 * absolute axis angles they stand for: X = -pitch, Y = roll, Z = yaw - 90
 * wrapped into [-180, 180).
 * @param roll   roll, deg
 * @param pitch  pitch, deg
 * @param yaw    yaw, deg
 * @param ax     receives the X-axis angle, deg (may be NULL)
 * @param ay     receives the Y-axis angle, deg (may be NULL)
 * @param az     receives the Z-axis angle, deg, in [-180, 180) (may be NULL)
 */
XF_API void xf_euler_to_axes(float roll, float pitch, float yaw, float *ax, float *ay, float *az);

#if XF_EMIT_DEFINITIONS

XF_API int32_t xf_units_round(double v, int32_t lo, int32_t hi)
{
    if (v != v) { /* NaN */
        v = 0.0;
    }
    if (v <= (double)lo) {
        return lo;
    }
    if (v >= (double)hi) {
        return hi;
    }
    return (int32_t)((v >= 0.0) ? (v + 0.5) : (v - 0.5));
}

XF_API double xf_units_wrap360(double deg, double lo)
{
    double r;
    int64_t turns;
    if (deg != deg || deg > 1e12 || deg < -1e12) {
        return lo < 0.0 ? 0.0 : lo; /* NaN or absurd: 0 if it is in range */
    }
    r = deg - lo;
    turns = (int64_t)(r / 360.0);
    r -= (double)turns * 360.0;
    if (r < 0.0) {
        r += 360.0;
    }
    if (r >= 360.0) {
        r -= 360.0;
    }
    return r + lo;
}

XF_API int32_t xf_units_roundf(float v, int32_t lo, int32_t hi)
{
    if (v != v) { /* NaN */
        v = 0.0f;
    }
    if (v <= (float)lo) {
        return lo;
    }
    if (v >= (float)hi) {
        return hi;
    }
    return (int32_t)((v >= 0.0f) ? (v + 0.5f) : (v - 0.5f));
}

XF_API float xf_units_wrap360f(float deg, float lo)
{
    float r;
    int32_t turns;
    if (deg != deg || deg > 1e7f || deg < -1e7f) {
        return lo < 0.0f ? 0.0f : lo; /* NaN or absurd: 0 if it is in range */
    }
    r = deg - lo;
    turns = (int32_t)(r / 360.0f);
    r -= (float)turns * 360.0f;
    if (r < 0.0f) {
        r += 360.0f;
    }
    if (r >= 360.0f) {
        r -= 360.0f;
    }
    return r + lo;
}

XF_API int16_t xf_carrier_roll_raw(float deg)
{
    int32_t v = xf_units_roundf(xf_units_wrap360f(deg, -180.0f) * 100.0f, -18000, 18000);
    return (int16_t)((v == 18000) ? -18000 : v); /* 179.999 rounds up to 180.00 = -180.00 */
}

XF_API int16_t xf_carrier_pitch_raw(float deg) { return (int16_t)xf_units_roundf(deg * 100.0f, -9000, 9000); }

XF_API uint16_t xf_carrier_yaw_raw(float deg)
{
    int32_t v = xf_units_roundf(xf_units_wrap360f(deg, 0.0f) * 100.0f, 0, 36000);
    return (uint16_t)((v == 36000) ? 0 : v);
}

XF_API int16_t xf_accel_raw(float mps2) { return (int16_t)xf_units_roundf(mps2 * 100.0f, -32768, 32767); }
XF_API int16_t xf_velocity_raw(float mps) { return (int16_t)xf_units_roundf(mps * 100.0f, -32768, 32767); }
XF_API int16_t xf_ctrl_angle_raw(float deg) { return (int16_t)xf_units_roundf(deg * 100.0f, -18000, 18000); }

XF_API int16_t xf_ctrl_rate_raw(float dps, float zoom)
{
    float z = (zoom >= 1.0f) ? zoom : 1.0f;
    return (int16_t)xf_units_roundf(dps * 10.0f * z, -1500, 1500);
}

XF_API int32_t xf_deg7_raw(double deg) { return xf_units_round(deg * 1e7, -1800000000, 1800000000); }
XF_API int32_t xf_mm_raw(double m) { return xf_units_round(m * 1000.0, INT32_MIN, INT32_MAX); }
XF_API float xf_cdeg(int32_t raw) { return (float)raw / 100.0f; }

XF_API float xf_gcu_rate_dps(int16_t raw, uint8_t version)
{
    return (float)raw / ((version >= XF_PROTOCOL_V2) ? 10.0f : 100.0f);
}

XF_API int16_t xf_gcu_rate_raw(float dps, uint8_t version)
{
    float scale = (version >= XF_PROTOCOL_V2) ? 10.0f : 100.0f;
    return (int16_t)xf_units_roundf(dps * scale, -32768, 32767);
}

XF_API float xf_zoom_x(uint16_t raw) { return (float)raw / 10.0f; }
XF_API uint16_t xf_zoom_raw(float x) { return (uint16_t)xf_units_roundf(x * 10.0f, 0, 65535); }
XF_API double xf_deg7(int32_t raw) { return (double)raw / 1e7; }

XF_API bool xf_distance_m(int32_t raw, float *m)
{
    if (raw <= 0) {
        return false;
    }
    if (m != NULL) {
        *m = (float)raw / 10.0f;
    }
    return true;
}

XF_API int16_t xf_zoom_to_rate_raw(float rate) { return (int16_t)xf_units_roundf(-rate * 10.0f, -32768, -10); }

XF_API xf_err xf_gnss_to_unix_ms(int16_t week, uint32_t ms, int leap_seconds, int64_t *unix_ms)
{
    if (unix_ms == NULL) {
        return XF_ERR_ARG;
    }
    if (week < 0 || ms >= XF_WEEK_MS) {
        return XF_ERR_RANGE;
    }
    *unix_ms = (XF_GPS_EPOCH_UNIX - (int64_t)leap_seconds) * 1000 + (int64_t)week * (int64_t)XF_WEEK_MS + (int64_t)ms;
    return XF_OK;
}

XF_API xf_err xf_unix_ms_to_gnss(int64_t unix_ms, int leap_seconds, int16_t *week, uint32_t *ms)
{
    int64_t epoch_ms, gps_ms;
    if (week == NULL || ms == NULL) {
        return XF_ERR_ARG;
    }
    epoch_ms = (XF_GPS_EPOCH_UNIX - (int64_t)leap_seconds) * 1000;
    if (unix_ms < epoch_ms) {
        return XF_ERR_RANGE; /* compared before subtracting: no overflow for any input */
    }
    gps_ms = unix_ms - epoch_ms;
    if (gps_ms / (int64_t)XF_WEEK_MS > 32767) {
        return XF_ERR_RANGE;
    }
    *week = (int16_t)(gps_ms / (int64_t)XF_WEEK_MS);
    *ms = (uint32_t)(gps_ms % (int64_t)XF_WEEK_MS);
    return XF_OK;
}

XF_API void xf_axes_to_euler(float ax, float ay, float az, float *roll, float *pitch, float *yaw)
{
    if (roll != NULL)
        *roll = ay;
    if (pitch != NULL)
        *pitch = -ax;
    if (yaw != NULL)
        *yaw = xf_units_wrap360f(az + 90.0f, 0.0f);
}

XF_API void xf_euler_to_axes(float roll, float pitch, float yaw, float *ax, float *ay, float *az)
{
    if (ax != NULL)
        *ax = -pitch;
    if (ay != NULL)
        *ay = roll;
    if (az != NULL)
        *az = xf_units_wrap360f(yaw - 90.0f, -180.0f);
}

#endif /* XF_EMIT_DEFINITIONS */

XF_END_DECLS

#endif /* XF_UNITS_H */
