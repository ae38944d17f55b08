/* mot_init.c: motmod's state at load: defaults of joints, axes, spindles, planner limits; homing set-up. */
#include <limits.h>
#include "rtapi.h"
#include "mot_priv.h"
#include "mot_control.h"
#include "mot_cmd.h"

#define NO_LIMIT 1e99

/* Joint defaults ([JOINT_n] defaults of ini.md). */
static void init_joint(mot_joint_t *joint)
{
    joint->min_limit = -NO_LIMIT;
    joint->max_limit = NO_LIMIT;
    joint->vel_limit = 1.0;
    joint->acc_limit = 1.0;
    joint->min_ferror = 1.0;
    joint->max_ferror = 1.0;
    joint->active = 1;
    joint->wheel_accel_fraction = 1.0;
    simple_tp_reset(&joint->free_tp, 0.0);
    simple_tp_reset(&joint->backlash_tp, 0.0);
    cubic_init(&joint->cubic, mot->interp_rate, 0.0);
}

/* Axis defaults ([AXIS_L] defaults). */
static void init_axis(mot_axis_t *axis)
{
    axis->min_limit = -NO_LIMIT;
    axis->max_limit = NO_LIMIT;
    axis->vel_limit = 1.0;
    axis->acc_limit = 1.0;
    axis->locking_joint = -1;
    simple_tp_reset(&axis->teleop_tp, 0.0);
    axis->teleop_tp.max_vel = 1.0;
    axis->teleop_tp.max_acc = 1.0;
    simple_tp_reset(&axis->ext_offset_tp, 0.0);
}

/* Spindle defaults ([SPINDLE_n] defaults). */
static void init_spindle(mot_spindle_t *s)
{
    s->scale = 1.0;
    s->override_enabled = 1;
    s->max_pos_speed = NO_LIMIT;
    s->min_pos_speed = 0.0;
    s->max_neg_speed = -NO_LIMIT;
    s->min_neg_speed = 0.0;
    s->increment = 100.0;
    s->brake = 1;
    s->at_speed = 1;
}

/* Homing callback: shift joint coordinates so the feedback reads pos. */
static void home_set_position(int j, double pos)
{
    mot_joint_t *joint = &mot->joint[j];
    double shift = pos - joint->pos_fb;

    joint->pos_cmd += shift;
    joint->pos_fb += shift;
    joint->free_tp.curr_pos += shift;
    joint->free_tp.pos_cmd += shift;
    joint->motor_offset -= shift;
}

/* Homing callback: the encoder was reset at the index, motor zero means pos. */
static void home_set_motor_zero(int j, double pos)
{
    mot_joint_t *joint = &mot->joint[j];

    joint->motor_offset = -pos;
    joint->pos_fb = joint->motor_pos_fb - joint->backlash_filt - joint->motor_offset;
    joint->pos_cmd = joint->pos_fb;
    simple_tp_reset(&joint->free_tp, joint->pos_fb);
}

/* Hand the homing module its joints and callbacks. */
static int init_homing(void)
{
    home_env_t env = {
        .comp_id = mot->comp_id,
        .num_joints = mot->max_joints,
        .num_extra_joints = mot->num_extra_joints,
        .servo_period = mot->servo_period,
        .joints = mot->home_joints,
        .report = mot_report,
        .set_position = home_set_position,
        .set_motor_zero = home_set_motor_zero,
    };
    int rc = mot->home->init(&env);

    if (rc < 0)
        rtapi_print_msg(RTAPI_MSG_ERR, "MOTION: homing module %s failed to start (%d)\n",
                        mot->home->name, rc);
    return rc;
}

/* Machine-wide defaults (SET_* commands override them). */
static void init_machine(void)
{
    mot->feed_scale = mot->rapid_scale = mot->net_feed_scale = 1.0;
    mot->fs_enabled = mot->fh_enabled = 1;
    mot->max_feed_override = 1.0;
    mot->scurve_peak_scale = 1.0;
    mot->vel = mot->ini_maxvel = 1.0;
    mot->vel_limit = mot->acc = NO_LIMIT;
    mot->jerk = 1e9;
    mot->planner_type_pending = -1;
    mot->kins_switch_refused = INT_MIN;
    mot->indexer_joint = -1;
    mot->motion_state = EMCMOT_MOTION_DISABLED;
    mot->tp_limits.arc_blend_enable = 1;
    mot->tp_limits.arc_blend_optimization_depth = 50;
    mot->tp_limits.arc_blend_gap_cycles = 4;
    mot->tp_limits.arc_blend_ramp_freq = 100;
    mot->tp_limits.arc_blend_tangent_kink_ratio = 0.1;
}

/* Everything at load, then a first status so readers see a sane snapshot. */
int mot_init_state(void)
{
    init_machine();
    for (int j = 0; j < MOT_MAX_JOINTS; j++)
        init_joint(&mot->joint[j]);
    for (int a = 0; a < MOT_NUM_AXES; a++)
        init_axis(&mot->axis[a]);
    for (int s = 0; s < MOT_MAX_SPINDLES; s++)
        init_spindle(&mot->spindle[s]);
    mot_tp_limits_changed();
    mot->tp_ops->set_pos(mot->tp, &mot->carte_pos_cmd);
    if (init_homing() < 0)
        return -EINVAL;
    mot_status_publish();
    return 0;
}
