/* matrix_math.c: linear XYZ correction (squareness, scale) with a 3x3 matrix. */
#include <math.h>
#include "cartesian_math.h"

/* Determinants below this (relative to the matrix scale) count as singular. */
#define MATRIX_SINGULAR 1e-12

/* J0..J2 = m * (X, Y, Z); the other joints follow their axes. */
void matrix_inverse_kins(const matrix3_t *mat, const EmcPose *pos, double *joints)
{
    const double v[3] = {pos->tran.x, pos->tran.y, pos->tran.z};
    for (int r = 0; r < 3; r++)
        joints[r] = mat->m[r][0] * v[0] + mat->m[r][1] * v[1] + mat->m[r][2] * v[2];
    cart_pass_inverse(pos, joints, 3);
}

/* Cofactor (r, c) of the matrix, signed. */
static double cofactor(const double m[3][3], int r, int c)
{
    int r0 = (r + 1) % 3, r1 = (r + 2) % 3, c0 = (c + 1) % 3, c1 = (c + 2) % 3;
    return m[r0][c0] * m[r1][c1] - m[r0][c1] * m[r1][c0];
}

/* Largest absolute entry, the scale the singularity test is relative to. */
static double max_abs(const double m[3][3])
{
    double big = 0.0;
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 3; c++)
            big = fmax(big, fabs(m[r][c]));
    return big;
}

/* (X, Y, Z) = m^-1 * (J0, J1, J2); -1 for a singular matrix. */
int matrix_forward_kins(const matrix3_t *mat, const double *joints, EmcPose *pos)
{
    double det = 0.0, scale = max_abs(mat->m);
    for (int c = 0; c < 3; c++)
        det += mat->m[0][c] * cofactor(mat->m, 0, c);
    if (!(fabs(det) > MATRIX_SINGULAR * scale * scale * scale))
        return -1;
    double out[3];
    for (int r = 0; r < 3; r++)
        out[r] = (cofactor(mat->m, 0, r) * joints[0] + cofactor(mat->m, 1, r) * joints[1]
                  + cofactor(mat->m, 2, r) * joints[2]) / det;
    pos->tran.x = out[0];
    pos->tran.y = out[1];
    pos->tran.z = out[2];
    cart_pass_forward(joints, pos, 3);
    return 0;
}
