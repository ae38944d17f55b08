/* tp_profile.c: closed-form speed profiles: velocity changes, braking distances and braking curves. */
#include <math.h>
#include "tp_profile.h"

/* Relative slack used when comparing speeds that came out of the same formulas. */
#define TP_PROF_EPS 1e-12
/* A speed this far (relative) above a cap is rounding, not an overshoot. */
#define TP_SPEED_EPS 1e-10

/* Real root of x^3 + p x + q = 0 for p >= 0: Cardano, polished by Newton steps. */
double tp_cubic_root(double p, double q)
{
    double x;
    if (p <= 0.0) {
        x = cbrt(-q);
    } else {
        double disc = q * q / 4.0 + p * p * p / 27.0;
        double u = cbrt(-q / 2.0 + sqrt(disc));
        x = (u != 0.0) ? u - p / (3.0 * u) : 0.0;
    }
    for (int k = 0; k < 3; k++) {
        double f = x * x * x + p * x + q;
        double df = 3.0 * x * x + p;
        if (df <= 0.0)
            break;
        x -= f / df;
    }
    return x;
}

/* Append a phase when it lasts a positive time. */
static void prof_push(tp_prof_t *p, double dur, double a, double j)
{
    if (dur > 0.0 && p->n < TP_PROF_PHASES) {
        p->ph[p->n].dur = dur;
        p->ph[p->n].a = a;
        p->ph[p->n].j = j;
        p->n++;
    }
}

/* Speed at the end of the phases, integrated from v0. */
static double prof_end_speed(const tp_prof_t *p)
{
    double v = p->v0;
    for (int k = 0; k < p->n; k++) {
        const tp_phase_t *ph = &p->ph[k];
        v += ph->a * ph->dur + 0.5 * ph->j * ph->dur * ph->dur;
    }
    return v;
}

/* Jerk-limited change from (v0, a0) to vt: ramp to a peak acceleration, hold, ramp to zero. */
static void prof_scurve(tp_prof_t *p, double v0, double a0, double vt, double A, double J)
{
    double v_rest = v0 + a0 * fabs(a0) / (2.0 * J);
    if (fabs(v_rest - vt) <= TP_PROF_EPS * (1.0 + fabs(vt))) {
        prof_push(p, fabs(a0) / J, a0, a0 > 0.0 ? -J : J);
        return;
    }
    double dir = vt > v_rest ? 1.0 : -1.0;
    double a = dir * a0;            /* mirrored so that the profile accelerates */
    double dv = dir * (vt - v0);
    double ap = A, t2 = 0.0;
    double t1 = fabs(A - a) / J;
    double gain = 0.5 * (a + A) * t1 + A * A / (2.0 * J);
    if (dv >= gain) {
        t2 = (dv - gain) / A;
    } else {
        double sq = 0.5 * (2.0 * J * dv + a * a);
        ap = sq > 0.0 ? sqrt(sq) : 0.0;
        if (ap < a)
            ap = a;
        t1 = (ap - a) / J;
    }
    prof_push(p, t1, dir * a, dir * (ap >= a ? J : -J));
    prof_push(p, t2, dir * ap, 0.0);
    prof_push(p, ap / J, dir * ap, -dir * J);
}

/* Build the fastest profile from (v0, a0) to (vt, 0) within lim. */
void tp_prof_velocity(tp_prof_t *p, double v0, double a0, double vt, const tp_lim1_t *lim)
{
    p->v0 = v0;
    p->n = 0;
    if (lim->jerk <= 0.0) {
        if (vt > v0)
            prof_push(p, (vt - v0) / lim->acc, lim->acc, 0.0);
        else if (vt < v0)
            prof_push(p, (v0 - vt) / lim->acc, -lim->acc, 0.0);
        p->v_end = vt;
        return;
    }
    prof_scurve(p, v0, a0, vt, lim->acc, lim->jerk);
    p->v_end = p->n ? prof_end_speed(p) : v0;
}

/* State after t seconds: exact integration of the constant-jerk phases, then cruise. */
tp_state1_t tp_prof_at(const tp_prof_t *p, double t)
{
    tp_state1_t st = {0.0, p->v0, 0.0};
    for (int k = 0; k < p->n; k++) {
        const tp_phase_t *ph = &p->ph[k];
        double d = t < ph->dur ? t : ph->dur;
        if (d < 0.0)
            d = 0.0;
        st.s += st.v * d + 0.5 * ph->a * d * d + ph->j * d * d * d / 6.0;
        if (t < ph->dur) {
            st.v += ph->a * d + 0.5 * ph->j * d * d;
            st.a = ph->a + ph->j * d;
            return st;
        }
        st.v += ph->a * ph->dur + 0.5 * ph->j * ph->dur * ph->dur;
        t -= ph->dur;
    }
    st.v = p->v_end;
    st.s += st.v * t;
    st.a = 0.0;
    return st;
}

