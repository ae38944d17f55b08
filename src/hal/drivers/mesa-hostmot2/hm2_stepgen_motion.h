/* hm2_stepgen_motion.h: the stepgen's per-cycle velocity choice (pure math, unit-tested). */
#ifndef HM2_STEPGEN_MOTION_H
#define HM2_STEPGEN_MOTION_H

/* Intermediate values of a position-mode step, shown on the dbg_* pins. */
typedef struct {
    double ff_vel;          /* commanded velocity from the position change */
    double vel_error;       /* velocity_fb - ff_vel */
    double s_to_match;      /* time until the velocities match, s */
    double err_at_match;    /* position error when they match */
} hm2_stepgen_debug_t;

/* Velocity for this cycle in position mode: match the commanded velocity and
   position within maxaccel (0 = unlimited). period_s > 0. */
double hm2_stepgen_position_velocity(double position_cmd, double old_position_cmd,
                                     double position_fb, double velocity_fb,
                                     double maxaccel, double period_s,
                                     hm2_stepgen_debug_t *dbg);
/* Velocity for this cycle in velocity mode: velocity_cmd, slewed by maxaccel (0 = unlimited). */
double hm2_stepgen_velocity_velocity(double velocity_cmd, double velocity_fb,
                                     double maxaccel, double period_s);
/* DDS rate register for a velocity: (uint32)(int32)(v * scale * 2^32 / clock). */
unsigned hm2_stepgen_rate_register(double velocity, double position_scale, double clock_hz);

#endif
