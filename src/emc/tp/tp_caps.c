/* tp_caps.c: caps of a piece: per axis |d1| a + |d2| v^2 <= A and |d1| j + 3 |d2| v a + |d3| v^3 <= J. */
#include <math.h>
#include "tp_caps.h"
#include "tp_profile.h"

/* Derivative bounds below this count as zero. */
#define TP_CAPS_TINY 1e-12
/* Lowest cap, as a share of the highest (a cap is never zero). */
#define TP_CAPS_V_FLOOR 1e-12
/* Closed-form speeds are taken this much low, so that rounding never puts them past the limit. */
#define TP_CAPS_ROOT_MARGIN (1.0 - 1e-9)
/* Weight of the speed-change time in the choice of the reserve; with the jerk limited much less:
 * the acceleration a curved piece keeps also takes jerk (3 |d2| v a), so keeping less pays more
 * (0.005 is the best of the bench's programs; 0.1 and 0.02 cost 4 % and 0.4 % of its time). */
#define TP_CAPS_CHANGE_SHARE 0.1
#define TP_CAPS_CHANGE_SHARE_JERK 0.005
/* Bisection steps for the top speed of a rest-to-rest crossing. */
#define TP_CAPS_REST_ITER 40
/* Bisection steps for the speed of a sinusoidal axis's jerk limit. */
#define TP_CAPS_PHASE_ITER 50

/* Largest x with k x <= limit over the limited axes that move (INFINITY if none). */
static double ratio_min(const double *lim, const double *k)
{
    double m = INFINITY;
    for (int i = 0; i < TP_NBOUND; i++)
        if (lim[i] > 0.0 && k[i] > TP_CAPS_TINY)
            m = fmin(m, lim[i] / k[i]);
    return m;
}

/* What a limit leaves for the part in phase with the first derivative when the part a quarter
 * period apart takes quad: their hypot (phase) or their sum must stay within total; negative when
 * quad alone exceeds it. */
static double room(double total, double quad, int phase)
{
    if (!phase)
        return total - quad;
    return quad > total ? -1.0 : sqrt((total - quad) * (total + quad));
}

/* Tangential acceleration left at speed v by the curvature terms. */
static double acc_left(const tp_bounds_t *b, const tp_axlim_t *l, double v)
{
    double m = INFINITY;
    for (int i = 0; i < TP_NBOUND; i++) {
        if (!(l->acc[i] > 0.0))
            continue;
        double rest = room(l->acc[i], b->d2[i] * v * v, b->phase[i]);
        if (rest < 0.0)
            return -1.0;
        if (b->d1[i] > TP_CAPS_TINY)
            m = fmin(m, rest / b->d1[i]);
    }
    return m;
}

/* Tangential jerk left at speed v and tangential acceleration a. */
static double jerk_left(const tp_bounds_t *b, const tp_axlim_t *l, double v, double a)
{
    double m = INFINITY;
    for (int i = 0; i < TP_NBOUND; i++) {
        if (!(l->jerk[i] > 0.0))
            continue;
        double rest = room(l->jerk[i], 3.0 * b->d2[i] * v * a, b->phase[i]);
        rest = rest < 0.0 ? rest : rest - b->d3[i] * v * v * v;
        if (rest < 0.0)
            return -1.0;
        if (b->d1[i] > TP_CAPS_TINY)
            m = fmin(m, rest / b->d1[i]);
    }
    return m;
}

/* Largest tangential acceleration at speed v that still leaves j_keep of tangential jerk. */
static double acc_for_jerk(const tp_bounds_t *b, const tp_axlim_t *l, double v, double j_keep)
{
    double m = INFINITY;
    for (int i = 0; i < TP_NBOUND; i++) {
        if (!(l->jerk[i] > 0.0))
            continue;
        double rest = room(l->jerk[i], b->d3[i] * v * v * v + j_keep * b->d1[i], b->phase[i]);
        if (rest < 0.0)
            return -1.0;
        double k = 3.0 * b->d2[i] * v;
        if (k > TP_CAPS_TINY)
            m = fmin(m, rest / k);
    }
    return m;
}

/* Usable tangential acceleration at speed v (negative when v is not feasible). */
static double usable_acc(const tp_bounds_t *b, const tp_axlim_t *l, double v, int with_jerk,
                         double j_keep)
{
    double a = acc_left(b, l, v);
    if (with_jerk && a >= 0.0)
        a = fmin(a, acc_for_jerk(b, l, v, j_keep));
    return a;
}

