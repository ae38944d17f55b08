/* arm6_math.c: forward and closed-form inverse of a 6R arm with a spherical wrist. */
#include <math.h>
#include "arm6_math.h"
#include "serial_rot.h"

#define ARM6_SINGULAR_FUZZ 1e-9

/* Orientation of link 3: Rz(q1) Rx(-90) Rz(q2 + q3). */
static void arm6_r03(double q1, double q23, serial_mat3_t out)
{
    serial_mat3_t z1, x, z23, tmp;
    serial_mat3_axis(2, q1, z1);
    serial_mat3_axis(0, -M_PI / 2, x);
    serial_mat3_axis(2, q23, z23);
    serial_mat3_mul(z1, x, tmp);
    serial_mat3_mul(tmp, z23, out);
}

/* Wrist rotation Ry(q4) Rz(q5) Ry(q6) Rx(-90) of links 4..6 relative to link 3. */
static void arm6_wrist(double q4, double q5, double q6, serial_mat3_t out)
{
    serial_mat3_t a, b, c, d, ab, abc;
    serial_mat3_axis(1, q4, a);
    serial_mat3_axis(2, q5, b);
    serial_mat3_axis(1, q6, c);
    serial_mat3_axis(0, -M_PI / 2, d);
    serial_mat3_mul(a, b, ab);
    serial_mat3_mul(ab, c, abc);
    serial_mat3_mul(abc, d, out);
}

/* Joints -> tool pose and the configuration flags of those joints. */
int arm6_forward(const arm6_params_t *p, const double *joints, EmcPose *pos, unsigned long *iflags)
{
    double q[ARM6_JOINTS];
    for (int i = 0; i < ARM6_JOINTS; i++)
        q[i] = joints[i] / SERIAL_DEG;
    double lateral = p->d2 + p->d3;
    double c1 = cos(q[0]), s1 = sin(q[0]), c2 = cos(q[1]), s2 = sin(q[1]);
    double c23 = cos(q[1] + q[2]), s23 = sin(q[1] + q[2]);
    double reach = p->a1 + p->a2 * c2 + p->a3 * c23 - p->d4 * s23;
    serial_mat3_t r03, w, r;
    arm6_r03(q[0], q[1] + q[2], r03);
    arm6_wrist(q[3], q[4], q[5], w);
    serial_mat3_mul(r03, w, r);
    pos->tran.x = c1 * reach - lateral * s1 + p->d6 * r[0][2];
    pos->tran.y = s1 * reach + lateral * c1 + p->d6 * r[1][2];
    pos->tran.z = p->d1 - p->a3 * s23 - p->a2 * s2 - p->d4 * c23 + p->d6 * r[2][2];
    serial_rot_to_rpy(r, &pos->a, &pos->b, &pos->c);
    pos->u = pos->v = pos->w = 0.0;
    serial_pose_snap(pos);
    unsigned long f = 0;
    if (reach < 0)
        f |= ARM6_SHOULDER_RIGHT;
    if (p->d4 * cos(q[2]) + p->a3 * sin(q[2]) < 0)
        f |= ARM6_ELBOW_DOWN;
    if (sin(q[4]) < 0)
        f |= ARM6_WRIST_FLIP;
    if (fabs(sin(q[4])) < ARM6_SINGULAR_FUZZ)
        f |= ARM6_SINGULAR;
    if (iflags)
        *iflags = f;
    return 0;
}

/* Shoulder, upper arm and elbow angles (radians) placing the wrist centre at w; 0 or -1. */
static int arm6_position(const arm6_params_t *p, const double w[3], unsigned long flags, double q[3])
{
    double lateral = p->d2 + p->d3;
    double r2 = w[0] * w[0] + w[1] * w[1] - lateral * lateral;
    if (r2 < 0 || p->a2 == 0)
        return -1;
    double reach = (flags & ARM6_SHOULDER_RIGHT) ? -sqrt(r2) : sqrt(r2);
    q[0] = atan2(w[1], w[0]) - atan2(lateral, reach);
    double t = reach - p->a1, h = w[2] - p->d1;
    double k = (t * t + h * h - p->a2 * p->a2 - p->a3 * p->a3 - p->d4 * p->d4) / (2 * p->a2);
    double e2 = p->a3 * p->a3 + p->d4 * p->d4 - k * k;
    if (e2 < 0)
        return -1;
    double e = (flags & ARM6_ELBOW_DOWN) ? -sqrt(e2) : sqrt(e2);
    q[2] = atan2(p->a3, p->d4) - atan2(k, e);
    double u = p->a2 + p->a3 * cos(q[2]) - p->d4 * sin(q[2]);
    double v = p->a3 * sin(q[2]) + p->d4 * cos(q[2]);
    q[1] = atan2(-h, t) - atan2(v, u);
    return 0;
}

