/* serial_rot.c: rotation matrices, roll-pitch-yaw conversion and angle wrapping for serial arms. */
#include <math.h>
#include "serial_rot.h"

/* Rotation Rz(c) Ry(b) Rx(a) from degrees. */
void serial_rot_from_rpy(double a_deg, double b_deg, double c_deg, serial_mat3_t r)
{
    double ca = cos(a_deg / SERIAL_DEG), sa = sin(a_deg / SERIAL_DEG);
    double cb = cos(b_deg / SERIAL_DEG), sb = sin(b_deg / SERIAL_DEG);
    double cc = cos(c_deg / SERIAL_DEG), sc = sin(c_deg / SERIAL_DEG);
    r[0][0] = cc * cb;
    r[0][1] = cc * sb * sa - sc * ca;
    r[0][2] = cc * sb * ca + sc * sa;
    r[1][0] = sc * cb;
    r[1][1] = sc * sb * sa + cc * ca;
    r[1][2] = sc * sb * ca - cc * sa;
    r[2][0] = -sb;
    r[2][1] = cb * sa;
    r[2][2] = cb * ca;
}

/* atan2 in degrees within (-180, 180]: a rounding-level -180 is reported as 180. */
static double serial_atan2_deg(double y, double x)
{
    double angle = atan2(y, x) * SERIAL_DEG;
    return angle < -180.0 + 1e-9 ? angle + 360.0 : angle;
}

/* Roll, pitch, yaw (degrees) of a rotation matrix. */
void serial_rot_to_rpy(const serial_mat3_t r, double *a_deg, double *b_deg, double *c_deg)
{
    double cb = sqrt(r[0][0] * r[0][0] + r[1][0] * r[1][0]);
    *b_deg = atan2(-r[2][0], cb) * SERIAL_DEG;
    if (cb < 1e-12) {
        *a_deg = 0.0;
        *c_deg = serial_atan2_deg(-r[0][1], r[1][1]);
        return;
    }
    *a_deg = serial_atan2_deg(r[2][1], r[2][2]);
    *c_deg = serial_atan2_deg(r[1][0], r[0][0]);
}

/* out = x * y. */
void serial_mat3_mul(const serial_mat3_t x, const serial_mat3_t y, serial_mat3_t out)
{
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            out[i][j] = x[i][0] * y[0][j] + x[i][1] * y[1][j] + x[i][2] * y[2][j];
}

/* out = transpose(x) * y. */
void serial_mat3_tmul(const serial_mat3_t x, const serial_mat3_t y, serial_mat3_t out)
{
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            out[i][j] = x[0][i] * y[0][j] + x[1][i] * y[1][j] + x[2][i] * y[2][j];
}

/* Elementary rotation about one coordinate axis. */
void serial_mat3_axis(int axis, double angle_rad, serial_mat3_t out)
{
    double c = cos(angle_rad), s = sin(angle_rad);
    int i = (axis + 1) % 3, j = (axis + 2) % 3;
    for (int row = 0; row < 3; row++)
        for (int col = 0; col < 3; col++)
            out[row][col] = row == col;
    out[i][i] = c;
    out[j][j] = c;
    out[i][j] = -s;
    out[j][i] = s;
}

/* Shift an angle by whole turns so it is nearest to near_deg. */
double serial_angle_near(double angle_deg, double near_deg)
{
    return angle_deg - 360.0 * round((angle_deg - near_deg) / 360.0);
}

/* Exactly 0 for values that are rounding noise, so outputs never show as -0. */
static double serial_snap(double v)
{
    return fabs(v) < 1e-12 ? 0.0 : v;
}

/* Snap every field of a pose. */
void serial_pose_snap(EmcPose *pos)
{
    pos->tran.x = serial_snap(pos->tran.x);
    pos->tran.y = serial_snap(pos->tran.y);
    pos->tran.z = serial_snap(pos->tran.z);
    pos->a = serial_snap(pos->a);
    pos->b = serial_snap(pos->b);
    pos->c = serial_snap(pos->c);
    pos->u = serial_snap(pos->u);
    pos->v = serial_snap(pos->v);
    pos->w = serial_snap(pos->w);
}

/* Snap count joint values. */
void serial_joints_snap(double *joints, int count)
{
    for (int i = 0; i < count; i++)
        joints[i] = serial_snap(joints[i]);
}
