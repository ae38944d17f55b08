// task_status.cc: EMC_STAT from motion status, task state and io state, written to emcStatus every cycle.
#include "task.hh"

namespace {

void copy_joint(const emcmot_joint_status_t &j, const JointConfig &c, EMC_JOINT_STAT &o)
{
    o.jointType = c.type;
    o.units = c.units;
    o.backlash = j.backlash;
    o.minPositionLimit = j.min_pos_limit;
    o.maxPositionLimit = j.max_pos_limit;
    o.maxFerror = j.max_ferror;
    o.minFerror = j.min_ferror;
    o.ferrorCurrent = j.ferror;
    o.ferrorHighMark = j.ferror_high_mark;
    o.output = j.pos_cmd;
    o.input = j.pos_fb;
    o.velocity = j.vel_cmd;
    o.inpos = j.inpos;
    o.homing = j.homing;
    o.homed = j.homed;
    o.fault = j.fault;
    o.enabled = j.enabled;
    o.minSoftLimit = j.min_soft_limit;
    o.maxSoftLimit = j.max_soft_limit;
    o.minHardLimit = j.min_hard_limit;
    o.maxHardLimit = j.max_hard_limit;
    o.overrideLimits = j.override_limits;
}

void copy_spindle(const emcmot_spindle_status_t &s, EMC_SPINDLE_STAT &o)
{
    o.speed = s.speed;
    o.spindle_scale = s.scale;
    o.css_maximum = s.css_maximum;
    o.css_factor = s.css_factor;
    o.state = s.state;
    o.direction = s.direction;
    o.brake = s.brake;
    o.increasing = s.increasing;
    o.enabled = s.state;
    o.orient_state = s.orient_state;
    o.orient_fault = s.orient_fault;
    o.spindle_override_enabled = s.override_enabled;
    o.homed = s.homed;
}

}  // namespace

void Task::fill_motion_status()
{
    EMC_MOTION_STAT &m = st_.motion;
    EMC_TRAJ_STAT &t = m.traj;
    const emcmot_status_t &s = mst_;
    t.linearUnits = cfg_.linear_units;
    t.angularUnits = cfg_.angular_units;
    t.cycleTime = s.cycle_time;
    t.joints = cfg_.joints;
    t.spindles = cfg_.spindles;
    t.axis_mask = cfg_.axis_mask;
    t.mode = traj_mode_;
    t.enabled = s.enabled;
    t.inpos = s.inpos;
    t.queue = s.queue_depth;
    t.activeQueue = s.active_depth;
    t.queueFull = s.queue_full;
    t.id = s.exec_id;
    t.paused = s.paused;
    t.single_stepping = s.stepping;
    t.scale = s.feed_scale;
    t.rapid_scale = s.rapid_scale;
    t.position = s.carte_pos_cmd;
    t.actualPosition = s.carte_pos_fb;
    t.velocity = s.vel;
    t.acceleration = s.acc;
    t.maxVelocity = s.vel_limit;
    t.maxAcceleration = s.acc;
    t.probedPosition = s.probed_pos;
    t.probe_tripped = s.probe_tripped;
    t.probing = s.probing;
    t.probeval = s.probe_val;
    t.kinematics_type = s.kinematics_type;
    t.motion_type = s.motion_type;
    t.distance_to_go = s.distance_to_go;
    t.dtg = s.dtg;
    t.current_vel = s.current_vel;
    t.feed_override_enabled = s.feed_scale_enabled;
    t.adaptive_feed_enabled = s.adaptive_feed_enabled;
    t.feed_hold_enabled = s.feed_hold_enabled;
    t.tag = s.exec_tag;
    for (int j = 0; j < cfg_.joints; j++) copy_joint(s.joint[j], cfg_.joint[j], m.joint[j]);
    for (int a = 0; a < EMCMOT_MAX_AXIS; a++) {
        m.axis[a].minPositionLimit = s.axis[a].min_pos_limit;
        m.axis[a].maxPositionLimit = s.axis[a].max_pos_limit;
        m.axis[a].velocity = s.axis[a].teleop_vel_cmd;
    }
    for (int i = 0; i < EMCMOT_MAX_SPINDLES; i++) copy_spindle(s.spindle[i], m.spindle[i]);
    for (int i = 0; i < EMCMOT_MAX_DIO; i++) { m.synch_di[i] = s.synch_di[i]; m.synch_do[i] = s.synch_do[i]; }
    for (int i = 0; i < EMCMOT_MAX_AIO; i++) { m.analog_input[i] = s.analog_input[i]; m.analog_output[i] = s.analog_output[i]; }
    for (int i = 0; i < EMCMOT_MAX_MISC_ERROR; i++) m.misc_error[i] = s.misc_error[i];
    m.debug = s.debug;
    m.on_soft_limit = s.on_soft_limit;
    m.external_offsets_applied = s.external_offsets_applied;
    m.eoffset_pose = s.eoffset_pose;
    m.numExtraJoints = s.num_extra_joints;
    m.jogging_active = s.jogging_active;
    m.heartbeat = s.heartbeat;
    m.status = RCS_DONE;
}

