// halui_status.cc: halui's output pins from task's status: machine, modes, program, coolant, spindles, overrides, joints, axes, tool.
#include "halui.hh"
#include "ui_pose.hh"

namespace {

// Write an output pin.
void set(hal_bit_t **pin, bool v) { **pin = v; }
void set(hal_float_t **pin, double v) { **pin = v; }

// Machine, E-stop, modes, coolant, program and override outputs.
void machine_outputs(HaluiPins &p, const EMC_STAT &s)
{
    const EMC_TASK_STAT &t = s.task;
    set(p.machine_is_on, t.state == EMC_TASK_STATE_ON);
    set(p.estop_is_activated, t.state == EMC_TASK_STATE_ESTOP);
    set(p.mode_is_manual, t.mode == EMC_TASK_MODE_MANUAL);
    set(p.mode_is_auto, t.mode == EMC_TASK_MODE_AUTO);
    set(p.mode_is_mdi, t.mode == EMC_TASK_MODE_MDI);
    set(p.mode_is_teleop, s.motion.traj.mode == EMC_TRAJ_MODE_TELEOP);
    set(p.mode_is_joint, s.motion.traj.mode == EMC_TRAJ_MODE_FREE);
    set(p.mist_is_on, s.io.coolant.mist != 0);
    set(p.flood_is_on, s.io.coolant.flood != 0);
    set(p.program_is_idle, t.interpState == EMC_TASK_INTERP_IDLE);
    set(p.program_is_running, t.interpState == EMC_TASK_INTERP_READING ||
                                  t.interpState == EMC_TASK_INTERP_WAITING);
    set(p.program_is_paused, t.interpState == EMC_TASK_INTERP_PAUSED);
    set(p.optional_stop_is_on, t.optional_stop_state != 0);
    set(p.block_delete_is_on, t.block_delete_state != 0);
    set(p.feed_override.value, s.motion.traj.scale);
    set(p.rapid_override.value, s.motion.traj.rapid_scale);
    set(p.max_velocity.value, s.motion.traj.maxVelocity);
}

// The status pins of one spindle.
void spindle_outputs(SpindlePins &p, const EMC_SPINDLE_STAT &sp)
{
    set(p.is_on, sp.enabled != 0);
    set(p.runs_forward, sp.enabled != 0 && sp.direction > 0);
    set(p.runs_backward, sp.enabled != 0 && sp.direction < 0);
    set(p.brake_is_on, sp.brake != 0);
    set(p.override.value, sp.spindle_scale);
}

// The status pins of one joint (or of the selected one).
void joint_status(JointStatusPins &p, const EMC_JOINT_STAT &j)
{
    set(p.is_homed, j.homed != 0);
    set(p.has_fault, j.fault != 0);
    set(p.on_soft_min, j.minSoftLimit != 0);
    set(p.on_soft_max, j.maxSoftLimit != 0);
    set(p.on_hard_min, j.minHardLimit != 0);
    set(p.on_hard_max, j.maxHardLimit != 0);
    set(p.override_limits, j.overrideLimits != 0);
}

// Every joint and the selected joint.
void joint_outputs(Halui &h, const EMC_STAT &s)
{
    for (int j = 0; j < h.cfg.joints; j++) joint_status(h.pins.joint[j].status, s.motion.joint[j]);
    joint_status(h.pins.joint_selected_status, s.motion.joint[h.selected_joint]);
}

// Axis positions, tool offsets, tool number and diameter.
void axis_outputs(Halui &h, const EMC_STAT &s)
{
    double rel[EMCMOT_MAX_AXIS];
    ui_relative_position(s.task, s.motion.traj.position, rel);
    for (int a = 0; a < EMCMOT_MAX_AXIS; a++) {
        if (!(h.cfg.axis_mask & (1u << a))) continue;
        AxisPins &p = h.pins.axis[a];
        set(p.pos_commanded, ui_pose_at(s.motion.traj.position, a));
        set(p.pos_feedback, ui_pose_at(s.motion.traj.actualPosition, a));
        set(p.pos_relative, rel[a]);
        set(h.pins.tool_length_offset[a], ui_pose_at(s.task.toolOffset, a));
    }
    const EMC_TOOL_STAT &tool = s.io.tool;
    **h.pins.tool_number = tool.toolInSpindle > 0 ? static_cast<uint32_t>(tool.toolInSpindle) : 0;
    set(h.pins.tool_diameter, tool.toolInSpindle > 0 ? tool.toolTableCurrent.diameter : 0.0);
}

// Selection outputs (kept current even without a machine).
void selection_outputs(Halui &h)
{
    for (int j = 0; j < h.cfg.joints; j++) set(h.pins.joint[j].is_selected, j == h.selected_joint);
    **h.pins.joint_selected = static_cast<uint32_t>(h.selected_joint);
    for (int a = 0; a < EMCMOT_MAX_AXIS; a++)
        if (h.cfg.axis_mask & (1u << a)) set(h.pins.axis[a].is_selected, a == h.selected_axis);
    **h.pins.axis_selected = static_cast<uint32_t>(h.selected_axis);
}

} // namespace

// Write every output pin.
void halui_outputs(Halui &h)
{
    selection_outputs(h);
    if (!h.client.have_status()) return;
    const EMC_STAT &s = h.client.status();
    machine_outputs(h.pins, s);
    for (int n = 0; n < h.cfg.spindles; n++) spindle_outputs(h.pins.spindle[n], s.motion.spindle[n]);
    joint_outputs(h, s);
    axis_outputs(h, s);
}
