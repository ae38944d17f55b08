/* homemod.c: the homing module: exports home_ops (versioned), owns the joint homing pins. */
#include <string.h>
#include "rtapi.h"
#include "rtapi_app.h"
#include "rtapi_math.h"
#include "home_priv.h"

MODULE_LICENSE("GPL");
MODULE_AUTHOR("OpenEMC");
MODULE_DESCRIPTION("Homing module for motmod: switch, latch, index, absolute encoders, sequences");

static char *home_parms = "";
RTAPI_MP_STRING(home_parms, "parameters for custom homing modules (ignored by homemod)");

home_t home;
static int comp_id;

/* Pins of joint j under motmod's component. */
static int make_pins(int j)
{
    home_pins_t *p = &home.pins[j];
    int id = home.env.comp_id;
    int rc = hal_pin_bit_newf(HAL_IN, &p->home_sw_in, id, "joint.%d.home-sw-in", j);

    if (rc == 0)
        rc = hal_pin_bit_newf(HAL_OUT, &p->homing, id, "joint.%d.homing", j);
    if (rc == 0)
        rc = hal_pin_bit_newf(HAL_OUT, &p->homed, id, "joint.%d.homed", j);
    if (rc == 0)
        rc = hal_pin_s32_newf(HAL_OUT, &p->home_state, id, "joint.%d.home-state", j);
    if (rc == 0)
        rc = hal_pin_bit_newf(HAL_IO, &p->index_enable, id, "joint.%d.index-enable", j);
    return rc;
}

/* Keep motion's environment, make the pins, start every joint idle and unhomed. */
static int h_init(const home_env_t *env)
{
    if (env->num_joints < 1 || env->num_joints > HOME_MAX_JOINTS || !env->joints ||
        !env->report || !env->set_position || !env->set_motor_zero)
        return -EINVAL;
    memset(&home, 0, sizeof home);
    home.env = *env;
    home.num_joints = env->num_joints;
    home.pins = hal_malloc(env->num_joints * sizeof(home_pins_t));
    if (!home.pins)
        return -ENOMEM;
    for (int j = 0; j < env->num_joints; j++) {
        int rc = make_pins(j);
        if (rc < 0)
            return rc;
        home.joint[j].params.home_final_vel = -1.0;
        home.joint[j].params.home_sequence = 999;
    }
    return 0;
}

/* Read the home switches and index-enable. */
static void h_read_inputs(void)
{
    for (int j = 0; j < home.env.num_joints; j++) {
        home.joint[j].home_sw = *home.pins[j].home_sw_in != 0;
        home.joint[j].index_enable = *home.pins[j].index_enable != 0;
    }
}

/* Run the state machines; 1 when a run finished with every joint in use homed. */
static int h_do_homing(void)
{
    home_seq_cycle();
    if (!home.run_completed)
        return 0;
    for (int j = 0; j < home.num_joints; j++)
        if (home_joint_in_use(j) && !home.joint[j].homed)
            return 0;
    return 1;
}

/* Write homing, homed and home-state. */
static void h_write_outputs(void)
{
    for (int j = 0; j < home.env.num_joints; j++) {
        *home.pins[j].homing = home.joint[j].homing;
        *home.pins[j].homed = home.joint[j].homed;
        *home.pins[j].home_state = home.joint[j].state;
    }
}

/* Home one joint or (-1) all. */
static int h_home_joint(int j)
{
    if (j == -1)
        return home_seq_start_all();
    if (j < 0 || j >= home.num_joints)
        return -1;
    return home_seq_start_joint(j);
}

/* Abort: every homing joint stops at once. */
static void h_cancel(void)
{
    home_seq_abort();
}

/* Refuse to unhome a joint that homes or moves; 0 when joint j may be unhomed. */
static int unhome_refused(int j, int motion_enabled)
{
    if (home.joint[j].homing) {
        home.env.report("Cannot unhome while homing, joint %d", j);
        return 1;
    }
    if (motion_enabled && home.env.joints[j].free_tp_active) {
        home.env.report("Cannot unhome while moving, joint %d", j);
        return 1;
    }
    return 0;
}

