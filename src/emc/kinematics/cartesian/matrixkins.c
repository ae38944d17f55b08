/* matrixkins.c: XYZ correction kinematics; params C_xx..C_zz give joints = C * (X Y Z). */
#include "rtapi.h"
#include "rtapi_app.h"
#include "hal.h"
#include "emc/kinematics/kinematics.h"
#include "cartesian_math.h"

MODULE_LICENSE("GPL");
MODULE_AUTHOR("OpenEMC");
MODULE_DESCRIPTION("Matrix kinematics: a 3x3 correction matrix between XYZ and joints 0-2");

/* The nine matrix entries live in HAL memory so halcmd setp can change them. */
typedef struct {
    hal_float_t c[3][3];
} matrix_params_t;

static matrix_params_t *params;
static int comp_id;

/* Snapshot of the HAL params as a plain matrix. */
static void current_matrix(matrix3_t *mat)
{
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 3; c++)
            mat->m[r][c] = params->c[r][c];
}

/* Joints -> world with the inverted matrix; -1 when it is singular. */
int kinematicsForward(const double *joint, EmcPose *world,
                      const KINEMATICS_FORWARD_FLAGS *fflags, KINEMATICS_INVERSE_FLAGS *iflags)
{
    matrix3_t mat;
    (void)fflags;
    (void)iflags;
    current_matrix(&mat);
    return matrix_forward_kins(&mat, joint, world);
}

/* World -> joints through the matrix. */
int kinematicsInverse(const EmcPose *world, double *joint,
                      const KINEMATICS_INVERSE_FLAGS *iflags, KINEMATICS_FORWARD_FLAGS *fflags)
{
    matrix3_t mat;
    (void)iflags;
    (void)fflags;
    current_matrix(&mat);
    matrix_inverse_kins(&mat, world, joint);
    return 0;
}

/* Both directions are available. */
KINEMATICS_TYPE kinematicsType(void)
{
    return KINEMATICS_BOTH;
}

/* Not switchable. */
int kinematicsSwitchable(void)
{
    return 0;
}

/* No-op: there is only one kinematics. */
int kinematicsSwitch(int switchkins_type)
{
    (void)switchkins_type;
    return 0;
}

KINS_EXPORT_OPS("matrixkins");

/* Create matrixkins.C_xx .. C_zz (RW), set to the identity matrix. */
static int make_params(void)
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

/* Register the component and its matrix params. */
int rtapi_app_main(void)
{
    comp_id = hal_init("matrixkins");
    if (comp_id < 0)
        return comp_id;
    int rc = make_params();
    if (rc < 0) {
        rtapi_print_msg(RTAPI_MSG_ERR, "matrixkins: ERROR: cannot create params\n");
        hal_exit(comp_id);
        return rc;
    }
    hal_ready(comp_id);
    return 0;
}

/* Remove the component. */
void rtapi_app_exit(void)
{
    hal_exit(comp_id);
}
