/* home_joint.c: one joint's homing state machine as a table of state handlers (motion.md sec. 8). */
#include <stdarg.h>
#include "rtapi.h"
#include "rtapi_math.h"
#include "home_priv.h"

typedef void (*state_fn_t)(int j);

/* Shorthands. */
static home_jstate_t *J(int j) { return &home.joint[j]; }
static home_joint_t *IO(int j) { return &home.env.joints[j]; }
static int flag(int j, int f) { return (J(j)->params.home_flags & f) != 0; }
static double sign_of(double v) { return v < 0.0 ? -1.0 : 1.0; }

/* Abort every homing joint (one failure stops the whole run), reporting why. */
static void fail(const char *fmt, ...) __attribute__((format(printf, 1, 2)));
static void fail(const char *fmt, ...)
{
    char text[256];
    va_list ap;

    va_start(ap, fmt);
    rtapi_vsnprintf(text, sizeof text, fmt, ap);
    va_end(ap);
    home.env.report("%s", text);
    home_seq_abort();
}

/* Next state (from the next cycle on). */
static void go(int j, int state)
{
    J(j)->state = state;
    J(j)->pause_started = 0;
}

/* Next state, run in this same cycle (states that only compute never show on home-state). */
static void go_now(int j, int state)
{
    go(j, state);
    J(j)->chain = 1;
}

/* Non-zero while the 0.1 s pause before a move (and the group barrier) holds. */
static int waiting(int j)
{
    home_jstate_t *s = J(j);

    if (!home_seq_group_ready(j, s->state))
        return 1;
    if (!s->pause_started) {
        s->pause_started = 1;
        s->pause_cycles = (int)(HOME_PAUSE_S / home.env.servo_period + 0.5);
    }
    return s->pause_cycles-- > 0;
}

/* Usable travel of joint j for search/latch moves; 0 when the limits are unset. */
static double travel(int j)
{
    double t = IO(j)->max_limit - IO(j)->min_limit;

    return (isfinite(t) && t > 0.0 && t < HOME_TRAVEL_MAX) ? t * HOME_TRAVEL_MARGIN : 0.0;
}

/* Start a move of at most the usable travel at vel (signed). */
static void move_by_travel(int j, double vel)
{
    home_joint_t *io = IO(j);
    double speed = fmin(fabs(vel), io->vel_limit);

    io->free_pos_cmd = io->pos_cmd + sign_of(vel) * travel(j);
    io->free_vel_lim = speed;
    io->free_tp_enable = 1;
}

/* Stop the joint's planner (it decelerates). */
static void stop(int j)
{
    IO(j)->free_tp_enable = 0;
}

/* Non-zero when the joint's planner has come to rest. */
static int stopped(int j)
{
    return !IO(j)->free_tp_active;
}

/* Limit switches abort homing unless HOME_IGNORE_LIMITS. */
static int limit_hit(int j)
{
    if (flag(j, EMCMOT_HOME_IGNORE_LIMITS))
        return 0;
    if (!IO(j)->pos_limit_sw && !IO(j)->neg_limit_sw)
        return 0;
    if (J(j)->state == HOME_FINAL_MOVE_WAIT)
        fail("hit limit in home state j=%d", j);
    else
        fail("j%d hit limit in home state %d", j, J(j)->state);
    return 1;
}

/* A move ended without the event it waited for. */
static int end_of_move(int j)
{
    if (!stopped(j) || IO(j)->free_tp_enable == 0)
        return 0;
    fail("j%d end of move in home state %d", j, J(j)->state);
    return 1;
}

/* Where to go after the switch (or index) part, by configuration. */
static void after_start_checks(int j)
{
    const home_params_t *p = &J(j)->params;

    if (p->home_search_vel == 0.0) {
        if (p->home_latch_vel == 0.0) {
            home.env.set_position(j, p->home_offset);
            go(j, HOME_FINAL_MOVE_START);
        } else {
            go(j, HOME_INDEX_ONLY_START);
        }
    } else if (travel(j) == 0.0) {
        fail("j%d: homing search needs [JOINT_%d]MIN_LIMIT and MAX_LIMIT", j, j);
    } else {
        go(j, J(j)->home_sw ? HOME_INITIAL_BACKOFF_START : HOME_INITIAL_SEARCH_START);
    }
}

