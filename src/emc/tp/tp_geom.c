/* tp_geom.c: evaluation and derivative bounds of lines, arcs and degree-7 (septic) blends. */
#include <math.h>
#include <string.h>
#include "tp_geom.h"

/* Below this a length counts as zero (machine units). */
#define TP_GEO_TINY 1e-12

/* Metric of a displacement: XYZ if it moves, else UVW, else ABC. */
static tp_metric_t metric_of(const tp_vec_t *d, double *len)
{
    double xyz = tp_vec_norm3(d, TP_AX_X), uvw = tp_vec_norm3(d, TP_AX_U);
    if (xyz > TP_GEO_TINY) {
        *len = xyz;
        return TP_METRIC_XYZ;
    }
    if (uvw > TP_GEO_TINY) {
        *len = uvw;
        return TP_METRIC_UVW;
    }
    *len = tp_vec_norm3(d, TP_AX_A);
    return TP_METRIC_ABC;
}

/* Make a line; -1 when no axis group moves. */
int tp_geo_line(tp_geo_t *g, const tp_vec_t *start, const tp_vec_t *end)
{
    tp_vec_t d = tp_vec_sub(end, start);
    double len;
    memset(g, 0, sizeof(*g));
    g->kind = TP_GEO_LINE;
    g->metric = metric_of(&d, &len);
    if (!(len > TP_GEO_TINY))
        return -1;
    g->len = len;
    g->u.line.start = *start;
    g->u.line.end = *end;
    g->u.line.dir = tp_vec_scale(&d, 1.0 / len);
    return 0;
}

static double dot3(const double *a, const double *b)
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static void cross3(const double *a, const double *b, double *r)
{
    r[0] = a[1] * b[2] - a[2] * b[1];
    r[1] = a[2] * b[0] - a[0] * b[2];
    r[2] = a[0] * b[1] - a[1] * b[0];
}

/* Fill the plane basis, radii, sweep and axial rise of an arc; -1 when degenerate. */
static int arc_frame(tp_arc_t *a, const double nrm[3], int turn)
{
    double nn = sqrt(dot3(nrm, nrm));
    if (!(nn > TP_GEO_TINY))
        return -1;
    double dir = turn < 0 ? -1.0 : 1.0;
    int extra = turn < 0 ? -turn - 1 : turn;
    for (int i = 0; i < 3; i++)
        a->n[i] = dir * nrm[i] / nn;
    double ps[3], pe[3];
    for (int i = 0; i < 3; i++) {
        ps[i] = a->start.x[i] - a->c[i];
        pe[i] = a->end.x[i] - a->c[i];
    }
    double hs = dot3(ps, a->n), he = dot3(pe, a->n);
    for (int i = 0; i < 3; i++) {
        ps[i] -= hs * a->n[i];
        pe[i] -= he * a->n[i];
    }
    a->r0 = sqrt(dot3(ps, ps));
    a->r1 = sqrt(dot3(pe, pe));
    if (!(a->r0 > TP_GEO_TINY) || !(a->r1 > TP_GEO_TINY))
        return -1;
    for (int i = 0; i < 3; i++)
        a->e1[i] = ps[i] / a->r0;
    cross3(a->n, a->e1, a->e2);
    double ang = atan2(dot3(pe, a->e2), dot3(pe, a->e1));
    if (ang <= 1e-12)
        ang += 2.0 * M_PI;
    a->sweep = ang + 2.0 * M_PI * extra;
    a->h = he - hs;
    return 0;
}

/* Make an arc from start to end about center; the length is the helix length in XYZ. */
int tp_geo_arc(tp_geo_t *g, const tp_vec_t *start, const tp_vec_t *end, const double center[3],
               const double normal[3], int turn)
{
    memset(g, 0, sizeof(*g));
    g->kind = TP_GEO_ARC;
    g->metric = TP_METRIC_XYZ;
    tp_arc_t *a = &g->u.arc;
    a->start = *start;
    a->end = *end;
    for (int i = 0; i < 3; i++)
        a->c[i] = center[i];
    if (arc_frame(a, normal, turn) < 0)
        return -1;
    double planar = 0.5 * (a->r0 + a->r1) * a->sweep;
    g->len = sqrt(planar * planar + a->h * a->h);
    return g->len > TP_GEO_TINY ? 0 : -1;
}

