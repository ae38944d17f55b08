/* hm2_encoder_math.c: encoder register values and the timestamp velocity estimator (pure, unit-tested). */
#include <math.h>
#include "hm2_encoder.h"

#define FILTER_RATE_FULL_SPEED 0xFFFu
#define FILTER_RATE_MAX 0xFFEu
#define SKEW_MAX 15u

/* clock/2e6 - 2 (or clock/1e7 - 2), so timestamps tick at about 2 MHz (10 MHz). */
uint32_t hm2_encoder_timestamp_divider(uint32_t clock_hz, bool hires)
{
    double d = clock_hz / (hires ? 1e7 : 2e6) - 2.0;
    return d < 0 ? 0 : (uint32_t)d;
}

/* rate = clock/f - 2 (1 means full speed, 0xFFF); the achieved frequency is clock/(rate+2). */
uint32_t hm2_encoder_filter_rate(uint32_t clock_hz, uint32_t sample_hz, uint32_t *achieved)
{
    if (sample_hz == 0)
        sample_hz = 1;
    long rate = (long)(clock_hz / sample_hz) - 2;
    if (rate == 1 || rate < 0) {
        *achieved = clock_hz;
        return FILTER_RATE_FULL_SPEED;
    }
    if (rate > (long)FILTER_RATE_MAX)
        rate = FILTER_RATE_MAX;
    *achieved = clock_hz / (uint32_t)(rate + 2);
    return (uint32_t)rate;
}

/* Skew in clock periods, rounded, at most 15. */
uint32_t hm2_encoder_skew_bits(uint32_t clock_hz, uint32_t skew_ns)
{
    double periods = skew_ns * (clock_hz / 1e9) + 0.5;
    return periods > SKEW_MAX ? SKEW_MAX : (uint32_t)periods;
}

/* An event stamped after the counter's current value happened before its last rollover. */
int64_t hm2_encoder_event_ticks(uint32_t epoch, uint16_t tsc, uint16_t ts)
{
    int64_t e = ts <= tsc ? (int64_t)epoch : (int64_t)epoch - 1;
    return e * 65536 + ts;
}

/* Velocity from the time between counting events; decays towards zero without new counts. */
double hm2_encoder_velocity(hm2_encoder_vel_t *v, double velocity, int64_t count64, bool new_counts,
                            int64_t event_ticks, int64_t now_ticks, double seconds_per_tick,
                            double scale, double vel_timeout, double *interp_offset)
{
    *interp_offset = 0.0;
    if (new_counts) {
        int64_t dcounts = count64 - v->prev_event_count;
        int dir = dcounts > 0 ? 1 : -1;
        if (v->state == HM2_ENCODER_STOPPED) {
            velocity = 0.0;
            v->state = HM2_ENCODER_MOVING;
        } else if ((dcounts == 1 || dcounts == -1) && dir != v->prev_dir) {
            velocity = 0.0;
        } else {
            double dt = (event_ticks - v->prev_event_ticks) * seconds_per_tick;
            if (dt > 0)
                velocity = (dcounts / scale) / dt;
        }
        v->prev_dir = dir;
        v->prev_event_count = count64;
        v->prev_event_ticks = event_ticks;
        return velocity;
    }
    if (v->state != HM2_ENCODER_MOVING)
        return 0.0;
    double dt = (now_ticks - v->prev_event_ticks) * seconds_per_tick;
    if (dt >= vel_timeout) {
        v->state = HM2_ENCODER_STOPPED;
        return 0.0;
    }
    if (dt > 0) {
        double vmax = fabs(1.0 / scale) / dt;
        if (velocity > vmax)
            velocity = vmax;
        else if (velocity < -vmax)
            velocity = -vmax;
        *interp_offset = dt * velocity;
    }
    return velocity;
}