/* START: check the configuration, absolute encoders, shared switches, locking. */
static void st_start(int j)
{
    const home_params_t *p = &J(j)->params;

    if (p->home_search_vel == 0.0 && p->home_latch_vel != 0.0 && !flag(j, EMCMOT_HOME_USE_INDEX)) {
        fail("invalid homing config: non-zero LATCH_VEL needs either SEARCH_VEL or USE_INDEX");
        return;
    }
    if (p->home_search_vel != 0.0 && p->home_latch_vel == 0.0) {
        fail("invalid homing config: non-zero SEARCH_VEL needs LATCH_VEL");
        return;
    }
    if (flag(j, EMCMOT_HOME_ABSOLUTE_ENCODER)) {
        home.env.set_position(j, IO(j)->pos_fb + p->home_offset);
        go_now(j, flag(j, EMCMOT_HOME_NO_FINAL_MOVE) ? HOME_LOCK : HOME_FINAL_MOVE_START);
        return;
    }
    if (flag(j, EMCMOT_HOME_IS_SHARED) && J(j)->home_sw) {
        fail("Cannot home while shared home switch is closed j=%d", j);
        return;
    }
    if (flag(j, EMCMOT_HOME_UNLOCK_FIRST)) {
        go(j, HOME_UNLOCK);
        return;
    }
    after_start_checks(j);
}

/* UNLOCK / UNLOCK_WAIT: release a locking indexer first. */
static void st_unlock(int j)
{
    IO(j)->unlock = 1;
    go(j, HOME_UNLOCK_WAIT);
}

static void st_unlock_wait(int j)
{
    if (IO(j)->is_unlocked)
        after_start_checks(j);
}

/* INITIAL_BACKOFF: the switch is already active: move off it at -SEARCH_VEL. */
static void st_initial_backoff_start(int j)
{
    if (waiting(j))
        return;
    move_by_travel(j, -J(j)->params.home_search_vel);
    go(j, HOME_INITIAL_BACKOFF_WAIT);
}

static void st_initial_backoff_wait(int j)
{
    if (!J(j)->home_sw) {
        stop(j);
        if (stopped(j))
            go(j, HOME_INITIAL_SEARCH_START);
        return;
    }
    if (!limit_hit(j))
        end_of_move(j);
}

/* INITIAL_SEARCH: move toward the switch at SEARCH_VEL. */
static void st_initial_search_start(int j)
{
    if (waiting(j))
        return;
    move_by_travel(j, J(j)->params.home_search_vel);
    go(j, HOME_INITIAL_SEARCH_WAIT);
}

static void st_initial_search_wait(int j)
{
    if (J(j)->home_sw) {
        stop(j);
        go_now(j, HOME_SET_COARSE_POSITION);
        return;
    }
    if (!limit_hit(j))
        end_of_move(j);
}

/* SET_COARSE_POSITION: position := HOME_OFFSET at the switch, then latch by direction. */
static void st_set_coarse_position(int j)
{
    const home_params_t *p = &J(j)->params;

    home.env.set_position(j, p->home_offset);
    if (sign_of(p->home_latch_vel) == sign_of(p->home_search_vel))
        go(j, HOME_FINAL_BACKOFF_START);
    else
        go(j, HOME_FALL_SEARCH_START);
}

/* FINAL_BACKOFF: same-sign latch: move off the switch against the search direction. */
static void st_final_backoff_start(int j)
{
    if (waiting(j))
        return;
    if (!J(j)->home_sw) {
        fail("Home switch inactive before start of backoff move j=%d", j);
        return;
    }
    move_by_travel(j, -J(j)->params.home_search_vel);
    go(j, HOME_FINAL_BACKOFF_WAIT);
}

static void st_final_backoff_wait(int j)
{
    if (!J(j)->home_sw) {
        stop(j);
        if (stopped(j))
            go(j, HOME_RISE_SEARCH_START);
        return;
    }
    if (!limit_hit(j))
        end_of_move(j);
}

