/* penta_math.c: pentapod (LinuxCNC pentakins): five struts to rings on the spindle axis set X Y Z A B. */
#include <math.h>
#include "parallel_math.h"
#include "gauss_jordan.h"

#define DEG (M_PI / 180.0)
#define PENTA_DOF 5
#define PENTA_DIFF_STEP 1e-4   /* forward-difference step of the Jacobian (mm / radians) */

/* LinuxCNC's default machine (pentakins params at load). */
const penta_geom_t penta_default_geom = {
    .base = {{-418.03, 324.56, 895.56}, {417.96, 324.56, 895.56}, {-418.03, -325.44, 895.56},
             {417.96, -325.44, 895.56}, {-0.06, -492.96, 895.56}},
    .ring_r = {80.32, 80.32, 80.32, 80.32, 80.32},
    .ring_z = {-185.5, -159.5, -67.5, -41.5, -14.0},
    .convergence = 1e-9,
    .limit_iterations = 120,
    .max_error = 100.0,
};

/* Strut lengths for q = (x, y, z, roll, pitch) with the angles in radians: each base point seen from
 * the effector frame (v = R^T (b - P)), then the distance to the ring of radius r at height z. */
static void strut_lengths(const penta_geom_t *g, const double *q, double *len)
{
    double cr = cos(q[3]), sr = sin(q[3]), cp = cos(q[4]), sp = sin(q[4]);
    double col_x[3] = {cp, 0, -sp}, col_y[3] = {sp * sr, cr, cp * sr}, col_z[3] = {sp * cr, -sr, cp * cr};
    for (int k = 0; k < PENTA_STRUTS; k++) {
        double d[3] = {g->base[k][0] - q[0], g->base[k][1] - q[1], g->base[k][2] - q[2]};
        double vx = col_x[0] * d[0] + col_x[1] * d[1] + col_x[2] * d[2];
        double vy = col_y[0] * d[0] + col_y[1] * d[1] + col_y[2] * d[2];
        double vz = col_z[0] * d[0] + col_z[1] * d[1] + col_z[2] * d[2];
        double radial = sqrt(vx * vx + vy * vy) - g->ring_r[k], axial = vz - g->ring_z[k];
        len[k] = sqrt(axial * axial + radial * radial);
    }
}

/* Strut lengths from the pose; other axes pass through. */
int penta_inverse(const penta_geom_t *g, const EmcPose *pos, double *joints)
{
    double q[PENTA_DOF] = {pos->tran.x, pos->tran.y, pos->tran.z, pos->a * DEG, pos->b * DEG};
    strut_lengths(g, q, joints);
    cart_pass_inverse(pos, joints, PENTA_DOF);
    return 0;
}

/* Forward-difference Jacobian d(strut k)/d(q i). */
static void jacobian(const penta_geom_t *g, const double *q, const double *len, double jac[GJ_MAX_N][GJ_MAX_N])
{
    for (int i = 0; i < PENTA_DOF; i++) {
        double qs[PENTA_DOF], ls[PENTA_STRUTS];
        for (int k = 0; k < PENTA_DOF; k++)
            qs[k] = q[k];
        qs[i] += PENTA_DIFF_STEP;
        strut_lengths(g, qs, ls);
        for (int k = 0; k < PENTA_STRUTS; k++)
            jac[k][i] = (ls[k] - len[k]) / PENTA_DIFF_STEP;
    }
}

/* One Newton step: q -= J^-1 diff; *err is the summed |diff|. Returns 1 when every |diff| is within
 * the convergence criterion (before the step), 0 to go on, -1 when the Jacobian is singular. */
static int newton_step(const penta_geom_t *g, const double *joints, double *q, double *err)
{
    double len[PENTA_STRUTS], diff[PENTA_STRUTS], jac[GJ_MAX_N][GJ_MAX_N], inv[GJ_MAX_N][GJ_MAX_N];
    int converged = 1;
    strut_lengths(g, q, len);
    *err = 0;
    for (int k = 0; k < PENTA_STRUTS; k++) {
        diff[k] = len[k] - joints[k];
        *err += fabs(diff[k]);
        if (!(fabs(diff[k]) <= g->convergence))
            converged = 0;
    }
    jacobian(g, q, len, jac);
    if (gj_invert(PENTA_DOF, jac, inv) < 0)
        return -1;
    for (int i = 0; i < PENTA_DOF; i++) {
        double delta = 0;
        for (int k = 0; k < PENTA_STRUTS; k++)
            delta += inv[i][k] * diff[k];
        q[i] -= delta;
    }
    return converged;
}

/* Newton iteration from the pose in *pos; the pose is only written on success. */
int penta_forward(const penta_geom_t *g, const double *joints, EmcPose *pos, unsigned *iterations)
{
    double q[PENTA_DOF] = {pos->tran.x, pos->tran.y, pos->tran.z, pos->a * DEG, pos->b * DEG};
    double err = 1.0;
    unsigned n = 0, limit = g->limit_iterations < PENTA_MAX_ITERATIONS ? g->limit_iterations
                                                                         : PENTA_MAX_ITERATIONS;
    int rc;
    *iterations = 0;
    for (int k = 0; k < PENTA_STRUTS; k++)
        if (!(joints[k] > 0))
            return -1;
    do {
        if (!(err <= g->max_error && err >= -g->max_error))
            return -2;
        if (++n > limit)
            return -5;
        rc = newton_step(g, joints, q, &err);
        if (rc < 0)
            return -2;
    } while (rc == 0);
    *iterations = n;
    pos->tran.x = q[0];
    pos->tran.y = q[1];
    pos->tran.z = q[2];
    pos->a = q[3] / DEG;
    pos->b = q[4] / DEG;
    cart_pass_forward(joints, pos, PENTA_DOF);
    return 0;
}
