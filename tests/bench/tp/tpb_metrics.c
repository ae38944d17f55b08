/* tpb_metrics.c: tp-bench's metrics (README "Metrics") computed offline: bounds, limit ratios, deviation. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "tpb.h"

/* A straight piece of the programmed path. */
typedef struct piece {
    double a[3], b[3];
    int move;
    double radius;              /* radius of the arc it tessellates, 0 for lines */
} piece_t;

typedef struct pieces {
    int n, cap;
    piece_t *p;
} pieces_t;

static void sub3(const double *a, const double *b, double *r)
{
    for (int i = 0; i < 3; i++)
        r[i] = a[i] - b[i];
}

static double norm3(const double *v)
{
    return sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
}

static void add_piece(pieces_t *ps, const double *a, const double *b, int move, double radius)
{
    double d[3];
    sub3(b, a, d);
    if (norm3(d) <= 1e-9)
        return;
    if (ps->n == ps->cap) {
        ps->cap = ps->cap ? 2 * ps->cap : 4096;
        ps->p = realloc(ps->p, (size_t)ps->cap * sizeof(*ps->p));
    }
    piece_t *p = &ps->p[ps->n++];
    memcpy(p->a, a, sizeof(p->a));
    memcpy(p->b, b, sizeof(p->b));
    p->move = move;
    p->radius = radius;
}

/* Tessellate an arc (helix or spiral) to 0.1 um sagitta, at most 20000 pieces. */
static void arc_pieces(pieces_t *ps, const double *s, const tpb_move_t *m, int move)
{
    int c = fabs(m->normal[0]) > 0.5 ? 0 : fabs(m->normal[1]) > 0.5 ? 1 : 2;
    int i = c == 2 ? 0 : c == 0 ? 1 : 2, j = c == 2 ? 1 : c == 0 ? 2 : 0;
    double dir = m->normal[c] > 0 ? 1.0 : -1.0;
    double r0 = hypot(s[i] - m->center[i], s[j] - m->center[j]);
    double r1 = hypot(m->end[i] - m->center[i], m->end[j] - m->center[j]);
    double a0 = atan2(s[j] - m->center[j], s[i] - m->center[i]);
    double a1 = atan2(m->end[j] - m->center[j], m->end[i] - m->center[i]);
    double sweep = dir > 0 ? fmod(a1 - a0 + 4 * M_PI, 2 * M_PI) : fmod(a0 - a1 + 4 * M_PI, 2 * M_PI);
    if (sweep < 1e-9)
        sweep = 2 * M_PI;
    sweep += 2 * M_PI * m->turn;
    double r = fmax(fmax(r0, r1), 1e-9), step = r > 1e-4 ? 2 * acos(1 - 1e-4 / r) : M_PI / 4;
    int n = (int)ceil(sweep / fmin(step, M_PI / 4));
    n = n < 2 ? 2 : n > 20000 ? 20000 : n;
    double prev[3] = {s[0], s[1], s[2]};
    for (int k = 1; k <= n; k++) {
        double f = (double)k / n, ang = a0 + dir * sweep * f, rr = r0 + (r1 - r0) * f, q[3];
        q[i] = m->center[i] + rr * cos(ang);
        q[j] = m->center[j] + rr * sin(ang);
        q[c] = s[c] + (m->end[c] - s[c]) * f;
        if (k == n)
            memcpy(q, m->end, sizeof(q));
        add_piece(ps, prev, q, move, 0.5 * (r0 + r1));
        memcpy(prev, q, sizeof(prev));
    }
}

/* The programmed polyline (arcs tessellated). */
static void build_pieces(const tpb_program_t *p, pieces_t *ps)
{
    const double *s = p->start;
    memset(ps, 0, sizeof(*ps));
    for (int k = 0; k < p->n; k++) {
        if (p->m[k].arc)
            arc_pieces(ps, s, &p->m[k], k);
        else
            add_piece(ps, s, p->m[k].end, k, 0.0);
        s = p->m[k].end;
    }
}

