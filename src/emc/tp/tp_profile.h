/* tp_profile.h: one-dimensional speed profiles along the path (trapezoid and jerk-limited S-curve). */
#ifndef TP_PROFILE_H
#define TP_PROFILE_H

/* Tangential limits for one profile; jerk 0 means unlimited (trapezoid: acceleration may jump). */
typedef struct tp_lim1 {
    double acc;                 /* units/s^2, > 0 */
    double jerk;                /* units/s^3, 0 = trapezoid */
} tp_lim1_t;

/* One phase: constant jerk j for dur seconds, acceleration a at its start. */
typedef struct tp_phase {
    double dur;
    double a;
    double j;
} tp_phase_t;

#define TP_PROF_PHASES 3

/* A speed change from (v0, a) to (v_end, 0), then cruise at v_end for ever. */
typedef struct tp_prof {
    double v0;
    double v_end;
    int n;
    tp_phase_t ph[TP_PROF_PHASES];
} tp_prof_t;

/* Motion state along the path: distance travelled, speed, acceleration. */
typedef struct tp_state1 {
    double s;
    double v;
    double a;
} tp_state1_t;

/* Build the fastest profile from speed v0 and acceleration a0 to speed vt with zero acceleration. */
void tp_prof_velocity(tp_prof_t *p, double v0, double a0, double vt, const tp_lim1_t *lim);
/* State after t seconds (distance from the profile start). */
tp_state1_t tp_prof_at(const tp_prof_t *p, double t);
/* Seconds until the profile reaches its end speed. */
double tp_prof_duration(const tp_prof_t *p);
/* Distance covered until the profile reaches its end speed. */
double tp_prof_length(const tp_prof_t *p);
/* Earliest time the profile has covered distance d (d above its reach at cruise 0: INFINITY). */
double tp_prof_time_at(const tp_prof_t *p, double d);
/* Distance needed from (v, a) until the speed is at most vt with zero acceleration; 0 if no braking is needed. */
double tp_brake_dist(double v, double a, double vt, const tp_lim1_t *lim);
/* Largest speed at rest acceleration from which a profile reaches vt within distance d. */
double tp_chain_vmax(double vt, double d, const tp_lim1_t *lim);
/* Speed d before a point reached at vt by the latest full-effort brake (the braking curve, any acceleration). */
double tp_brake_curve(double vt, double d, const tp_lim1_t *lim);
/* Distance of a full stop from (v, a). */
double tp_stop_dist(double v, double a, const tp_lim1_t *lim);
/* Real root of x^3 + p x + q = 0 for p >= 0 (a monotone cubic). */
double tp_cubic_root(double p, double q);

#endif
