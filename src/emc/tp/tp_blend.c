/* tp_blend.c: corner blends (degree-7 G2, parabolic G1): construction, sizing tables and deviation checks. */
#include <math.h>
#include <string.h>
#include "tp_blend.h"

#define TP_BLEND_TABLE 181          /* one entry per degree, 0..180 */
#define TP_BLEND_LAM_ITER 6
#define TP_BLEND_SAMPLES 9          /* points of each side of the original path in deviation checks */
#define TP_BLEND_RAMP 0.75          /* share of the triangle's curvature slope at the blend ends */

/* Per shape and unit cut of a line-line corner: vertex miss, largest |p''| and |p'''| along the
 * blend. */
static double tab_miss[2][TP_BLEND_TABLE], tab_d2[2][TP_BLEND_TABLE], tab_d3[2][TP_BLEND_TABLE];
static double tab_len[2][TP_BLEND_TABLE];
static int tab_ready;

/* Unit part of u perpendicular to t (zero when u is parallel to t). */
static tp_vec_t perp_unit(const tp_vec_t *u, const tp_vec_t *t)
{
    double tt = tp_vec_dot(t, t);
    tp_vec_t w = tp_vec_axpy(u, tt > 0.0 ? -tp_vec_dot(u, t) / tt : 0.0, t);
    double n = sqrt(tp_vec_dot(&w, &w));
    tp_vec_t zero = {{0}};
    return n > 1e-12 ? tp_vec_scale(&w, 1.0 / n) : zero;
}

/* Third derivatives (w.r.t. s) at the ends of the quintic G2 Hermite of the same end data and
 * scale: a septic with these is that quintic, whose curvature starts flat. */
static void quintic_thirds(const tp_jet_t *a, const tp_jet_t *b, double lam, tp_vec_t *a3, tp_vec_t *b3)
{
    double l1 = lam / 5.0, l2 = lam * lam / 20.0, k = 60.0 / (lam * lam * lam);
    for (int i = 0; i < TP_NAX; i++) {
        double q0 = a->p.x[i], q1 = q0 + l1 * a->d1.x[i], q2 = q0 + 2.0 * l1 * a->d1.x[i] + l2 * a->d2.x[i];
        double q5 = b->p.x[i], q4 = q5 - l1 * b->d1.x[i], q3 = q5 - 2.0 * l1 * b->d1.x[i] + l2 * b->d2.x[i];
        a3->x[i] = k * (q3 - 3.0 * q2 + 3.0 * q1 - q0);
        b3->x[i] = k * (q5 - 3.0 * q4 + 3.0 * q3 - q2);
    }
}

/* How much of the ramp a turn takes: curvature ka -> kp -> kb (in the turn's frame) at slopes sa
 * and sb.  All of it for a peak between straight ends (a corner); less as the ends carry
 * curvature; none without a peak (a tangent join's or a carried arc's curvature runs straight,
 * which the quintic already follows). */
static double ramp_weight(double ka, double kb, double kp, double sa, double sb)
{
    if (!(sa > 0.0 && sb < 0.0) || !(kp > 0.0))
        return 0.0;
    double apex = fabs(sa - sb) / (fabs(sa) + fabs(sb));
    return apex * fmax(0.0, 1.0 - 0.5 * (fabs(ka) + fabs(kb)) / kp);
}

/* The turn between a blend's end data: its angle, the directions towards it at both ends and the
 * end curvatures in them (what the ramp needs that does not depend on the blend's scale). */
typedef struct blend_turn {
    double th, ka, kb;
    tp_vec_t wa, wb;
} blend_turn_t;

/* Describe the turn from a's end data to b's. */
static void turn_of(const tp_jet_t *a, const tp_jet_t *b, blend_turn_t *t)
{
    double na = sqrt(tp_vec_dot(&a->d1, &a->d1)), nb = sqrt(tp_vec_dot(&b->d1, &b->d1));
    double cs = na > 0.0 && nb > 0.0 ? tp_vec_dot(&a->d1, &b->d1) / (na * nb) : 1.0;
    t->th = acos(fmax(-1.0, fmin(1.0, cs)));
    t->wa = perp_unit(&b->d1, &a->d1);
    t->wb = perp_unit(&a->d1, &b->d1);
    t->ka = tp_vec_dot(&a->d2, &t->wa);
    t->kb = -tp_vec_dot(&b->d2, &t->wb);
}

