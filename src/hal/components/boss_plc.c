/* boss_plc.c: fixed PLC logic of a Bridgeport BOSS mill: feed hold, limits from one switch per axis,
 * amp faults, spindle brake and direction, jog scale. */
#include <stddef.h>
#include "rtapi.h"
#include "rtapi_app.h"
#include "rtapi_string.h"
#include "rtapi_errno.h"
#include "hal.h"
#include "comp_args.h"

MODULE_LICENSE("GPL");
MODULE_AUTHOR("OpenEMC");
MODULE_DESCRIPTION("PLC logic for a Bridgeport BOSS mill");

#define BOSS_MAX_INSTANCES 4
#define BOSS_NS_PER_MS 1000000L

static long count = 1;
RTAPI_MP_LONG(count, "number of instances (at most 4)");
static int debug;
RTAPI_MP_INT(debug, "non-zero adds the state params");

/* Millisecond timer of the amps and the spindle. */
typedef struct {
    int running;
    long ns, ms, timeout_ms;
} boss_timer_t;

/* Limit state machine of one axis; state numbers as the debug params show them. */
enum { LIM_INIT, LIM_ON_LIMIT, LIM_NO_MOTION, LIM_POS_MOTION, LIM_NEG_MOTION };
typedef struct {
    hal_u32_t state;
    int limit_pos, limit_neg;
    double last_pos;
} boss_limit_t;

/* Spindle states; numbers as the debug param shows them. */
enum { SP_OFF, SP_WAIT_BRAKE_OFF, SP_WAIT_ON, SP_ON, SP_WAIT_OFF, SP_WAIT_BRAKE_ON };

#define BOSS_NAMPS 4
/* Pins of one instance. */
typedef struct {
    hal_bit_t *cycle_start_in, *cycle_hold_in, *feed_hold_out, *tool_change_in, *tool_changed_out,
        *wait_user_out, *mist_on_in, *mist_on_out, *flood_on_in, *flood_on_out, *limit_override_in,
        *limit_active_out;
    hal_float_t *adaptive_feed_in, *adaptive_feed_out, *spindle_speed_in, *spindle_lo_to_hi;
    hal_bit_t *x_jog_en_in, *y_jog_en_in, *z_jog_en_in, *x_limit_in, *y_limit_in, *z_limit_pos_in,
        *z_limit_neg_in, *x_limit_pos_out, *x_limit_neg_out, *y_limit_pos_out, *y_limit_neg_out,
        *z_limit_pos_out, *z_limit_neg_out;
    hal_float_t *x_position_in, *y_position_in;
    hal_u32_t *amp_ready_delay, *brake_on_delay, *brake_off_delay;
    hal_bit_t *amp_enable_in[BOSS_NAMPS], *amp_ready_in[BOSS_NAMPS], *amp_fault_out[BOSS_NAMPS];
    hal_bit_t *spindle_is_on_in, *spindle_fwd_out, *spindle_rev_out, *spindle_inc_in, *spindle_dec_in,
        *spindle_inc_out, *spindle_dec_out, *brake_en_in, *brake_en_out;
    hal_bit_t *jog_sel_in[3];
    hal_float_t *jog_scale[3], *jog_scale_out;
    /* state */
    int last_cycle_start;
    double last_spindle_speed;
    boss_limit_t xlim, ylim;
    boss_timer_t amp_timer[BOSS_NAMPS];
    int last_amp_enable[BOSS_NAMPS];
    boss_timer_t spindle_timer;
    hal_u32_t spindle_state;
} boss_t;

