/* mot_status.c: step 16: build the status snapshot and publish it (seqlock, never waits for readers). */
#include "rtapi.h"
#include "mot_priv.h"
#include "mot_control.h"

/* Configuration part of the status. */
static void config_status(emcmot_status_t *s)
{
    s->cycle_time = mot->traj_period;
    s->joints = mot->num_joints;
    s->num_extra_joints = mot->num_extra_joints;
    s->spindles = mot->num_spindles;
    s->num_dio = mot->num_dio;
    s->num_aio = mot->num_aio;
    s->num_misc_error = mot->num_misc_error;
    s->kinematics_type = mot->kins->type();
    s->kinematics_switchable = mot->kins->switchable();
    s->kinematics_switch_type = mot->kins_switch_type;
    s->planner_type = mot->planner_type;
    s->debug = mot->debug;
    s->vel = mot->vel;
    s->ini_maxvel = mot->ini_maxvel;
    s->vel_limit = mot->vel_limit;
    s->acc = mot->acc;
    s->jerk = mot->jerk;
    s->max_feed_override = mot->max_feed_override;
    s->scurve_peak_scale = mot->scurve_peak_scale;
    s->world_home = mot->world_home;
    s->tool_offset = mot->tool_offset;
    s->queue_capacity = MOT_TP_QUEUE_SIZE;
}

/* Mode, planner, probe and offset part. */
static void state_status(emcmot_status_t *s)
{
    s->motion_state = mot->motion_state;
    s->enabled = mot->enabled;
    s->coord = mot->coord;
    s->teleop = mot->teleop;
    s->inpos = mot->inpos;
    s->fault_code = mot->fault_code;
    s->homing_active = mot->home->homing_active();
    s->all_homed = mot->all_homed;
    s->on_soft_limit = mot->on_soft_limit;
    s->jogging_active = *mot->pins->jog_is_active;
    s->paused = mot->paused;
    s->stepping = mot->stepping;
    s->reverse = mot->reverse;
    s->probe_err_inhibit_jog = mot->probe_err_inhibit_jog;
    s->probe_err_inhibit_home = mot->probe_err_inhibit_home;
    s->queue_depth = mot->coord ? mot->queue_depth : 0;
    s->active_depth = mot->coord ? mot->active_depth : 0;
    s->queue_full = mot->coord ? mot_planner_full() : mot->queue_full;
    s->exec_id = mot->exec_id;
    s->exec_tag = mot->exec_tag;
    s->motion_type = *mot->pins->motion_type;
    s->term_cond = mot->term_cond;
    s->tolerance = mot->tolerance;
    s->current_vel = *mot->pins->current_vel;
    s->requested_vel = *mot->pins->requested_vel;
    s->distance_to_go = *mot->pins->distance_to_go;
    s->dtg = mot->dtg;
    s->feed_scale = mot->feed_scale;
    s->rapid_scale = mot->rapid_scale;
    s->net_feed_scale = mot->net_feed_scale;
    s->feed_scale_enabled = mot->fs_enabled;
    s->feed_hold_enabled = mot->fh_enabled;
    s->adaptive_feed_enabled = mot->af_enabled;
    s->spindle_sync_waiting = mot->spindle_sync_waiting;
    s->carte_pos_cmd = mot->carte_pos_cmd;
    s->carte_pos_fb = mot->carte_pos_fb_ok ? mot->carte_pos_fb : mot->carte_pos_cmd;
    s->carte_pos_fb_ok = mot->carte_pos_fb_ok;
    s->probed_pos = mot->probed_pos;
    s->probing = mot->probing;
    s->probe_tripped = mot->probe_tripped;
    s->probe_val = mot->probe_val;
    s->probe_type = mot->probe_type;
    s->external_offsets_applied = mot->eoffset_active;
    s->eoffset_limited = mot->eoffset_limited;
    for (int a = 0; a < MOT_NUM_AXES; a++)
        mot_pose_set(&s->eoffset_pose, a, mot->axis[a].ext_offset_tp.curr_pos);
}

