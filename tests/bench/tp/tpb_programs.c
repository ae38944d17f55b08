/* tpb_programs.c: tp-bench's generated programs (../shared/tp-bench gen-programs) as moves, mm, 5 decimals. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "tpb.h"

const char *const tpb_names[] = {"01_chords005_F6000", "02_chords001_F3000", "03_chords05_F12000",
                                 "04_surface_raster", "05_zigzag_corners", "06_small_arcs", NULL};

/* Program text carries 5 decimals. */
static double r5(double v)
{
    return round(v * 1e5) / 1e5;
}

/* Append a move; the arrays grow as needed. */
static tpb_move_t *push(tpb_program_t *p)
{
    if (p->n == p->cap) {
        p->cap = p->cap ? 2 * p->cap : 1024;
        p->m = realloc(p->m, (size_t)p->cap * sizeof(*p->m));
    }
    tpb_move_t *m = &p->m[p->n++];
    memset(m, 0, sizeof(*m));
    m->line = p->n + 3;
    return m;
}

/* Last end point (the start when empty). */
static const double *last(const tpb_program_t *p)
{
    return p->n ? p->m[p->n - 1].end : p->start;
}

static void line_to(tpb_program_t *p, double x, double y, double z, double f, double tol, double q)
{
    tpb_move_t *m = push(p);
    m->end[0] = r5(x);
    m->end[1] = r5(y);
    m->end[2] = r5(z);
    m->feed = f;
    m->tol = tol;
    m->naive = q;
}

/* Arc to end about center (both rounded) counter-clockwise about normal n. */
static void arc_to(tpb_program_t *p, const double *end, const double *center, const double *n, double f,
                   double tol)
{
    tpb_move_t *m = push(p);
    m->arc = 1;
    for (int i = 0; i < 3; i++) {
        m->end[i] = r5(end[i]);
        m->center[i] = r5(center[i]);
        m->normal[i] = n[i];
    }
    m->feed = f;
    m->tol = tol;
    m->naive = tol;
}

/* n chords of length c on a circle of radius 20 through the origin, centre (-20, 0). */
static void chords(tpb_program_t *p, int n, double c, double f)
{
    double R = 20.0, step = 2.0 * asin(c / (2.0 * R));
    for (int i = 1; i <= n; i++)
        line_to(p, -R + R * cos(i * step), R * sin(i * step), 0.0, f, 0.01, 0.0);
}

/* Boustrophedon raster of 200 x 100 points over a 2 mm bump. */
static void raster(tpb_program_t *p)
{
    int nx = 200, ny = 100;
    double lx = 19.9, ly = 19.8, amp = 2.0, dx = lx / (nx - 1), dy = ly / (ny - 1);
    for (int j = 0; j < ny; j++)
        for (int k = 0; k < nx; k++) {
            int i = j % 2 == 0 ? k : nx - 1 - k;
            double x = i * dx, y = j * dy;
            double sx = sin(M_PI * x / lx), sy = sin(M_PI * y / ly);
            line_to(p, x, y, amp * sx * sx * sy * sy, 3000, 0.01, 0.01);
        }
}

/* 200 legs of (2, +-5). */
static void zigzag(tpb_program_t *p)
{
    for (int i = 1; i <= 200; i++)
        line_to(p, i * 2.0, i % 2 ? 5.0 : 0.0, 0.0, 3000, 0.05, 0.05);
}

/* Arc in the plane of axes (a, b) with normal axis c: to (ea, eb), centre offset (ia, ib). */
static void plane_arc(tpb_program_t *p, int a, int b, int c, double ea, double eb, double ia, double ib,
                      int ccw, double ec)
{
    const double *s = last(p);
    double end[3] = {s[0], s[1], s[2]}, cen[3] = {s[0], s[1], s[2]}, n[3] = {0, 0, 0};
    end[a] = ea;
    end[b] = eb;
    end[c] = ec;
    cen[a] = s[a] + ia;
    cen[b] = s[b] + ib;
    n[c] = ccw ? 1.0 : -1.0;
    arc_to(p, end, cen, n, 3000, 0.01);
}

/* XY arc with R: the shorter arc to (x, y), counter-clockwise when ccw. */
static void radius_arc(tpb_program_t *p, double x, double y, double r, int ccw)
{
    const double *s = last(p);
    double mx = 0.5 * (s[0] + x), my = 0.5 * (s[1] + y), dx = x - s[0], dy = y - s[1];
    double c = hypot(dx, dy), h = sqrt(fmax(0.0, r * r - 0.25 * c * c));
    double side = ccw ? 1.0 : -1.0;
    double cen[3] = {mx - side * h * dy / c, my + side * h * dx / c, s[2]};
    double end[3] = {x, y, s[2]}, n[3] = {0, 0, ccw ? 1.0 : -1.0};
    arc_to(p, end, cen, n, 3000, 0.01);
}

