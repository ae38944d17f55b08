/* genhex_math.c: hexapod strut lengths from a pose (closed form) and a pose from lengths (Newton). */
#include <math.h>
#include <string.h>
#include "genhex_math.h"

#define DOF 6
#define FD_STEP 1e-6          /* finite-difference step of the Jacobian (mm, degrees) */

/* Default base joints (z 0) and platform joints of the sample machine, x and y pairs. */
static const double default_base_xy[GENHEX_STRUTS][2] = {
    {-22.950, 13.250}, {22.950, 13.250}, {22.950, 13.250},
    {0.000, -26.500}, {0.000, -26.500}, {-22.950, 13.250}};
static const double default_platform_xy[GENHEX_STRUTS][2] = {
    {-1.000, 11.500}, {1.000, 11.500}, {10.459, -4.884},
    {9.459, -6.616}, {-9.459, -6.616}, {-10.459, -4.884}};

/* Fill in the default geometry: joint axes along +Z, no twist correction, no tool. */
void genhex_default_geometry(genhex_geom_t *geom)
{
    memset(geom, 0, sizeof(*geom));
    for (int i = 0; i < GENHEX_STRUTS; i++) {
        geom->base[i] = (PmCartesian){default_base_xy[i][0], default_base_xy[i][1], 0.0};
        geom->platform[i] = (PmCartesian){default_platform_xy[i][0], default_platform_xy[i][1], 0.0};
        geom->base_n[i] = (PmCartesian){0.0, 0.0, 1.0};
        geom->platform_n[i] = (PmCartesian){0.0, 0.0, 1.0};
    }
}