/* Latched: go on to the index, or set the position at the latch point now. */
static void latched(int j)
{
    J(j)->latch_fb = IO(j)->pos_fb;
    stop(j);
    if (flag(j, EMCMOT_HOME_USE_INDEX))
        go(j, HOME_INDEX_SEARCH_START);
    else
        go_now(j, HOME_SET_SWITCH_POSITION);
}

/* RISE_SEARCH: approach the switch slowly until it trips. */
static void st_rise_search_start(int j)
{
    if (waiting(j))
        return;
    if (J(j)->home_sw) {
        fail("Home switch active before start of latch move j=%d", j);
        return;
    }
    move_by_travel(j, J(j)->params.home_latch_vel);
    go(j, HOME_RISE_SEARCH_WAIT);
}

static void st_rise_search_wait(int j)
{
    if (J(j)->home_sw) {
        latched(j);
        return;
    }
    if (!limit_hit(j))
        end_of_move(j);
}

/* FALL_SEARCH: opposite-sign latch: move slowly until the switch releases. */
static void st_fall_search_start(int j)
{
    if (waiting(j))
        return;
    if (!J(j)->home_sw) {
        fail("Home switch inactive before start of latch move j=%d", j);
        return;
    }
    move_by_travel(j, J(j)->params.home_latch_vel);
    go(j, HOME_FALL_SEARCH_WAIT);
}

static void st_fall_search_wait(int j)
{
    if (!J(j)->home_sw) {
        latched(j);
        return;
    }
    if (!limit_hit(j))
        end_of_move(j);
}

/* SET_SWITCH_POSITION: the latch point reads HOME_OFFSET. */
static void st_set_switch_position(int j)
{
    home.env.set_position(j, J(j)->params.home_offset + (IO(j)->pos_fb - J(j)->latch_fb));
    go(j, HOME_FINAL_MOVE_START);
}

/* INDEX_ONLY: no switch: position := HOME_OFFSET, then look for the index. */
static void st_index_only_start(int j)
{
    home.env.set_position(j, J(j)->params.home_offset);
    go(j, HOME_INDEX_SEARCH_START);
}

/* INDEX_SEARCH: arm index-enable and move at LATCH_VEL until the encoder clears it. */
static void st_index_search_start(int j)
{
    if (!stopped(j) || waiting(j))
        return;
    J(j)->index_enable = 1;
    *home.pins[j].index_enable = 1;
    move_by_travel(j, J(j)->params.home_latch_vel);
    go(j, HOME_INDEX_SEARCH_WAIT);
}

static void st_index_search_wait(int j)
{
    if (!J(j)->index_enable) {
        J(j)->latch_fb = IO(j)->pos_fb;
        stop(j);
        go(j, HOME_SET_INDEX_POSITION);
        return;
    }
    if (!limit_hit(j))
        end_of_move(j);
}

/* SET_INDEX_POSITION: the index reads HOME_OFFSET (encoder reset, or from the latched feedback). */
static void st_set_index_position(int j)
{
    if (!stopped(j))
        return;
    if (flag(j, EMCMOT_HOME_INDEX_NO_ENCODER_RESET))
        home.env.set_position(j, J(j)->params.home_offset + (IO(j)->pos_fb - J(j)->latch_fb));
    else
        home.env.set_motor_zero(j, J(j)->params.home_offset);
    go(j, HOME_FINAL_MOVE_START);
}

/* FINAL_MOVE: to HOME at HOME_FINAL_VEL (or the joint's MAX_VELOCITY). */
static void st_final_move_start(int j)
{
    const home_params_t *p = &J(j)->params;
    home_joint_t *io = IO(j);

    if (!stopped(j) || waiting(j))
        return;
    io->free_pos_cmd = p->home;
    io->free_vel_lim = p->home_final_vel > 0.0 ? fmin(p->home_final_vel, io->vel_limit)
                                               : io->vel_limit;
    io->free_tp_enable = 1;
    go(j, HOME_FINAL_MOVE_WAIT);
}

