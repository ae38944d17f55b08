/* rot3.c: 3x3 rotation matrices for the 5/6-axis kinematics math (pure C). */
#include <math.h>
#include "rot3.h"

#define DEG_TO_RAD (M_PI / 180.0)

/* Rotation by angle_deg about a unit axis vector (Rodrigues' formula). */
rot3_t rot3_about(const double axis[3], double angle_deg)
{
    double s = sin(angle_deg * DEG_TO_RAD), c = cos(angle_deg * DEG_TO_RAD), t = 1.0 - c;
    double x = axis[0], y = axis[1], z = axis[2];
    rot3_t r = {{
        {t * x * x + c,     t * x * y - s * z, t * x * z + s * y},
        {t * x * y + s * z, t * y * y + c,     t * y * z - s * x},
        {t * x * z - s * y, t * y * z + s * x, t * z * z + c},
    }};
    return r;
}

/* Rotation by angle_deg about machine axis 0 X, 1 Y or 2 Z. */
rot3_t rot3_principal(int axis, double angle_deg)
{
    double unit[3] = {0.0, 0.0, 0.0};
    unit[axis >= 0 && axis < 3 ? axis : 2] = 1.0;
    return rot3_about(unit, angle_deg);
}

/* Product a * b. */
rot3_t rot3_mul(const rot3_t *a, const rot3_t *b)
{
    rot3_t r;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            r.m[i][j] = a->m[i][0] * b->m[0][j] + a->m[i][1] * b->m[1][j] +
                        a->m[i][2] * b->m[2][j];
    return r;
}

/* out = r * v (out may alias v). */
void rot3_apply(const rot3_t *r, const double v[3], double out[3])
{
    double t[3];
    for (int i = 0; i < 3; i++)
        t[i] = r->m[i][0] * v[0] + r->m[i][1] * v[1] + r->m[i][2] * v[2];
    out[0] = t[0];
    out[1] = t[1];
    out[2] = t[2];
}

/* out = transpose(r) * v, the inverse rotation (out may alias v). */
void rot3_apply_inv(const rot3_t *r, const double v[3], double out[3])
{
    double t[3];
    for (int i = 0; i < 3; i++)
        t[i] = r->m[0][i] * v[0] + r->m[1][i] * v[1] + r->m[2][i] * v[2];
    out[0] = t[0];
    out[1] = t[1];
    out[2] = t[2];
}

/* 1 when all n values are finite numbers. */
int rot3_all_finite(const double *v, int n)
{
    for (int i = 0; i < n; i++)
        if (!isfinite(v[i]))
            return 0;
    return 1;
}
