/* ml_state.c: motion-logger's stand-in status: modes, homing and moves take effect at once. */
#include <string.h>
#include "ml_state.h"

typedef void (*ml_apply_t)(emcmot_status_t *st, const emcmot_command_t *c);

/* Start: disabled, free, one spindle, three joints, in position. */
void ml_state_init(emcmot_status_t *st)
{
    memset(st, 0, sizeof *st);
    st->joints = 3;
    st->spindles = 1;
    st->num_dio = st->num_aio = 4;
    st->kinematics_type = 1;
    st->cycle_time = 0.001;
    st->inpos = 1;
    st->feed_scale = st->rapid_scale = st->net_feed_scale = 1.0;
    st->feed_scale_enabled = st->feed_hold_enabled = 1;
    st->queue_capacity = 2000;
    for (int j = 0; j < EMCMOT_MAX_JOINTS; j++)
        st->joint[j].inpos = 1;
    for (int s = 0; s < EMCMOT_MAX_SPINDLES; s++) {
        st->spindle[s].scale = 1.0;
        st->spindle[s].brake = 1;
        st->spindle[s].at_speed = 1;
    }
}

/* Motion state from the enable flag and the requested mode. */
static void set_mode(emcmot_status_t *st, int coord, int teleop)
{
    st->coord = coord;
    st->teleop = teleop;
    st->motion_state = !st->enabled ? EMCMOT_MOTION_DISABLED :
        coord ? EMCMOT_MOTION_COORD : teleop ? EMCMOT_MOTION_TELEOP : EMCMOT_MOTION_FREE;
}

static void a_enable(emcmot_status_t *st, const emcmot_command_t *c)
{
    st->enabled = c->command == EMCMOT_ENABLE;
    for (int j = 0; j < EMCMOT_MAX_JOINTS; j++)
        st->joint[j].enabled = st->enabled && j < st->joints;
    set_mode(st, st->coord && st->enabled, st->teleop && st->enabled);
}

static void a_mode(emcmot_status_t *st, const emcmot_command_t *c)
{
    set_mode(st, c->command == EMCMOT_COORD, c->command == EMCMOT_TELEOP);
}

static void a_num(emcmot_status_t *st, const emcmot_command_t *c)
{
    if (c->command == EMCMOT_SET_NUM_JOINTS && c->count > 0 && c->count <= EMCMOT_MAX_JOINTS)
        st->joints = c->count;
    if (c->command == EMCMOT_SET_NUM_SPINDLES && c->count >= 0 && c->count <= EMCMOT_MAX_SPINDLES)
        st->spindles = c->count;
}

/* Non-zero when j names joint m (-1 all; -2 volatile joints are unknown here: all). */
static int names_joint(int j, int m)
{
    return j < 0 || j == m;
}

static void a_home(emcmot_status_t *st, const emcmot_command_t *c)
{
    int homed = c->command == EMCMOT_JOINT_HOME;

    for (int m = 0; m < st->joints; m++) {
        if (!names_joint(c->joint, m) || (!homed && c->joint == EMCMOT_JOINT_VOLATILE))
            continue;
        st->joint[m].homed = homed;
        st->joint[m].home_state = 0;
    }
    st->all_homed = 1;
    for (int m = 0; m < st->joints; m++)
        st->all_homed &= st->joint[m].homed;
}

/* A queued move completes at once: the pose is its end, its id the executing one. */
static void a_move(emcmot_status_t *st, const emcmot_command_t *c)
{
    st->carte_pos_cmd = c->pos;
    st->carte_pos_fb = c->pos;
    st->exec_id = c->id;
    st->exec_tag = c->tag;
    if (c->command == EMCMOT_PROBE)
        st->probed_pos = c->pos;
}

static void a_scale(emcmot_status_t *st, const emcmot_command_t *c)
{
    if (c->command == EMCMOT_FEED_SCALE)
        st->feed_scale = c->scale;
    else
        st->rapid_scale = c->scale;
}

static void a_enables(emcmot_status_t *st, const emcmot_command_t *c)
{
    int32_t *flag = c->command == EMCMOT_FS_ENABLE ? &st->feed_scale_enabled :
        c->command == EMCMOT_FH_ENABLE ? &st->feed_hold_enabled : &st->adaptive_feed_enabled;
    *flag = c->enable != 0;
}