/* Unhome joint j, -1 all, -2 the VOLATILE_HOME joints. */
static int h_set_unhomed(int j, int motion_enabled)
{
    int first = j < 0 ? 0 : j, last = j < 0 ? home.num_joints - 1 : j;

    if (j >= home.num_joints || j < -2)
        return -1;
    for (int m = first; m <= last; m++) {
        if (j == -2 && !home.joint[m].params.volatile_home)
            continue;
        if (unhome_refused(m, motion_enabled))
            return -1;
    }
    for (int m = first; m <= last; m++)
        if (j != -2 || home.joint[m].params.volatile_home)
            home.joint[m].homed = 0;
    return 0;
}

/* SET_JOINT_HOMING_PARAMS (not while that joint homes). */
static int h_set_params(int j, const home_params_t *p)
{
    if (j < 0 || j >= home.env.num_joints || home.joint[j].homing)
        return -1;
    home.joint[j].params = *p;
    return 0;
}

/* UPDATE_JOINT_HOMING_PARAMS (not while that joint homes). */
static int h_update_params(int j, double home_offset, double home_pos, int sequence)
{
    if (j < 0 || j >= home.env.num_joints || home.joint[j].homing)
        return -1;
    home.joint[j].params.home_offset = home_offset;
    home.joint[j].params.home = home_pos;
    home.joint[j].params.home_sequence = sequence;
    return 0;
}

/* SET_NUM_JOINTS. */
static void h_set_num_joints(int n)
{
    if (n >= 1 && n <= home.env.num_joints)
        home.num_joints = n;
}

/* Queries. */
static int valid(int j) { return j >= 0 && j < home.env.num_joints; }
static int h_homing_active(void) { return home.run_active; }
static int h_joint_homing(int j) { return valid(j) && home.joint[j].homing; }
static int h_joint_homed(int j) { return valid(j) && home.joint[j].homed; }
static int h_joint_home_state(int j) { return valid(j) ? home.joint[j].state : 0; }
static int h_joint_home_sequence(int j) { return valid(j) ? home.joint[j].params.home_sequence : 999; }
static int h_joint_sync_final_move(int j) { return valid(j) && home.joint[j].params.home_sequence < 0; }
static int h_joint_volatile(int j) { return valid(j) && home.joint[j].params.volatile_home; }
static double h_joint_home_offset(int j) { return valid(j) ? home.joint[j].params.home_offset : 0.0; }
static double h_joint_home(int j) { return valid(j) ? home.joint[j].params.home : 0.0; }

/* Absolute-encoder joints. */
static int h_joint_absolute_encoder(int j)
{
    return valid(j) && (home.joint[j].params.home_flags & EMCMOT_HOME_ABSOLUTE_ENCODER);
}

/* Homed and resting at HOME. */
static int h_joint_at_home(int j)
{
    return h_joint_homed(j) && !home.env.joints[j].free_tp_active &&
        fabs(home.env.joints[j].pos_cmd - home.joint[j].params.home) < 1e-9;
}

const home_ops_t home_ops = {
    HOME_OPS_VERSION, sizeof(home_ops_t), "homemod",
    h_init, h_read_inputs, h_do_homing, h_write_outputs,
    h_home_joint, h_cancel, h_set_unhomed, h_set_params, h_update_params, h_set_num_joints,
    h_homing_active, h_joint_homing, h_joint_homed, h_joint_at_home, h_joint_home_state,
    h_joint_home_sequence, h_joint_sync_final_move, h_joint_volatile, h_joint_absolute_encoder,
    h_joint_home_offset, h_joint_home,
};
EXPORT_SYMBOL(home_ops);

/* A pinless component, like LinuxCNC's homemod. */
int rtapi_app_main(void)
{
    comp_id = hal_init("homemod");
    if (comp_id < 0)
        return comp_id;
    hal_ready(comp_id);
    return 0;
}

/* Remove the component. */
void rtapi_app_exit(void)
{
    hal_exit(comp_id);
}
