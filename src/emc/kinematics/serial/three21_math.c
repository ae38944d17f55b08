/* three21_math.c: LinuxCNC's three21kins formulas (forward with configuration flags, closed-form inverse). */
#include <math.h>
#include "three21_math.h"

#define DEG (M_PI / 180.0)
#define FLAG_FUZZ 1e-6
#define GIMBAL_FUZZ 1e-9

/* Columns of a rotation matrix. */
typedef struct {
    double x[3], y[3], z[3];
} three21_rot_t;

/* The rotation of the arm at joint angles q (radians) and the wrist centre w. */
static void three21_chain(const three21_params_t *p, const double *q, three21_rot_t *r, double w[3])
{
    double s1 = sin(q[0]), c1 = cos(q[0]), s2 = sin(q[1]), c2 = cos(q[1]), s3 = sin(q[2]), c3 = cos(q[2]);
    double s4 = sin(q[3]), c4 = cos(q[3]), s5 = sin(q[4]), c5 = cos(q[4]), s6 = sin(q[5]), c6 = cos(q[5]);
    double s23 = s2 * c3 + c2 * s3, c23 = c2 * c3 - s2 * s3, d23 = p->d2 + p->d3;
    double m = c4 * c5 * c6 - s4 * s6, u = c23 * m - s23 * s5 * c6, v = s4 * c5 * c6 + c4 * s6;
    double mp = -c4 * c5 * s6 - s4 * c6, up = c23 * mp + s23 * s5 * s6, vp = c4 * c6 - s4 * c5 * s6;
    double n = c23 * c4 * s5 + s23 * c5, e = p->a1 + p->a2 * c2 + p->a3 * c23 - p->d4 * s23;
    *r = (three21_rot_t){{c1 * u + s1 * v, s1 * u - c1 * v, -s23 * m - c23 * s5 * c6},
                         {c1 * up + s1 * vp, s1 * up - c1 * vp, -s23 * mp + c23 * s5 * s6},
                         {-c1 * n - s1 * s4 * s5, -s1 * n + c1 * s4 * s5, s23 * c4 * s5 - c23 * c5}};
    w[0] = c1 * e - d23 * s1;
    w[1] = s1 * e + d23 * c1;
    w[2] = p->d1 - p->a3 * s23 - p->a2 * s2 - p->d4 * c23;
}

/* The configuration flags of joint angles q (radians) with wrist centre w and rotation r. */
static unsigned long three21_flags(const three21_params_t *p, const double *q, const double w[3],
                                   const three21_rot_t *r)
{
    double s1 = sin(q[0]), c1 = cos(q[0]), s23 = sin(q[1] + q[2]), c23 = cos(q[1] + q[2]);
    double d23 = p->d2 + p->d3, sq = fmax(0, w[0] * w[0] + w[1] * w[1] - d23 * d23);
    double k = (sq + (w[2] - p->d1) * (w[2] - p->d1) + p->a1 * p->a1 - 2 * p->a1 * (c1 * w[0] + s1 * w[1])
                - p->a2 * p->a2 - p->a3 * p->a3 - p->d4 * p->d4) / (2 * p->a2);
    unsigned long f = 0;
    if (fabs(q[0] - atan2(w[1], w[0]) + atan2(d23, -sqrt(sq))) < FLAG_FUZZ)
        f |= THREE21_SHOULDER_RIGHT;
    if (fabs(q[2] - atan2(p->a3, p->d4) + atan2(k, -sqrt(fmax(0, p->a3 * p->a3 + p->d4 * p->d4 - k * k))))
        < FLAG_FUZZ)
        f |= THREE21_ELBOW_DOWN;
    double a = -r->z[0] * s1 + r->z[1] * c1, b = -r->z[0] * c1 * c23 - r->z[1] * s1 * c23 + r->z[2] * s23;
    if (fabs(a) < FLAG_FUZZ && fabs(b) < FLAG_FUZZ)
        f |= THREE21_SINGULAR;
    else if (fabs(q[3] - atan2(a, b)) >= FLAG_FUZZ)
        f |= THREE21_WRIST_FLIP;
    return f;
}

/* Roll, pitch, yaw (radians) of a rotation; at pitch +-90 degrees yaw is 0 and roll comes from y. */
static void three21_rpy(const three21_rot_t *r, double *roll, double *pitch, double *yaw)
{
    double cp = sqrt(r->x[0] * r->x[0] + r->x[1] * r->x[1]);
    *pitch = atan2(-r->x[2], cp);
    if (cp < GIMBAL_FUZZ) {
        *yaw = 0;
        *roll = *pitch > 0 ? atan2(r->y[0], r->y[1]) : atan2(-r->y[0], r->y[1]);
        return;
    }
    *roll = atan2(r->y[2], r->z[2]);
    *yaw = atan2(r->x[1], r->x[0]);
}

