/* tp_caps.h: speed, tangential acceleration and jerk caps of a piece of path from per-axis limits. */
#ifndef TP_CAPS_H
#define TP_CAPS_H

#include "tp_geom.h"

/* Per-axis limits plus the path pseudo-axis (TP_PATH_AX); 0 = no limit. */
typedef struct tp_axlim {
    double vel[TP_NBOUND];
    double acc[TP_NBOUND];
    double jerk[TP_NBOUND];
} tp_axlim_t;

/* What a piece allows: speed cap and the tangential acceleration and jerk usable at or below it. */
typedef struct tp_caps {
    double v;
    double a;
    double j;                   /* 0 when jerk is not limited */
    double a_rest;              /* tangential acceleration usable at rest (trapezoid: the usable
                                 * acceleration at speed w is at least the chord from a_rest at 0
                                 * to a at v, in w^2; S-curve: a) */
} tp_caps_t;

/* Share of the straight-line acceleration and jerk a curved piece keeps for speed changes (the
 * rest goes to curvature); a quarter or a sixteenth of it when that makes a short piece faster. */
#define TP_CAPS_RESERVE 0.25
/* Share of the straight-line jerk a curved piece keeps for speed changes: its speed changes take
 * longer the less it keeps, its cap drops the more it keeps (0.35 is the best of the bench's
 * programs at 0.05 steps). */
#define TP_CAPS_JERK_RESERVE 0.35

/* Share a parabolic corner blend keeps when the straight moves on both sides have room for the
 * speed changes around it (trapezoid planning): it then runs at one parameter speed while the
 * lines brake and speed up, and the acceleration it does not keep turns it faster. */
#define TP_CAPS_RESERVE_CORNER 0.02

/* Caps of a piece of length len with derivative bounds b, wanting speed up to v_need;
 * with_jerk 0 = trapezoid; rest_ends: how many of its ends (0..2) are stops. */
void tp_caps_compute(const tp_bounds_t *b, const tp_axlim_t *lim, double v_need, int with_jerk,
                     double len, int rest_ends, tp_caps_t *out);
/* Caps keeping exactly reserve share r of the straight-line acceleration (no choice of share). */
void tp_caps_with_reserve(const tp_bounds_t *b, const tp_axlim_t *lim, double v_need, int with_jerk,
                          double r, tp_caps_t *out);
/* Time to cross len within caps c (speed, acceleration, jerk 0 = none) from rest (ends 1) or from
 * rest to rest (ends 2). */
double tp_caps_rest_time(const tp_caps_t *c, double len, int ends);

#endif