/* Third derivatives at the blend's ends.  A corner's curvature best runs up to a peak in the
 * middle and down again, a triangle of the turn's area (the clothoid pair turns with the least
 * curvature change); the ends take TP_BLEND_RAMP of its slope (the polynomial cannot follow
 * the apex; the full slope overshoots it), weighed against the quintic's by ramp_weight. */
static void end_thirds(const tp_jet_t *a, const tp_jet_t *b, const blend_turn_t *t, double lam,
                       tp_vec_t *a3, tp_vec_t *b3)
{
    double d = 0.5 * lam, ka = t->ka, kb = t->kb;
    double kp = t->th / d - 0.5 * (ka + kb), sa = (kp - ka) / d, sb = (kb - kp) / d;
    double w = ramp_weight(ka, kb, kp, sa, sb);
    tp_vec_t ra = tp_vec_scale(&t->wa, TP_BLEND_RAMP * sa), rb = tp_vec_scale(&t->wb, -TP_BLEND_RAMP * sb);
    ra = tp_vec_axpy(&ra, -tp_vec_dot(&a->d2, &a->d2), &a->d1);
    rb = tp_vec_axpy(&rb, -tp_vec_dot(&b->d2, &b->d2), &b->d1);
    quintic_thirds(a, b, lam, a3, b3);
    for (int i = 0; i < TP_NAX; i++) {
        a3->x[i] += w * (ra.x[i] - a3->x[i]);
        b3->x[i] += w * (rb.x[i] - b3->x[i]);
    }
}

/* Degree-7 blend with scale lam matching its own length (so length is the parameter). */
static int build_septic(tp_septic_t *q, const tp_jet_t *a, const tp_jet_t *b, tp_metric_t m,
                        double lam_max, double *lam_out)
{
    tp_vec_t chord = tp_vec_sub(&b->p, &a->p);
    double lam = tp_vec_metric_norm(&chord, m);
    if (!(lam > 1e-12))
        return -1;
    blend_turn_t turn;
    turn_of(a, b, &turn);
    for (int k = 0; k < TP_BLEND_LAM_ITER; k++) {
        tp_vec_t a3, b3;
        end_thirds(a, b, &turn, lam, &a3, &b3);
        tp_septic_hermite(q, a, b, lam, &a3, &b3);
        double len = tp_septic_length(q, m);
        if (!(len > 0.0) || !isfinite(len) || len > lam_max)
            return -1;
        double step = len - lam;
        lam = len;
        if (fabs(step) <= 1e-6 * len)
            break;
    }
    tp_vec_t a3, b3;
    end_thirds(a, b, &turn, lam, &a3, &b3);
    tp_septic_hermite(q, a, b, lam, &a3, &b3);
    *lam_out = lam;
    return 0;
}

/* End data of a G1 blend: the parabola from a.p to b.p whose tangents meet at the corner (for
 * lines: the quadratic Bezier a.p, corner, b.p), reparameterised by u + c u (1 - u) so that its
 * parameter speed is the same at both ends; that speed (the harmonic mean of 2 da and 2 db) is
 * returned, with the end derivatives of the reparameterised curve (second in a, b; third in a3,
 * b3).  Run at constant parameter speed it is the constant-acceleration change from one velocity
 * to the other: the smallest acceleration on every axis a corner of these cuts allows. */