/* Bernstein weights of degree n at u (n <= TP_BEZ_DEG). */
static void bernstein(int n, double u, double *w)
{
    double pu[TP_BEZ_DEG + 1], pv[TP_BEZ_DEG + 1], binom = 1.0;
    pu[0] = pv[0] = 1.0;
    for (int k = 1; k <= n; k++) {
        pu[k] = pu[k - 1] * u;
        pv[k] = pv[k - 1] * (1.0 - u);
    }
    for (int k = 0; k <= n; k++) {
        w[k] = binom * pu[k] * pv[n - k];
        binom = binom * (n - k) / (k + 1);
    }
}

/* Sum of weighted control vectors. */
static tp_vec_t bez_sum(const tp_vec_t *c, const double *w, int n)
{
    tp_vec_t r = {{0}};
    for (int k = 0; k <= n; k++)
        for (int i = 0; i < TP_NAX; i++)
            r.x[i] += w[k] * c[k].x[i];
    return r;
}

/* Forward differences of a control polygon, times the degree. */
static void bez_diff(const tp_vec_t *c, int n, tp_vec_t *out)
{
    for (int k = 0; k < n; k++)
        for (int i = 0; i < TP_NAX; i++)
            out[k].x[i] = n * (c[k + 1].x[i] - c[k].x[i]);
}

_Static_assert(TP_BEZ_DEG == 7, "septic_power's binomials and tp_septic_hermite are of degree 7");

/* Power-basis coefficients from the control points (for Horner evaluation): c_k = C(n, k)
 * times the k-th forward difference of the control points at 0. */
static void septic_power(tp_septic_t *q)
{
    static const double binom[TP_BEZ_DEG + 1] = {1, 7, 21, 35, 35, 21, 7, 1};
    for (int i = 0; i < TP_NAX; i++) {
        double d[TP_BEZ_DEG + 1];
        for (int k = 0; k <= TP_BEZ_DEG; k++)
            d[k] = q->b[k].x[i];
        for (int k = 0; k <= TP_BEZ_DEG; k++) {
            q->c[k].x[i] = binom[k] * d[0];
            for (int m = 0; m < TP_BEZ_DEG - k; m++)
                d[m] = d[m + 1] - d[m];
        }
    }
}

/* Point of a septic at u (Horner). */
tp_vec_t tp_septic_point(const tp_septic_t *q, double u)
{
    tp_vec_t r;
    if (u >= 1.0)
        return q->b[TP_BEZ_DEG];
    if (u <= 0.0)
        return q->b[0];
    for (int i = 0; i < TP_NAX; i++) {
        double v = q->c[TP_BEZ_DEG].x[i];
        for (int k = TP_BEZ_DEG - 1; k >= 0; k--)
            v = v * u + q->c[k].x[i];
        r.x[i] = v;
    }
    return r;
}

/* Septic position and derivatives w.r.t. length (u = s / len). */
static tp_jet_t septic_jet(const tp_geo_t *g, double s)
{
    tp_vec_t d1[TP_BEZ_DEG], d2[TP_BEZ_DEG - 1];
    double w[TP_BEZ_DEG + 1], u = s / g->len;
    tp_jet_t j;
    bez_diff(g->u.q.b, TP_BEZ_DEG, d1);
    bez_diff(d1, TP_BEZ_DEG - 1, d2);
    j.p = tp_septic_point(&g->u.q, u);
    bernstein(TP_BEZ_DEG - 1, u, w);
    j.d1 = bez_sum(d1, w, TP_BEZ_DEG - 1);
    j.d1 = tp_vec_scale(&j.d1, 1.0 / g->len);
    bernstein(TP_BEZ_DEG - 2, u, w);
    j.d2 = bez_sum(d2, w, TP_BEZ_DEG - 2);
    j.d2 = tp_vec_scale(&j.d2, 1.0 / (g->len * g->len));
    return j;
}

