/* millturn.c: mill-turn kinematics (LinuxCNC's userkins-template module): type 0 milling (identity),
 * type 1 turning (X = joint 2, Y = -joint 1, Z = joint 0). */
#include "rtapi.h"
#include "hal.h"
#include "emc/kinematics/kins_template.h"
#include "emc/kinematics/kins_demo.h"
#include "millturn_math.h"

MODULE_DESCRIPTION("Mill-turn kinematics: milling (type 0) and turning (type 1)");

/* The demo echo pins and kinstype.is-0/1, at the first type query. */
static int setup(int comp_id)
{
    return kins_demo_echo_pins(comp_id, "millturn");
}

/* Joints -> world: X Y Z A from joints 0..3 (turning swaps the slides); B C U V W are 0. */
static int forward(int t, const double *joints, EmcPose *pos)
{
    kins_demo_echo_forward("millturn");
    if (t == 1) {
        millturn_turn_forward(joints, pos);
    } else {
        pos->tran.x = joints[0];
        pos->tran.y = joints[1];
        pos->tran.z = joints[2];
    }
    pos->a = joints[3];
    pos->b = pos->c = pos->u = pos->v = pos->w = 0;
    return 0;
}

/* World -> joints 0..3 (turning swaps the slides); in is echoed on out. */
static int inverse(int t, const EmcPose *pos, double *joints)
{
    kins_demo_echo_inverse();
    if (t == 1) {
        millturn_turn_inverse(pos, joints);
    } else {
        joints[0] = pos->tran.x;
        joints[1] = pos->tran.y;
        joints[2] = pos->tran.z;
    }
    joints[3] = pos->a;
    return 0;
}

const kins_template_def_t kins_template_def = {
    "millturn", "millturn", kins_demo_instance, setup, 2, forward, inverse,
};
