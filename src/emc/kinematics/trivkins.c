/* trivkins.c: identity kinematics; coordinates= maps joints to axes, kinstype= picks the type. */
#include "rtapi.h"
#include "hal.h"
#include "kins_frame.h"
#include "kins_coords.h"

MODULE_DESCRIPTION("Trivial (identity) kinematics");

static char *coordinates = KINS_DEFAULT_COORDINATES;
RTAPI_MP_STRING(coordinates, "Axis letter of each joint, in joint order");
static char *kinstype = "1";
RTAPI_MP_STRING(kinstype, "Kinematics type: B(oth), F(orward only), I(nverse only), else identity");

static kins_coords_t coords;

/* Joints -> world through the coordinates map. */
static int trivkins_forward(const double *joints, EmcPose *pos)
{
    kins_identity_forward(&coords, joints, pos);
    return 0;
}

/* World -> joints through the coordinates map. */
static int trivkins_inverse(const EmcPose *pos, double *joints)
{
    kins_identity_inverse(&coords, pos, joints);
    return 0;
}

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

/* Parse coordinates= and kinstype= (the component has no pins). */
static int trivkins_check(KINEMATICS_TYPE *type)
{
    char why[160];
    if (kins_coords_parse(coordinates, &coords, why, sizeof(why)) < 0) {
        rtapi_print_msg(RTAPI_MSG_ERR, "trivkins: ERROR: %s\n", why);
        return -EINVAL;
    }
    *type = parse_kinstype(kinstype);
    return 0;
}

const kins_frame_def_t kins_frame_def = {
    .name = "trivkins", .type = KINEMATICS_IDENTITY, .check = trivkins_check,
    .forward = trivkins_forward, .inverse = trivkins_inverse,
};
