/* tp_math.c: unit tests of the planner's pure math: speed profiles, braking curves, caps and blends. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>
#include "tp_blend.h"
#include "tp_caps.h"
#include "tp_geom.h"
#include "tp_profile.h"

static int failures;

#define CHECK(cond, ...)                                                                         \
    do {                                                                                         \
        if (!(cond)) {                                                                           \
            failures++;                                                                          \
            if (failures < 20) {                                                                 \
                printf("FAIL %s:%d: ", __func__, __LINE__);                                      \
                printf(__VA_ARGS__);                                                             \
                printf("\n");                                                                    \
            }                                                                                    \
        }                                                                                        \
    } while (0)

static uint64_t rng = 0x9e3779b97f4a7c15ull;
static double urand(void)
{
    rng ^= rng >> 12;
    rng ^= rng << 25;
    rng ^= rng >> 27;
    return (double)((rng * 2685821657736338717ull) >> 11) / 9007199254740992.0;
}

/* Sample a profile finely: speed, acceleration and jerk stay in the limits, the end state is right. */
static void profile_random(int n)
{
    int bad = 0;
    for (int k = 0; k < n; k++) {
        tp_lim1_t lim = {100.0 + 9900.0 * urand(), urand() < 0.2 ? 0.0 : 1e3 + 1e6 * urand()};
        double v0 = 200.0 * urand(), vt = 200.0 * urand();
        double a0 = lim.jerk > 0.0 ? lim.acc * (2.0 * urand() - 1.0) : 0.0;
        if (lim.jerk > 0.0 && v0 + a0 * fabs(a0) / (2.0 * lim.jerk) < 0.0)
            a0 = 0.0;
        tp_prof_t p;
        tp_prof_velocity(&p, v0, a0, vt, &lim);
        double dur = tp_prof_duration(&p), prev_a = a0;
        for (int i = 1; i <= 200; i++) {
            double t = dur * i / 200.0;
            tp_state1_t st = tp_prof_at(&p, t);
            if (fabs(st.a) > fmax(lim.acc, fabs(a0)) * (1.0 + 1e-9))
                bad++;
            if (lim.jerk > 0.0 && fabs(st.a - prev_a) > lim.jerk * dur / 200.0 * (1.0 + 1e-9) + 1e-9)
                bad++;
            if (st.v < -1e-9 * (1.0 + v0))
                bad++;
            prev_a = st.a;
        }
        tp_state1_t end = tp_prof_at(&p, dur);
        if (fabs(end.v - vt) > 1e-9 * (1.0 + vt) || fabs(end.a) > 1e-6 * lim.acc)
            bad++;
    }
    CHECK(bad == 0, "%d profile samples out of limits", bad);
    printf("profiles: %d random speed changes sampled within limits\n", n);
}

/* Braking distance, chain speed and braking curve agree with each other. */
static void braking_consistency(int n)
{
    int bad = 0;
    for (int k = 0; k < n; k++) {
        tp_lim1_t lim = {100.0 + 9900.0 * urand(), urand() < 0.2 ? 0.0 : 1e3 + 1e6 * urand()};
        double vt = 100.0 * urand(), d = 10.0 * urand() * urand();
        double v = tp_chain_vmax(vt, d, &lim);
        double back = tp_brake_dist(v, 0.0, vt, &lim);
        if (fabs(back - d) > 1e-7 * (1.0 + d))
            bad++;
        double bc = tp_brake_curve(vt, d, &lim);
        if (bc < v * (1.0 - 1e-12))
            bad++;                      /* the braking curve is above any rest-acceleration start */
    }
    CHECK(bad == 0, "%d inconsistent braking computations", bad);
    printf("braking: %d chain speeds invert their braking distance\n", n);
}

/* Closed forms against hand values: trapezoid and S-curve. */
static void known_values(void)
{
    tp_lim1_t trap = {100.0, 0.0}, sc = {100.0, 1000.0};
    printf("trapezoid stop from 10: %.6f\n", tp_stop_dist(10.0, 0.0, &trap));
    printf("S-curve stop from 10: %.6f\n", tp_stop_dist(10.0, 0.0, &sc));
    printf("S-curve stop from 0.05: %.6f\n", tp_stop_dist(0.05, 0.0, &sc));
    printf("chain from 0 over 0.5 (trapezoid): %.6f\n", tp_chain_vmax(0.0, 0.5, &trap));
    printf("cubic root of x^3 + 2x - 3: %.12f\n", tp_cubic_root(2.0, -3.0));
}