/* Caps at speed v: what is left of the limits there, at least reserve share r of the line's. */
static void caps_at_speed(const tp_bounds_t *b, const tp_axlim_t *l, double v, int with_jerk, double r,
                          tp_caps_t *out)
{
    double a_line = ratio_min(l->acc, b->d1);
    double j_line = with_jerk ? ratio_min(l->jerk, b->d1) : 0.0;
    double a_keep = r * a_line, j_keep = with_jerk ? TP_CAPS_JERK_RESERVE * j_line : 0.0;
    out->v = v;
    out->a = fmin(usable_acc(b, l, v, with_jerk, j_keep), a_line);
    if (!(out->a > 0.0))
        out->a = a_keep > 0.0 ? a_keep : 1e-9;
    out->j = with_jerk ? fmin(jerk_left(b, l, v, out->a), j_line) : 0.0;
    if (with_jerk && !(out->j > 0.0))
        out->j = j_keep > 0.0 ? j_keep : 1e-9;
    /* trapezoid: min over axes of (A - |d2| w^2) / |d1| is concave in w^2, so above its chord */
    out->a_rest = with_jerk || !(a_line > out->a) ? out->a : a_line;
}

/* Highest speed v at which hypot(d3 v^3 + d1 j_keep, 3 d2 v a_keep) stays within axis i's jerk
 * limit (increasing in v): bisection from the root of the sum, which lies below it, to the speed the
 * in-phase part alone allows. */
static double phase_jerk_root(const tp_bounds_t *b, const tp_axlim_t *l, int i, double a_keep,
                              double j_keep, double lo)
{
    double J = l->jerk[i], in0 = b->d1[i] * j_keep, c = 3.0 * b->d2[i] * a_keep;
    double hi = cbrt(fmax(J - in0, 0.0) / b->d3[i]);
    if (!(hi > lo))
        return lo;
    for (int k = 0; k < TP_CAPS_PHASE_ITER; k++) {
        double mid = 0.5 * (lo + hi);
        if (hypot(b->d3[i] * mid * mid * mid + in0, c * mid) <= J)
            lo = mid;
        else
            hi = mid;
    }
    return lo;
}

/* Highest speed at which every axis leaves a_keep of tangential acceleration and j_keep of
 * tangential jerk: per axis d2 v^2 <= A - a_keep d1 and d3 v^3 + 3 d2 a_keep v <= J - j_keep d1,
 * both increasing in v, so each has one root in closed form; -1 when even rest is too fast. */
static double speed_keeping(const tp_bounds_t *b, const tp_axlim_t *l, int with_jerk, double a_keep,
                            double j_keep)
{
    double v = INFINITY;
    for (int i = 0; i < TP_NBOUND; i++) {
        if (l->acc[i] > 0.0) {
            double rest = room(l->acc[i], b->d1[i] > TP_CAPS_TINY ? a_keep * b->d1[i] : 0.0, b->phase[i]);
            if (rest < 0.0)
                return -1.0;
            if (b->d2[i] > 0.0)
                v = fmin(v, sqrt(rest / b->d2[i]));
        }
        if (!with_jerk || !(l->jerk[i] > 0.0))
            continue;
        double rest = l->jerk[i] - j_keep * b->d1[i];
        double c = 3.0 * b->d2[i] * a_keep;
        if (rest < 0.0)
            return -1.0;
        if (b->d3[i] > 0.0) {
            double root = tp_cubic_root(c / b->d3[i], -rest / b->d3[i]);
            v = fmin(v, b->phase[i] ? phase_jerk_root(b, l, i, a_keep, j_keep, root) : root);
        } else if (c > 0.0) {
            v = fmin(v, b->phase[i] ? sqrt((l->jerk[i] - j_keep * b->d1[i]) * (l->jerk[i] + j_keep * b->d1[i])) / c
                                    : rest / c);
        }
    }
    return v;
}

