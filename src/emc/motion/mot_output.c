/* mot_output.c: step 14: joint, axis, motion, interp.* and I/O output pins. */
#include "rtapi.h"
#include "rtapi_math.h"
#include "mot_priv.h"
#include "mot_control.h"
#include "mot_coord.h"
#include "mot_jog.h"

#define DEG_PER_RAD (180.0 / M_PI)
#define GCODE_UNITS_SLOT 5      /* state_tag gcodes[] slot of G20/G21 */
#define GCODE_MOTION_SLOT 1     /* state_tag gcodes[] slot of the motion mode */

/* Angle in degrees folded into 0..360. */
static double wrap_deg(double deg)
{
    deg = fmod(deg, 360.0);
    return deg < 0.0 ? deg + 360.0 : deg;
}

/* One joint's pins. */
static void joint_out(int j)
{
    mot_joint_t *joint = &mot->joint[j];
    mot_joint_pins_t *p = &mot->pins->joint[j];
    int in_use = j < mot->num_joints && joint->active;

    joint->motor_pos_cmd = joint->pos_cmd + joint->backlash_filt + joint->motor_offset;
    joint->enabled = mot->enabled && in_use;
    *p->amp_enable_out = joint->enabled;
    *p->coarse_pos_cmd = mot->coord ? joint->coarse_pos : joint->pos_cmd;
    *p->pos_cmd = joint->pos_cmd;
    *p->pos_fb = joint->pos_fb;
    *p->motor_pos_cmd = joint->motor_pos_cmd;
    *p->motor_offset = joint->motor_offset;
    *p->vel_cmd = joint->vel_cmd;
    *p->acc_cmd = joint->acc_cmd;
    *p->jerk_cmd = joint->jerk_cmd;
    *p->backlash_corr = joint->backlash_corr;
    *p->backlash_filt = joint->backlash_filt;
    *p->backlash_vel = joint->backlash_vel;
    *p->f_error = joint->ferror;
    *p->f_error_lim = joint->ferror_limit;
    *p->free_pos_cmd = joint->free_tp.pos_cmd;
    *p->free_vel_lim = joint->free_tp.max_vel;
    *p->free_tp_enable = joint->free_tp.enable;
    *p->kb_jog_active = joint->kb_jog_active;
    *p->wheel_jog_active = joint->wheel_jog_active;
    joint->inpos = !joint->free_tp.active;
    *p->in_position = joint->inpos;
    *p->pos_hard_limit = joint->pos_hard;
    *p->neg_hard_limit = joint->neg_hard;
    *p->active = in_use;
    *p->error = joint->error;
    *p->f_errored = joint->ferror_tripped;
    *p->faulted = joint->faulted;
}

/* One axis' pins. */
static void axis_out(int a)
{
    mot_axis_t *axis = &mot->axis[a];
    mot_axis_pins_t *p = &mot->pins->axis[a];

    *p->pos_cmd = mot_pose_get(&mot->carte_pos_cmd, a);
    *p->teleop_pos_cmd = axis->teleop_tp.curr_pos;
    *p->teleop_vel_cmd = axis->teleop_tp.curr_vel;
    *p->teleop_vel_lim = axis->teleop_tp.max_vel;
    *p->teleop_tp_enable = axis->teleop_tp.enable;
    *p->kb_jog_active = axis->kb_jog_active;
    *p->wheel_jog_active = axis->wheel_jog_active;
    *p->eoffset = axis->ext_offset_tp.curr_pos;
    *p->eoffset_request = axis->eoffset_request;
}

/* Speed shown as motion.current-vel in each mode. */
static double current_vel(void)
{
    double sum = 0.0;

    if (mot->coord)
        return mot->current_vel;
    if (mot->teleop) {
        for (int a = 0; a < MOT_NUM_AXES; a++)
            sum += mot->axis[a].teleop_tp.curr_vel * mot->axis[a].teleop_tp.curr_vel;
        return sqrt(sum);
    }
    for (int j = 0; j < mot->num_joints; j++)
        if (mot->joint[j].free_tp.active)
            sum += mot->joint[j].vel_cmd * mot->joint[j].vel_cmd;
    return sqrt(sum);
}

/* feed-upm and its unit conversions (the programmed F times the net feed scale). */
static void feed_pins(void)
{
    mot_pins_t *p = mot->pins;
    int feeding = mot->coord && (mot->motion_type == TP_MOTION_FEED ||
                                 mot->motion_type == TP_MOTION_ARC);
    double upm = feeding ? mot->exec_tag.settings[1] * mot->net_feed_scale : 0.0;
    int inch = mot->exec_tag.gcodes[GCODE_UNITS_SLOT] == 200;

    *p->feed_upm = upm;
    *p->feed_inches_per_minute = inch ? upm : upm / 25.4;
    *p->feed_inches_per_second = *p->feed_inches_per_minute / 60.0;
    *p->feed_mm_per_minute = inch ? upm * 25.4 : upm;
    *p->feed_mm_per_second = *p->feed_mm_per_minute / 60.0;
}