static double g1_ends(tp_jet_t *a, tp_jet_t *b, tp_vec_t *a3, tp_vec_t *b3, double da, double db)
{
    double c = (db - da) / (da + db), lam = 4.0 * da * db / (da + db), l2 = lam * lam;
    double l3 = l2 * lam;
    for (int i = 0; i < TP_NAX; i++) {
        double corner = 0.5 * (a->p.x[i] + da * a->d1.x[i] + b->p.x[i] - db * b->d1.x[i]);
        double q2 = 2.0 * (a->p.x[i] - 2.0 * corner + b->p.x[i]);
        a->d2.x[i] = (q2 * (1.0 + c) * (1.0 + c) - 4.0 * c * da * a->d1.x[i]) / l2;
        b->d2.x[i] = (q2 * (1.0 - c) * (1.0 - c) - 4.0 * c * db * b->d1.x[i]) / l2;
        a3->x[i] = -6.0 * c * (1.0 + c) * q2 / l3;
        b3->x[i] = -6.0 * c * (1.0 - c) * q2 / l3;
    }
    return lam;
}

/* The G1 blend: its end data, then the polynomial through them at their parameter scale (it
 * reproduces the reparameterised parabola exactly: no length fixed point). */
static int g1_blend(tp_septic_t *q, tp_jet_t *a, tp_jet_t *b, double da, double db,
                    double *lam_out)
{
    tp_vec_t a3, b3;
    double lam = g1_ends(a, b, &a3, &b3, da, db);
    if (!(lam > 1e-12) || !isfinite(lam))
        return -1;
    tp_septic_hermite(q, a, b, lam, &a3, &b3);
    *lam_out = lam;
    return 0;
}

/* Largest |p''| and |p'''| (w.r.t. length) sampled along a unit corner blend. */
static void unit_peaks(const tp_geo_t *g, double *d2, double *d3)
{
    tp_bounds_t b;
    *d2 = *d3 = 0.0;
    for (int k = 0; k < 16; k++) {
        tp_geo_bounds(g, g->len * k / 16.0, g->len * (k + 1) / 16.0, &b);
        *d2 = fmax(*d2, b.d2[TP_PATH_AX]);
        *d3 = fmax(*d3, b.d3[TP_PATH_AX]);
    }
}

/* Closest distance from point c to a blend polynomial: 17 samples, then golden sections around the best. */
static double septic_miss(const tp_septic_t *q, const tp_vec_t *c)
{
    int best = 0;
    double dbest = INFINITY;
    for (int k = 0; k <= 16; k++) {
        tp_vec_t p = tp_septic_point(q, k / 16.0), d = tp_vec_sub(&p, c);
        double dist = tp_vec_dot(&d, &d);
        if (dist < dbest) {
            dbest = dist;
            best = k;
        }
    }
    double lo = fmax(0.0, (best - 1) / 16.0), hi = fmin(1.0, (best + 1) / 16.0);
    const double gr = 0.6180339887498949;
    double m1 = hi - gr * (hi - lo), m2 = lo + gr * (hi - lo);
    tp_vec_t p1 = tp_septic_point(q, m1), p2 = tp_septic_point(q, m2);
    tp_vec_t e1 = tp_vec_sub(&p1, c), e2 = tp_vec_sub(&p2, c);
    double f1 = tp_vec_dot(&e1, &e1), f2 = tp_vec_dot(&e2, &e2);
    for (int it = 0; it < 14; it++) {
        if (f1 < f2) {
            hi = m2;
            m2 = m1;
            f2 = f1;
            m1 = hi - gr * (hi - lo);
            tp_vec_t p = tp_septic_point(q, m1), e = tp_vec_sub(&p, c);
            f1 = tp_vec_dot(&e, &e);
        } else {
            lo = m1;
            m1 = m2;
            f1 = f2;
            m2 = lo + gr * (hi - lo);
            tp_vec_t p = tp_septic_point(q, m2), e = tp_vec_sub(&p, c);
            f2 = tp_vec_dot(&e, &e);
        }
    }
    return sqrt(fmin(dbest, fmin(f1, f2)));
}

