/* penta_math.c: pentapod: five struts to rings on the tool axis set X Y Z A B. */
#include <math.h>
#include "parallel_math.h"

#define DEG (M_PI / 180.0)
#define PENTA_DOF 5
#define PENTA_STEP 1e-6        /* finite-difference step (mm / degrees) */
#define PENTA_PIVOT_MIN 1e-12  /* smaller pivots make the Jacobian singular */

/* Base joints on a 500 mm circle at mixed heights; 80 mm rings at three heights on the tool. */
const penta_geom_t penta_default_geom = {
    .base = {{0.0, 500.0, 1100.0}, {-475.53, 154.51, 600.0}, {-293.89, -404.51, 1100.0},
             {293.89, -404.51, 700.0}, {475.53, 154.51, 700.0}},
    .ring_r = {80.0, 80.0, 80.0, 80.0, 80.0},
    .ring_z = {0.0, 0.0, 300.0, 400.0, 400.0},
    .convergence = 1e-9,
    .limit_iterations = 120,
    .max_error = 500.0,
};

/* Distance from base point b to the ring around point p with axis n. */
static double strut_length(const double *b, const double *p, const double *n, double r, double z)
{
    double d[3], h = 0.0, rho2 = 0.0;
    for (int i = 0; i < 3; i++) {
        d[i] = b[i] - (p[i] + z * n[i]);
        h += d[i] * n[i];
    }
    for (int i = 0; i < 3; i++)
        rho2 += (d[i] - h * n[i]) * (d[i] - h * n[i]);
    double radial = sqrt(rho2) - r;
    return sqrt(h * h + radial * radial);
}

/* All strut lengths for q = (x, y, z, a, b) with a, b in degrees. */
static void strut_lengths(const penta_geom_t *g, const double *q, double *len)
{
    double a = q[3] * DEG, b = q[4] * DEG;
    double n[3] = {cos(a) * sin(b), -sin(a), cos(a) * cos(b)};
    for (int k = 0; k < PENTA_STRUTS; k++)
        len[k] = strut_length(g->base[k], q, n, g->ring_r[k], g->ring_z[k]);
}

/* Strut lengths from the pose; other axes pass through. */
int penta_inverse(const penta_geom_t *g, const EmcPose *pos, double *joints)
{
    double q[PENTA_DOF] = {pos->tran.x, pos->tran.y, pos->tran.z, pos->a, pos->b};
    double len[PENTA_STRUTS];
    strut_lengths(g, q, len);
    for (int k = 0; k < PENTA_STRUTS; k++) {
        if (!isfinite(len[k]))
            return -1;
        joints[k] = len[k];
    }
    cart_pass_inverse(pos, joints, PENTA_DOF);
    return 0;
}

/* Central-difference Jacobian d(strut k)/d(q i). */
static void jacobian(const penta_geom_t *g, const double *q, double jac[PENTA_DOF][PENTA_DOF])
{
    for (int i = 0; i < PENTA_DOF; i++) {
        double qp[PENTA_DOF], qm[PENTA_DOF], lp[PENTA_STRUTS], lm[PENTA_STRUTS];
        for (int k = 0; k < PENTA_DOF; k++)
            qp[k] = qm[k] = q[k];
        qp[i] += PENTA_STEP;
        qm[i] -= PENTA_STEP;
        strut_lengths(g, qp, lp);
        strut_lengths(g, qm, lm);
        for (int k = 0; k < PENTA_STRUTS; k++)
            jac[k][i] = (lp[k] - lm[k]) / (2.0 * PENTA_STEP);
    }
}

/* Swap rows r and s of the augmented system. */
static void swap_rows(double m[PENTA_DOF][PENTA_DOF], double *v, int r, int s)
{
    for (int c = 0; c < PENTA_DOF; c++) {
        double t = m[r][c];
        m[r][c] = m[s][c];
        m[s][c] = t;
    }
    double t = v[r];
    v[r] = v[s];
    v[s] = t;
}

/* Solve m x = v in place (x left in v) by elimination with partial pivoting; -1 if singular. */
static int solve5(double m[PENTA_DOF][PENTA_DOF], double *v)
{
    for (int c = 0; c < PENTA_DOF; c++) {
        int piv = c;
        for (int r = c + 1; r < PENTA_DOF; r++)
            if (fabs(m[r][c]) > fabs(m[piv][c]))
                piv = r;
        if (!(fabs(m[piv][c]) > PENTA_PIVOT_MIN))
            return -1;
        swap_rows(m, v, c, piv);
        for (int r = c + 1; r < PENTA_DOF; r++) {
            double f = m[r][c] / m[c][c];
            for (int k = c; k < PENTA_DOF; k++)
                m[r][k] -= f * m[c][k];
            v[r] -= f * v[c];
        }
    }
    for (int c = PENTA_DOF - 1; c >= 0; c--) {
        for (int k = c + 1; k < PENTA_DOF; k++)
            v[c] -= m[c][k] * v[k];
        v[c] /= m[c][c];
    }
    return 0;
}

/* One Newton step; 1 when converged, 0 to go on, -1 on a singular or oversized step. */
static int newton_step(const penta_geom_t *g, const double *joints, double *q)
{
    double len[PENTA_STRUTS], jac[PENTA_DOF][PENTA_DOF], err = 0.0;
    strut_lengths(g, q, len);
    for (int k = 0; k < PENTA_STRUTS; k++) {
        len[k] = joints[k] - len[k];
        err = fmax(err, fabs(len[k]));
    }
    if (!isfinite(err))
        return -1;
    if (err < g->convergence)
        return 1;
    jacobian(g, q, jac);
    if (solve5(jac, len) < 0)
        return -1;
    for (int i = 0; i < PENTA_DOF; i++) {
        if (!(fabs(len[i]) <= g->max_error))
            return -1;
        q[i] += len[i];
    }
    return 0;
}

/* Newton iteration from the pose in *pos; the pose is only written on success. */
int penta_forward(const penta_geom_t *g, const double *joints, EmcPose *pos, unsigned *iterations)
{
    double q[PENTA_DOF] = {pos->tran.x, pos->tran.y, pos->tran.z, pos->a, pos->b};
    unsigned n = 0;
    int rc = 0;
    while (n < g->limit_iterations && n < PENTA_MAX_ITERATIONS && (rc = newton_step(g, joints, q)) == 0)
        n++;
    *iterations = n;
    if (rc != 1)
        return -1;
    pos->tran.x = q[0];
    pos->tran.y = q[1];
    pos->tran.z = q[2];
    pos->a = q[3];
    pos->b = q[4];
    cart_pass_forward(joints, pos, PENTA_DOF);
    return 0;
}