/* Largest speed along unit u within per-axis limits and a path cap. */
static double dir_cap(const double *u, const double *lim, double cap)
{
    double m = cap;
    for (int i = 0; i < 3; i++)
        if (fabs(u[i]) > 1e-12)
            m = fmin(m, lim[i] / fabs(u[i]));
    return m;
}

/* Distance from point x to segment [a, b]. */
static double seg_dist(const double *x, const double *a, const double *b)
{
    double ab[3], ax[3];
    sub3(b, a, ab);
    sub3(x, a, ax);
    double l2 = ab[0] * ab[0] + ab[1] * ab[1] + ab[2] * ab[2];
    double t = l2 > 0 ? (ax[0] * ab[0] + ax[1] * ab[1] + ax[2] * ab[2]) / l2 : 0.0;
    t = fmax(0.0, fmin(1.0, t));
    double d[3] = {ax[0] - t * ab[0], ax[1] - t * ab[1], ax[2] - t * ab[2]};
    return norm3(d);
}

/* Model G64 Q (naive CAM): chains of G1 points within Q of their chord become one line. */
void tpb_naive_merge(const tpb_program_t *p, tpb_program_t *out)
{
    memset(out, 0, sizeof(*out));
    out->m = malloc((size_t)(p->n + 1) * sizeof(*p->m));
    memcpy(out->start, p->start, sizeof(out->start));
    int k = 0;
    const double *s = p->start;
    while (k < p->n) {
        const tpb_move_t *m = &p->m[k];
        int j = k + 1;
        if (!m->arc && !m->exact && m->naive > 0) {
            while (j < p->n && j - k < 100 && !p->m[j].arc && p->m[j].naive == m->naive &&
                   p->m[j].tol == m->tol && p->m[j].feed == m->feed) {
                int ok = 1;
                for (int q = k; q < j && ok; q++)
                    ok = seg_dist(p->m[q].end, s, p->m[j].end) <= m->naive;
                if (!ok)
                    break;
                j++;
            }
        }
        out->m[out->n] = p->m[j - 1];
        out->m[out->n].line = m->line;
        out->n++;
        s = p->m[j - 1].end;
        k = j;
    }
}

/* Time of a piece from v0 to v1 with acceleration a and cruise cap vc. */
static double piece_time(double v0, double v1, double l, double a, double vc)
{
    double vp2 = (2 * a * l + v0 * v0 + v1 * v1) / 2;
    if (vp2 <= vc * vc)
        return (2 * sqrt(vp2) - v0 - v1) / a;
    double da = (vc * vc - v0 * v0) / (2 * a), dd = (vc * vc - v1 * v1) / (2 * a);
    return (vc - v0) / a + (vc - v1) / a + (l - da - dd) / vc;
}

/* Speed limit at the vertex between pieces k-1 and k. */
static double corner_limit(const tpb_program_t *p, const pieces_t *ps, const double *mlen, int k,
                           const tpb_machine_t *mc)
{
    const piece_t *a = &ps->p[k - 1], *b = &ps->p[k];
    double u[3], w[3], n[3];
    sub3(a->b, a->a, u);
    sub3(b->b, b->a, w);
    double lu = norm3(u), lw = norm3(w);
    for (int i = 0; i < 3; i++) {
        u[i] /= lu;
        w[i] /= lw;
        n[i] = w[i] - u[i];
    }
    double c = fmax(-1.0, fmin(1.0, u[0] * w[0] + u[1] * w[1] + u[2] * w[2])), th = acos(c);
    if (th < 1e-7)
        return INFINITY;
    double nn = norm3(n);
    for (int i = 0; i < 3; i++)
        n[i] /= nn;
    double an = dir_cap(n, mc->acc, mc->atraj);
    if (a->move == b->move)
        return sqrt(an * a->radius);
    const tpb_move_t *mv = &p->m[a->move];
    if (mv->exact)
        return th > 1e-3 ? 0.0 : INFINITY;
    double ch = cos(th / 2), r_tol = mv->tol > 0 && ch < 1 ? mv->tol * ch / (1 - ch) : INFINITY;
    double half = 0.5 * fmin(mlen[a->move], mlen[b->move]);
    double r_len = th < M_PI - 1e-9 ? half / tan(th / 2) : 0.0;
    return sqrt(an * fmin(r_tol, r_len));
}