/* Arc position and derivatives at s. */
static tp_jet_t arc_jet(const tp_geo_t *g, double s)
{
    const tp_arc_t *a = &g->u.arc;
    double f = s / g->len, om = a->sweep / g->len, rho = (a->r1 - a->r0) / g->len;
    double ph = a->sweep * f, cs = cos(ph), sn = sin(ph), r = a->r0 + (a->r1 - a->r0) * f;
    tp_jet_t j;
    for (int i = 0; i < 3; i++) {
        double rad = cs * a->e1[i] + sn * a->e2[i], tan = -sn * a->e1[i] + cs * a->e2[i];
        j.p.x[i] = a->c[i] + r * rad + a->n[i] * (dot3(a->start.x, a->n) - dot3(a->c, a->n) + a->h * f);
        j.d1.x[i] = rho * rad + r * om * tan + a->n[i] * a->h / g->len;
        j.d2.x[i] = 2.0 * rho * om * tan - r * om * om * rad;
    }
    for (int i = 3; i < TP_NAX; i++) {
        double d = a->end.x[i] - a->start.x[i];
        j.p.x[i] = a->start.x[i] + d * f;
        j.d1.x[i] = d / g->len;
        j.d2.x[i] = 0.0;
    }
    return j;
}

/* Position and derivatives at s. */
tp_jet_t tp_geo_jet(const tp_geo_t *g, double s)
{
    tp_jet_t j;
    if (s < 0.0)
        s = 0.0;
    if (s > g->len)
        s = g->len;
    switch (g->kind) {
    case TP_GEO_ARC:
        j = arc_jet(g, s);
        break;
    case TP_GEO_SEPTIC:
        j = septic_jet(g, s);
        break;
    default:
        j.d1 = g->u.line.dir;
        memset(&j.d2, 0, sizeof(j.d2));
        break;
    }
    j.p = tp_geo_eval(g, s);            /* exact end points at both ends */
    return j;
}

/* Position at s; the exact end point at (or past) the end. */
tp_vec_t tp_geo_eval(const tp_geo_t *g, double s)
{
    if (s >= g->len)
        return g->kind == TP_GEO_SEPTIC ? g->u.q.b[TP_BEZ_DEG] : g->kind == TP_GEO_ARC ? g->u.arc.end
                                                                          : g->u.line.end;
    if (s <= 0.0)
        return g->kind == TP_GEO_SEPTIC ? g->u.q.b[0] : g->kind == TP_GEO_ARC ? g->u.arc.start
                                                                          : g->u.line.start;
    switch (g->kind) {
    case TP_GEO_ARC:
        return arc_jet(g, s).p;
    case TP_GEO_SEPTIC:
        return tp_septic_point(&g->u.q, s / g->len);
    default:
        if (s > 0.5 * g->len)
            return tp_vec_axpy(&g->u.line.end, s - g->len, &g->u.line.dir);
        return tp_vec_axpy(&g->u.line.start, s, &g->u.line.dir);
    }
}

/* Line bounds: constant direction, no curvature. */
static void line_bounds(const tp_geo_t *g, tp_bounds_t *b)
{
    memset(b, 0, sizeof(*b));
    for (int i = 0; i < TP_NAX; i++)
        b->d1[i] = fabs(g->u.line.dir.x[i]);
    b->d1[TP_PATH_AX] = 1.0;
}

/* Arc bounds: the rotating part bounded per axis by its in-plane share, plus the linear parts. */
static void arc_bounds(const tp_geo_t *g, tp_bounds_t *b)
{
    const tp_arc_t *a = &g->u.arc;
    double om = a->sweep / g->len, rho = fabs(a->r1 - a->r0) / g->len, r = fmax(a->r0, a->r1);
    double w1 = hypot(rho, r * om), w2 = hypot(2.0 * rho * om, r * om * om);
    double w3 = hypot(3.0 * rho * om * om, r * om * om * om), ax = fabs(a->h) / g->len;
    memset(b, 0, sizeof(*b));
    for (int i = 0; i < 3; i++) {
        double f = hypot(a->e1[i], a->e2[i]);
        b->d1[i] = w1 * f + fabs(a->n[i]) * ax;
        b->d2[i] = w2 * f;
        b->d3[i] = w3 * f;
    }
    for (int i = 3; i < TP_NAX; i++)
        b->d1[i] = fabs(a->end.x[i] - a->start.x[i]) / g->len;
    b->d1[TP_PATH_AX] = hypot(w1, ax);
    b->d2[TP_PATH_AX] = w2;
    b->d3[TP_PATH_AX] = w3;
    if (rho > 0.0)
        return;                         /* a spiral: its radius changes, the generic sums hold */
    for (int i = 0; i < 3; i++)         /* in the plane only: an axial part moves linearly */
        b->phase[i] = !(fabs(a->n[i]) * ax > 0.0 && hypot(a->e1[i], a->e2[i]) > 0.0);
    b->phase[TP_PATH_AX] = 1;
}