static void st_final_move_wait(int j)
{
    if (limit_hit(j))
        return;
    if (stopped(j) && IO(j)->pos_cmd == J(j)->params.home)
        go_now(j, HOME_LOCK);
}

/* LOCK / LOCK_WAIT: lock a locking indexer again. */
static void st_lock(int j)
{
    if (!flag(j, EMCMOT_HOME_UNLOCK_FIRST)) {
        go_now(j, HOME_FINISHED);
        return;
    }
    IO(j)->unlock = 0;
    go(j, HOME_LOCK_WAIT);
}

static void st_lock_wait(int j)
{
    if (!IO(j)->is_unlocked)
        go_now(j, HOME_FINISHED);
}

/* FINISHED: homed. */
static void st_finished(int j)
{
    J(j)->homed = 1;
    J(j)->homing = 0;
    IO(j)->free_tp_enable = 0;
    go(j, HOME_IDLE);
}

/* IDLE and ABORT do nothing per cycle. */
static void st_idle(int j)
{
    (void)j;
}

static const state_fn_t handlers[] = {
    [HOME_IDLE] = st_idle, [HOME_START] = st_start, [HOME_UNLOCK] = st_unlock,
    [HOME_UNLOCK_WAIT] = st_unlock_wait,
    [HOME_INITIAL_BACKOFF_START] = st_initial_backoff_start,
    [HOME_INITIAL_BACKOFF_WAIT] = st_initial_backoff_wait,
    [HOME_INITIAL_SEARCH_START] = st_initial_search_start,
    [HOME_INITIAL_SEARCH_WAIT] = st_initial_search_wait,
    [HOME_SET_COARSE_POSITION] = st_set_coarse_position,
    [HOME_FINAL_BACKOFF_START] = st_final_backoff_start,
    [HOME_FINAL_BACKOFF_WAIT] = st_final_backoff_wait,
    [HOME_RISE_SEARCH_START] = st_rise_search_start,
    [HOME_RISE_SEARCH_WAIT] = st_rise_search_wait,
    [HOME_FALL_SEARCH_START] = st_fall_search_start,
    [HOME_FALL_SEARCH_WAIT] = st_fall_search_wait,
    [HOME_SET_SWITCH_POSITION] = st_set_switch_position,
    [HOME_INDEX_ONLY_START] = st_index_only_start,
    [HOME_INDEX_SEARCH_START] = st_index_search_start,
    [HOME_INDEX_SEARCH_WAIT] = st_index_search_wait,
    [HOME_SET_INDEX_POSITION] = st_set_index_position,
    [HOME_FINAL_MOVE_START] = st_final_move_start,
    [HOME_FINAL_MOVE_WAIT] = st_final_move_wait,
    [HOME_LOCK] = st_lock, [HOME_LOCK_WAIT] = st_lock_wait,
    [HOME_FINISHED] = st_finished, [HOME_ABORT] = st_idle,
};

#define MAX_CHAINED_STATES 6

/* One cycle of joint j: its state, plus the states it moves to at once. */
void home_joint_cycle(int j)
{
    for (int n = 0; n < MAX_CHAINED_STATES; n++) {
        int state = J(j)->state;
        if (state < 0 || state > HOME_ABORT || !J(j)->homing)
            return;
        J(j)->chain = 0;
        handlers[state](j);
        if (!J(j)->chain)
            return;
    }
}

/* Begin homing joint j: unhomed, state START. */
void home_joint_begin(int j)
{
    J(j)->homed = 0;
    J(j)->homing = 1;
    IO(j)->free_tp_enable = 0;
    go(j, HOME_START);
}

/* Stop joint j's homing motion now (it decelerates) and leave it idle, not homed. */
void home_joint_stop(int j)
{
    if (!J(j)->homing)
        return;
    IO(j)->free_tp_enable = 0;
    IO(j)->unlock = 0;
    J(j)->homing = 0;
    J(j)->homed = 0;
    J(j)->index_enable = 0;
    *home.pins[j].index_enable = 0;
    go(j, HOME_IDLE);
}