#define P(sfx, t, d, f, v) { sfx, t, d, offsetof(boss_t, f), v }
static const comp_pin_def_t boss_pins[] = {
    P("cycle-start-in", HAL_BIT, HAL_IN, cycle_start_in, 0),
    P("cycle-hold-in", HAL_BIT, HAL_IN, cycle_hold_in, 0),
    P("feed-hold-out", HAL_BIT, HAL_OUT, feed_hold_out, 0),
    P("adaptive-feed-in", HAL_FLOAT, HAL_IN, adaptive_feed_in, 1.0),
    P("adaptive-feed-out", HAL_FLOAT, HAL_OUT, adaptive_feed_out, 0),
    P("tool-change-in", HAL_BIT, HAL_IN, tool_change_in, 0),
    P("tool-changed-out", HAL_BIT, HAL_OUT, tool_changed_out, 0),
    P("wait-user-out", HAL_BIT, HAL_OUT, wait_user_out, 0),
    P("mist-on-in", HAL_BIT, HAL_IN, mist_on_in, 0),
    P("mist-on-out", HAL_BIT, HAL_OUT, mist_on_out, 0),
    P("flood-on-in", HAL_BIT, HAL_IN, flood_on_in, 0),
    P("flood-on-out", HAL_BIT, HAL_OUT, flood_on_out, 0),
    P("limit-override-in", HAL_BIT, HAL_IN, limit_override_in, 0),
    P("limit-active-out", HAL_BIT, HAL_OUT, limit_active_out, 0),
    P("x-jog-en-in", HAL_BIT, HAL_IN, x_jog_en_in, 0),
    P("y-jog-en-in", HAL_BIT, HAL_IN, y_jog_en_in, 0),
    P("z-jog-en-in", HAL_BIT, HAL_IN, z_jog_en_in, 0),
    P("x-limit-in", HAL_BIT, HAL_IN, x_limit_in, 0),
    P("y-limit-in", HAL_BIT, HAL_IN, y_limit_in, 0),
    P("z-limit-pos-in", HAL_BIT, HAL_IN, z_limit_pos_in, 0),
    P("z-limit-neg-in", HAL_BIT, HAL_IN, z_limit_neg_in, 0),
    P("x-position-in", HAL_FLOAT, HAL_IN, x_position_in, 0),
    P("y-position-in", HAL_FLOAT, HAL_IN, y_position_in, 0),
    P("x-limit-pos-out", HAL_BIT, HAL_OUT, x_limit_pos_out, 0),
    P("x-limit-neg-out", HAL_BIT, HAL_OUT, x_limit_neg_out, 0),
    P("y-limit-pos-out", HAL_BIT, HAL_OUT, y_limit_pos_out, 0),
    P("y-limit-neg-out", HAL_BIT, HAL_OUT, y_limit_neg_out, 0),
    P("z-limit-pos-out", HAL_BIT, HAL_OUT, z_limit_pos_out, 0),
    P("z-limit-neg-out", HAL_BIT, HAL_OUT, z_limit_neg_out, 0),
    P("amp-ready-delay", HAL_U32, HAL_IO, amp_ready_delay, 50),
    P("x-amp-enable-in", HAL_BIT, HAL_IN, amp_enable_in[0], 0),
    P("x-amp-ready-in", HAL_BIT, HAL_IN, amp_ready_in[0], 0),
    P("x-amp-fault-out", HAL_BIT, HAL_OUT, amp_fault_out[0], 0),
    P("y-amp-enable-in", HAL_BIT, HAL_IN, amp_enable_in[1], 0),
    P("y-amp-ready-in", HAL_BIT, HAL_IN, amp_ready_in[1], 0),
    P("y-amp-fault-out", HAL_BIT, HAL_OUT, amp_fault_out[1], 0),
    P("z-amp-enable-in", HAL_BIT, HAL_IN, amp_enable_in[2], 0),
    P("z-amp-ready-in", HAL_BIT, HAL_IN, amp_ready_in[2], 0),
    P("z-amp-fault-out", HAL_BIT, HAL_OUT, amp_fault_out[2], 0),
    P("a-amp-enable-in", HAL_BIT, HAL_IN, amp_enable_in[3], 0),
    P("a-amp-ready-in", HAL_BIT, HAL_IN, amp_ready_in[3], 0),
    P("a-amp-fault-out", HAL_BIT, HAL_OUT, amp_fault_out[3], 0),
    P("spindle-speed-in", HAL_FLOAT, HAL_IN, spindle_speed_in, 0),
    P("spindle-lo-to-hi", HAL_FLOAT, HAL_IO, spindle_lo_to_hi, 500),
    P("spindle-is-on-in", HAL_BIT, HAL_IN, spindle_is_on_in, 0),
    P("spindle-fwd-out", HAL_BIT, HAL_OUT, spindle_fwd_out, 0),
    P("spindle-rev-out", HAL_BIT, HAL_OUT, spindle_rev_out, 0),
    P("spindle-inc-in", HAL_BIT, HAL_IN, spindle_inc_in, 0),
    P("spindle-dec-in", HAL_BIT, HAL_IN, spindle_dec_in, 0),
    P("spindle-inc-out", HAL_BIT, HAL_OUT, spindle_inc_out, 0),
    P("spindle-dec-out", HAL_BIT, HAL_OUT, spindle_dec_out, 0),
    P("brake-en-in", HAL_BIT, HAL_IN, brake_en_in, 0),
    P("brake-en-out", HAL_BIT, HAL_OUT, brake_en_out, 0),
    P("brake-on-delay", HAL_U32, HAL_IO, brake_on_delay, 300),
    P("brake-off-delay", HAL_U32, HAL_IO, brake_off_delay, 500),
    P("jog-sel-in-0", HAL_BIT, HAL_IN, jog_sel_in[0], 0),
    P("jog-sel-in-1", HAL_BIT, HAL_IN, jog_sel_in[1], 0),
    P("jog-sel-in-2", HAL_BIT, HAL_IN, jog_sel_in[2], 0),
    P("jog-scale-0", HAL_FLOAT, HAL_IO, jog_scale[0], 0.0001),
    P("jog-scale-1", HAL_FLOAT, HAL_IO, jog_scale[1], 0.001),
    P("jog-scale-2", HAL_FLOAT, HAL_IO, jog_scale[2], 0.01),
    P("jog-scale-out", HAL_FLOAT, HAL_OUT, jog_scale_out, 0),
};
#define BOSS_NPINS ((int)(sizeof(boss_pins) / sizeof(boss_pins[0])))