/* Curvature-limited point-mass bound (forward and backward passes), after Q merging. */
static double pass_bound(const tpb_program_t *p0, const tpb_machine_t *mc)
{
    tpb_program_t p;
    pieces_t ps;
    tpb_naive_merge(p0, &p);
    build_pieces(&p, &ps);
    int n = ps.n;
    double *L = calloc(n, sizeof(double)), *vc = calloc(n, sizeof(double)), *ac = calloc(n, sizeof(double));
    double *v = calloc(n + 1, sizeof(double)), *mlen = calloc(p.n, sizeof(double)), t = 0.0;
    for (int k = 0; k < n; k++) {
        double d[3];
        sub3(ps.p[k].b, ps.p[k].a, d);
        L[k] = norm3(d);
        mlen[ps.p[k].move] += L[k];
    }
    for (int k = 0; k < n; k++) {
        double u[3], d[3];
        sub3(ps.p[k].b, ps.p[k].a, d);
        for (int i = 0; i < 3; i++)
            u[i] = d[i] / L[k];
        const tpb_move_t *m = &p.m[ps.p[k].move];
        vc[k] = fmin(m->feed / 60.0, dir_cap(u, mc->vel, mc->vtraj));
        if (ps.p[k].radius > 0)
            vc[k] = fmin(vc[k], sqrt(fmin(mc->acc[0], fmin(mc->acc[1], mc->acc[2])) * ps.p[k].radius));
        ac[k] = dir_cap(u, mc->acc, mc->atraj);
    }
    for (int k = 1; k < n; k++)
        v[k] = fmin(fmin(vc[k - 1], vc[k]), corner_limit(&p, &ps, mlen, k, mc));
    for (int k = 1; k <= n; k++)
        v[k] = fmin(v[k], sqrt(v[k - 1] * v[k - 1] + 2 * ac[k - 1] * L[k - 1]));
    for (int k = n - 1; k >= 0; k--)
        v[k] = fmin(v[k], sqrt(v[k + 1] * v[k + 1] + 2 * ac[k] * L[k]));
    for (int k = 0; k < n; k++)
        t += piece_time(v[k], v[k + 1], L[k], ac[k], vc[k]);
    free(L), free(vc), free(ac), free(v), free(mlen), free(ps.p), tpb_free(&p);
    return t;
}

/* Feed bound: length over min(F, machine speed along the piece). */
static double feed_bound(const tpb_program_t *p, const pieces_t *ps, const tpb_machine_t *mc)
{
    double t = 0.0;
    for (int k = 0; k < ps->n; k++) {
        double d[3], u[3];
        sub3(ps->p[k].b, ps->p[k].a, d);
        double l = norm3(d);
        for (int i = 0; i < 3; i++)
            u[i] = d[i] / l;
        t += l / fmin(p->m[ps->p[k].move].feed / 60.0, dir_cap(u, mc->vel, mc->vtraj));
    }
    return t;
}

/* Motion window: first and last sample whose position changed. */
static void motion_window(const tpb_program_t *p, const tpb_trace_t *tr, int *i1, int *i2)
{
    *i1 = -1;
    *i2 = -1;
    for (int k = 0; k < tr->n; k++) {
        const double *q = k ? tr->p[k - 1] : p->start;
        if (memcmp(q, tr->p[k], sizeof(tr->p[k])) != 0) {
            if (*i1 < 0)
                *i1 = k;
            *i2 = k;
        }
    }
}

