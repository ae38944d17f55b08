/* matrixkins.c: 3x3 calibration-matrix kinematics (LinuxCNC's template module): the params C_xx..C_zz
 * appear at the first type query. */
#include "rtapi.h"
#include "hal.h"
#include "emc/kinematics/kins_template.h"
#include "cartesian_math.h"

MODULE_DESCRIPTION("Cartesian kinematics with a 3x3 squareness and scale calibration matrix");

static hal_float_t *coef;   /* C_xx C_xy C_xz C_yx ... C_zz, row by row, in HAL memory */

/* Load-time pin of one instance: <prefix>.dummy (bit OUT, TRUE). */
static int instance(int comp_id, int i, const char *prefix)
{
    hal_bit_t **dummy = hal_malloc(sizeof(*dummy));
    (void)i;
    if (!dummy)
        return -ENOMEM;
    int r = hal_pin_bit_newf(HAL_OUT, dummy, comp_id, "%s.dummy", prefix);
    if (r == 0)
        **dummy = 1;
    return r;
}

/* Params matrixkins.C_xx .. C_zz (the identity), at the first type query. */
static int setup(int comp_id)
{
    static const char axis[3] = {'x', 'y', 'z'};
    coef = hal_malloc(9 * sizeof(*coef));
    if (!coef)
        return -ENOMEM;
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 3; c++) {
            int e = hal_param_float_newf(HAL_RW, &coef[3 * r + c], comp_id, "matrixkins.C_%c%c", axis[r], axis[c]);
            if (e)
                return e;
            coef[3 * r + c] = r == c;
        }
    return 0;
}

/* The matrix from the params (identity before they exist). */
static matrix3_t matrix(void)
{
    matrix3_t m;
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 3; c++)
            m.m[r][c] = coef ? coef[3 * r + c] : r == c;
    return m;
}

/* Joints -> world: X Y Z = M^-1 (J0 J1 J2); A..W = J3..J8; a singular matrix is refused (LinuxCNC
 * returns inf/NaN there). */
static int forward(int t, const double *joints, EmcPose *pos)
{
    matrix3_t m = matrix();
    (void)t;
    return matrix_forward_kins(&m, joints, pos);
}

/* World -> joints: J0..J2 = M (X Y Z); J3..J8 = A..W. */
static int inverse(int t, const EmcPose *pos, double *joints)
{
    matrix3_t m = matrix();
    (void)t;
    matrix_inverse_kins(&m, pos, joints);
    return 0;
}

const kins_template_def_t kins_template_def = {
    "matrixkins", "matrixkins", instance, setup, 1, forward, inverse,
};
