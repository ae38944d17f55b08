/* homecomp_api.h: the homing API exported by the homecomp template (skeleton: joints are homed by
 * motion.allow-sim-homed or their home switch; nothing moves). Included by homecomp.comp. */
#include <stdbool.h>

static char *home_parms;
RTAPI_MP_STRING(home_parms, "parameters for a custom homing module");

/* Homing pins of one joint (owned by motion's component). */
typedef struct {
    hal_bit_t *home_sw_in, *homing, *homed, *index_enable;
    hal_s32_t *home_state;
} homecomp_joint_t;

/* Pins of the module as a whole (their pointers live in HAL memory, as HAL requires). */
typedef struct {
    hal_bit_t *allow_sim_homed;
} homecomp_global_t;

/* State of the skeleton homing module. */
typedef struct {
    homecomp_global_t *global;
    int njoints;
    int all_homed;
    homecomp_joint_t *joint;
} homecomp_t;

static homecomp_t homecomp;

/* Report the parameters at load, as the template does. */
EXTRA_SETUP()
{
    (void)__comp_inst;
    (void)prefix;
    (void)extra_arg;
    rtapi_print("homecomp: %s: home_parms=%s\n", __func__, home_parms ? home_parms : "no_home_parms");
    return 0;
}

/* The rotary-unlock callbacks of motion; the skeleton never unlocks anything. */
void homeMotFunctions(void (*set_rotary_unlock)(int, int), int (*get_rotary_unlock)(int))
{
    (void)set_rotary_unlock;
    (void)get_rotary_unlock;
}
EXPORT_SYMBOL(homeMotFunctions);

/* Pins of joint n. */
static int homecomp_joint_pins(int id, int n)
{
    homecomp_joint_t *j = &homecomp.joint[n];
    int r = hal_pin_bit_newf(HAL_IN, &j->home_sw_in, id, "joint.%d.home-sw-in", n);
    if (r == 0) r = hal_pin_bit_newf(HAL_OUT, &j->homing, id, "joint.%d.homing", n);
    if (r == 0) r = hal_pin_bit_newf(HAL_OUT, &j->homed, id, "joint.%d.homed", n);
    if (r == 0) r = hal_pin_s32_newf(HAL_OUT, &j->home_state, id, "joint.%d.home-state", n);
    if (r == 0) r = hal_pin_bit_newf(HAL_IO, &j->index_enable, id, "joint.%d.index-enable", n);
    return r;
}

/* Create the homing pins in motion's component id; 0 on success. */
int homing_init(int id, double servo_period, int n_joints, int n_extrajoints, void *joints)
{
    (void)servo_period;
    (void)n_extrajoints;
    (void)joints;
    if (n_joints < 0)
        return -EINVAL;
    homecomp.joint = hal_malloc(sizeof(homecomp_joint_t) * (n_joints ? n_joints : 1));
    if (!homecomp.joint)
        return -ENOMEM;
    homecomp.global = hal_malloc(sizeof(homecomp_global_t));
    if (!homecomp.global)
        return -ENOMEM;
    homecomp.njoints = n_joints;
    int r = hal_pin_bit_newf(HAL_IO, &homecomp.global->allow_sim_homed, id, "motion.allow-sim-homed");
    if (r)
        return r;
    *homecomp.global->allow_sim_homed = 1;
    for (int n = 0; n < n_joints && r == 0; n++)
        r = homecomp_joint_pins(id, n);
    return r;
}
EXPORT_SYMBOL(homing_init);

/* Joint jno is homed: by allow-sim-homed, else by its home switch (out of range: not homed). */
bool get_homed(int jno)
{
    if (jno < 0 || jno >= homecomp.njoints)
        return false;
    return *homecomp.global->allow_sim_homed || *homecomp.joint[jno].home_sw_in;
}
EXPORT_SYMBOL(get_homed);

/* Every joint is homed. */
bool get_allhomed(void)
{
    for (int n = 0; n < homecomp.njoints; n++)
        if (!get_homed(n))
            return false;
    return true;
}
EXPORT_SYMBOL(get_allhomed);

/* Start of a servo period: nothing to read beyond what get_homed looks at. */
void read_homing_in_pins(int njoints)
{
    (void)njoints;
}
EXPORT_SYMBOL(read_homing_in_pins);

/* TRUE once on each change from not all homed to all homed (motion then goes to teleop). */
bool do_homing(void)
{
    int now = get_allhomed();
    bool rose = now && !homecomp.all_homed;
    homecomp.all_homed = now;
    return rose;
}
EXPORT_SYMBOL(do_homing);

/* End of a servo period: homing FALSE, homed per the rule, state 0. */
void write_homing_out_pins(int njoints)
{
    for (int n = 0; n < njoints && n < homecomp.njoints; n++) {
        *homecomp.joint[n].homing = 0;
        *homecomp.joint[n].homed = get_homed(n);
        *homecomp.joint[n].home_state = 0;
    }
}
EXPORT_SYMBOL(write_homing_out_pins);

/* Requests the skeleton ignores: homing, cancelling, unhoming and parameter updates. */
void do_home_joint(int jno) { (void)jno; }
EXPORT_SYMBOL(do_home_joint);
void do_cancel_homing(int jno) { (void)jno; }
EXPORT_SYMBOL(do_cancel_homing);
void set_unhomed(int jno, int motion_state) { (void)jno; (void)motion_state; }
EXPORT_SYMBOL(set_unhomed);

/* Homing parameters of a joint (unused by the skeleton). */
void set_joint_homing_params(int jno, double offset, double home, double home_final_vel, double home_search_vel,
                             double home_latch_vel, int home_flags, int home_sequence, bool volatile_home)
{
    (void)jno; (void)offset; (void)home; (void)home_final_vel; (void)home_search_vel;
    (void)home_latch_vel; (void)home_flags; (void)home_sequence; (void)volatile_home;
}
EXPORT_SYMBOL(set_joint_homing_params);

/* Updated homing parameters of a joint (unused by the skeleton). */
void update_joint_homing_params(int jno, double offset, double home, int home_sequence)
{
    (void)jno; (void)offset; (void)home; (void)home_sequence;
}
EXPORT_SYMBOL(update_joint_homing_params);

/* Queries: idle, never synchronized, no unlock, sequence 0, not homing, no index search. */
bool get_home_is_idle(int jno) { (void)jno; return true; }
EXPORT_SYMBOL(get_home_is_idle);
bool get_home_is_synchronized(int jno) { (void)jno; return false; }
EXPORT_SYMBOL(get_home_is_synchronized);
bool get_home_needs_unlock_first(int jno) { (void)jno; return false; }
EXPORT_SYMBOL(get_home_needs_unlock_first);
int get_home_sequence(int jno) { (void)jno; return 0; }
EXPORT_SYMBOL(get_home_sequence);
bool get_homing(int jno) { (void)jno; return false; }
EXPORT_SYMBOL(get_homing);
bool get_homing_at_index_search_wait(int jno) { (void)jno; return false; }
EXPORT_SYMBOL(get_homing_at_index_search_wait);
bool get_homing_is_active(void) { return false; }
EXPORT_SYMBOL(get_homing_is_active);
bool get_index_enable(int jno) { (void)jno; return false; }
EXPORT_SYMBOL(get_index_enable);