/* A line-line blend: G2 joins, inside the tolerance, derivative bounds hold along it. */
static void blend_corner(double deg, double tol)
{
    tp_geo_t a, b, bl;
    tp_vec_t p0 = {{0}}, p1 = {{10, 0, 0}}, p2;
    memset(&p2, 0, sizeof(p2));
    p2.x[0] = 10 + 10 * cos(deg * M_PI / 180.0);
    p2.x[1] = 10 * sin(deg * M_PI / 180.0);
    tp_geo_line(&a, &p0, &p1);
    tp_geo_line(&b, &p1, &p2);
    tp_blend_init();
    tp_corner_t c;
    tp_corner_describe(&c, &a, &b);
    tp_blend_spec_t spec;
    memset(&spec, 0, sizeof(spec));
    spec.da = spec.db = fmin(tp_blend_tol_cut(&c, tol), 5.0);
    CHECK(tp_blend_build(&bl, &c, &spec) == 0, "blend of %g deg not built", deg);
    double miss, dev;
    tp_blend_deviation(&bl, &c, &spec, &miss, &dev);
    tp_jet_t j0 = tp_geo_jet(&bl, 0.0), j1 = tp_geo_jet(&bl, bl.len);
    tp_jet_t ea = tp_geo_jet(&a, a.len - spec.da), eb = tp_geo_jet(&b, spec.db);
    double g0 = 0.0, g1 = 0.0;
    for (int i = 0; i < TP_NAX; i++) {
        g0 = fmax(g0, fabs(j0.p.x[i] - ea.p.x[i]) + fabs(j0.d1.x[i] - ea.d1.x[i]) + fabs(j0.d2.x[i]));
        g1 = fmax(g1, fabs(j1.p.x[i] - eb.p.x[i]) + fabs(j1.d1.x[i] - eb.d1.x[i]) + fabs(j1.d2.x[i]));
    }
    tp_bounds_t bd;
    tp_geo_bounds(&bl, 0.0, bl.len, &bd);
    int over = 0;
    for (int k = 0; k <= 400; k++) {
        tp_jet_t j = tp_geo_jet(&bl, bl.len * k / 400.0);
        for (int i = 0; i < TP_NAX; i++)
            if (fabs(j.d1.x[i]) > bd.d1[i] * (1 + 1e-12) + 1e-15 || fabs(j.d2.x[i]) > bd.d2[i] * (1 + 1e-12) + 1e-12)
                over++;
    }
    CHECK(g0 < 1e-9 && g1 < 1e-9, "%g deg: joins not G2 (%g %g)", deg, g0, g1);
    CHECK(miss <= tol * (1 + 1e-9) && dev <= tol * (1 + 1e-9), "%g deg: miss %g dev %g above %g", deg, miss, dev, tol);
    CHECK(over == 0, "%g deg: %d samples above the derivative bounds", deg, over);
    printf("blend %5.1f deg tol %g: G2 joins, vertex miss %s tolerance, bounds hold\n", deg, tol,
           miss <= tol * (1 + 1e-9) ? "within" : "beyond");
}

/* Caps of a straight move are the per-axis limits projected on its direction. */
static void caps_line(void)
{
    tp_geo_t g;
    tp_vec_t p0 = {{0}}, p1 = {{3, 4, 0}};
    tp_geo_line(&g, &p0, &p1);
    tp_bounds_t b;
    tp_geo_bounds(&g, 0.0, g.len, &b);
    tp_axlim_t l;
    memset(&l, 0, sizeof(l));
    for (int i = 0; i < 3; i++) {
        l.vel[i] = 4.0;
        l.acc[i] = 100.0;
    }
    l.vel[1] = 2.0;
    tp_caps_t c;
    tp_caps_compute(&b, &l, 1e9, 0, 1.0, 0, &c);
    printf("line (3,4) caps: speed %.4f acceleration %.4f\n", c.v, c.a);
}

/* Caps of a circle: its in-plane axes and the path run as sinusoids, so the curvature and speed-change
 * parts of their acceleration and jerk add as a hypot.  The caps hold sampled around the circle for
 * every sign of the tangential acceleration and jerk, and allow more than the sum bound would. */
static void caps_circle(void)
{
    tp_geo_t g;
    tp_vec_t p0 = {{1, 0, 0}}, p1 = {{-1, 0, 0}};
    const double centre[3] = {0, 0, 0}, normal[3] = {0, 0, 1}, A = 5000.0, J = 2e5;
    CHECK(tp_geo_arc(&g, &p0, &p1, centre, normal, 0) == 0, "circle not built");
    tp_bounds_t b;
    tp_geo_bounds(&g, 0.0, g.len, &b);
    tp_axlim_t l;
    memset(&l, 0, sizeof(l));
    for (int i = 0; i < 3; i++) {
        l.vel[i] = 500.0;
        l.acc[i] = A;
        l.jerk[i] = J;
    }
    l.acc[TP_PATH_AX] = A;
    l.jerk[TP_PATH_AX] = J;
    tp_caps_t c, sum;
    tp_caps_compute(&b, &l, 1e9, 1, g.len, 0, &c);
    memset(b.phase, 0, sizeof(b.phase));
    tp_caps_compute(&b, &l, 1e9, 1, g.len, 0, &sum);
    double worst_a = 0.0, worst_j = 0.0, v = c.v;
    for (int k = 0; k < 720; k++) {
        double ps = 2.0 * M_PI * k / 720.0, sn = sin(ps), cs = cos(ps);
        for (int q = 0; q < 4; q++) {
            double a = q & 1 ? -c.a : c.a, j = q & 2 ? -c.j : c.j;
            /* x = cos(s): x' = -sin, x'' = -cos, x''' = sin (radius 1) */
            worst_a = fmax(worst_a, fabs(-cs * v * v - sn * a) / A);
            worst_j = fmax(worst_j, fabs(sn * v * v * v - 3.0 * cs * v * a - sn * j) / J);
            worst_a = fmax(worst_a, hypot(a, v * v) / A);
            worst_j = fmax(worst_j, hypot(j - v * v * v, 3.0 * v * a) / J);
        }
    }
    CHECK(worst_a <= 1.0 + 1e-9 && worst_j <= 1.0 + 1e-9, "circle caps exceed the limits: %g %g", worst_a, worst_j);
    CHECK(c.v > sum.v, "circle caps %g not above the sum bound's %g", c.v, sum.v);
    printf("circle R1 caps: speed %.3f (sum bound %.3f), within the limits around it\n", c.v, sum.v);
}

