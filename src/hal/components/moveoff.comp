component moveoff "Joint offsets applied by HAL alone, removed along the recorded path";
pin in bit power_on "Machine power; FALSE clears every offset and the recorded path at once (connect motion.motion-enabled)";
pin in bit move_enable "Operator request to apply offsets";
pin in bit apply_offsets "Permission to apply offsets (e.g. halui.program.is-paused, or TRUE for always)";
pin in bit backtrack_enable = TRUE "Remove offsets by retracing the recorded waypoints before heading to zero";
pin in float epsilon = 0.0005 "Distance from zero within which every offset counts as removed";
pin in float waypoint_threshold = 0.02 "Smallest move of any joint recorded as a new waypoint; also how close a waypoint must be approached while backtracking";
pin in float waypoint_sample_secs = 0.02 "Shortest time between two recorded waypoints";
pin out bit warning "TRUE while offsets are applied but apply-offsets is FALSE";
pin out bit offset_applied "TRUE from enabling until the offsets are removed again";
pin out bit waypoint_limit "TRUE after the waypoint store ran full (offsets frozen) until the offsets are removed";
pin out s32 waypoint_ct "Number of waypoints recorded";
pin out s32 waypoint_percent_used "Fill level of the waypoint store in percent";
pin in float offset_in_#[16 : personality] "Requested offset of joint #";
pin in float pos_#[16 : personality] "Position command of joint # (from joint.#.motor-pos-cmd)";
pin in float fb_#[16 : personality] "Position feedback of joint # (from the drive)";
pin out float offset_current_#[16 : personality] "Offset applied now to joint #";
pin in float offset_vel_#[16 : personality] = 10 "Largest offset speed of joint #";
pin in float offset_accel_#[16 : personality] = 100 "Largest offset acceleration of joint #";
pin in float offset_min_#[16 : personality] = -1e20 "Smallest offset of joint #";
pin in float offset_max_#[16 : personality] = 1e20 "Largest offset of joint #";
pin out float pos_plusoffset_#[16 : personality] "pos-# plus the applied offset (to the drive)";
pin out float fb_minusoffset_#[16 : personality] "fb-# minus the applied offset (to joint.#.motor-pos-fb)";
pin in bit dbg_waypoint_limit_test "Test aid: limit the waypoint store to a handful of entries";
pin out s32 dbg_state "State: 0 idle, 1 offsetting, 2 backtracking along waypoints, 3 returning to zero";
variable double cur[16];
variable double vel[16];
variable double wp[16000];
variable int state;
variable int n_wp;
variable int overflow;
variable double since_wp;
function read_inputs "Compute fb-minusoffset-# from fb-# and the applied offsets; add before motion-command-handler";
function write_outputs "Move the offsets and compute pos-plusoffset-#; add after motion-controller";
option default_personality 3;
option extra_setup yes;
include <rtapi_math.h>;
license "GPL";
author "OpenEMC";
description """
Offsets the joints of a machine without the motion controller knowing. Put it between
motion and the drives: joint.N.motor-pos-cmd to pos-N, pos-plusoffset-N to the drive,
the drive feedback to fb-N and fb-minusoffset-N to joint.N.motor-pos-fb.

personality is the number of joints (1 to 16, default 3), as in
loadrt moveoff names=mv personality=3.

Offsets are applied only while power-on, move-enable and apply-offsets are all TRUE.
Then each offset-current-N follows offset-in-N, clamped to offset-min-N..offset-max-N,
at no more than offset-vel-N and offset-accel-N. While offsets move, a waypoint (the
offsets of all joints) is recorded whenever waypoint-sample-secs have passed and some
joint moved more than waypoint-threshold since the last waypoint. When the store
(1000 waypoints; 5 while dbg-waypoint-limit-test is TRUE) is full, the offsets stop
where they are and waypoint-limit is set until the offsets are removed (an enabling
input must be dropped to remove them). offset-applied is TRUE from enabling until the
offsets are removed again; warning is TRUE while offsets are applied but apply-offsets
is FALSE.

When the enable condition goes away the offsets are removed: with backtrack-enable
they retrace the waypoints in reverse order (a waypoint counts as passed once every
joint is within waypoint-threshold of it), then they go straight to zero, all under
the same speed and acceleration limits. Enabling again during the removal resumes
following offset-in-N. When every offset is within epsilon of zero the component is
idle again. power-on FALSE drops the offsets and the waypoints at once.
""";
;;
#define MOVEOFF_MAX_JOINTS 16
#define MOVEOFF_MAX_WAYPOINTS 1000
#define MOVEOFF_TEST_WAYPOINTS 5