/* Fill the line-line tables: a unit cut on each side of corners of 0..180 degrees, each shape. */
void tp_blend_init(void)
{
    if (tab_ready)
        return;
    for (int shape = TP_BLEND_G2; shape <= TP_BLEND_G1; shape++)
        for (int k = 0; k < TP_BLEND_TABLE; k++) {
            double th = fmin(k, 179.0) * M_PI / 180.0;
            tp_jet_t a, b;
            memset(&a, 0, sizeof(a));
            memset(&b, 0, sizeof(b));
            a.p.x[0] = -1.0;
            a.d1.x[0] = 1.0;
            b.p.x[0] = cos(th);
            b.p.x[1] = sin(th);
            b.d1.x[0] = cos(th);
            b.d1.x[1] = sin(th);
            tp_geo_t g;
            memset(&g, 0, sizeof(g));
            g.kind = TP_GEO_SEPTIC;
            g.metric = TP_METRIC_XYZ;
            int bad = shape == TP_BLEND_G1
                          ? g1_blend(&g.u.q, &a, &b, 1.0, 1.0, &g.len)
                          : build_septic(&g.u.q, &a, &b, TP_METRIC_XYZ, 8.0, &g.len);
            if (bad < 0) {
                tab_miss[shape][k] = 1.0;
                tab_d2[shape][k] = tab_d3[shape][k] = 1e6;
                tab_len[shape][k] = 2.0;
                continue;
            }
            tp_vec_t origin = {{0}};
            tab_miss[shape][k] = septic_miss(&g.u.q, &origin);
            tab_len[shape][k] = g.len;
            unit_peaks(&g, &tab_d2[shape][k], &tab_d3[shape][k]);
        }
    tab_ready = 1;
}

/* Linear interpolation in a table indexed by degrees. */
static double tab_at(const double *tab, double theta)
{
    double deg = theta * 180.0 / M_PI;
    if (deg <= 0.0)
        return tab[0];
    if (deg >= TP_BLEND_TABLE - 1)
        return tab[TP_BLEND_TABLE - 1];
    int k = (int)deg;
    double f = deg - k;
    return tab[k] + f * (tab[k + 1] - tab[k]);
}

/* Tangent angle and curvature jump at the corner between ga's end and gb's start. */
void tp_corner_describe(tp_corner_t *c, const tp_geo_t *ga, const tp_geo_t *gb)
{
    tp_jet_t ja = tp_geo_jet(ga, ga->len), jb = tp_geo_jet(gb, 0.0);
    double na = sqrt(tp_vec_dot(&ja.d1, &ja.d1)), nb = sqrt(tp_vec_dot(&jb.d1, &jb.d1));
    double cs = tp_vec_dot(&ja.d1, &jb.d1) / (na * nb);
    c->ga = ga;
    c->gb = gb;
    c->theta = acos(fmax(-1.0, fmin(1.0, cs)));
    c->shape = TP_BLEND_G2;
    tp_vec_t dk = tp_vec_sub(&ja.d2, &jb.d2);
    c->kink = sqrt(tp_vec_dot(&dk, &dk));
}

/* Symmetric cut whose line-line blend misses the corner by tol (curvature jumps: a clothoid estimate). */
double tp_blend_tol_cut(const tp_corner_t *c, double tol)
{
    double d = INFINITY;
    double miss = tab_at(tab_miss[c->shape], c->theta);
    if (c->theta > 1e-9 && miss > 1e-15)
        d = tol / miss;
    if (c->kink > 1e-12)
        d = fmin(d, sqrt(24.0 * tol / c->kink));
    return d;
}

/* Smallest symmetric cut for which the blend's curvature and its change allow speed v. */
double tp_blend_need_cut(const tp_corner_t *c, double v, double acc, double jerk)
{
    double d2 = tab_at(tab_d2[c->shape], c->theta), d3 = tab_at(tab_d3[c->shape], c->theta);
    double d = 0.0;
    if (acc > 0.0)
        d = fmax(d, v * v * d2 / acc);
    if (jerk > 0.0)
        d = fmax(d, sqrt(v * v * v * d3 / jerk));
    if (c->kink > 1e-12) {
        if (acc > 0.0)
            d = fmax(d, v * v * c->kink / acc);
        if (jerk > 0.0)
            d = fmax(d, 2.0 * v * v * v * c->kink / jerk);
    }
    return d;
}

/* Speed a symmetric blend of cut d allows with normal acceleration acc and jerk jerk (0 = none),
 * the inverse of tp_blend_need_cut; *len is the blend's length (line-line estimate). */
