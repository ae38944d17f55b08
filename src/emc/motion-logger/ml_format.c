/* ml_format.c: motion-logger's line for each EMCMOT command, in LinuxCNC's motion-logger format. */
#include <stdio.h>
#include "ml_format.h"

typedef void (*ml_fmt_t)(FILE *out, const emcmot_command_t *c);

/* The nine axes of a pose: "x=1, y=2, ..., w=9". */
static void pose(FILE *out, const EmcPose *p)
{
    fprintf(out, "x=%.6g, y=%.6g, z=%.6g, a=%.6g, b=%.6g, c=%.6g, u=%.6g, v=%.6g, w=%.6g",
            p->tran.x, p->tran.y, p->tran.z, p->a, p->b, p->c, p->u, p->v, p->w);
}

/* Commands logged by name alone. */
static void f_name(FILE *out, const emcmot_command_t *c)
{
    fprintf(out, "%s\n", emcmot_command_name(c->command));
}

/* "NAME joint=N". */
static void f_joint(FILE *out, const emcmot_command_t *c)
{
    fprintf(out, "%s joint=%d\n", emcmot_command_name(c->command), c->joint);
}

/* "NAME scale=S". */
static void f_scale(FILE *out, const emcmot_command_t *c)
{
    fprintf(out, "%s scale=%.6g\n", emcmot_command_name(c->command), c->scale);
}

/* "NAME mode=E" for the override enables. */
static void f_enable(FILE *out, const emcmot_command_t *c)
{
    fprintf(out, "%s mode=%d\n", emcmot_command_name(c->command), c->enable);
}

static void f_spindle_scale(FILE *out, const emcmot_command_t *c)
{
    fprintf(out, "SPINDLE_SCALE spindle=%d, scale=%.6g\n", c->spindle, c->scale);
}

static void f_ss_enable(FILE *out, const emcmot_command_t *c)
{
    fprintf(out, "SS_ENABLE spindle=%d, mode=%d\n", c->spindle, c->enable);
}

static void f_override_limits(FILE *out, const emcmot_command_t *c)
{
    fprintf(out, "OVERRIDE_LIMITS joint=%d, override=%d\n", c->joint, c->enable);
}

/* The tail SET_LINE, SET_CIRCLE and PROBE share. */
static void move_tail(FILE *out, const emcmot_command_t *c)
{
    fprintf(out, "id=%d, motion_type=%d, vel=%.6g, ini_maxvel=%.6g, acc=%.6g", c->id,
            c->motion_type, c->vel, c->ini_maxvel, c->acc);
}

static void f_set_line(FILE *out, const emcmot_command_t *c)
{
    fprintf(out, "SET_LINE ");
    pose(out, &c->pos);
    fprintf(out, ", ");
    move_tail(out, c);
    fprintf(out, ", turn=%d\n", c->turn);
}

static void f_set_circle(FILE *out, const emcmot_command_t *c)
{
    fprintf(out, "SET_CIRCLE ");
    pose(out, &c->pos);
    fprintf(out, ", center=(%.6g, %.6g, %.6g), normal=(%.6g, %.6g, %.6g), ", c->center.x,
            c->center.y, c->center.z, c->normal.x, c->normal.y, c->normal.z);
    move_tail(out, c);
    fprintf(out, ", turn=%d\n", c->turn);
}

static void f_probe(FILE *out, const emcmot_command_t *c)
{
    fprintf(out, "PROBE ");
    pose(out, &c->pos);
    fprintf(out, ", ");
    move_tail(out, c);
    fprintf(out, ", probe_type=%d\n", c->probe_type);
}

static void f_rigid_tap(FILE *out, const emcmot_command_t *c)
{
    fprintf(out, "RIGID_TAP ");
    pose(out, &c->pos);
    fprintf(out, ", id=%d, vel=%.6g, ini_maxvel=%.6g, acc=%.6g, spindle=%d, pitch=%.6g\n",
            c->id, c->vel, c->ini_maxvel, c->acc, c->spindle, c->tap_pitch);
}

static void f_set_vel(FILE *out, const emcmot_command_t *c)
{
    fprintf(out, "SET_VEL vel=%.6g, ini_maxvel=%.6g\n", c->vel, c->ini_maxvel);
}

static void f_set_vel_limit(FILE *out, const emcmot_command_t *c)
{
    fprintf(out, "SET_VEL_LIMIT vel=%.6g\n", c->vel);
}

static void f_set_acc(FILE *out, const emcmot_command_t *c)
{
    fprintf(out, "SET_ACC acc=%.6g\n", c->acc);
}