/* de Casteljau restriction of a degree-n polynomial (one axis, control values c) to [u0, u1]. */
static void bez_restrict1(const double *c, int n, double u0, double u1, double *out)
{
    double tmp[TP_BEZ_DEG + 1];
    /* split at u1, keep the left part; then split that at u0/u1, keep the right part */
    for (int k = 0; k <= n; k++)
        tmp[k] = c[k];
    for (int r = 1; r <= n; r++) {
        out[r - 1] = tmp[0];
        for (int k = 0; k <= n - r; k++)
            tmp[k] += u1 * (tmp[k + 1] - tmp[k]);
    }
    out[n] = tmp[0];
    double t = u1 > 0.0 ? u0 / u1 : 0.0;
    for (int k = 0; k <= n; k++)
        tmp[k] = out[k];
    for (int r = 1; r <= n; r++) {
        out[n - r + 1] = tmp[n - r + 1];
        for (int k = 0; k <= n - r; k++)
            tmp[k] += t * (tmp[k + 1] - tmp[k]);
    }
    out[0] = tmp[0];
}

/* Split a polygon (one axis, degree n) at its middle: left and right halves. */
static void bez_halves(const double *c, int n, double *left, double *right)
{
    double tmp[TP_BEZ_DEG + 1];
    for (int k = 0; k <= n; k++)
        tmp[k] = c[k];
    for (int r = 0; r <= n; r++) {
        left[r] = tmp[0];
        right[n - r] = tmp[n - r];
        for (int k = 0; k < n - r; k++)
            tmp[k] = 0.5 * (tmp[k] + tmp[k + 1]);
    }
}

/* Fold the hull bounds of one order into out (largest |value| per axis and largest metric norm
 * of the control vectors; a metric axis that does not move counts 0). */
static void fold_order(double (*d)[TP_BEZ_DEG + 1], int m, int nax, const int *ax, const int *mq,
                       double scale, double *out)
{
    for (int q = 0; q < nax; q++)
        for (int k = 0; k < m; k++)
            out[ax[q]] = fmax(out[ax[q]], fabs(d[q][k]) * scale);
    for (int k = 0; k < m; k++) {
        double x = mq[0] >= 0 ? d[mq[0]][k] : 0.0, y = mq[1] >= 0 ? d[mq[1]][k] : 0.0;
        double z = mq[2] >= 0 ? d[mq[2]][k] : 0.0;
        out[TP_PATH_AX] = fmax(out[TP_PATH_AX], sqrt(x * x + y * y + z * z) * scale);
    }
}

/* Fold the first three derivatives' hulls of polygons restricted to a span du of the parameter
 * (nax axes; the derivative of a restricted polygon is the restricted derivative, times 1/du). */
static void fold_derivs(double (*r)[TP_BEZ_DEG + 1], int nax, const int *ax, const int *mq,
                        double du, double len, tp_bounds_t *b)
{
    double d[TP_NAX][TP_BEZ_DEG + 1];
    double *outs[3] = {b->d1, b->d2, b->d3}, scale = 1.0;
    for (int q = 0; q < nax; q++)
        for (int k = 0; k <= TP_BEZ_DEG; k++)
            d[q][k] = r[q][k];
    for (int o = 0; o < 3; o++) {
        int n = TP_BEZ_DEG - o;           /* degree of the polygon being differenced */
        for (int q = 0; q < nax; q++)
            for (int k = 0; k < n; k++)
                d[q][k] = n * (d[q][k + 1] - d[q][k]);
        scale /= du * len;
        fold_order(d, n, nax, ax, mq, scale, outs[o]);
    }
}

/* Septic bounds over [s0, s1]: the control polygon (relative to its first point, so rounding
 * scales with the blend, not with the coordinates) restricted once, split in halves (the hull of
 * a degree-7 polygon is loose over a long range; halves give caps about 2 % higher), and the
 * derivative hulls of each half.  Only the axes that move are computed. */