/* Rotation matrix Rz(c) Ry(b) Rx(a) (roll a, pitch b, yaw c in degrees). */
void genhex_rotation(double a_deg, double b_deg, double c_deg, double m[3][3])
{
    double ra = a_deg * M_PI / 180.0, rb = b_deg * M_PI / 180.0, rc = c_deg * M_PI / 180.0;
    double sa = sin(ra), ca = cos(ra), sb = sin(rb), cb = cos(rb), sc = sin(rc), cc = cos(rc);
    m[0][0] = cc * cb; m[0][1] = cc * sb * sa - sc * ca; m[0][2] = cc * sb * ca + sc * sa;
    m[1][0] = sc * cb; m[1][1] = sc * sb * sa + cc * ca; m[1][2] = sc * sb * ca - cc * sa;
    m[2][0] = -sb;     m[2][1] = cb * sa;                m[2][2] = cb * ca;
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

/* v / |v| into *unit; -1 when v is (nearly) zero. */
static int unit(PmCartesian v, PmCartesian *unit_out)
{
    double n = sqrt(dot(v, v));
    if (n < 1e-12)
        return -1;
    *unit_out = (PmCartesian){v.x / n, v.y / n, v.z / n};
    return 0;
}

/* Length change from the twist between the two joint axes of a strut: lead * angle / 2pi. */
static int twist_correction(const genhex_geom_t *geom, int i, PmCartesian strut_unit,
                            const double rot[3][3], double *correction)
{
    PmCartesian base_perp, plat_perp;
    *correction = 0.0;
    if (geom->screw_lead == 0.0)
        return 0;
    PmCartesian nb = cross(strut_unit, cross(geom->base_n[i], strut_unit));
    PmCartesian np = cross(mat_vec(rot, geom->platform_n[i]), strut_unit);
    if (unit(nb, &base_perp) < 0 || unit(np, &plat_perp) < 0)
        return GENHEX_DEGENERATE;
    double s = dot(base_perp, plat_perp);
    s = s > 1.0 ? 1.0 : (s < -1.0 ? -1.0 : s);
    *correction = geom->screw_lead * asin(s) / (2.0 * M_PI);
    return 0;
}

/* Pose -> six strut lengths: |origin + R p_i - b_i| plus the twist correction. */
int genhex_inverse(const genhex_geom_t *geom, const EmcPose *pos, double lengths[GENHEX_STRUTS])
{
    double rot[3][3];
    genhex_rotation(pos->a, pos->b, pos->c, rot);
    PmCartesian down = mat_vec(rot, (PmCartesian){0.0, 0.0, geom->tool_length});
    PmCartesian origin = {pos->tran.x + down.x, pos->tran.y + down.y, pos->tran.z + down.z};
    for (int i = 0; i < GENHEX_STRUTS; i++) {
        PmCartesian p = mat_vec(rot, geom->platform[i]), u;
        PmCartesian strut = {origin.x + p.x - geom->base[i].x, origin.y + p.y - geom->base[i].y,
                             origin.z + p.z - geom->base[i].z};
        double correction;
        if (unit(strut, &u) < 0 || twist_correction(geom, i, u, rot, &correction) < 0)
            return GENHEX_DEGENERATE;
        lengths[i] = sqrt(dot(strut, strut)) + correction;
    }
    return 0;
}

/* Pose <-> the six unknowns x y z a b c. */
static void pose_to_q(const EmcPose *pos, double q[DOF])
{
    q[0] = pos->tran.x; q[1] = pos->tran.y; q[2] = pos->tran.z;
    q[3] = pos->a; q[4] = pos->b; q[5] = pos->c;
}

/* Copy the six unknowns into a pose (U V W untouched). */
static void q_to_pose(const double q[DOF], EmcPose *pos)
{
    pos->tran.x = q[0]; pos->tran.y = q[1]; pos->tran.z = q[2];
    pos->a = q[3]; pos->b = q[4]; pos->c = q[5];
}

/* Strut lengths at q minus the targets. */
static int residual(const genhex_geom_t *geom, const double q[DOF], const double *target, double r[DOF])
{
    EmcPose p;
    memset(&p, 0, sizeof(p));
    q_to_pose(q, &p);
    if (genhex_inverse(geom, &p, r) < 0)
        return GENHEX_DEGENERATE;
    for (int i = 0; i < DOF; i++)
        r[i] -= target[i];
    return 0;
}

/* Jacobian d(lengths)/dq by forward differences around q (r0 = residual at q). */
static int jacobian(const genhex_geom_t *geom, const double q[DOF], const double *target,
                    const double r0[DOF], double jac[DOF][DOF])
{
    double qs[DOF], r[DOF];
    for (int k = 0; k < DOF; k++) {
        memcpy(qs, q, sizeof(qs));
        qs[k] += FD_STEP;
        if (residual(geom, qs, target, r) < 0)
            return GENHEX_DEGENERATE;
        for (int i = 0; i < DOF; i++)
            jac[i][k] = (r[i] - r0[i]) / FD_STEP;
    }
    return 0;
}

/* Solve jac * x = rhs by Gaussian elimination with partial pivoting; GENHEX_SINGULAR if stuck. */
static int solve6(double jac[DOF][DOF], double rhs[DOF], double x[DOF])
{
    for (int col = 0; col < DOF; col++) {
        int piv = col;
        for (int row = col + 1; row < DOF; row++)
            if (fabs(jac[row][col]) > fabs(jac[piv][col]))
                piv = row;
        if (fabs(jac[piv][col]) < 1e-12)
            return GENHEX_SINGULAR;
        for (int k = 0; k < DOF; k++) {
            double t = jac[col][k]; jac[col][k] = jac[piv][k]; jac[piv][k] = t;
        }
        double t = rhs[col]; rhs[col] = rhs[piv]; rhs[piv] = t;
        for (int row = col + 1; row < DOF; row++) {
            double f = jac[row][col] / jac[col][col];
            for (int k = col; k < DOF; k++)
                jac[row][k] -= f * jac[col][k];
            rhs[row] -= f * rhs[col];
        }
    }
    for (int row = DOF - 1; row >= 0; row--) {
        double s = rhs[row];
        for (int k = row + 1; k < DOF; k++)
            s -= jac[row][k] * x[k];
        x[row] = s / jac[row][row];
    }
    return 0;
}

/* Largest absolute value of the six residuals. */
static double largest(const double r[DOF])
{
    double m = 0.0;
    for (int i = 0; i < DOF; i++)
        m = fmax(m, fabs(r[i]));
    return m;
}

/* One Newton step q -= J^-1 r (r = residual at q); 0 or a failure code. */
static int newton_step(const genhex_geom_t *geom, double q[DOF], const double *target,
                       double r[DOF], double max_step)
{
    double jac[DOF][DOF], dq[DOF];
    if (jacobian(geom, q, target, r, jac) < 0)
        return GENHEX_DEGENERATE;
    if (solve6(jac, r, dq) < 0)
        return GENHEX_SINGULAR;
    for (int k = 0; k < DOF; k++) {
        if (!isfinite(dq[k]) || fabs(dq[k]) > max_step)
            return GENHEX_RUNAWAY;
        q[k] -= dq[k];
    }
    return 0;
}

/* Strut lengths -> pose by Newton-Raphson from *pos, at most limit_iterations steps. */
int genhex_forward(const genhex_geom_t *geom, const double lengths[GENHEX_STRUTS], EmcPose *pos,
                   genhex_solve_t *solve)
{
    double q[DOF], r[DOF];
    pose_to_q(pos, q);
    solve->iterations = 0;
    for (;;) {
        if (residual(geom, q, lengths, r) < 0)
            return GENHEX_DEGENERATE;
        solve->error = largest(r);
        if (solve->error < solve->conv_criterion) {
            q_to_pose(q, pos);
            return 0;
        }
        if (solve->iterations >= solve->limit_iterations || solve->iterations >= GENHEX_MAX_ITERATIONS)
            return GENHEX_NO_CONVERGENCE;
        solve->iterations++;
        int rc = newton_step(geom, q, lengths, r, solve->max_error);
        if (rc < 0)
            return rc;
    }
}
