/* scara_math.c: SCARA forward kinematics and its two-solution closed-form inverse. */
#include <math.h>
#include "scara_math.h"
#include "serial_rot.h"

/* Joints -> pose: planar two-link reach plus the tool offset, Z from the quill. */
int scara_forward(const scara_params_t *p, const double *joints, EmcPose *pos, unsigned long *iflags)
{
    double q0 = joints[0] / SERIAL_DEG;
    double q01 = (joints[0] + joints[1]) / SERIAL_DEG;
    double tool = (joints[0] + joints[1] + joints[3]) / SERIAL_DEG;
    pos->tran.x = p->d2 * cos(q0) + p->d4 * cos(q01) + p->d6 * cos(tool);
    pos->tran.y = p->d2 * sin(q0) + p->d4 * sin(q01) + p->d6 * sin(tool);
    pos->tran.z = p->d1 + p->d3 - p->d5 - joints[2];
    pos->a = joints[4];
    pos->b = joints[5];
    pos->c = tool * SERIAL_DEG;
    pos->u = pos->v = pos->w = 0.0;
    serial_pose_snap(pos);
    if (iflags)
        *iflags = serial_angle_near(joints[1], 0.0) < 0 ? SCARA_ELBOW_NEGATIVE : 0;
    return 0;
}

/* Pose -> joints with the chosen elbow sign. */
int scara_inverse(const scara_params_t *p, const EmcPose *pos, unsigned long flags, double *joints)
{
    if (!isfinite(pos->tran.x) || !isfinite(pos->tran.y) || !isfinite(pos->tran.z) ||
        !isfinite(pos->a) || !isfinite(pos->b) || !isfinite(pos->c) || p->d2 <= 0 || p->d4 <= 0)
        return -1;
    double c = pos->c / SERIAL_DEG;
    double x = pos->tran.x - p->d6 * cos(c), y = pos->tran.y - p->d6 * sin(c);
    double cos1 = (x * x + y * y - p->d2 * p->d2 - p->d4 * p->d4) / (2 * p->d2 * p->d4);
    if (!(cos1 >= -1.0 && cos1 <= 1.0))
        return -1;
    double q1 = acos(cos1);
    if (flags & SCARA_ELBOW_NEGATIVE)
        q1 = -q1;
    double q0 = atan2(y, x) - atan2(p->d4 * sin(q1), p->d2 + p->d4 * cos(q1));
    double j0 = serial_angle_near(q0 * SERIAL_DEG, joints[0]);
    double j1 = serial_angle_near(q1 * SERIAL_DEG, joints[1]);
    joints[3] = serial_angle_near(pos->c - j0 - j1, joints[3]);
    joints[0] = j0;
    joints[1] = j1;
    joints[2] = p->d1 + p->d3 - p->d5 - pos->tran.z;
    joints[4] = pos->a;
    joints[5] = pos->b;
    serial_joints_snap(joints, SCARA_JOINTS);
    return 0;
}

/* Pose -> joints on the same side of the elbow as now. */
int scara_inverse_keep_elbow(const scara_params_t *p, const EmcPose *pos, double *joints)
{
    double elbow = serial_angle_near(joints[1], 0.0);
    return scara_inverse(p, pos, elbow < 0 ? SCARA_ELBOW_NEGATIVE : 0, joints);
}