/* Rest-to-rest and from-rest crossing times of a piece (the estimate caps use to choose how much
 * acceleration a curved piece keeps): closed forms for reaching the cap, and pieces too short for
 * it; the time grows with the length and falls with the limits. */
static void rest_times(void)
{
    tp_caps_t trap = {10.0, 100.0, 0.0, 100.0}, sc = {10.0, 100.0, 1000.0, 100.0};
    printf("rest to rest over 10 (trapezoid): %.6f, from rest: %.6f\n", tp_caps_rest_time(&trap, 10.0, 2),
           tp_caps_rest_time(&trap, 10.0, 1));
    printf("rest to rest over 0.25 (trapezoid): %.6f\n", tp_caps_rest_time(&trap, 0.25, 2));
    printf("rest to rest over 10 (S-curve): %.6f, over 0.002: %.6f\n", tp_caps_rest_time(&sc, 10.0, 2),
           tp_caps_rest_time(&sc, 0.002, 2));
    int bad = 0;
    for (int k = 0; k < 2000; k++) {
        tp_caps_t c = {1.0 + 99.0 * urand(), 10.0 + 990.0 * urand(), urand() < 0.3 ? 0.0 : 100.0 + 1e5 * urand(), 0.0};
        double len = 1e-3 + 10.0 * urand();
        int ends = 1 + (urand() < 0.5);
        double t = tp_caps_rest_time(&c, len, ends), t_long = tp_caps_rest_time(&c, 1.1 * len, ends);
        tp_caps_t more = c;
        more.a *= 1.5;
        bad += !(t > 0.0) || !(t_long > t) || !(tp_caps_rest_time(&more, len, ends) <= t * (1.0 + 1e-9)) ||
               !(t >= len / c.v);
    }
    CHECK(bad == 0, "%d crossing times not monotonic", bad);
    printf("rest times: 2000 random pieces, %d not monotonic\n", bad);
}

/* The speed a blend of a given cut allows and the cut a speed needs are inverses, and the blend's
 * length estimate lies between its chord and the path through the corner. */
static void blend_speed_inverse(void)
{
    int bad = 0;
    tp_blend_init();
    for (int k = 0; k < 2000; k++) {
        tp_corner_t c;
        memset(&c, 0, sizeof(c));
        c.theta = (0.01 + 3.0 * urand());
        c.kink = urand() < 0.3 ? 10.0 * urand() : 0.0;
        double d = 1e-3 + urand(), acc = 10.0 + 1e4 * urand(), jerk = urand() < 0.2 ? 0.0 : 1e3 + 1e6 * urand();
        double len, v = tp_blend_speed_at_cut(&c, d, acc, jerk, &len);
        double back = tp_blend_need_cut(&c, v, acc, jerk);
        double chord = 2.0 * d * cos(0.5 * c.theta);
        if (!(fabs(back - d) <= 1e-6 * d) || !(len >= chord * (1.0 - 1e-9)) || !(len <= 2.0 * d * (1.0 + 1e-9)))
            bad++;
        CHECK(fabs(back - d) <= 1e-6 * d, "theta %g kink %g: cut %g gives speed %g, which needs cut %g", c.theta,
              c.kink, d, v, back);
        CHECK(len >= chord * (1.0 - 1e-9) && len <= 2.0 * d * (1.0 + 1e-9), "theta %g: length %g of cut %g",
              c.theta, len, d);
    }
    printf("blend speed at cut: 2000 random corners, %d not inverse to the cut a speed needs\n", bad);
}

int main(void)
{
    known_values();
    profile_random(20000);
    braking_consistency(20000);
    caps_line();
    rest_times();
    caps_circle();
    blend_corner(90.0, 0.01);
    blend_corner(10.0, 0.001);
    blend_corner(170.0, 0.05);
    blend_corner(0.5, 0.01);
    blend_speed_inverse();
    if (failures)
        printf("%d check(s) failed\n", failures);
    else
        printf("all planner math checks passed\n");
    return failures != 0;
}