static void septic_bounds(const tp_geo_t *g, double s0, double s1, tp_bounds_t *b)
{
    double r[TP_NAX][TP_BEZ_DEG + 1], lo[TP_NAX][TP_BEZ_DEG + 1], hi[TP_NAX][TP_BEZ_DEG + 1];
    double u0 = s0 / g->len, u1 = s1 / g->len;
    int ax[TP_NAX], nax = 0, first = tp_metric_first(g->metric), mq[3] = {-1, -1, -1};
    memset(b, 0, sizeof(*b));
    for (int i = 0; i < TP_NAX; i++) {
        double c[TP_BEZ_DEG + 1];
        int moves = 0;
        for (int k = 0; k <= TP_BEZ_DEG; k++) {
            c[k] = g->u.q.b[k].x[i] - g->u.q.b[0].x[i];
            moves |= c[k] != 0.0;
        }
        if (!moves)
            continue;
        if (i >= first && i < first + 3)
            mq[i - first] = nax;
        bez_restrict1(c, TP_BEZ_DEG, u0, u1, r[nax]);
        bez_halves(r[nax], TP_BEZ_DEG, lo[nax], hi[nax]);
        ax[nax++] = i;
    }
    fold_derivs(lo, nax, ax, mq, 0.5 * (u1 - u0), g->len, b);
    fold_derivs(hi, nax, ax, mq, 0.5 * (u1 - u0), g->len, b);
}

/* Derivative bounds over [s0, s1]. */
void tp_geo_bounds(const tp_geo_t *g, double s0, double s1, tp_bounds_t *b)
{
    switch (g->kind) {
    case TP_GEO_ARC:
        arc_bounds(g, b);
        break;
    case TP_GEO_SEPTIC:
        septic_bounds(g, s0, s1, b);
        break;
    default:
        line_bounds(g, b);
        break;
    }
}

/* Speed |dp/du| of a septic at u in the three axes from first on (Horner). */
static double septic_speed3(const tp_septic_t *q, int first, double u)
{
    double d[3];
    for (int k = 0; k < 3; k++) {
        int i = first + k;
        double v = TP_BEZ_DEG * q->c[TP_BEZ_DEG].x[i];
        for (int j = TP_BEZ_DEG - 1; j >= 1; j--)
            v = v * u + j * q->c[j].x[i];
        d[k] = v;
    }
    return sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
}

/* Length of a septic in a metric: Gauss-Legendre with 8 nodes on |dp/du| (only the metric's
 * axes are evaluated: blends are built several times per corner). */
double tp_septic_length(const tp_septic_t *q, tp_metric_t m)
{
    static const double xg[4] = {0.1834346424956498, 0.5255324099163290, 0.7966664774136267,
                                 0.9602898564975363};
    static const double wg[4] = {0.3626837833783620, 0.3137066458778873, 0.2223810344533745,
                                 0.1012285362903763};
    double sum = 0.0;
    int first = tp_metric_first(m);
    for (int k = 0; k < 8; k++) {
        double u = 0.5 + 0.5 * (k < 4 ? -xg[k] : xg[k - 4]);
        sum += (k < 4 ? wg[k] : wg[k - 4]) * septic_speed3(q, first, u);
    }
    return 0.5 * sum;
}

/* G2 Hermite of degree 7: position, first, second and third derivative (a3, b3; NULL for zero)
 * at both ends, the derivatives w.r.t. u = s / lam. */
void tp_septic_hermite(tp_septic_t *q, const tp_jet_t *a, const tp_jet_t *b, double lam,
                       const tp_vec_t *a3, const tp_vec_t *b3)
{
    double l1 = lam / 7.0, l2 = lam * lam / 42.0, l3 = lam * lam * lam / 210.0;
    for (int i = 0; i < TP_NAX; i++) {
        double ja = a3 ? a3->x[i] : 0.0, jb = b3 ? b3->x[i] : 0.0;
        q->b[0].x[i] = a->p.x[i];
        q->b[1].x[i] = a->p.x[i] + l1 * a->d1.x[i];
        q->b[2].x[i] = a->p.x[i] + 2.0 * l1 * a->d1.x[i] + l2 * a->d2.x[i];
        q->b[3].x[i] = a->p.x[i] + 3.0 * l1 * a->d1.x[i] + 3.0 * l2 * a->d2.x[i] + l3 * ja;
        q->b[7].x[i] = b->p.x[i];
        q->b[6].x[i] = b->p.x[i] - l1 * b->d1.x[i];
        q->b[5].x[i] = b->p.x[i] - 2.0 * l1 * b->d1.x[i] + l2 * b->d2.x[i];
        q->b[4].x[i] = b->p.x[i] - 3.0 * l1 * b->d1.x[i] + 3.0 * l2 * b->d2.x[i] - l3 * jb;
    }
    septic_power(q);
}