static void f_set_jerk(FILE *out, const emcmot_command_t *c)
{
    fprintf(out, "SET_JERK jerk=%.6g\n", c->jerk);
}

static void f_planner_type(FILE *out, const emcmot_command_t *c)
{
    fprintf(out, "SET_PLANNER_TYPE planner_type=%d\n", c->planner_type);
}

static void f_term_cond(FILE *out, const emcmot_command_t *c)
{
    fprintf(out, "SET_TERM_COND termCond=%d, tolerance=%.6g\n", c->term_cond, c->tolerance);
}

static void f_count(FILE *out, const emcmot_command_t *c)
{
    fprintf(out, "%s %d\n", emcmot_command_name(c->command), c->count);
}

static void f_world_home(FILE *out, const emcmot_command_t *c)
{
    fprintf(out, "SET_WORLD_HOME ");
    pose(out, &c->pos);
    fprintf(out, "\n");
}

static void f_set_offset(FILE *out, const emcmot_command_t *c)
{
    fprintf(out, "SET_OFFSET ");
    pose(out, &c->pos);
    fprintf(out, "\n");
}

static void f_set_debug(FILE *out, const emcmot_command_t *c)
{
    fprintf(out, "SET_DEBUG debug=%d\n", c->debug);
}

static void f_set_dout(FILE *out, const emcmot_command_t *c)
{
    fprintf(out, "SET_DOUT index=%d, start=%d, end=%d, now=%d\n", c->io_index, c->dout_start,
            c->dout_end, c->now);
}

static void f_set_aout(FILE *out, const emcmot_command_t *c)
{
    fprintf(out, "SET_AOUT index=%d, start=%.6g, end=%.6g, now=%d\n", c->io_index, c->aout_start,
            c->aout_end, c->now);
}

static void f_spindlesync(FILE *out, const emcmot_command_t *c)
{
    fprintf(out, "SET_SPINDLESYNC sync=%f, flags=0x%08x\n", c->spindle_sync,
            (unsigned)c->sync_velocity_mode);
}

static void f_spindle_on(FILE *out, const emcmot_command_t *c)
{
    fprintf(out, "SPINDLE_ON spindle=%d, speed=%.6g, css_factor=%.6g, xoffset=%.6g, wait=%d\n",
            c->spindle, c->speed, c->css_factor, c->css_xoffset, c->wait_for_at_speed);
}

static void f_spindle_orient(FILE *out, const emcmot_command_t *c)
{
    fprintf(out, "SPINDLE_ORIENT spindle=%d, orientation=%.6g, mode=%d\n", c->spindle,
            c->orientation, c->orient_mode);
}

static void f_max_feed_override(FILE *out, const emcmot_command_t *c)
{
    fprintf(out, "SET_MAX_FEED_OVERRIDE %.6g\n", c->scale);
}

static void f_probe_err_inhibit(FILE *out, const emcmot_command_t *c)
{
    fprintf(out, "SETUP_SET_PROBE_ERR_INHIBIT %d %d\n", c->probe_jog_err_inhibit,
            c->probe_home_err_inhibit);
}

static void f_jog(FILE *out, const emcmot_command_t *c)
{
    fprintf(out, "%s joint=%d, axis=%d, vel=%.6g", emcmot_command_name(c->command), c->joint,
            c->axis, c->vel);
    if (c->command == EMCMOT_JOG_INCR)
        fprintf(out, ", offset=%.6g", c->offset);
    else if (c->command == EMCMOT_JOG_ABS)
        fprintf(out, ", pos=%.6g", c->offset);
    fprintf(out, "\n");
}

static void f_joint_limits(FILE *out, const emcmot_command_t *c)
{
    fprintf(out, "SET_JOINT_POSITION_LIMITS joint=%d, min=%.6g, max=%.6g\n", c->joint,
            c->min_limit, c->max_limit);
}

static void f_joint_backlash(FILE *out, const emcmot_command_t *c)
{
    fprintf(out, "SET_JOINT_BACKLASH joint=%d, backlash=%.6g\n", c->joint, c->backlash);
}

static void f_joint_min_ferror(FILE *out, const emcmot_command_t *c)
{
    fprintf(out, "SET_JOINT_MIN_FERROR joint=%d, minFerror=%.6g\n", c->joint, c->min_ferror);
}

static void f_joint_max_ferror(FILE *out, const emcmot_command_t *c)
{
    fprintf(out, "SET_JOINT_MAX_FERROR joint=%d, maxFerror=%.6g\n", c->joint, c->max_ferror);
}

