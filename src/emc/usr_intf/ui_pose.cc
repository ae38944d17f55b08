// ui_pose.cc: pose component access and machine-to-relative position conversion for halui and linuxcncrsh.
#include "ui_pose.hh"

#include <cmath>

// Component i of a pose.
double ui_pose_at(const EmcPose &p, int i)
{
    const double v[EMCMOT_MAX_AXIS] = {p.tran.x, p.tran.y, p.tran.z, p.a, p.b, p.c, p.u, p.v, p.w};
    return i >= 0 && i < EMCMOT_MAX_AXIS ? v[i] : 0.0;
}

// Machine position to the current coordinate system.
void ui_relative_position(const EMC_TASK_STAT &t, const EmcPose &machine, double out[EMCMOT_MAX_AXIS])
{
    for (int i = 0; i < EMCMOT_MAX_AXIS; i++)
        out[i] = ui_pose_at(machine, i) - ui_pose_at(t.g5x_offset, i) - ui_pose_at(t.toolOffset, i);
    double r = -t.rotation_xy * M_PI / 180.0;
    double x = out[0] * std::cos(r) - out[1] * std::sin(r);
    double y = out[0] * std::sin(r) + out[1] * std::cos(r);
    out[0] = x;
    out[1] = y;
    for (int i = 0; i < EMCMOT_MAX_AXIS; i++) out[i] -= ui_pose_at(t.g92_offset, i);
}