void Task::fill_task_status()
{
    EMC_TASK_STAT &t = st_.task;
    t.mode = task_mode();
    t.state = task_state();
    t.execState = exec_error_ ? EMC_TASK_EXEC_ERROR : exec_state_;
    t.interpState = interp_state_;
    t.callLevel = interp_->state().call_level;
    bool running = interp_state_ != EMC_TASK_INTERP_IDLE && task_mode() == EMC_TASK_MODE_AUTO;
    t.motionLine = running ? mst_.exec_id : 0;
    t.currentLine = current_line_;
    t.readLine = running ? read_line_ : 0;
    t.optional_stop_state = optional_stop_;
    t.block_delete_state = block_delete_;
    emc_set_text(t.command, mdi_text_.c_str());
    t.programUnits = canon_->program_units();
    t.interpreter_errcode = errcode_;
    t.task_paused = task_paused_;
    t.queuedMDIcommands = (int)mdi_queue_.size();
    t.taskbeat++;
    bool tag_valid = running && (mst_.exec_tag.flags & STATE_TAG_VALID) && mst_.queue_depth > 0;
    if (tag_valid) {
        for (int i = 0; i < STATE_TAG_GCODES; i++) t.activeGCodes[i] = mst_.exec_tag.gcodes[i];
        for (int i = 0; i < STATE_TAG_MCODES; i++) t.activeMCodes[i] = mst_.exec_tag.mcodes[i];
        for (int i = 0; i < STATE_TAG_SETTINGS; i++) t.activeSettings[i] = mst_.exec_tag.settings[i];
    } else {
        interp_codes(t.activeGCodes, t.activeMCodes, t.activeSettings);
    }
}

// RCS status: ERROR after a refused or failed command; DONE when nothing is pending (no move,
// jog, homing, tool change, queued MDI or program).
int Task::rcs_status() const
{
    if (command_failed_ || exec_error_) return RCS_ERROR;
    bool coord_busy = traj_mode_ == EMC_TRAJ_MODE_COORD && !motion_done();
    bool joint_jog = traj_mode_ == EMC_TRAJ_MODE_FREE && mst_.jogging_active && !mst_.homing_active;
    bool echoed = !mot_ || (int32_t)(mst_.echo.serial - last_serial_) >= 0;
    // a homing in progress keeps the home command executing (wait_complete() returns homed)
    bool idle = exec_state_ == EMC_TASK_EXEC_DONE && !coord_busy && !joint_jog && !mst_.homing_active &&
                echoed && io_.done() &&
                mdi_queue_.empty() && list_.empty() && !has_pending_ && !wait_synch_ &&
                interp_state_ == EMC_TASK_INTERP_IDLE;
    return idle ? RCS_DONE : RCS_EXEC;
}

// The status echoes a command once motion has taken what it issued (as LinuxCNC, where task waits
// for motion's acknowledgement): a client that sent M64 and polls after the echo sees the output.
void Task::update_echo()
{
    if (!echo_pending_ || !motion_echoed()) return;
    echo_pending_ = false;
    st_.echo_serial_number = st_.task.echo_serial_number = echo_serial_;
    st_.command_type = st_.task.command_type = echo_type_;
}

void Task::update_status()
{
    update_echo();
    fill_motion_status();
    fill_task_status();
    int rcs = rcs_status();
    st_.status = rcs;
    st_.task.status = rcs;
    if (stat_ch_) stat_ch_->write(st_);
}