static void f_joint_vel(FILE *out, const emcmot_command_t *c)
{
    fprintf(out, "SET_JOINT_VEL_LIMIT joint=%d, vel=%.6g\n", c->joint, c->vel);
}

static void f_joint_acc(FILE *out, const emcmot_command_t *c)
{
    fprintf(out, "SET_JOINT_ACC_LIMIT joint=%d, acc=%.6g\n", c->joint, c->acc);
}

static void f_joint_jerk(FILE *out, const emcmot_command_t *c)
{
    fprintf(out, "SET_JOINT_JERK_LIMIT joint=%d, jerk=%.6g\n", c->joint, c->jerk);
}

static void f_homing_params(FILE *out, const emcmot_command_t *c)
{
    fprintf(out, "SET_JOINT_HOMING_PARAMS joint=%d, offset=%.6g home=%.6g, final_vel=%.6g, "
            "search_vel=%.6g, latch_vel=%.6g, flags=0x%08x, sequence=%d, volatile=%d\n",
            c->joint, c->home_offset, c->home, c->home_final_vel, c->home_search_vel,
            c->home_latch_vel, (unsigned)c->home_flags, c->home_sequence, c->volatile_home);
}

static void f_update_homing(FILE *out, const emcmot_command_t *c)
{
    fprintf(out, "UPDATE_JOINT_HOMING_PARAMS joint=%d, offset=%.6g, home=%.6g, sequence=%d\n",
            c->joint, c->home_offset, c->home, c->home_sequence);
}

static void f_motor_offset(FILE *out, const emcmot_command_t *c)
{
    fprintf(out, "SET_JOINT_MOTOR_OFFSET joint=%d, offset=%.6g\n", c->joint, c->offset);
}

static void f_joint_comp(FILE *out, const emcmot_command_t *c)
{
    fprintf(out, "SET_JOINT_COMP joint=%d, nominal=%.6g, forward=%.6g, reverse=%.6g\n", c->joint,
            c->comp_nominal, c->comp_forward, c->comp_reverse);
}

static void f_axis_limits(FILE *out, const emcmot_command_t *c)
{
    fprintf(out, "SET_AXIS_POSITION_LIMITS axis=%d, min=%.6g, max=%.6g\n", c->axis, c->min_limit,
            c->max_limit);
}

static void f_axis_vel(FILE *out, const emcmot_command_t *c)
{
    fprintf(out, "SET_AXIS_VEL_LIMIT axis=%d vel=%.6g\n", c->axis, c->vel);
}

static void f_axis_acc(FILE *out, const emcmot_command_t *c)
{
    fprintf(out, "SET_AXIS_ACC_LIMIT axis=%d, acc=%.6g\n", c->axis, c->acc);
}

static void f_axis_locking(FILE *out, const emcmot_command_t *c)
{
    fprintf(out, "SET_AXIS_LOCKING_JOINT axis=%d, locking_joint=%d\n", c->axis, c->locking_joint);
}

static void f_axis_jerk(FILE *out, const emcmot_command_t *c)
{
    fprintf(out, "SET_AXIS_JERK_LIMIT axis=%d, jerk=%.6g\n", c->axis, c->jerk);
}

static void f_spindle_params(FILE *out, const emcmot_command_t *c)
{
    fprintf(out, "SET_SPINDLE_PARAMS, %.2e, %.2e, %.2e, %.2e\n", c->max_pos_speed,
            c->min_pos_speed, c->max_neg_speed, c->min_neg_speed);
}