/* Start a timer: the ms count restarts, the ns remainder is kept. */
static void timer_start(boss_timer_t *t, long timeout_ms)
{
    t->running = 1;
    t->ms = 0;
    t->timeout_ms = timeout_ms;
}

/* Advance a running timer by one period; it stops once the ms count reaches its timeout. */
static void timer_advance(boss_timer_t *t, long period)
{
    if (!t->running)
        return;
    t->ns += period;
    if (t->ns > BOSS_NS_PER_MS) {
        t->ms += t->ns / BOSS_NS_PER_MS;
        t->ns %= BOSS_NS_PER_MS;
    }
    if (t->ms >= t->timeout_ms)
        t->running = 0;
}

/* Feed hold, adaptive feed, tool change handshake, coolant. */
static void boss_feed(boss_t *b)
{
    int rise = *b->cycle_start_in && !b->last_cycle_start;
    double s = *b->spindle_speed_in;
    b->last_cycle_start = *b->cycle_start_in;
    *b->feed_hold_out = *b->cycle_hold_in || (s != 0 && !*b->spindle_is_on_in) ||
                        (*b->spindle_is_on_in && s != b->last_spindle_speed) ||
                        (*b->feed_hold_out && !rise);
    b->last_spindle_speed = s;
    *b->adaptive_feed_out = (*b->limit_override_in && *b->adaptive_feed_in > 0.01) ? 0.01
                                                                                  : *b->adaptive_feed_in;
    *b->tool_changed_out = (*b->tool_change_in && rise) || (*b->tool_changed_out && *b->tool_change_in);
    *b->wait_user_out = *b->feed_hold_out || (*b->tool_change_in && !*b->tool_changed_out);
    *b->mist_on_out = *b->mist_on_in && !*b->tool_change_in;
    *b->flood_on_out = *b->flood_on_in && !*b->tool_change_in;
}