/* Wrist angles (radians) giving n = Ry(q4) Rz(q5) Ry(q6); q4_now is kept at a singularity. */
static void arm6_orientation(const serial_mat3_t n, unsigned long flags, double q4_now, double q[3])
{
    double s5 = sqrt(n[0][1] * n[0][1] + n[2][1] * n[2][1]);
    if (s5 < ARM6_SINGULAR_FUZZ)
        q[0] = q4_now;
    else
        q[0] = atan2(n[2][1], -n[0][1]) + ((flags & ARM6_WRIST_FLIP) ? M_PI : 0.0);
    serial_mat3_t y4, pm, z5, qm;
    serial_mat3_axis(1, q[0], y4);
    serial_mat3_tmul(y4, n, pm);
    q[1] = atan2(-pm[0][1], pm[1][1]);
    serial_mat3_axis(2, q[1], z5);
    serial_mat3_tmul(z5, pm, qm);
    q[2] = atan2(qm[0][2], qm[0][0]);
}

/* True when every pose value used is a finite number. */
static int arm6_pose_finite(const EmcPose *pos)
{
    return isfinite(pos->tran.x) && isfinite(pos->tran.y) && isfinite(pos->tran.z) &&
           isfinite(pos->a) && isfinite(pos->b) && isfinite(pos->c);
}

/* Pose -> joints in the given configuration. */
int arm6_inverse(const arm6_params_t *p, const EmcPose *pos, unsigned long flags, double *joints)
{
    if (!arm6_pose_finite(pos))
        return -1;
    serial_mat3_t r, r03, n0, n, xr;
    serial_rot_from_rpy(pos->a, pos->b, pos->c, r);
    double w[3] = { pos->tran.x - p->d6 * r[0][2], pos->tran.y - p->d6 * r[1][2],
                    pos->tran.z - p->d6 * r[2][2] };
    double q[ARM6_JOINTS];
    if (arm6_position(p, w, flags, q) < 0)
        return -1;
    arm6_r03(q[0], q[1] + q[2], r03);
    serial_mat3_tmul(r03, r, n0);
    serial_mat3_axis(0, M_PI / 2, xr);
    serial_mat3_mul(n0, xr, n);
    arm6_orientation(n, flags, joints[3] / SERIAL_DEG, q + 3);
    for (int i = 0; i < ARM6_JOINTS; i++)
        q[i] = serial_angle_near(q[i] * SERIAL_DEG, joints[i]);
    serial_joints_snap(q, ARM6_JOINTS);
    for (int i = 0; i < ARM6_JOINTS; i++)
        if (!isfinite(q[i]))
            return -1;
    for (int i = 0; i < ARM6_JOINTS; i++)
        joints[i] = q[i];
    return 0;
}

/* Pose -> joints: of the eight configurations, the one closest to the current joints. */
int arm6_inverse_nearest(const arm6_params_t *p, const EmcPose *pos, double *joints)
{
    double best[ARM6_JOINTS], best_dist = INFINITY;
    for (unsigned long flags = 0; flags < 8; flags++) {
        double trial[ARM6_JOINTS], dist = 0;
        for (int i = 0; i < ARM6_JOINTS; i++)
            trial[i] = joints[i];
        if (arm6_inverse(p, pos, flags, trial) < 0)
            continue;
        for (int i = 0; i < ARM6_JOINTS; i++)
            dist += (trial[i] - joints[i]) * (trial[i] - joints[i]);
        if (dist < best_dist) {
            best_dist = dist;
            for (int i = 0; i < ARM6_JOINTS; i++)
                best[i] = trial[i];
        }
    }
    if (!(best_dist < INFINITY))
        return -1;
    for (int i = 0; i < ARM6_JOINTS; i++)
        joints[i] = best[i];
    return 0;
}