static const ml_fmt_t formats[EMCMOT_LAST_COMMAND + 1] = {
    [EMCMOT_ABORT] = f_name, [EMCMOT_ENABLE] = f_name, [EMCMOT_DISABLE] = f_name,
    [EMCMOT_PAUSE] = f_name, [EMCMOT_REVERSE] = f_name, [EMCMOT_FORWARD] = f_name,
    [EMCMOT_RESUME] = f_name, [EMCMOT_STEP] = f_name, [EMCMOT_FREE] = f_name,
    [EMCMOT_COORD] = f_name, [EMCMOT_TELEOP] = f_name,
    [EMCMOT_SPINDLE_SCALE] = f_spindle_scale, [EMCMOT_SS_ENABLE] = f_ss_enable,
    [EMCMOT_FEED_SCALE] = f_scale, [EMCMOT_RAPID_SCALE] = f_scale,
    [EMCMOT_FS_ENABLE] = f_enable, [EMCMOT_FH_ENABLE] = f_enable, [EMCMOT_AF_ENABLE] = f_enable,
    [EMCMOT_OVERRIDE_LIMITS] = f_override_limits, [EMCMOT_SET_LINE] = f_set_line,
    [EMCMOT_SET_CIRCLE] = f_set_circle, [EMCMOT_CLEAR_PROBE_FLAGS] = f_name,
    [EMCMOT_PROBE] = f_probe, [EMCMOT_RIGID_TAP] = f_rigid_tap, [EMCMOT_SET_VEL] = f_set_vel,
    [EMCMOT_SET_VEL_LIMIT] = f_set_vel_limit, [EMCMOT_SET_ACC] = f_set_acc,
    [EMCMOT_SET_JERK] = f_set_jerk, [EMCMOT_SET_PLANNER_TYPE] = f_planner_type,
    [EMCMOT_SET_SCURVE_PEAK_SCALE] = f_scale, [EMCMOT_SET_TERM_COND] = f_term_cond,
    [EMCMOT_SET_NUM_JOINTS] = f_count, [EMCMOT_SET_NUM_SPINDLES] = f_count,
    [EMCMOT_SET_WORLD_HOME] = f_world_home, [EMCMOT_SET_DEBUG] = f_set_debug,
    [EMCMOT_SET_DOUT] = f_set_dout, [EMCMOT_SET_AOUT] = f_set_aout,
    [EMCMOT_SET_SPINDLESYNC] = f_spindlesync, [EMCMOT_SPINDLE_ON] = f_spindle_on,
    [EMCMOT_SPINDLE_OFF] = f_name, [EMCMOT_SPINDLE_INCREASE] = f_name,
    [EMCMOT_SPINDLE_DECREASE] = f_name, [EMCMOT_SPINDLE_BRAKE_ENGAGE] = f_name,
    [EMCMOT_SPINDLE_BRAKE_RELEASE] = f_name, [EMCMOT_SPINDLE_ORIENT] = f_spindle_orient,
    [EMCMOT_SET_OFFSET] = f_set_offset, [EMCMOT_SET_MAX_FEED_OVERRIDE] = f_max_feed_override,
    [EMCMOT_SETUP_ARC_BLENDS] = f_name, [EMCMOT_SET_PROBE_ERR_INHIBIT] = f_probe_err_inhibit,
    [EMCMOT_JOG_CONT] = f_jog, [EMCMOT_JOG_INCR] = f_jog, [EMCMOT_JOG_ABS] = f_jog,
    [EMCMOT_JOG_ABORT] = f_joint, [EMCMOT_JOINT_ACTIVATE] = f_joint,
    [EMCMOT_JOINT_DEACTIVATE] = f_joint, [EMCMOT_JOINT_HOME] = f_joint,
    [EMCMOT_JOINT_UNHOME] = f_joint, [EMCMOT_SET_JOINT_POSITION_LIMITS] = f_joint_limits,
    [EMCMOT_SET_JOINT_BACKLASH] = f_joint_backlash,
    [EMCMOT_SET_JOINT_MIN_FERROR] = f_joint_min_ferror,
    [EMCMOT_SET_JOINT_MAX_FERROR] = f_joint_max_ferror,
    [EMCMOT_SET_JOINT_VEL_LIMIT] = f_joint_vel, [EMCMOT_SET_JOINT_ACC_LIMIT] = f_joint_acc,
    [EMCMOT_SET_JOINT_HOMING_PARAMS] = f_homing_params,
    [EMCMOT_SET_JOINT_JERK_LIMIT] = f_joint_jerk,
    [EMCMOT_UPDATE_JOINT_HOMING_PARAMS] = f_update_homing,
    [EMCMOT_SET_JOINT_MOTOR_OFFSET] = f_motor_offset, [EMCMOT_SET_JOINT_COMP] = f_joint_comp,
    [EMCMOT_SET_AXIS_POSITION_LIMITS] = f_axis_limits, [EMCMOT_SET_AXIS_VEL_LIMIT] = f_axis_vel,
    [EMCMOT_SET_AXIS_ACC_LIMIT] = f_axis_acc, [EMCMOT_SET_AXIS_LOCKING_JOINT] = f_axis_locking,
    [EMCMOT_SET_AXIS_JERK_LIMIT] = f_axis_jerk, [EMCMOT_SET_SPINDLE_PARAMS] = f_spindle_params,
};

/* Write the line of one command (unknown codes are logged as such). */
void ml_format(FILE *out, const emcmot_command_t *c)
{
    if (c->command < EMCMOT_FIRST_COMMAND || c->command > EMCMOT_LAST_COMMAND) {
        fprintf(out, "unknown command %d\n", c->command);
        return;
    }
    formats[c->command](out, c);
}