/* Per-axis velocity, acceleration and jerk from differences of the samples. */
static void limit_ratios(const tpb_program_t *p, const tpb_machine_t *mc, const tpb_trace_t *tr, int i1,
                         int i2, tpb_result_t *r)
{
    double T = mc->period, h[4][3];
    for (int k = 0; k < 4; k++)
        memcpy(h[k], p->start, sizeof(h[k]));
    for (int k = i1 - 3; k <= i2 + 3; k++) {
        memmove(h[1], h[0], 3 * sizeof(h[0]));
        const double *q = k < 0 ? p->start : k >= tr->n ? tr->p[tr->n - 1] : tr->p[k];
        memcpy(h[0], q, sizeof(h[0]));
        for (int i = 0; i < 3; i++) {
            double v = fabs(h[0][i] - h[1][i]) / T / mc->vel[i];
            double a = fabs(h[0][i] - 2 * h[1][i] + h[2][i]) / (T * T) / mc->acc[i];
            double j = mc->jerk > 0 ? fabs(h[0][i] - 3 * h[1][i] + 3 * h[2][i] - h[3][i]) / (T * T * T) / mc->jerk : 0;
            r->vel_ratio = fmax(r->vel_ratio, v);
            r->acc_ratio = fmax(r->acc_ratio, a);
            r->jerk_ratio = fmax(r->jerk_ratio, j);
            r->vel_viol += v > 1.01;
            r->acc_viol += a > 1.01;
            r->jerk_viol += j > 1.01;
        }
    }
}

/* Deviation of samples from the path and how close the path comes to every vertex. */
static void deviation(const tpb_program_t *p, const pieces_t *ps, const tpb_trace_t *tr, int i1, int i2,
                      tpb_result_t *r)
{
    double *miss = malloc((size_t)p->n * sizeof(double));
    for (int k = 0; k < p->n; k++)
        miss[k] = INFINITY;
    int near = 0;
    const double slack = 1e-5;
    for (int k = i1; k <= i2; k++) {
        double best = INFINITY;
        int bi = near;
        int lo = near - 200 < 0 ? 0 : near - 200, hi = near + 200 >= ps->n ? ps->n - 1 : near + 200;
        for (int j = lo; j <= hi; j++) {
            double d = seg_dist(tr->p[k], ps->p[j].a, ps->p[j].b);
            if (d < best) {
                best = d;
                bi = j;
            }
        }
        near = bi;
        int mv = ps->p[bi].move;
        double allow = p->m[mv].tol > 0 ? p->m[mv].tol + p->m[mv].naive : INFINITY;
        r->max_dev = fmax(r->max_dev, best);
        r->dev_viol += best > 1.01 * allow + slack;
        /* vertex miss: distance from the vertex to the sampled trajectory (chords between samples) */
        const double *prev = k > 0 ? tr->p[k - 1] : p->start;
        for (int q = mv - 12; q <= mv + 12; q++) {
            if (q < 0 || q >= p->n)
                continue;
            miss[q] = fmin(miss[q], seg_dist(p->m[q].end, prev, tr->p[k]));
        }
    }
    for (int k = 0; k < p->n; k++) {
        double allow = p->m[k].tol > 0 ? p->m[k].tol + p->m[k].naive : INFINITY;
        if (isfinite(miss[k])) {
            r->max_miss = fmax(r->max_miss, miss[k]);
            r->miss_viol += miss[k] > 1.01 * allow + slack;
        }
        r->tol = fmax(r->tol, allow);
    }
    free(miss);
}

/* All metrics of one run. */
void tpb_measure(const tpb_program_t *p, const tpb_machine_t *mc, const tpb_trace_t *tr, tpb_result_t *r)
{
    pieces_t ps;
    int i1, i2;
    memset(r, 0, sizeof(*r));
    build_pieces(p, &ps);
    motion_window(p, tr, &i1, &i2);
    r->cycles = i2 - i1 + 1;
    r->feed_bound = feed_bound(p, &ps, mc);
    r->pass_bound = pass_bound(p, mc);
    limit_ratios(p, mc, tr, i1, i2, r);
    deviation(p, &ps, tr, i1, i2, r);
    free(ps.p);
}