/* Direction-of-travel state for one axis with a single shared limit switch. */
static void limit_state(boss_limit_t *l, int sw, double pos)
{
    if (l->state == LIM_INIT) {
        l->limit_pos = l->limit_neg = 1;
        l->last_pos = pos;
        l->state = LIM_ON_LIMIT;
    }
    if (l->state == LIM_ON_LIMIT) {
        if (!sw) {
            l->limit_pos = l->limit_neg = 0;
            l->state = pos == l->last_pos ? LIM_NO_MOTION : pos > l->last_pos ? LIM_POS_MOTION : LIM_NEG_MOTION;
        }
    } else if (sw) {
        l->limit_pos = l->state != LIM_NEG_MOTION;
        l->limit_neg = l->state != LIM_POS_MOTION;
        l->state = LIM_ON_LIMIT;
    } else if (pos != l->last_pos) {
        l->state = pos > l->last_pos ? LIM_POS_MOTION : LIM_NEG_MOTION;
    } else if (l->state != LIM_NO_MOTION) {
        l->state = LIM_NO_MOTION;
    }
    l->last_pos = pos;
}

/* Limit outputs of X, Y (derived from travel) and Z (own switches), each overridable while jogging. */
static void boss_limits(boss_t *b)
{
    int ovr = *b->limit_override_in;
    limit_state(&b->xlim, *b->x_limit_in, *b->x_position_in);
    limit_state(&b->ylim, *b->y_limit_in, *b->y_position_in);
    *b->x_limit_pos_out = b->xlim.limit_pos && !(*b->x_jog_en_in && ovr);
    *b->x_limit_neg_out = b->xlim.limit_neg && !(*b->x_jog_en_in && ovr);
    *b->y_limit_pos_out = b->ylim.limit_pos && !(*b->y_jog_en_in && ovr);
    *b->y_limit_neg_out = b->ylim.limit_neg && !(*b->y_jog_en_in && ovr);
    *b->z_limit_pos_out = *b->z_limit_pos_in && !(*b->z_jog_en_in && ovr);
    *b->z_limit_neg_out = *b->z_limit_neg_in && !(*b->z_jog_en_in && ovr);
    *b->limit_active_out = *b->x_limit_in || *b->y_limit_in || *b->z_limit_pos_in || *b->z_limit_neg_in;
}

/* Amp faults: not ready once amp-ready-delay ms have passed since enable rose. */
static void boss_amps(boss_t *b, long period)
{
    for (int i = 0; i < BOSS_NAMPS; i++) {
        boss_timer_t *t = &b->amp_timer[i];
        int en = *b->amp_enable_in[i];
        timer_advance(t, period);
        if (en && !b->last_amp_enable[i])
            timer_start(t, *b->amp_ready_delay);
        else if (!en)
            t->running = 0;
        b->last_amp_enable[i] = en;
        *b->amp_fault_out[i] = en && !*b->amp_ready_in[i] && !t->running;
    }
}

/* Both spindle direction outputs FALSE. */
static void spindle_stop(boss_t *b)
{
    *b->spindle_fwd_out = 0;
    *b->spindle_rev_out = 0;
}

/* WAIT_BRAKE_OFF: brake back on, or start in the direction the gear range needs once released. */
static void spindle_wait_brake_off(boss_t *b, double s, double l)
{
    if (*b->brake_en_in) {
        b->spindle_state = SP_OFF;
        *b->brake_en_out = 1;
        b->spindle_timer.running = 0;
    } else if (s != 0 && !b->spindle_timer.running) {
        b->spindle_state = SP_WAIT_ON;
        if (s > l || (s >= -l && s < 0))
            *b->spindle_fwd_out = 1;
        else
            *b->spindle_rev_out = 1;
    }
}