/* One joint. */
static void joint_status(int j, emcmot_joint_status_t *s)
{
    const mot_joint_t *joint = &mot->joint[j];
    const home_ops_t *h = mot->home;

    s->pos_cmd = joint->pos_cmd;
    s->pos_fb = joint->pos_fb;
    s->vel_cmd = joint->vel_cmd;
    s->acc_cmd = joint->acc_cmd;
    s->ferror = joint->ferror;
    s->ferror_high_mark = joint->ferror_high_mark;
    s->ferror_limit = joint->ferror_limit;
    s->min_ferror = joint->min_ferror;
    s->max_ferror = joint->max_ferror;
    s->min_pos_limit = joint->min_limit;
    s->max_pos_limit = joint->max_limit;
    s->vel_limit = joint->vel_limit;
    s->acc_limit = joint->acc_limit;
    s->jerk_limit = joint->jerk_limit;
    s->backlash = joint->backlash;
    s->backlash_filt = joint->backlash_filt;
    s->motor_offset = joint->motor_offset;
    s->home_offset = h->joint_home_offset(j);
    s->home = h->joint_home(j);
    s->home_sequence = h->joint_home_sequence(j);
    s->home_state = h->joint_home_state(j);
    s->active = joint->active && j < mot->num_joints;
    s->enabled = joint->enabled;
    s->inpos = joint->inpos;
    s->homing = h->joint_homing(j);
    s->homed = h->joint_homed(j);
    s->error = joint->error;
    s->fault = joint->faulted;
    s->ferror_tripped = joint->ferror_tripped;
    s->min_soft_limit = joint->neg_soft;
    s->max_soft_limit = joint->pos_soft;
    s->min_hard_limit = joint->neg_hard;
    s->max_hard_limit = joint->pos_hard;
    s->override_limits = joint->override_mask;
    s->jogging = joint->kb_jog_active || joint->wheel_jog_active;
    s->locking_indexer = joint->locking_indexer;
    s->unlocked = mot->pins->joint[j].is_unlocked ? *mot->pins->joint[j].is_unlocked : 0;
}

/* One axis. */
static void axis_status(int a, emcmot_axis_status_t *s)
{
    const mot_axis_t *axis = &mot->axis[a];

    s->min_pos_limit = axis->min_limit;
    s->max_pos_limit = axis->max_limit;
    s->vel_limit = axis->vel_limit;
    s->acc_limit = axis->acc_limit;
    s->jerk_limit = axis->jerk_limit;
    s->teleop_pos_cmd = axis->teleop_tp.curr_pos;
    s->teleop_vel_cmd = axis->teleop_tp.curr_vel;
    s->eoffset = axis->ext_offset_tp.curr_pos;
    s->eoffset_request = axis->eoffset_request;
    s->locking_joint = axis->locking_joint;
    s->teleop_jogging = axis->kb_jog_active || axis->wheel_jog_active;
}

/* One spindle. */
static void spindle_status(int n, emcmot_spindle_status_t *s)
{
    const mot_spindle_t *sp = &mot->spindle[n];

    s->speed = sp->speed;
    s->speed_out = sp->speed_out;
    s->scale = sp->scale;
    s->css_maximum = sp->css_factor != 0.0 ? sp->speed : 0.0;
    s->css_factor = sp->css_factor;
    s->css_xoffset = sp->css_xoffset;
    s->speed_fb_rps = sp->speed_fb_rps;
    s->revs = sp->revs;
    s->orient_angle = sp->orient_angle;
    s->max_pos_speed = sp->max_pos_speed;
    s->min_pos_speed = sp->min_pos_speed;
    s->max_neg_speed = sp->max_neg_speed;
    s->min_neg_speed = sp->min_neg_speed;
    s->increment = sp->increment;
    s->state = sp->on;
    s->direction = sp->on ? sp->direction : 0;
    s->brake = sp->brake;
    s->increasing = sp->increasing;
    s->override_enabled = sp->override_enabled;
    s->orient_state = sp->orient_state;
    s->orient_fault = sp->orient_fault;
    s->at_speed = sp->at_speed;
    s->inhibit = sp->inhibit;
    s->homed = 0;
    s->locked = sp->locked;
}

/* 16. Fill and publish. */
void mot_status_publish(void)
{
    emcmot_status_t *s = &mot->status;

    s->heartbeat = mot->heartbeat;
    s->echo = mot->echo;
    config_status(s);
    state_status(s);
    for (int i = 0; i < mot->num_dio; i++)
        s->synch_do[i] = mot->dout[i];
    for (int i = 0; i < mot->num_aio; i++)
        s->analog_output[i] = mot->aout[i];
    for (int j = 0; j < mot->max_joints; j++)
        joint_status(j, &s->joint[j]);
    for (int a = 0; a < MOT_NUM_AXES; a++)
        axis_status(a, &s->axis[a]);
    for (int n = 0; n < mot->max_spindles; n++)
        spindle_status(n, &s->spindle[n]);
    emcmot_status_publish(mot->shm, s);
}
