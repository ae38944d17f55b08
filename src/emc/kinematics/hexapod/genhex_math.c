/* genhex_math.c: hexapod strut lengths from a pose (closed form) and a pose from lengths (Newton with the
 * analytic Jacobian and LinuxCNC's Gauss-Jordan inverse). */
#include <math.h>
#include <string.h>
#include "genhex_math.h"
#include "emc/kinematics/parallel/gauss_jordan.h"

#define DOF 6
#define DEG (M_PI / 180.0)
#define SQRT_HALF 0.707107
#define SIN_60 0.866025

/* LinuxCNC's sample machine: base and platform joints, then their joint axes. */
static const double default_base[GENHEX_STRUTS][3] = {
    {-22.95, 13.25, 0}, {22.95, 13.25, 0}, {22.95, 13.25, 0}, {0, -26.5, 0}, {0, -26.5, 0}, {-22.95, 13.25, 0}};
static const double default_platform[GENHEX_STRUTS][3] = {
    {-1, 11.5, 0}, {1, 11.5, 0}, {10.459, -4.884, 0}, {9.459, -6.616, 0}, {-9.459, -6.616, 0}, {-10.459, -4.884, 0}};
static const double default_base_n[GENHEX_STRUTS][3] = {
    {SQRT_HALF, 0, SQRT_HALF}, {0, -SQRT_HALF, SQRT_HALF}, {-SQRT_HALF, 0, SQRT_HALF},
    {-SQRT_HALF, 0, SQRT_HALF}, {0, SQRT_HALF, SQRT_HALF}, {SQRT_HALF, 0, SQRT_HALF}};
static const double default_platform_n[GENHEX_STRUTS][3] = {
    {-1, 0, 0}, {SIN_60, 0.5, 0}, {SIN_60, 0.5, 0}, {SIN_60, -0.5, 0}, {SIN_60, -0.5, 0}, {-1, 0, 0}};

/* A PmCartesian from three numbers. */
static PmCartesian vec(const double v[3])
{
    return (PmCartesian){v[0], v[1], v[2]};
}

/* Fill in the default geometry. */
void genhex_default_geometry(genhex_geom_t *geom)
{
    memset(geom, 0, sizeof(*geom));
    for (int i = 0; i < GENHEX_STRUTS; i++) {
        geom->base[i] = vec(default_base[i]);
        geom->platform[i] = vec(default_platform[i]);
        geom->base_n[i] = vec(default_base_n[i]);
        geom->platform_n[i] = vec(default_platform_n[i]);
    }
}

/* Rotation matrix Rz(c) Ry(b) Rx(a) from radians. */
static void rotation_rad(double ra, double rb, double rc, double m[3][3])
{
    double sa = sin(ra), ca = cos(ra), sb = sin(rb), cb = cos(rb), sc = sin(rc), cc = cos(rc);
    m[0][0] = cc * cb; m[0][1] = cc * sb * sa - sc * ca; m[0][2] = cc * sb * ca + sc * sa;
    m[1][0] = sc * cb; m[1][1] = sc * sb * sa + cc * ca; m[1][2] = sc * sb * ca - cc * sa;
    m[2][0] = -sb;     m[2][1] = cb * sa;                m[2][2] = cb * ca;
}

/* Rotation matrix Rz(c) Ry(b) Rx(a) (roll a, pitch b, yaw c in degrees). */
void genhex_rotation(double a_deg, double b_deg, double c_deg, double m[3][3])
{
    rotation_rad(a_deg * DEG, b_deg * DEG, c_deg * DEG, m);
}

/* m * v. */
static PmCartesian mat_vec(const double m[3][3], PmCartesian v)
{
    return (PmCartesian){m[0][0] * v.x + m[0][1] * v.y + m[0][2] * v.z,
                         m[1][0] * v.x + m[1][1] * v.y + m[1][2] * v.z,
                         m[2][0] * v.x + m[2][1] * v.y + m[2][2] * v.z};
}