double tp_blend_speed_at_cut(const tp_corner_t *c, double d, double acc, double jerk, double *len)
{
    double d2 = tab_at(tab_d2[c->shape], c->theta), d3 = tab_at(tab_d3[c->shape], c->theta);
    double v = INFINITY;
    *len = d * tab_at(tab_len[c->shape], c->theta);
    if (acc > 0.0 && d2 > 0.0)
        v = fmin(v, sqrt(acc * d / d2));
    if (jerk > 0.0 && d3 > 0.0)
        v = fmin(v, cbrt(jerk * d * d / d3));
    if (c->kink > 1e-12) {
        if (acc > 0.0)
            v = fmin(v, sqrt(acc * d / c->kink));
        if (jerk > 0.0)
            v = fmin(v, cbrt(jerk * d / (2.0 * c->kink)));
    }
    return v;
}

/* A tiling point at s along line g carrying curvature k: moved from the line onto the arc of
 * that curvature through the line's end points (the sampled curve the line stands for), with the
 * arc's tangent there, so that blends meeting at the middles of units of different lengths follow
 * the curve instead of the chords' sagittas. */
static void onto_arc(tp_jet_t *j, const tp_geo_t *g, double s, const tp_vec_t *k)
{
    if (g->kind != TP_GEO_LINE)
        return;
    j->p = tp_vec_axpy(&j->p, -0.5 * s * (g->len - s), k);
    tp_vec_t t = tp_vec_axpy(&j->d1, s - 0.5 * g->len, k);
    double n = sqrt(tp_vec_dot(&t, &t));
    if (n > 0.0)
        j->d1 = tp_vec_scale(&t, 1.0 / n);
}

/* Build the blend from ga at (len - da) to gb at db. */
int tp_blend_build(tp_geo_t *out, const tp_corner_t *c, const tp_blend_spec_t *spec)
{
    tp_jet_t a = tp_geo_jet(c->ga, c->ga->len - spec->da);
    tp_jet_t b = tp_geo_jet(c->gb, spec->db);
    if (spec->ka_set)
        onto_arc(&a, c->ga, c->ga->len - spec->da, &spec->ka);
    if (spec->kb_set)
        onto_arc(&b, c->gb, spec->db, &spec->kb);
    memset(out, 0, sizeof(*out));
    out->kind = TP_GEO_SEPTIC;
    out->metric = c->ga->metric;
    if (c->shape == TP_BLEND_G1)
        return g1_blend(&out->u.q, &a, &b, spec->da, spec->db, &out->len);
    if (spec->ka_set)
        a.d2 = spec->ka;
    if (spec->kb_set)
        b.d2 = spec->kb;
    double lam_max = 2.0 * (spec->da + spec->db);
    return build_septic(&out->u.q, &a, &b, out->metric, lam_max, &out->len);
}

/* Distance from p to the segment [a, b] in nine axes. */
static double seg_dist(const tp_vec_t *p, const tp_vec_t *a, const tp_vec_t *b)
{
    tp_vec_t ab = tp_vec_sub(b, a), ap = tp_vec_sub(p, a);
    double l2 = tp_vec_dot(&ab, &ab), t = l2 > 0.0 ? tp_vec_dot(&ap, &ab) / l2 : 0.0;
    t = fmax(0.0, fmin(1.0, t));
    tp_vec_t q = tp_vec_axpy(a, t, &ab), d = tp_vec_sub(p, &q);
    return sqrt(tp_vec_dot(&d, &d));
}