/* Joints -> tool pose and configuration flags. */
int three21_forward(const three21_params_t *p, const double *joints, EmcPose *pos, unsigned long *iflags)
{
    double q[6], w[3], roll, pitch, yaw;
    three21_rot_t r;
    for (int i = 0; i < 6; i++)
        q[i] = joints[i] * DEG;
    three21_chain(p, q, &r, w);
    if (iflags)
        *iflags = three21_flags(p, q, w, &r);
    three21_rpy(&r, &roll, &pitch, &yaw);
    pos->tran = (PmCartesian){w[0] + p->d6 * r.z[0], w[1] + p->d6 * r.z[1], w[2] + p->d6 * r.z[2]};
    pos->a = roll / DEG;
    pos->b = pitch / DEG;
    pos->c = yaw / DEG;
    return 0;
}

/* Rotation R(roll, pitch, yaw) = Rz(yaw) Ry(pitch) Rx(roll), angles in degrees. */
static three21_rot_t three21_rotation(double a, double b, double c)
{
    double sr = sin(a * DEG), cr = cos(a * DEG), sp = sin(b * DEG), cp = cos(b * DEG);
    double sy = sin(c * DEG), cy = cos(c * DEG);
    return (three21_rot_t){{cy * cp, sy * cp, -sp},
                           {cy * sp * sr - sy * cr, sy * sp * sr + cy * cr, cp * sr},
                           {cy * sp * cr + sy * sr, sy * sp * cr - cy * sr, cp * cr}};
}

/* Arm angles 1..3 (radians) for wrist centre (px, py, pz above D1); s23, c23 of the result. */
static void three21_arm(const three21_params_t *p, double px, double py, double pz, unsigned long iflags,
                        double *q, double *s23, double *c23)
{
    double d23 = p->d2 + p->d3, sq = fmax(0, px * px + py * py - d23 * d23);
    q[0] = atan2(py, px) - atan2(d23, (iflags & THREE21_SHOULDER_RIGHT) ? -sqrt(sq) : sqrt(sq));
    double s1 = sin(q[0]), c1 = cos(q[0]);
    double k = (sq + pz * pz + p->a1 * p->a1 - 2 * p->a1 * (c1 * px + s1 * py) - p->a2 * p->a2
                - p->a3 * p->a3 - p->d4 * p->d4) / (2 * p->a2);
    double dk = fmax(0, p->a3 * p->a3 + p->d4 * p->d4 - k * k);
    q[2] = atan2(p->a3, p->d4) - atan2(k, (iflags & THREE21_ELBOW_DOWN) ? -sqrt(dk) : sqrt(dk));
    double s3 = sin(q[2]), c3 = cos(q[2]), h = c1 * px + s1 * py - p->a1;
    double t1 = (-p->a3 - p->a2 * c3) * pz + h * (p->a2 * s3 - p->d4);
    double t2 = (p->a2 * s3 - p->d4) * pz + (p->a3 + p->a2 * c3) * h, t3 = pz * pz + h * h;
    q[1] = atan2(t1, t2) - q[2];
    *s23 = t1 / t3;
    *c23 = t2 / t3;
}

/* Pose -> joints for the configuration in iflags. */
int three21_inverse(const three21_params_t *p, const EmcPose *pos, unsigned long iflags, double *joints,
                    unsigned long *fflags)
{
    three21_rot_t r = three21_rotation(pos->a, pos->b, pos->c);
    double q[6], s23, c23;
    three21_arm(p, pos->tran.x - p->d6 * r.z[0], pos->tran.y - p->d6 * r.z[1],
                pos->tran.z - p->d1 - p->d6 * r.z[2], iflags, q, &s23, &c23);
    double s1 = sin(q[0]), c1 = cos(q[0]);
    double a = -r.z[0] * s1 + r.z[1] * c1, b = -r.z[0] * c1 * c23 - r.z[1] * s1 * c23 + r.z[2] * s23;
    if (fflags)
        *fflags = 0;
    if (fabs(a) < FLAG_FUZZ && fabs(b) < FLAG_FUZZ) {
        q[3] = joints[3] * DEG;
        if (fflags)
            *fflags = THREE21_REACH;
    } else {
        q[3] = atan2(a, b);
    }
    double s4 = sin(q[3]), c4 = cos(q[3]);
    double s5 = r.z[2] * s23 * c4 - r.z[0] * (c1 * c23 * c4 + s1 * s4) - r.z[1] * (s1 * c23 * c4 - c1 * s4);
    double c5 = -r.z[0] * c1 * s23 - r.z[1] * s1 * s23 - r.z[2] * c23;
    q[4] = atan2(s5, c5);
    double s6 = r.x[2] * s23 * s4 - r.x[0] * (c1 * c23 * s4 - s1 * c4) - r.x[1] * (s1 * c23 * s4 + c1 * c4);
    double c6 = r.x[0] * ((c1 * c23 * c4 + s1 * s4) * c5 - c1 * s23 * s5)
                + r.x[1] * ((s1 * c23 * c4 - c1 * s4) * c5 - s1 * s23 * s5) - r.x[2] * (s23 * c4 * c5 + c23 * s5);
    q[5] = atan2(s6, c6);
    if (iflags & THREE21_WRIST_FLIP) {
        q[3] += M_PI;
        q[4] = -q[4];
        q[5] += M_PI;
    }
    for (int i = 0; i < 6; i++)
        joints[i] = q[i] / DEG;
    return 0;
}
