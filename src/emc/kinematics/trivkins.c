/* trivkins.c: identity kinematics; coordinates= maps joints to axes, kinstype= picks the type. */
#include "rtapi.h"
#include "rtapi_app.h"
#include "hal.h"
#include "kinematics.h"
#include "kins_coords.h"

MODULE_LICENSE("GPL");
MODULE_AUTHOR("OpenEMC");
MODULE_DESCRIPTION("Trivial (identity) kinematics");

static char *coordinates = KINS_DEFAULT_COORDINATES;
RTAPI_MP_STRING(coordinates, "Axis letter of each joint, in joint order");
static char *kinstype = "1";
RTAPI_MP_STRING(kinstype, "Kinematics type: B(oth), F(orward only), I(nverse only), else identity");

static kins_coords_t coords;
static KINEMATICS_TYPE ktype = KINEMATICS_IDENTITY;
static int comp_id;

/* Joints -> world through the coordinates map. */
int kinematicsForward(const double *joint, EmcPose *world,
                      const KINEMATICS_FORWARD_FLAGS *fflags, KINEMATICS_INVERSE_FLAGS *iflags)
{
    (void)fflags;
    (void)iflags;
    kins_identity_forward(&coords, joint, world);
    return 0;
}

/* World -> joints through the coordinates map. */
int kinematicsInverse(const EmcPose *world, double *joint,
                      const KINEMATICS_INVERSE_FLAGS *iflags, KINEMATICS_FORWARD_FLAGS *fflags)
{
    (void)iflags;
    (void)fflags;
    kins_identity_inverse(&coords, world, joint);
    return 0;
}

/* The type chosen with kinstype=. */
KINEMATICS_TYPE kinematicsType(void)
{
    return ktype;
}

/* trivkins cannot switch. */
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

KINS_EXPORT_OPS("trivkins");

/* First letter of kinstype=: b BOTH, f FORWARD_ONLY, i INVERSE_ONLY, else IDENTITY. */
static KINEMATICS_TYPE parse_kinstype(const char *text)
{
    switch (text ? text[0] : 0) {
    case 'b': case 'B': return KINEMATICS_BOTH;
    case 'f': case 'F': return KINEMATICS_FORWARD_ONLY;
    case 'i': case 'I': return KINEMATICS_INVERSE_ONLY;
    default: return KINEMATICS_IDENTITY;
    }
}

/* Parse the module arguments and register the (pinless) component. */
int rtapi_app_main(void)
{
    char why[160];
    if (kins_coords_parse(coordinates, &coords, why, sizeof(why)) < 0) {
        rtapi_print_msg(RTAPI_MSG_ERR, "trivkins: ERROR: %s\n", why);
        return -EINVAL;
    }
    ktype = parse_kinstype(kinstype);
    comp_id = hal_init("trivkins");
    if (comp_id < 0)
        return comp_id;
    hal_ready(comp_id);
    return 0;
}

/* Remove the component. */
void rtapi_app_exit(void)
{
    hal_exit(comp_id);
}