/* Sample the replaced path: the end of ga and the start of gb, and how far chords stray from it. */
static double replaced_polyline(const tp_corner_t *c, const tp_blend_spec_t *spec, tp_vec_t *pts)
{
    int n = TP_BLEND_SAMPLES;
    double sag = 0.0;
    for (int k = 0; k < n; k++) {
        double sa = c->ga->len - spec->da * (1.0 - (double)k / (n - 1));
        double sb = spec->db * (double)k / (n - 1);
        pts[k] = tp_geo_eval(c->ga, sa);
        pts[n - 1 + k] = tp_geo_eval(c->gb, sb);
    }
    for (int k = 0; k + 1 < 2 * n - 1; k++) {
        const tp_geo_t *g = k < n - 1 ? c->ga : c->gb;
        if (g->kind == TP_GEO_LINE)
            continue;
        double s = k < n - 1 ? c->ga->len - spec->da * (1.0 - (k + 0.5) / (n - 1))
                             : spec->db * (k - n + 1.5) / (n - 1);
        tp_vec_t mid = tp_geo_eval(g, s);
        tp_vec_t half = tp_vec_sub(&pts[k + 1], &pts[k]);
        tp_vec_t cm = tp_vec_axpy(&pts[k], 0.5, &half), d = tp_vec_sub(&mid, &cm);
        sag = fmax(sag, sqrt(tp_vec_dot(&d, &d)));
    }
    return sag;
}

/* Vertex miss and path deviation of a blend against the geometry it replaces. */
void tp_blend_deviation(const tp_geo_t *blend, const tp_corner_t *c, const tp_blend_spec_t *spec,
                        double *vertex_miss, double *path_dev)
{
    tp_vec_t corner = tp_geo_eval(c->ga, c->ga->len);
    tp_vec_t pts[2 * TP_BLEND_SAMPLES - 1];
    int npts;
    double sag = 0.0, dev = 0.0;
    *vertex_miss = septic_miss(&blend->u.q, &corner);
    if (c->ga->kind == TP_GEO_LINE && c->gb->kind == TP_GEO_LINE) {
        pts[0] = tp_geo_eval(c->ga, c->ga->len - spec->da);
        pts[1] = corner;
        pts[2] = tp_geo_eval(c->gb, spec->db);
        npts = 3;
    } else {
        sag = replaced_polyline(c, spec, pts);
        npts = 2 * TP_BLEND_SAMPLES - 1;
    }
    for (int k = 1; k < 8; k++) {
        tp_vec_t p = tp_septic_point(&blend->u.q, k / 8.0);
        double best = INFINITY;
        for (int m = 0; m + 1 < npts; m++)
            best = fmin(best, seg_dist(&p, &pts[m], &pts[m + 1]));
        dev = fmax(dev, best);
    }
    *path_dev = dev + sag;
}

/* Cheap estimate for a line-line blend: the corner to the blend's middle (a bound on the vertex
 * miss) and the quarter points to their lines. */
static double quick_deviation(const tp_geo_t *blend, const tp_corner_t *c, const tp_blend_spec_t *spec,
                              const tp_vec_t *corner)
{
    tp_vec_t qa = tp_geo_eval(c->ga, c->ga->len - spec->da), qb = tp_geo_eval(c->gb, spec->db);
    tp_vec_t m = tp_septic_point(&blend->u.q, 0.5), d = tp_vec_sub(&m, corner);
    tp_vec_t p1 = tp_septic_point(&blend->u.q, 0.25), p2 = tp_septic_point(&blend->u.q, 0.75);
    double w = sqrt(tp_vec_dot(&d, &d));
    w = fmax(w, fmin(seg_dist(&p1, &qa, corner), seg_dist(&p1, corner, &qb)));
    return fmax(w, fmin(seg_dist(&p2, &qa, corner), seg_dist(&p2, corner, &qb)));
}

/* The larger of the vertex miss and the path deviation (exact where the estimate is not clearly
 * inside tol).  A line-line blend without end curvature, or a parabolic one, stays inside the
 * corner, so its vertex miss is its deviation. */
double tp_blend_worst(const tp_geo_t *blend, const tp_corner_t *c, const tp_blend_spec_t *spec, double tol)
{
    if (c->ga->kind == TP_GEO_LINE && c->gb->kind == TP_GEO_LINE) {
        tp_vec_t corner = c->ga->u.line.end;
        double quick = quick_deviation(blend, c, spec, &corner);
        if (quick <= 0.5 * tol)
            return quick;
        if (c->shape == TP_BLEND_G1 || (!spec->ka_set && !spec->kb_set))
            return septic_miss(&blend->u.q, &corner);
    }
    double miss, dev;
    tp_blend_deviation(blend, c, spec, &miss, &dev);
    return fmax(miss, dev);
}
