/* canon_limits.c: path velocity/acceleration/jerk limits from per-axis limits (pure math, no HAL). */
#include <math.h>
#include <stddef.h>
#include "canon_limits.h"

#define TINY 1e-12

/* sqrt of the sum of squares of delta[from..from+2]. */
static double group_length(const double *delta, int from)
{
    return sqrt(delta[from] * delta[from] + delta[from + 1] * delta[from + 1] +
                delta[from + 2] * delta[from + 2]);
}

/* Lower *value to limit * length / share when the axis moves (share > 0). */
static void clamp_share(double *value, double limit, double length, double share)
{
    if (share <= TINY || length <= TINY) return;
    double v = limit * length / share;
    if (v < *value) *value = v;
}

/* Jerk: 0 (none) wins as soon as a moving axis has no jerk limit configured. */
static void clamp_jerk(double *value, int *unlimited, double limit, double length, double share)
{
    if (share <= TINY || length <= TINY) return;
    if (limit <= 0) { *unlimited = 1; return; }
    clamp_share(value, limit, length, share);
}

/* Smallest limit of all axes: what a zero-length move may use. */
static void smallest(const canon_axis_limits_t *lim, canon_path_limits_t *out)
{
    out->vel = out->acc = CANON_LIMIT_NONE;
    out->jerk = 0;
    for (int i = 0; i < CANON_AXES; i++) {
        if (lim->vel[i] < out->vel) out->vel = lim->vel[i];
        if (lim->acc[i] < out->acc) out->acc = lim->acc[i];
    }
}

/* Apply every axis's share; skip[] marks axes handled by the caller. */
static void apply_axes(const double delta[CANON_AXES], const int skip[CANON_AXES],
                       const canon_axis_limits_t *lim, canon_path_limits_t *out, int *no_jerk)
{
    for (int i = 0; i < CANON_AXES; i++) {
        if (skip && skip[i]) continue;
        double share = fabs(delta[i]);
        clamp_share(&out->vel, lim->vel[i], out->length, share);
        clamp_share(&out->acc, lim->acc[i], out->length, share);
        clamp_jerk(&out->jerk, no_jerk, lim->jerk[i], out->length, share);
    }
}

void canon_line_limits(const double delta[CANON_AXES], const canon_axis_limits_t *lim,
                       canon_path_limits_t *out)
{
    double len = group_length(delta, 0);
    if (len <= TINY) len = group_length(delta, 3);
    if (len <= TINY) len = group_length(delta, 6);
    out->length = len;
    if (len <= TINY) {
        smallest(lim, out);
        return;
    }
    out->vel = out->acc = out->jerk = CANON_LIMIT_NONE;
    int no_jerk = 0;
    apply_axes(delta, NULL, lim, out, &no_jerk);
    if (no_jerk || out->jerk >= CANON_LIMIT_NONE) out->jerk = 0;
}

void canon_arc_limits(int p1, int p2, double arc_len, const double delta[CANON_AXES],
                      const canon_axis_limits_t *lim, canon_path_limits_t *out)
{
    int skip[CANON_AXES] = {0};
    skip[p1] = skip[p2] = 1;
    double other = 0;
    for (int i = 0; i < CANON_AXES; i++)
        if (!skip[i] && i < 3) other += delta[i] * delta[i];
    out->length = sqrt(arc_len * arc_len + other);
    if (out->length <= TINY) {
        smallest(lim, out);
        return;
    }
    out->vel = out->acc = out->jerk = CANON_LIMIT_NONE;
    int no_jerk = 0;
    double plane_vel = fmin(lim->vel[p1], lim->vel[p2]);
    double plane_acc = fmin(lim->acc[p1], lim->acc[p2]);
    double plane_jerk = fmin(lim->jerk[p1], lim->jerk[p2]);
    clamp_share(&out->vel, plane_vel, out->length, fabs(arc_len));
    clamp_share(&out->acc, plane_acc, out->length, fabs(arc_len));
    clamp_jerk(&out->jerk, &no_jerk, plane_jerk, out->length, fabs(arc_len));
    apply_axes(delta, skip, lim, out, &no_jerk);
    if (no_jerk || out->jerk >= CANON_LIMIT_NONE) out->jerk = 0;
}
