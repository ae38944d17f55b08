// genser_math.cc: forward by DH product and Jacobian-iteration inverse of a 6R chain (Eigen).
#include <algorithm>
#include <cmath>
#include <Eigen/Dense>
#include "genser_math.h"
#include "serial_rot.h"

namespace {

using Mat3 = Eigen::Matrix3d;
using Vec3 = Eigen::Vector3d;
using Vec6 = Eigen::Matrix<double, 6, 1>;
using Mat6 = Eigen::Matrix<double, 6, 6>;

constexpr double kLinearTolerance = 1e-9;   // machine units
constexpr double kAngularTolerance = 1e-10; // radians
constexpr double kDamping = 1e-6;           // damped least squares lambda^2
constexpr double kMaxStep = 0.5;            // radians per joint per iteration

// Frame origins and z axes of every joint plus the tool frame, in world coordinates.
struct ChainFrames {
    Vec3 origin[GENSER_JOINTS];
    Vec3 axis[GENSER_JOINTS];
    Mat3 rot;
    Vec3 tran;
};

// Fixed part of link i (rotation, then translation in the previous frame) and its joint axis.
void link_fixed(const genser_params_t *p, int i, Mat3 &rot, Vec3 &tran, Vec3 &axis)
{
    if (p->chain) {
        const genser_chain_t *c = p->chain;
        for (int r = 0; r < 3; r++)
            for (int k = 0; k < 3; k++)
                rot(r, k) = c->rot[i][r][k];
        tran = Vec3(c->tran[i][0], c->tran[i][1], c->tran[i][2]);
        axis = Vec3(c->axis[i][0], c->axis[i][1], c->axis[i][2]);
        return;
    }
    rot = Eigen::AngleAxisd(p->alpha[i], Vec3::UnitX()).toRotationMatrix();
    tran = Vec3(p->a[i], 0, 0) + rot * Vec3(0, 0, p->d[i]);
    axis = Vec3::UnitZ();
}

// Walk the chain for joint angles theta (radians, after unrotate).
void chain_frames(const genser_params_t *p, const double *theta, ChainFrames &f)
{
    Mat3 rot = Mat3::Identity();
    Vec3 tran = Vec3::Zero();
    for (int i = 0; i < GENSER_JOINTS; i++) {
        Mat3 fixed_rot;
        Vec3 fixed_tran, axis;
        link_fixed(p, i, fixed_rot, fixed_tran, axis);
        tran += rot * fixed_tran;
        rot = rot * fixed_rot;
        f.origin[i] = tran;
        f.axis[i] = rot * axis;
        rot = rot * Eigen::AngleAxisd(theta[i], axis).toRotationMatrix();
    }
    if (p->chain) {
        const genser_chain_t *c = p->chain;
        Mat3 tool_rot;
        for (int r = 0; r < 3; r++)
            for (int k = 0; k < 3; k++)
                tool_rot(r, k) = c->tool_rot[r][k];
        tran += rot * Vec3(c->tool_tran[0], c->tool_tran[1], c->tool_tran[2]);
        rot = rot * tool_rot;
    }
    f.rot = rot;
    f.tran = tran;
}

// Motor joints (degrees) -> chain angles (radians): theta_i = J_i - unrotate_i * theta_(i-1).
void joints_to_theta(const genser_params_t *p, const double *joints, double *theta)
{
    for (int i = 0; i < GENSER_JOINTS; i++) {
        theta[i] = joints[i] / SERIAL_DEG;
        if (i > 0 && p->unrotate[i])
            theta[i] -= p->unrotate[i] * theta[i - 1];
    }
}

// Chain angles (radians) -> motor joints (degrees), the inverse of joints_to_theta.
void theta_to_joints(const genser_params_t *p, const double *theta, double *joints)
{
    for (int i = 0; i < GENSER_JOINTS; i++) {
        double t = theta[i];
        if (i > 0 && p->unrotate[i])
            t += p->unrotate[i] * theta[i - 1];
        joints[i] = t * SERIAL_DEG;
    }
}

// Pose error (translation; rotation vector) from the chain's tool frame to the goal, world frame.
Vec6 pose_error(const ChainFrames &f, const Mat3 &goal_rot, const Vec3 &goal_tran)
{
    Eigen::AngleAxisd diff(goal_rot * f.rot.transpose());
    Vec6 e;
    e.head<3>() = goal_tran - f.tran;
    e.tail<3>() = diff.axis() * diff.angle();
    return e;
}

// Geometric Jacobian of the tool point and orientation with respect to the chain angles.
Mat6 jacobian(const ChainFrames &f)
{
    Mat6 j;
    for (int i = 0; i < GENSER_JOINTS; i++) {
        j.block<3, 1>(0, i) = f.axis[i].cross(f.tran - f.origin[i]);
        j.block<3, 1>(3, i) = f.axis[i];
    }
    return j;
}

// One damped Newton step for error e, scaled so no joint moves more than kMaxStep.
Vec6 newton_step(const Mat6 &j, const Vec6 &e)
{
    Mat6 a = j.transpose() * j + kDamping * Mat6::Identity();
    Vec6 step = a.ldlt().solve(j.transpose() * e);
    double biggest = step.cwiseAbs().maxCoeff();
    if (biggest > kMaxStep)
        step *= kMaxStep / biggest;
    return step;
}

// Goal rotation and translation of a world pose.
void goal_of_pose(const EmcPose *pos, Mat3 &rot, Vec3 &tran)
{
    serial_mat3_t r;
    serial_rot_from_rpy(pos->a, pos->b, pos->c, r);
    for (int i = 0; i < 3; i++)
        for (int k = 0; k < 3; k++)
            rot(i, k) = r[i][k];
    tran = Vec3(pos->tran.x, pos->tran.y, pos->tran.z);
}

} // namespace

