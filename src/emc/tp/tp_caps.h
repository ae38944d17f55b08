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
} tp_caps_t;

/* Share of the tangential capability a curved piece keeps (the rest goes to curvature). */
#define TP_CAPS_ACC_RESERVE 0.25
#define TP_CAPS_JERK_RESERVE 0.25

/* Caps of a piece with derivative bounds b, wanting speed up to v_need; with_jerk 0 = trapezoid. */
void tp_caps_compute(const tp_bounds_t *b, const tp_axlim_t *lim, double v_need, int with_jerk,
                     tp_caps_t *out);

#endif
