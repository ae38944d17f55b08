/* mot_kins.c: calls into the kinematics table: forward/inverse with checks, switchable kinematics. */
#include "rtapi.h"
#include "rtapi_math.h"
#include "mot_priv.h"
#include "mot_control.h"

static KINEMATICS_FORWARD_FLAGS fflags;
static KINEMATICS_INVERSE_FLAGS iflags;

/* Axis 0..8 of a pose. */
double mot_pose_get(const EmcPose *p, int axis)
{
    switch (axis) {
    case 0: return p->tran.x;
    case 1: return p->tran.y;
    case 2: return p->tran.z;
    case 3: return p->a;
    case 4: return p->b;
    case 5: return p->c;
    case 6: return p->u;
    case 7: return p->v;
    default: return p->w;
    }
}

/* Set axis 0..8 of a pose. */
void mot_pose_set(EmcPose *p, int axis, double v)
{
    double *cells[] = { &p->tran.x, &p->tran.y, &p->tran.z, &p->a, &p->b, &p->c, &p->u, &p->v, &p->w };

    if (axis >= 0 && axis < MOT_NUM_AXES)
        *cells[axis] = v;
}

/* Non-zero when world moves need every joint homed first (not IDENTITY kinematics). */
int mot_kins_homing_required(void)
{
    return mot->kins->type() != KINEMATICS_IDENTITY;
}

/* Non-zero when every active joint in use is homed. */
int mot_joints_homed(void)
{
    for (int j = 0; j < mot->num_joints; j++)
        if (mot->joint[j].active && !mot->home->joint_homed(j))
            return 0;
    return 1;
}

/* Joints of the kinematic chain for pos; 0, or -1 after a failure (motion is disabled). */
int mot_inverse_kins(const EmcPose *pos, double *joints)
{
    if (mot->kins->inverse(pos, joints, &iflags, &fflags) != 0)
        return -1;
    for (int j = 0; j < mot->num_kins_joints; j++)
        if (!isfinite(joints[j]))
            return -(j + 2);
    return 0;
}

/* Forward kinematics of joint values into pos; 0 or -1. */
static int forward(const double *joints, EmcPose *pos)
{
    EmcPose p;

    if (mot->kins->forward(joints, &p, &fflags, &iflags) != 0)
        return -1;
    if (!isfinite(p.tran.x) || !isfinite(p.tran.y) || !isfinite(p.tran.z) || !isfinite(p.a) ||
        !isfinite(p.b) || !isfinite(p.c) || !isfinite(p.u) || !isfinite(p.v) || !isfinite(p.w))
        return -1;
    *pos = p;
    return 0;
}

/* Non-zero when forward kinematics may be trusted now. */
static int forward_usable(void)
{
    KINEMATICS_TYPE t = mot->kins->type();

    if (t == KINEMATICS_IDENTITY)
        return 1;
    if (t == KINEMATICS_INVERSE_ONLY)
        return 0;
    return mot_joints_homed();
}

/* 4. The feedback pose (IDENTITY always, others only when every joint is homed). */
void mot_forward_kins_feedback(void)
{
    double joints[MOT_MAX_JOINTS] = { 0 };

    mot->carte_pos_fb_old = mot->carte_pos_fb;
    mot->carte_pos_fb_ok = 0;
    if (!forward_usable())
        return;
    for (int j = 0; j < mot->max_joints; j++)
        joints[j] = mot->joint[j].pos_fb;
    mot->carte_pos_fb_ok = forward(joints, &mot->carte_pos_fb) == 0;
}

/* The commanded pose from the joint commands (free mode, mode changes). */
void mot_forward_kins_cmd(void)
{
    double joints[MOT_MAX_JOINTS] = { 0 };

    if (!forward_usable())
        return;
    for (int j = 0; j < mot->max_joints; j++)
        joints[j] = mot->joint[j].pos_cmd;
    forward(joints, &mot->carte_pos_cmd);
}

/* 2. motion.switchkins-type changed: switch while nothing moves, then resynchronise. */
void mot_kins_switch_input(void)
{
    int want;

    if (!mot->pins->switchkins_type)
        return;
    want = (int)*mot->pins->switchkins_type;
    if (want == mot->kins_switch_type || want == mot->kins_switch_refused)
        return;
    if (mot_any_joint_moving() || (mot->coord && !mot->tp_ops->is_done(mot->tp)))
        return;
    if (mot->kins->switch_type(want) != 0) {
        mot_report("kinematicsSwitch:BAD VALUE <%d>", want);
        mot->kins_switch_refused = want;
        return;
    }
    mot->kins_switch_type = want;
    mot->kins_switch_refused = -1;
    mot_forward_kins_cmd();
    mot->tp_ops->set_pos(mot->tp, &mot->carte_pos_cmd);
    mot->queued_end = mot->carte_pos_cmd;
    mot_sync_teleop_to_cmd();
}