/* a x b. */
static PmCartesian cross(PmCartesian a, PmCartesian b)
{
    return (PmCartesian){a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

/* a . b. */
static double dot(PmCartesian a, PmCartesian b)
{
    return a.x * b.x + a.y * b.y + a.z * b.z;
}

/* v / |v| (zero stays zero). */
static PmCartesian unit(PmCartesian v)
{
    double n = sqrt(dot(v, v));
    return n > 0 ? (PmCartesian){v.x / n, v.y / n, v.z / n} : v;
}

/* Joint i of the base and of the platform (in the platform frame), with the z offset added. */
static void joints_of(const genhex_geom_t *g, int i, PmCartesian *b, PmCartesian *a)
{
    *b = g->base[i];
    *a = g->platform[i];
    b->z += g->z_offset;
    a->z += g->z_offset;
}

/* Length change of a non-captive screw from the twist between the joint axes: lead * angle / 2pi. */
static double screw_correction(const genhex_geom_t *g, int i, PmCartesian u, const double rot[3][3])
{
    PmCartesian n3 = unit(cross(u, cross(g->base_n[i], u)));
    PmCartesian m2 = unit(cross(mat_vec(rot, g->platform_n[i]), u));
    double s = dot(n3, m2);
    s = s > 1.0 ? 1.0 : (s < -1.0 ? -1.0 : s);
    return g->screw_lead * asin(s) / (2.0 * M_PI);
}

/* Strut i at origin p and rotation rot: its vector, length (with correction) and correction. */
static int strut(const genhex_geom_t *g, int i, PmCartesian p, const double rot[3][3], PmCartesian *ra,
                 PmCartesian *u, double *length, double *corr)
{
    PmCartesian b, a;
    joints_of(g, i, &b, &a);
    *ra = mat_vec(rot, a);
    PmCartesian s = {p.x + ra->x - b.x, p.y + ra->y - b.y, p.z + ra->z - b.z};
    double len = sqrt(dot(s, s));
    if (!(len > 0))
        return GENHEX_DEGENERATE;
    *u = (PmCartesian){s.x / len, s.y / len, s.z / len};
    *corr = g->screw_lead != 0.0 ? screw_correction(g, i, *u, rot) : 0.0;
    *length = len + *corr;
    return 0;
}

/* Pose -> six strut lengths: |P + R a_i - b_i| plus the screw correction. */
int genhex_inverse(const genhex_geom_t *geom, const EmcPose *pos, double lengths[GENHEX_STRUTS],
                   double corrections[GENHEX_STRUTS])
{
    double rot[3][3];
    genhex_rotation(pos->a, pos->b, pos->c, rot);
    for (int i = 0; i < GENHEX_STRUTS; i++) {
        PmCartesian ra, u;
        double corr;
        if (strut(geom, i, pos->tran, rot, &ra, &u, &lengths[i], &corr) < 0)
            return GENHEX_DEGENERATE;
        if (corrections)
            corrections[i] = corr;
    }
    return 0;
}

/* One Newton step at q = (x, y, z, roll, pitch, yaw in radians): q -= J^-1 diff. Returns 1 when every
 * |diff| was within the criterion, 0 to go on, or a failure code; *err is the summed |diff|. */
static int newton_step(const genhex_geom_t *g, const double *target, double q[DOF], double conv, double *err)
{
    double rot[3][3], jac[GJ_MAX_N][GJ_MAX_N], inv[GJ_MAX_N][GJ_MAX_N], diff[DOF];
    PmCartesian p = {q[0], q[1], q[2]};
    int converged = 1;
    rotation_rad(q[3], q[4], q[5], rot);
    *err = 0;
    for (int i = 0; i < GENHEX_STRUTS; i++) {
        PmCartesian ra, u;
        double len, corr;
        if (strut(g, i, p, rot, &ra, &u, &len, &corr) < 0)
            return GENHEX_DEGENERATE;
        diff[i] = len - target[i];
        *err += fabs(diff[i]);
        converged &= fabs(diff[i]) <= conv;
        PmCartesian w = cross(ra, u);
        double row[DOF] = {u.x, u.y, u.z, w.x, w.y, w.z};
        for (int k = 0; k < DOF; k++)
            jac[i][k] = row[k];
    }
    if (gj_invert(DOF, jac, inv) < 0)
        return GENHEX_RUNAWAY;
    for (int k = 0; k < DOF; k++) {
        double d = 0;
        for (int i = 0; i < GENHEX_STRUTS; i++)
            d += inv[k][i] * diff[i];
        q[k] -= d;
    }
    return converged;
}

/* Strut lengths -> pose by Newton-Raphson from *pos (LinuxCNC's checks and return codes). */
int genhex_forward(const genhex_geom_t *geom, const double lengths[GENHEX_STRUTS], EmcPose *pos,
                   genhex_solve_t *solve)
{
    double q[DOF] = {pos->tran.x, pos->tran.y, pos->tran.z, pos->a * DEG, pos->b * DEG, pos->c * DEG};
    double err = 1.0;
    unsigned limit = solve->limit_iterations < GENHEX_MAX_ITERATIONS ? solve->limit_iterations
                                                                      : GENHEX_MAX_ITERATIONS;
    int rc;
    solve->iterations = 0;
    for (int i = 0; i < GENHEX_STRUTS; i++)
        if (!(lengths[i] > 0))
            return GENHEX_DEGENERATE;
    do {
        if (!(err <= solve->max_error && err >= -solve->max_error))
            return GENHEX_RUNAWAY;
        if (++solve->iterations > limit)
            return GENHEX_NO_CONVERGENCE;
        rc = newton_step(geom, lengths, q, solve->conv_criterion, &err);
        if (rc < 0)
            return rc;
    } while (rc == 0);
    pos->tran = (PmCartesian){q[0], q[1], q[2]};
    pos->a = q[3] / DEG;
    pos->b = q[4] / DEG;
    pos->c = q[5] / DEG;
    return 0;
}