enum moveoff_state { ST_IDLE, ST_OFFSETTING, ST_BACKTRACK, ST_RETURN };

/* Refuse a joint count outside 1..16 when an instance is made. */
EXTRA_SETUP()
{
    if (personality < 1 || personality > MOVEOFF_MAX_JOINTS) {
        rtapi_print_msg(RTAPI_MSG_ERR,
                        "moveoff: %s: personality=%d is not a joint count from 1 to %d\n",
                        prefix, personality, MOVEOFF_MAX_JOINTS);
        return -EINVAL;
    }
    return 0;
}

/* Next offset of one joint moving to target under speed and acceleration limits. */
static double step_toward(double now, double *v, double target, double vmax, double amax,
                          double dt)
{
    double err = target - now, dv_max = fabs(amax) * dt;
    double brake = dv_max > 0 ?
        2.0 * fabs(err) / dt / (sqrt(0.25 + 2.0 * fabs(err) / (dv_max * dt)) + 0.5) : 0;
    double want = fmin(fmin(fabs(vmax), brake), fabs(err) / dt);
    if (err < 0)
        want = -want;
    if (want - *v > dv_max)
        want = *v + dv_max;
    else if (*v - want > dv_max)
        want = *v - dv_max;
    *v = want;
    if (fabs(target - (now + want * dt)) < 1e-12) {
        *v = 0;
        return target;
    }
    return now + want * dt;
}

/* Forget every offset and waypoint (power lost). */
static void reset_all(struct __comp_state *__comp_inst)
{
    int j;
    for (j = 0; j < personality; j++) {
        cur[j] = 0;
        vel[j] = 0;
    }
    n_wp = 0;
    overflow = 0;
    since_wp = 0;
    state = ST_IDLE;
}

/* Offset joint j had at waypoint n (n < 0 is the origin). */
static double waypoint(struct __comp_state *__comp_inst, int n, int j)
{
    return n < 0 ? 0.0 : wp[n * MOVEOFF_MAX_JOINTS + j];
}

/* TRUE when every offset is near waypoint n: within waypoint-threshold while passing
   recorded waypoints, within epsilon of zero (n < 0) at the end. */
static int at_waypoint(struct __comp_state *__comp_inst, int n)
{
    int j;
    double tol = n < 0 ? fabs(epsilon) : fmax(fabs(epsilon), fabs(waypoint_threshold));
    for (j = 0; j < personality; j++)
        if (fabs(cur[j] - waypoint(__comp_inst, n, j)) > tol)
            return 0;
    return 1;
}

/* Move every offset toward waypoint n (n < 0: toward zero). */
static void move_to_waypoint(struct __comp_state *__comp_inst, int n, double dt)
{
    int j;
    for (j = 0; j < personality; j++)
        cur[j] = step_toward(cur[j], &vel[j], waypoint(__comp_inst, n, j),
                             offset_vel(j), offset_accel(j), dt);
}

/* Clamped target offset of joint j (a NaN request holds the offset). */
static double wanted_offset(struct __comp_state *__comp_inst, int j)
{
    double t = offset_in(j);
    if (t != t)
        return cur[j];
    if (t > offset_max(j))
        t = offset_max(j);
    if (t < offset_min(j))
        t = offset_min(j);
    return t;
}

