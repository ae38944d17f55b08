// genser_urdf.cc: walk a URDF (urdfdom) from its root link and turn it into a genser chain.
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <Eigen/Geometry>
#include <urdf_parser/urdf_parser.h>
#include "genser_urdf.h"

namespace {

// A rigid transform: rotation then translation, both relative to the parent frame.
struct Rigid {
    Eigen::Matrix3d rot = Eigen::Matrix3d::Identity();
    Eigen::Vector3d tran = Eigen::Vector3d::Zero();
};

// The joint origin of a URDF joint as a rigid transform, lengths scaled.
Rigid joint_origin(const urdf::Joint &joint, double scale)
{
    const urdf::Pose &o = joint.parent_to_joint_origin_transform;
    Rigid r;
    r.rot = Eigen::Quaterniond(o.rotation.w, o.rotation.x, o.rotation.y, o.rotation.z)
                .normalized().toRotationMatrix();
    r.tran = Eigen::Vector3d(o.position.x, o.position.y, o.position.z) * scale;
    return r;
}

// a followed by b.
Rigid compose(const Rigid &a, const Rigid &b)
{
    Rigid r;
    r.rot = a.rot * b.rot;
    r.tran = a.tran + a.rot * b.tran;
    return r;
}

// Store the fixed part and axis of chain joint n.
void store_joint(genser_chain_t *chain, int n, const Rigid &fixed, const Eigen::Vector3d &axis)
{
    for (int r = 0; r < 3; r++) {
        for (int k = 0; k < 3; k++)
            chain->rot[n][r][k] = fixed.rot(r, k);
        chain->tran[n][r] = fixed.tran(r);
        chain->axis[n][r] = axis(r);
    }
}

// Store the tool transform after the last joint.
void store_tool(genser_chain_t *chain, const Rigid &tool)
{
    for (int r = 0; r < 3; r++) {
        for (int k = 0; k < 3; k++)
            chain->tool_rot[r][k] = tool.rot(r, k);
        chain->tool_tran[r] = tool.tran(r);
    }
}

// Walk state: the chain built so far and the fixed transform waiting for the next joint.
struct Walk {
    genser_chain_t *chain;
    double scale;
    int joints = 0;
    Rigid pending;
    std::string error;
};

// Take one URDF joint into the walk; false with walk.error set when it cannot be used.
bool take_joint(Walk &walk, const urdf::Joint &joint)
{
    walk.pending = compose(walk.pending, joint_origin(joint, walk.scale));
    if (joint.type == urdf::Joint::FIXED)
        return true;
    if (joint.type != urdf::Joint::REVOLUTE && joint.type != urdf::Joint::CONTINUOUS) {
        walk.error = "joint '" + joint.name + "' is not revolute, continuous or fixed";
        return false;
    }
    Eigen::Vector3d axis(joint.axis.x, joint.axis.y, joint.axis.z);
    if (!(axis.norm() > 1e-9)) {
        walk.error = "joint '" + joint.name + "' has a zero axis";
        return false;
    }
    if (walk.joints >= GENSER_JOINTS) {
        walk.error = "more than 6 revolute joints (at joint '" + joint.name + "')";
        return false;
    }
    store_joint(walk.chain, walk.joints++, walk.pending, axis.normalized());
    walk.pending = Rigid();
    return true;
}

// Follow the only child of every link from the root; false with walk.error on a branch.
bool walk_chain(Walk &walk, urdf::LinkConstSharedPtr link)
{
    while (link && !link->child_joints.empty()) {
        if (link->child_joints.size() > 1) {
            walk.error = "link '" + link->name + "' has " +
                         std::to_string(link->child_joints.size()) +
                         " child joints (a single chain is needed)";
            return false;
        }
        if (!take_joint(walk, *link->child_joints[0]))
            return false;
        link = link->child_links[0];
    }
    return true;
}

} // namespace

// Parse the file and fill the chain; every failure names the file.
extern "C" int genser_urdf_load(const char *path, double scale, genser_chain_t *chain,
                                char *why, size_t why_size)
{
    FILE *probe = fopen(path, "r");
    if (!probe) {
        snprintf(why, why_size, "urdf '%s': cannot open: %s", path, strerror(errno));
        return -ENOENT;
    }
    fclose(probe);
    urdf::ModelInterfaceSharedPtr model;
    try {
        model = urdf::parseURDFFile(path);
    } catch (const std::exception &) {
        model = nullptr;
    }
    if (!model || !model->getRoot()) {
        snprintf(why, why_size, "urdf '%s': cannot read or parse the robot description", path);
        return -EINVAL;
    }
    Walk walk;
    walk.chain = chain;
    walk.scale = scale;
    if (walk_chain(walk, model->getRoot()) && walk.joints != GENSER_JOINTS)
        walk.error = "has " + std::to_string(walk.joints) + " revolute joints, 6 are needed";
    if (!walk.error.empty()) {
        snprintf(why, why_size, "urdf '%s': %s", path, walk.error.c_str());
        return -EINVAL;
    }
    store_tool(chain, walk.pending);
    return 0;
}