/* Seconds of the phases. */
double tp_prof_duration(const tp_prof_t *p)
{
    double t = 0.0;
    for (int k = 0; k < p->n; k++)
        t += p->ph[k].dur;
    return t;
}

/* Distance of the phases. */
double tp_prof_length(const tp_prof_t *p)
{
    return tp_prof_at(p, tp_prof_duration(p)).s;
}

/* Time within one phase at which distance d (from the phase start) is covered: safeguarded Newton. */
static double phase_time_at(double v, const tp_phase_t *ph, double d)
{
    double lo = 0.0, hi = ph->dur, t = 0.5 * (lo + hi);
    for (int k = 0; k < 60; k++) {
        double f = v * t + 0.5 * ph->a * t * t + ph->j * t * t * t / 6.0 - d;
        double df = v + ph->a * t + 0.5 * ph->j * t * t;
        if (f > 0.0)
            hi = t;
        else
            lo = t;
        double tn = df > 0.0 ? t - f / df : 0.5 * (lo + hi);
        if (!(tn > lo && tn < hi))
            tn = 0.5 * (lo + hi);
        if (fabs(tn - t) <= 1e-15 * (1.0 + t))
            return tn;
        t = tn;
    }
    return t;
}

/* Earliest time at which distance d is covered. */
double tp_prof_time_at(const tp_prof_t *p, double d)
{
    double s = 0.0, v = p->v0, t = 0.0;
    if (d <= 0.0)
        return 0.0;
    for (int k = 0; k < p->n; k++) {
        const tp_phase_t *ph = &p->ph[k];
        double ds = v * ph->dur + 0.5 * ph->a * ph->dur * ph->dur + ph->j * ph->dur * ph->dur * ph->dur / 6.0;
        if (s + ds >= d)
            return t + phase_time_at(v, ph, d - s);
        s += ds;
        v += ph->a * ph->dur + 0.5 * ph->j * ph->dur * ph->dur;
        t += ph->dur;
    }
    if (p->v_end <= 0.0)
        return INFINITY;
    return t + (d - s) / p->v_end;
}

/* Distance until the speed is at most vt with the acceleration settled (0 if already so). */
double tp_brake_dist(double v, double a, double vt, const tp_lim1_t *lim)
{
    if (lim->jerk <= 0.0)
        return v > vt ? (v * v - vt * vt) / (2.0 * lim->acc) : 0.0;
    double J = lim->jerk;
    double v_rest = v + a * fabs(a) / (2.0 * J);
    if (v <= vt && v_rest <= vt * (1.0 + TP_SPEED_EPS) + TP_SPEED_EPS)
        return 0.0;                     /* never above vt (to rounding) */
    if (v > vt && a < 0.0 && v_rest < vt) {
        /* the speed falls through vt while the acceleration ramps back: first crossing */
        double disc = a * a - 2.0 * J * (v - vt);
        double t = (-a - sqrt(disc > 0.0 ? disc : 0.0)) / J;
        return v * t + 0.5 * a * t * t + J * t * t * t / 6.0;
    }
    tp_prof_t p;
    tp_prof_velocity(&p, v, a, vt, lim);
    return tp_prof_length(&p);
}

/* Distance of a full stop from (v, a). */
double tp_stop_dist(double v, double a, const tp_lim1_t *lim)
{
    return tp_brake_dist(v, a, 0.0, lim);
}

/* Largest v such that the profile (v, 0) -> (vt, 0) is at most d long. */
double tp_chain_vmax(double vt, double d, const tp_lim1_t *lim)
{
    double A = lim->acc, J = lim->jerk;
    if (d <= 0.0)
        return vt;
    if (J <= 0.0)
        return sqrt(vt * vt + 2.0 * A * d);
    double c = A * A / J;
    double d_full = (2.0 * vt + c) * A / J;
    if (d >= d_full) {
        double disc = c * c + 4.0 * (vt * vt - vt * c + 2.0 * A * d);
        return 0.5 * (-c + sqrt(disc));
    }
    double x = tp_cubic_root(2.0 * vt / J, -d / J);
    if (x < 0.0)
        x = 0.0;
    return vt + J * x * x;
}

/* Speed d before the arrival point on the latest full-effort brake that arrives at (vt, 0). */
double tp_brake_curve(double vt, double d, const tp_lim1_t *lim)
{
    double A = lim->acc, J = lim->jerk;
    if (d <= 0.0)
        return vt;
    if (J <= 0.0)
        return sqrt(vt * vt + 2.0 * A * d);
    double tr = A / J;
    double d_ramp = vt * tr + J * tr * tr * tr / 6.0;
    if (d <= d_ramp) {
        double tau = tp_cubic_root(6.0 * vt / J, -6.0 * d / J);
        return vt + 0.5 * J * tau * tau;
    }
    double v_ramp = vt + 0.5 * A * tr;
    return sqrt(v_ramp * v_ramp + 2.0 * A * (d - d_ramp));
}