/* Record a waypoint when due; set the overflow flag when the store is full. */
static void record_waypoint(struct __comp_state *__comp_inst, double dt)
{
    int j, n = n_wp, moved = 0;
    int limit = dbg_waypoint_limit_test ? MOVEOFF_TEST_WAYPOINTS : MOVEOFF_MAX_WAYPOINTS;
    since_wp += dt;
    if (since_wp < waypoint_sample_secs)
        return;
    for (j = 0; j < personality; j++)
        if (fabs(cur[j] - waypoint(__comp_inst, n - 1, j)) > waypoint_threshold)
            moved = 1;
    if (!moved)
        return;
    if (n >= limit) {
        overflow = 1;
        return;
    }
    for (j = 0; j < personality; j++)
        wp[n * MOVEOFF_MAX_JOINTS + j] = cur[j];
    n_wp = n + 1;
    since_wp = 0;
}

/* Follow offset-in while enabled (frozen after an overflow). */
static void follow_offsets(struct __comp_state *__comp_inst, double dt)
{
    int j;
    if (overflow) {
        for (j = 0; j < personality; j++)
            vel[j] = 0;
        return;
    }
    for (j = 0; j < personality; j++)
        cur[j] = step_toward(cur[j], &vel[j], wanted_offset(__comp_inst, j),
                             offset_vel(j), offset_accel(j), dt);
    record_waypoint(__comp_inst, dt);
}

/* Remove the offsets: retrace waypoints (if allowed), then head to zero. */
static void remove_offsets(struct __comp_state *__comp_inst, double dt)
{
    int j;
    if (!backtrack_enable)
        n_wp = 0;
    state = n_wp > 0 ? ST_BACKTRACK : ST_RETURN;
    move_to_waypoint(__comp_inst, n_wp - 1, dt);
    if (!at_waypoint(__comp_inst, n_wp - 1))
        return;
    if (n_wp > 0) {
        n_wp--;
        return;
    }
    for (j = 0; j < personality; j++) {
        cur[j] = 0;
        vel[j] = 0;
    }
    overflow = 0;
    since_wp = 0;
    state = ST_IDLE;
}

/* Advance the state machine by one period. */
static void update_offsets(struct __comp_state *__comp_inst, double dt)
{
    int enabled = power_on && move_enable && apply_offsets;
    if (!power_on) {
        reset_all(__comp_inst);
    } else if (enabled) {
        state = ST_OFFSETTING;
        follow_offsets(__comp_inst, dt);
    } else if (state != ST_IDLE) {
        remove_offsets(__comp_inst, dt);
    }
}

/* Copy the state to the status pins. */
static void publish_status(struct __comp_state *__comp_inst)
{
    int j, limit = dbg_waypoint_limit_test ? MOVEOFF_TEST_WAYPOINTS : MOVEOFF_MAX_WAYPOINTS;
    for (j = 0; j < personality; j++)
        offset_current(j) = cur[j];
    offset_applied = state != ST_IDLE;
    waypoint_limit = overflow;
    warning = state != ST_IDLE && !apply_offsets;
    waypoint_ct = n_wp;
    waypoint_percent_used = (100 * n_wp) / limit;
    dbg_state = state;
}

/* Feedback seen by motion: the drive feedback without the applied offset. */
FUNCTION(read_inputs)
{
    int j;
    for (j = 0; j < personality; j++)
        fb_minusoffset(j) = fb(j) - cur[j];
}

/* Move the offsets one period and drive the position outputs. */
FUNCTION(write_outputs)
{
    int j;
    double dt = fperiod;
    if (dt <= 0)
        return;
    update_offsets(__comp_inst, dt);
    for (j = 0; j < personality; j++)
        pos_plusoffset(j) = pos(j) + cur[j];
    publish_status(__comp_inst);
}
