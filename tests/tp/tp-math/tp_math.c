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
    double h = bl.len / 400.0;
    tp_jet_t prev = tp_geo_jet(&bl, 0.0);
    for (int k = 0; k <= 400; k++) {
        tp_jet_t j = tp_geo_jet(&bl, h * k);
        for (int i = 0; i < TP_NAX; i++) {
            double d3 = k > 0 ? fabs(j.d2.x[i] - prev.d2.x[i]) / h : 0.0;   /* mean over the step */
            if (fabs(j.d1.x[i]) > bd.d1[i] * (1 + 1e-12) + 1e-15 || fabs(j.d2.x[i]) > bd.d2[i] * (1 + 1e-12) + 1e-12 ||
                d3 > bd.d3[i] * (1 + 1e-9) + 1e-9)
                over++;
        }
        prev = j;
    }
    CHECK(g0 < 1e-9 && g1 < 1e-9, "%g deg: joins not G2 (%g %g)", deg, g0, g1);
    CHECK(miss <= tol * (1 + 1e-9) && dev <= tol * (1 + 1e-9), "%g deg: miss %g dev %g above %g", deg, miss, dev, tol);
    CHECK(over == 0, "%g deg: %d samples above the derivative bounds", deg, over);
    printf("blend %5.1f deg tol %g: G2 joins, vertex miss %s tolerance, bounds hold\n", deg, tol,
           miss <= tol * (1 + 1e-9) ? "within" : "beyond");
}

/* A random vector of the first three axes (the others zero). */
static tp_vec_t rand_vec3(double scale)
{
    tp_vec_t v;
    memset(&v, 0, sizeof(v));
    for (int i = 0; i < 3; i++)
        v.x[i] = scale * (2.0 * urand() - 1.0);
    return v;
}

/* Largest difference over the first three axes. */
static double vec_gap(const tp_vec_t *a, const tp_vec_t *b)
{
    double g = 0.0;
    for (int i = 0; i < 3; i++)
        g = fmax(g, fabs(a->x[i] - b->x[i]));
    return g;
}

/* Derivative of order r (0 to 3) at u of the septic's power form, per axis. */
static tp_vec_t septic_deriv(const tp_septic_t *q, int r, double u)
{
    tp_vec_t out;
    for (int i = 0; i < TP_NAX; i++) {
        double v = 0.0;
        for (int k = TP_BEZ_DEG; k >= r; k--) {
            double f = 1.0;
            for (int m = 0; m < r; m++)
                f *= k - m;
            v = v * u + f * q->c[k].x[i];
        }
        out.x[i] = v;
    }
    return out;
}

/* The septic Hermite takes its end data: position and first three derivatives (w.r.t. s = u lam),
 * read back from its power form. */
static void septic_ends(int n)
{
    int bad = 0;
    for (int k = 0; k < n; k++) {
        tp_jet_t a, b;
        a.p = rand_vec3(10.0), a.d1 = rand_vec3(1.0), a.d2 = rand_vec3(3.0);
        b.p = rand_vec3(10.0), b.d1 = rand_vec3(1.0), b.d2 = rand_vec3(3.0);
        tp_vec_t a3 = rand_vec3(5.0), b3 = rand_vec3(5.0);
        double lam = 0.1 + 5.0 * urand();
        tp_septic_t q;
        tp_septic_hermite(&q, &a, &b, lam, &a3, &b3);
        const tp_vec_t *want[2][4] = {{&a.p, &a.d1, &a.d2, &a3}, {&b.p, &b.d1, &b.d2, &b3}};
        for (int side = 0; side < 2; side++)
            for (int r = 0; r <= 3; r++) {
                tp_vec_t got = septic_deriv(&q, r, side);
                got = tp_vec_scale(&got, pow(lam, -r));
                if (!(vec_gap(&got, want[side][r]) < 1e-9 * (1.0 + pow(lam, -r))))
                    bad++;
            }
    }
    CHECK(bad == 0, "%d of %d septic end values do not match their data", bad, 8 * n);
    printf("septic Hermite: %d random end pairs, %d end values off their data\n", n, bad);
}

/* A G1 blend of unequal cuts is the parabola between the cut points whose tangents meet at the
 * corner, reparameterised by w = u + c u (1 - u): checked point by point. */
static void g1_parabola(void)
{
    tp_geo_t a, b, bl;
    tp_vec_t p0 = {{0}}, p1 = {{10, 0, 0}}, p2;
    memset(&p2, 0, sizeof(p2));
    p2.x[0] = 10 + 10 * cos(M_PI / 3.0);
    p2.x[1] = 10 * sin(M_PI / 3.0);
    tp_geo_line(&a, &p0, &p1);
    tp_geo_line(&b, &p1, &p2);
    tp_corner_t c;
    tp_corner_describe(&c, &a, &b);
    c.shape = TP_BLEND_G1;
    tp_blend_spec_t spec;
    memset(&spec, 0, sizeof(spec));
    spec.da = 1.0;
    spec.db = 3.0;
    CHECK(tp_blend_build(&bl, &c, &spec) == 0, "G1 blend not built");
    tp_vec_t qa = tp_geo_eval(&a, a.len - spec.da), qb = tp_geo_eval(&b, spec.db);
    double cw = (spec.db - spec.da) / (spec.da + spec.db), worst = 0.0;
    for (int k = 0; k <= 50; k++) {
        double u = k / 50.0, w = u + cw * u * (1.0 - u);
        tp_vec_t want, got = tp_geo_eval(&bl, bl.len * u);
        for (int i = 0; i < TP_NAX; i++)
            want.x[i] = (1 - w) * (1 - w) * qa.x[i] + 2 * w * (1 - w) * p1.x[i] + w * w * qb.x[i];
        worst = fmax(worst, vec_gap(&want, &got));
    }
    CHECK(worst < 1e-9, "G1 blend leaves its parabola by %g", worst);
    printf("G1 blend of cuts 1 and 3: %s its reparameterised parabola\n", worst < 1e-9 ? "on" : "off");
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
    septic_ends(2000);
    g1_parabola();
    if (failures)
        printf("%d check(s) failed\n", failures);
    else
        printf("all planner math checks passed\n");
    return failures != 0;
}