/* Heading of the tool in XY: arcs from their centre, lines from the feedback motion. */
static void heading(const mot_shadow_seg_t *seg)
{
    const EmcPose *now = mot->carte_pos_fb_ok ? &mot->carte_pos_fb : &mot->carte_pos_cmd;
    const EmcPose *old = &mot->carte_pos_fb_old;

    if (seg && seg->is_circle) {
        double normal = atan2(seg->center.y - now->tran.y, seg->center.x - now->tran.x);
        mot->normal_heading = wrap_deg(normal * DEG_PER_RAD);
        mot->heading = wrap_deg(mot->normal_heading + (seg->clockwise ? 90.0 : -90.0));
        return;
    }
    double dx = now->tran.x - old->tran.x, dy = now->tran.y - old->tran.y;
    if (hypot(dx, dy) > 1e-12) {
        mot->heading = wrap_deg(atan2(dy, dx) * DEG_PER_RAD);
        mot->normal_heading = wrap_deg(mot->heading - 90.0);
    }
}

/* motion.interp.*: the executing segment's interpreter state and geometry. */
static void interp_pins(void)
{
    mot_pins_t *p = mot->pins;
    const mot_shadow_seg_t *seg = mot_executing_segment();
    int tagged = mot->coord && (mot->exec_tag.flags & STATE_TAG_VALID);

    *p->interp_line_number = tagged ? mot->exec_tag.line_number : 0;
    *p->interp_motion_type = tagged ? mot->exec_tag.gcodes[GCODE_MOTION_SLOT] : -1;
    *p->interp_feedrate = tagged ? mot->exec_tag.settings[1] : 0.0;
    *p->interp_iscircle = seg && seg->is_circle;
    *p->interp_arc_radius = seg && seg->is_circle ? seg->radius : 0.0;
    *p->interp_arc_center_x = seg && seg->is_circle ? seg->center.x : 0.0;
    *p->interp_arc_center_y = seg && seg->is_circle ? seg->center.y : 0.0;
    *p->interp_arc_center_z = seg && seg->is_circle ? seg->center.z : 0.0;
    heading(seg);
    *p->interp_heading = mot->heading;
    *p->interp_normal_heading = mot->normal_heading;
}

/* motion.* state pins. */
static void motion_pins(void)
{
    mot_pins_t *p = mot->pins;

    mot->inpos = mot->enabled ? !mot_any_joint_moving() && !mot->home->homing_active() &&
        (!mot->coord || mot_coord_settled()) : 1;
    for (int a = 0; a < MOT_NUM_AXES && mot->teleop; a++)
        if (mot->axis[a].teleop_tp.active)
            mot->inpos = 0;
    mot->all_homed = mot_joints_homed();
    *p->motion_enabled = mot->enabled;
    *p->in_position = mot->inpos;
    *p->coord_mode = mot->coord;
    *p->teleop_mode = mot->teleop;
    *p->on_soft_limit = mot->on_soft_limit;
    *p->jog_is_active = mot_jog_active();
    *p->is_all_homed = mot->all_homed;
    *p->tp_reverse = mot->coord && mot->reverse_running;
    *p->eoffset_active = mot->eoffset_active;
    *p->eoffset_limited = mot->eoffset_limited;
    *p->motion_type = mot->coord ? mot->motion_type : 0;
    *p->program_line = mot->coord ? mot->exec_id : 0;
    *p->current_vel = current_vel();
    *p->requested_vel = mot->coord ? mot->requested_vel : 0.0;
    *p->distance_to_go = mot->coord ? mot->distance_to_go : 0.0;
    for (int a = 0; a < MOT_NUM_AXES; a++)
        *p->tooloffset[a] = mot_pose_get(&mot->tool_offset, a);
    p->traj_vel_out = *p->current_vel;
    p->traj_pos_out = *p->distance_to_go;
    p->traj_active_tc = (uint32_t)(mot->coord ? mot->active_depth : 0);
}

/* 14. All outputs. */
void mot_output(void)
{
    for (int j = 0; j < mot->max_joints; j++)
        joint_out(j);
    for (int a = 0; a < MOT_NUM_AXES; a++)
        axis_out(a);
    motion_pins();
    feed_pins();
    interp_pins();
    mot_spindle_outputs();
    for (int i = 0; i < mot->num_dio; i++)
        *mot->pins->digital_out[i] = mot->dout[i];
    for (int i = 0; i < mot->num_aio; i++)
        *mot->pins->analog_out[i] = mot->aout[i];
}