static void a_pause(emcmot_status_t *st, const emcmot_command_t *c)
{
    st->paused = c->command == EMCMOT_PAUSE;
}

static void a_spindle(emcmot_status_t *st, const emcmot_command_t *c)
{
    int first = c->spindle < 0 ? 0 : c->spindle, last = c->spindle < 0 ? st->spindles - 1 : c->spindle;

    for (int s = first; s <= last && s < EMCMOT_MAX_SPINDLES; s++) {
        emcmot_spindle_status_t *sp = &st->spindle[s];
        int on = c->command == EMCMOT_SPINDLE_ON;
        sp->state = on;
        sp->speed = on ? c->speed : 0.0;
        sp->direction = on ? (c->speed < 0.0 ? -1 : 1) : 0;
        sp->brake = !on;
    }
}

static void a_io(emcmot_status_t *st, const emcmot_command_t *c)
{
    if (c->io_index < 0 || c->io_index >= EMCMOT_MAX_DIO)
        return;
    if (c->command == EMCMOT_SET_DOUT)
        st->synch_do[c->io_index] = c->dout_start != 0;
    else
        st->analog_output[c->io_index] = c->aout_start;
}

static void a_poses(emcmot_status_t *st, const emcmot_command_t *c)
{
    if (c->command == EMCMOT_SET_WORLD_HOME)
        st->world_home = c->pos;
    else
        st->tool_offset = c->pos;
}

static void a_joint_limits(emcmot_status_t *st, const emcmot_command_t *c)
{
    if (c->joint < 0 || c->joint >= EMCMOT_MAX_JOINTS)
        return;
    st->joint[c->joint].min_pos_limit = c->min_limit;
    st->joint[c->joint].max_pos_limit = c->max_limit;
}

static void a_axis_limits(emcmot_status_t *st, const emcmot_command_t *c)
{
    if (c->axis < 0 || c->axis >= EMCMOT_MAX_AXIS)
        return;
    st->axis[c->axis].min_pos_limit = c->min_limit;
    st->axis[c->axis].max_pos_limit = c->max_limit;
}

static const ml_apply_t appliers[EMCMOT_LAST_COMMAND + 1] = {
    [EMCMOT_ENABLE] = a_enable, [EMCMOT_DISABLE] = a_enable, [EMCMOT_FREE] = a_mode,
    [EMCMOT_COORD] = a_mode, [EMCMOT_TELEOP] = a_mode, [EMCMOT_SET_NUM_JOINTS] = a_num,
    [EMCMOT_SET_NUM_SPINDLES] = a_num, [EMCMOT_JOINT_HOME] = a_home,
    [EMCMOT_JOINT_UNHOME] = a_home, [EMCMOT_SET_LINE] = a_move, [EMCMOT_SET_CIRCLE] = a_move,
    [EMCMOT_PROBE] = a_move, [EMCMOT_RIGID_TAP] = a_move, [EMCMOT_FEED_SCALE] = a_scale,
    [EMCMOT_RAPID_SCALE] = a_scale, [EMCMOT_FS_ENABLE] = a_enables,
    [EMCMOT_FH_ENABLE] = a_enables, [EMCMOT_AF_ENABLE] = a_enables, [EMCMOT_PAUSE] = a_pause,
    [EMCMOT_RESUME] = a_pause, [EMCMOT_SPINDLE_ON] = a_spindle, [EMCMOT_SPINDLE_OFF] = a_spindle,
    [EMCMOT_SET_DOUT] = a_io, [EMCMOT_SET_AOUT] = a_io, [EMCMOT_SET_WORLD_HOME] = a_poses,
    [EMCMOT_SET_OFFSET] = a_poses, [EMCMOT_SET_JOINT_POSITION_LIMITS] = a_joint_limits,
    [EMCMOT_SET_AXIS_POSITION_LIMITS] = a_axis_limits,
};

/* Apply c to the status (commands without an applier only get echoed). */
void ml_state_apply(emcmot_status_t *st, const emcmot_command_t *c)
{
    if (c->command >= EMCMOT_FIRST_COMMAND && c->command <= EMCMOT_LAST_COMMAND &&
        appliers[c->command])
        appliers[c->command](st, c);
}