/* Spindle brake and direction sequence. */
static void boss_spindle(boss_t *b, long period)
{
    double s = *b->spindle_speed_in, l = *b->spindle_lo_to_hi;
    timer_advance(&b->spindle_timer, period);
    switch (b->spindle_state) {
    case SP_OFF:
        if (!*b->brake_en_in) {
            b->spindle_state = SP_WAIT_BRAKE_OFF;
            *b->brake_en_out = 0;
            timer_start(&b->spindle_timer, *b->brake_off_delay);
        }
        break;
    case SP_WAIT_BRAKE_OFF:
        spindle_wait_brake_off(b, s, l);
        break;
    case SP_WAIT_ON:
        if (*b->spindle_is_on_in) {
            b->spindle_state = SP_ON;
        } else if (s == 0) {
            b->spindle_state = SP_WAIT_BRAKE_OFF;
            spindle_stop(b);
        }
        break;
    case SP_ON:
        if (s == 0) {
            b->spindle_state = SP_WAIT_OFF;
            spindle_stop(b);
        }
        break;
    case SP_WAIT_OFF:
        if (!*b->spindle_is_on_in) {
            b->spindle_state = SP_WAIT_BRAKE_ON;
            timer_start(&b->spindle_timer, *b->brake_on_delay);
        }
        break;
    case SP_WAIT_BRAKE_ON:
        if (!b->spindle_timer.running)
            b->spindle_state = SP_WAIT_BRAKE_OFF;
        break;
    default:
        b->spindle_state = SP_WAIT_OFF;
        spindle_stop(b);
        break;
    }
    *b->spindle_inc_out = *b->spindle_inc_in && !*b->spindle_dec_in && *b->spindle_is_on_in;
    *b->spindle_dec_out = *b->spindle_dec_in && !*b->spindle_inc_in && *b->spindle_is_on_in;
}

/* The first selected jog scale, if any, becomes the output. */
static void boss_jog(boss_t *b)
{
    for (int i = 0; i < 3; i++) {
        if (*b->jog_sel_in[i]) {
            *b->jog_scale_out = *b->jog_scale[i];
            return;
        }
    }
}

/* Funct boss_plc.N.refresh. */
static void boss_refresh(void *arg, long period)
{
    boss_t *b = arg;
    boss_feed(b);
    boss_limits(b);
    boss_amps(b, period);
    boss_spindle(b, period);
    boss_jog(b);
}

/* Create the pins, debug params and funct of instance n. */
static int boss_make(int comp_id, int n)
{
    char name[HAL_NAME_LEN + 1];
    boss_t *b = hal_malloc(sizeof(*b));
    int r;
    if (!b) return -ENOMEM;
    memset(b, 0, sizeof(*b));
    b->last_cycle_start = 1;
    rtapi_snprintf(name, sizeof(name), "boss_plc.%d.", n);
    r = comp_pin_table(comp_id, b, boss_pins, BOSS_NPINS, name);
    if (r == 0 && debug > 0) {
        r = hal_param_u32_newf(HAL_RO, &b->xlim.state, comp_id, "boss_plc.%d.x-limit-state", n);
        if (r == 0) r = hal_param_u32_newf(HAL_RO, &b->ylim.state, comp_id, "boss_plc.%d.y-limit-state", n);
        if (r == 0) r = hal_param_u32_newf(HAL_RO, &b->spindle_state, comp_id, "boss_plc.%d.spindle-state", n);
    }
    if (r) return r;
    rtapi_snprintf(name, sizeof(name), "boss_plc.%d.refresh", n);
    return hal_export_funct(name, boss_refresh, b, 1, 0, comp_id);
}

/* Create count instances (values above 4 become 4). */
int rtapi_app_main(void)
{
    if (count < 1) {
        rtapi_print_msg(RTAPI_MSG_ERR, "BOSS_PLC: ERROR: invalid count: %ld\n", count);
        return -EINVAL;
    }
    if (count > BOSS_MAX_INSTANCES)
        count = BOSS_MAX_INSTANCES;
    return comp_setup("boss_plc", (int)count, boss_make);
}

/* Remove the component. */
void rtapi_app_exit(void)
{
    comp_teardown();
}