/* Small arcs: S-curves of semicircles, quarter-arc cusps, XZ and YZ arcs, a helix, a spiral. */
static void small_arcs(tpb_program_t *p)
{
    static const double radii[8] = {0.2, 0.5, 1.0, 2.0, 0.3, 0.8, 1.5, 0.25};
    double x = 0, y = 0, z = 0;
    for (int k = 0; k < 64; k++) {
        double r = radii[k % 8];
        plane_arc(p, 0, 1, 2, r5(x + 2 * r), r5(y), r, 0, k % 2 != 0, z);
        x += 2 * r;
        if (k % 4 == 3) {
            x += 0.3;
            line_to(p, x, y, z, 3000, 0.01, 0.01);
        }
    }
    for (int k = 0; k < 48; k++) {
        double r = radii[(k + 3) % 8];
        if (k % 2 == 0) {
            plane_arc(p, 0, 1, 2, r5(x + r), r5(y + r), 0, r, 1, z);
            x += r;
            y += r;
        } else {
            plane_arc(p, 0, 1, 2, r5(x + r), r5(y - r), 0, -r, 0, z);
            x += r;
            y -= r;
        }
    }
    for (int k = 0; k < 32; k++) {
        double r = radii[(k + 1) % 8];
        /* G18: Z first, X second; counter-clockwise about +Y */
        plane_arc(p, 2, 0, 1, r5(z), r5(x + 2 * r), 0, r, k % 2 == 0, y);
        x += 2 * r;
    }
    for (int k = 0; k < 32; k++) {
        double r = radii[(k + 5) % 8];
        plane_arc(p, 1, 2, 0, r5(y + 2 * r), r5(z), r, 0, k % 2 == 0, x);
        y += 2 * r;
    }
    double cx = x - 1.0;
    for (int k = 0; k < 8; k++) {
        z += 0.1;
        plane_arc(p, 0, 1, 2, r5(x), r5(y), -1.0, 0.0, 0, r5(z));
    }
    for (int k = 0; k < 24; k++) {
        double r = 1.0 + 0.05 * (k + 1), a = (k + 1) * M_PI / 3.0;
        radius_arc(p, r5(cx + r * cos(a)), r5(y + r * sin(a)), r, 1);
    }
}

/* The picture in docs/planner.md: a five-pointed star (sharp corners), a short line out to a circle
 * of 0.1 mm chords around it (a 90 degree corner); G64 P0.05, F24000. */
static void demo(tpb_program_t *p)
{
    double R = 20.0, r = 8.0, Rc = 22.5;
    for (int k = 0; k <= 10; k++) {
        double a = M_PI / 2 + k * M_PI / 5, rr = k % 2 ? r : R;
        line_to(p, rr * cos(a), rr * sin(a), 0.0, 24000, 0.05, 0.0);
    }
    line_to(p, 0.0, Rc, 0.0, 24000, 0.05, 0.0);
    double step = 2.0 * asin(0.05 / Rc);
    int chords = (int)(2.0 * M_PI / step);
    for (int k = 1; k <= chords; k++)
        line_to(p, Rc * sin(k * step), Rc * cos(k * step), 0.0, 24000, 0.05, 0.0);
}

/* Build a named program; 0, or -1 for an unknown name. */
int tpb_make(tpb_program_t *p, const char *name)
{
    memset(p, 0, sizeof(*p));
    p->name = name;
    if (!strcmp(name, tpb_names[0]))
        chords(p, 5000, 0.05, 6000);
    else if (!strcmp(name, tpb_names[1]))
        chords(p, 5000, 0.01, 3000);
    else if (!strcmp(name, tpb_names[2]))
        chords(p, 2000, 0.5, 12000);
    else if (!strcmp(name, tpb_names[3]))
        raster(p);
    else if (!strcmp(name, tpb_names[4]))
        zigzag(p);
    else if (!strcmp(name, tpb_names[5]))
        small_arcs(p);
    else if (!strcmp(name, "demo"))
        demo(p);
    else
        return -1;
    return 0;
}

/* A long CAM-like program: chords along a wandering curve, segments 0.02-0.2 mm, F3000. */
int tpb_make_long(tpb_program_t *p, int segments)
{
    memset(p, 0, sizeof(*p));
    p->name = "long";
    double x = 0, y = 0, z = 0, h = 0;
    for (int k = 0; k < segments; k++) {
        double len = 0.02 + 0.18 * (0.5 + 0.5 * sin(k * 0.013));
        h += 0.02 * sin(k * 0.0071) + 0.3 * (k % 997 == 0);
        x += len * cos(h);
        y += len * sin(h);
        z = 0.5 * sin(k * 0.0037);
        line_to(p, x, y, z, 3000, 0.01, 0.0);
    }
    return 0;
}

void tpb_free(tpb_program_t *p)
{
    free(p->m);
    p->m = NULL;
    p->n = p->cap = 0;
}