/* Caps keeping reserve share r of the straight-line acceleration and jerk for speed changes. */
static void caps_with_reserve(const tp_bounds_t *b, const tp_axlim_t *l, double v_need, int with_jerk,
                              double r, tp_caps_t *out)
{
    double a_line = ratio_min(l->acc, b->d1);
    double j_line = with_jerk ? ratio_min(l->jerk, b->d1) : 0.0;
    double a_keep = r * a_line;
    double j_keep = with_jerk ? TP_CAPS_JERK_RESERVE * j_line : 0.0;
    double v_hi = fmin(ratio_min(l->vel, b->d1), v_need);
    if (!isfinite(v_hi))
        v_hi = 1e9;
    double v = v_hi;
    if (!with_jerk) {
        /* closed form: |d1| a_keep + |d2| v^2 <= A on every axis */
        for (int i = 0; i < TP_NBOUND; i++)
            if (l->acc[i] > 0.0 && b->d2[i] > TP_CAPS_TINY)
                v = fmin(v, sqrt(fmax(0.0, room(l->acc[i], a_keep * b->d1[i], b->phase[i])) / b->d2[i]));
    } else if (usable_acc(b, l, v_hi, with_jerk, j_keep) < a_keep) {
        /* a cap is never zero: a region that may not be crossed would stall the executor */
        double root = speed_keeping(b, l, with_jerk, a_keep, j_keep) * TP_CAPS_ROOT_MARGIN;
        v = fmin(v_hi, fmax(root, v_hi * TP_CAPS_V_FLOOR));
    }
    caps_at_speed(b, l, v, with_jerk, r, out);
}

/* Caps keeping exactly reserve share r (the caller knows where the speed changes happen). */
void tp_caps_with_reserve(const tp_bounds_t *b, const tp_axlim_t *l, double v_need, int with_jerk,
                          double r, tp_caps_t *out)
{
    caps_with_reserve(b, l, v_need, with_jerk, r, out);
}

/* Rough time a piece of length len costs with caps c: crossing it at the cap plus a share of the
 * time to change speed by the cap inside it. */
static double caps_cost(const tp_caps_t *c, double len)
{
    if (!(c->v > 0.0))
        return INFINITY;
    return len / c->v + (c->j > 0.0 ? TP_CAPS_CHANGE_SHARE_JERK : TP_CAPS_CHANGE_SHARE) * c->v / c->a;
}

/* Time to speed up from rest to v with acceleration a and jerk j (0 = none), and the distance. */
static double rise_time(double v, double a, double j, double *dist)
{
    double t = v / a;
    if (j > 0.0)
        t = v * j >= a * a ? v / a + a / j : 2.0 * sqrt(v / j);
    *dist = 0.5 * v * t;                /* the profile is point-symmetric about its middle */
    return t;
}

/* Time to cross a piece of length len with caps c from rest (ends 1) or from rest to rest (ends 2):
 * up to the cap (and down again), or, when too short for that, to the highest speed it leaves room
 * for (bisection). */
double tp_caps_rest_time(const tp_caps_t *c, double len, int ends)
{
    double d, t = rise_time(c->v, c->a, c->j, &d);
    if (ends * d <= len)
        return ends * t + (len - ends * d) / c->v;
    double lo = 0.0, hi = c->v;
    for (int k = 0; k < TP_CAPS_REST_ITER; k++) {
        double mid = 0.5 * (lo + hi);
        rise_time(mid, c->a, c->j, &d);
        if (ends * d <= len)
            lo = mid;
        else
            hi = mid;
    }
    return ends * rise_time(lo, c->a, c->j, &d);
}

/* Estimated time of a piece with caps c: from or to rest when rest_ends of its ends are stops, else
 * the rough crossing time. */
static double piece_cost(const tp_caps_t *c, double len, int rest_ends)
{
    if (!(c->v > 0.0) || !(c->a > 0.0))
        return INFINITY;
    return rest_ends > 0 ? tp_caps_rest_time(c, len, rest_ends) : caps_cost(c, len);
}

/* Compute the caps.  A sharply curved piece spends most of the limits on its curvature: keeping a
 * smaller share for speed changes raises its speed, which pays on short pieces (the speed then
 * changes mostly outside them); the share with the least estimated time wins.  A piece that starts
 * or ends at rest (rest_ends of its ends) changes its speed inside: its time is estimated as such. */
void tp_caps_compute(const tp_bounds_t *b, const tp_axlim_t *l, double v_need, int with_jerk,
                     double len, int rest_ends, tp_caps_t *out)
{
    static const double reserve[] = {TP_CAPS_RESERVE, TP_CAPS_RESERVE / 4.0, TP_CAPS_RESERVE / 16.0};
    caps_with_reserve(b, l, v_need, with_jerk, reserve[0], out);
    if (out->v >= fmin(ratio_min(l->vel, b->d1), v_need))
        return;                         /* not held back by the curvature: nothing to gain */
    double best = piece_cost(out, len, rest_ends);
    for (int k = 1; k < (int)(sizeof(reserve) / sizeof(reserve[0])); k++) {
        tp_caps_t c;
        caps_with_reserve(b, l, v_need, with_jerk, reserve[k], &c);
        double cost = piece_cost(&c, len, rest_ends);
        if (!(c.v > out->v) || !(cost < best))
            break;
        *out = c;
        best = cost;
    }
}
