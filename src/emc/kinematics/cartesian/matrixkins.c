/* matrixkins.c: XYZ correction kinematics; params C_xx..C_zz give joints = C * (X Y Z). */
#include "rtapi.h"
#include "hal.h"
#include "emc/kinematics/kins_frame.h"
#include "cartesian_math.h"

MODULE_DESCRIPTION("Matrix kinematics: a 3x3 correction matrix between XYZ and joints 0-2");

/* The nine matrix entries live in HAL memory so halcmd setp can change them. */
typedef struct {
    hal_float_t c[3][3];
} matrix_params_t;

static matrix_params_t *params;

/* Snapshot of the HAL params as a plain matrix. */
static void current_matrix(matrix3_t *mat)
{
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 3; c++)
            mat->m[r][c] = params->c[r][c];
}

/* Joints -> world with the inverted matrix; -1 when it is singular. */
static int matrix_fwd(const double *joints, EmcPose *pos)
{
    matrix3_t mat;
    current_matrix(&mat);
    return matrix_forward_kins(&mat, joints, pos);
}

/* World -> joints through the matrix. */
static int matrix_inv(const EmcPose *pos, double *joints)
{
    matrix3_t mat;
    current_matrix(&mat);
    matrix_inverse_kins(&mat, pos, joints);
    return 0;
}

/* Create matrixkins.C_xx .. C_zz (RW), set to the identity matrix. */
static int make_params(int comp_id)
{
    static const char axis[3] = {'x', 'y', 'z'};
    params = hal_malloc(sizeof(*params));
    if (!params)
        return -ENOMEM;
    for (int r = 0; r < 3; r++) {
        for (int c = 0; c < 3; c++) {
            int rc = hal_param_float_newf(HAL_RW, &params->c[r][c], comp_id,
                                          "matrixkins.C_%c%c", axis[r], axis[c]);
            if (rc < 0)
                return rc;
            params->c[r][c] = r == c ? 1.0 : 0.0;
        }
    }
    return 0;
}

const kins_frame_def_t kins_frame_def = {
    .name = "matrixkins", .type = KINEMATICS_BOTH, .setup = make_params,
    .setup_error = "cannot create params", .forward = matrix_fwd, .inverse = matrix_inv,
};