// PUMA 560-like chain: the genserkins pin defaults.
extern "C" void genser_defaults(genser_params_t *p)
{
    static const double a[GENSER_JOINTS] = {0, 0, 300, 50, 0, 0};
    static const double alpha[GENSER_JOINTS] = {0, -M_PI / 2, 0, -M_PI / 2, M_PI / 2, -M_PI / 2};
    static const double d[GENSER_JOINTS] = {0, 0, 70, 400, 0, 0};
    for (int i = 0; i < GENSER_JOINTS; i++) {
        p->a[i] = a[i];
        p->alpha[i] = alpha[i];
        p->d[i] = d[i];
        p->unrotate[i] = 0;
    }
    p->max_iterations = GENSER_DEFAULT_MAX_ITERATIONS;
    p->chain = nullptr;
}

// Forward kinematics: product of the link transforms.
extern "C" int genser_forward(const genser_params_t *p, const double *joints, EmcPose *pos)
{
    double theta[GENSER_JOINTS];
    joints_to_theta(p, joints, theta);
    ChainFrames f;
    chain_frames(p, theta, f);
    serial_mat3_t r;
    for (int i = 0; i < 3; i++)
        for (int k = 0; k < 3; k++)
            r[i][k] = f.rot(i, k);
    pos->tran.x = f.tran.x();
    pos->tran.y = f.tran.y();
    pos->tran.z = f.tran.z();
    serial_rot_to_rpy(r, &pos->a, &pos->b, &pos->c);
    pos->u = pos->v = pos->w = 0.0;
    serial_pose_snap(pos);
    return 0;
}

// Inverse kinematics: Newton iteration from the current joints, capped by max_iterations.
extern "C" int genser_inverse(const genser_params_t *p, const EmcPose *pos, double *joints,
                              unsigned int *iterations)
{
    Mat3 goal_rot;
    Vec3 goal_tran;
    goal_of_pose(pos, goal_rot, goal_tran);
    double theta[GENSER_JOINTS];
    joints_to_theta(p, joints, theta);
    *iterations = 0;
    if (!goal_rot.allFinite() || !goal_tran.allFinite())
        return -1;
    unsigned int cap = std::min(p->max_iterations, (unsigned int)GENSER_ITERATION_LIMIT);
    for (unsigned int it = 0; it <= cap; it++) {
        ChainFrames f;
        chain_frames(p, theta, f);
        Vec6 e = pose_error(f, goal_rot, goal_tran);
        *iterations = it;
        if (!e.allFinite())
            return -1;
        if (e.head<3>().norm() < kLinearTolerance && e.tail<3>().norm() < kAngularTolerance) {
            theta_to_joints(p, theta, joints);
            serial_joints_snap(joints, GENSER_JOINTS);
            return 0;
        }
        if (it == cap)
            break;
        Vec6 step = newton_step(jacobian(f), e);
        for (int i = 0; i < GENSER_JOINTS; i++)
            theta[i] += step(i);
    }
    return -1;
}
