component stepgen "Software step pulse generator (position or velocity mode)";
pin in bit enable "Pulses are generated only while TRUE";
pin in float position_cmd if !(personality & 0x100) "Commanded position, in position units";
pin in float velocity_cmd if personality & 0x100 "Commanded velocity, in position units per second";
pin out s32 counts "Feedback position in whole steps";
pin out float position_fb "Feedback position in position units, including the fraction of a step";
pin out bit step if (personality & 0xff) == 0 "Step output (type 0)";
pin out bit dir if (personality & 0xff) == 0 "Direction output (type 0), TRUE while moving negative";
pin out bit up if (personality & 0xff) == 1 "Count-up output (type 1)";
pin out bit down if (personality & 0xff) == 1 "Count-down output (type 1)";
pin out bit phase_A if (personality & 0xff) >= 2 "Phase output A (types 2 and up)";
pin out bit phase_B if (personality & 0xff) >= 2 "Phase output B (types 2 and up)";
pin out bit phase_C if ((personality >> 12) & 7) >= 3 "Phase output C (3, 4 and 5 phase types)";
pin out bit phase_D if ((personality >> 12) & 7) >= 4 "Phase output D (4 and 5 phase types)";
pin out bit phase_E if ((personality >> 12) & 7) >= 5 "Phase output E (5 phase types)";
param rw float position_scale = 1.0 "Steps per position unit";
param rw float maxvel = 0.0 "Velocity limit in position units per second (0 = only the pulse timing limit)";
param rw float maxaccel = 0.0 "Acceleration limit in position units per second squared (0 = none)";
param r float frequency "Current step rate in steps per second";
param r s32 rawcounts "Steps output so far (updated by make-pulses)";
param rw u32 steplen = 1 "Step pulse length (types 0, 1) or minimum time in one phase state, in ns";
param rw u32 stepspace = 1 if (personality & 0xff) <= 1 "Minimum space between step pulses in ns";
param rw u32 dirsetup = 1 if (personality & 0xff) == 0 "Time from a direction change to the next step, in ns";
param rw u32 dirhold = 1 if (personality & 0xff) == 0 "Time from the end of a step pulse to a direction change, in ns";
param rw u32 dirdelay = 1 if (personality & 0xff) >= 1 "Time from the end of a step to a step in the other direction, in ns";
variable long long accum = 134217728;
variable long long addval;
variable long long target_addval;
variable long long deltalim;
variable long pulse_ns;
variable long dir_ok_ns;
variable long setup_ns;
variable int curr_dir = 1;
variable double freq;
variable double old_pos_cmd;
variable int state;
variable int warned;
option rtapi_app no;
include <rtapi_math.h>;
license "GPL";
author "OpenEMC";
description """Load with step_type=T0,T1,... (one entry per channel, at most 16) and
ctrl_type=C0,C1,... where only the first letter of each entry counts: p or P
(position mode, also when the entry is missing or empty) or v or V (velocity mode).
Step types: 0 step/dir, 1 up/down, 2 quadrature, 3 three-wire, 4 three-wire half
step, 5 and 6 unipolar full step, 7 and 8 bipolar full step, 9 unipolar half step,
10 bipolar half step, 11 five-wire unipolar, 12 five-wire wave, 13 five-wire
unipolar half step, 14 five-wire wave half step, 15 user defined by
user_step_type=P0,P1,... (2 to 10 patterns, bit 0 = phase A, bit 4 = phase E).

Phase patterns of types 2..14, one per state, written as bits E..A (A rightmost);
a step forward moves to the next state, a step backward to the previous one, and
the cycle wraps. Every channel starts in state 0 (the first pattern), and
make-pulses writes the pattern of the current state on every call:
  2: 01 11 10 00
  3: 001 010 100
  4: 001 011 010 110 100 101
  5: 0001 0010 0100 1000
  6: 0011 0110 1100 1001
  7: 0001 0111 1110 1000
  8: 0101 0110 1010 1001
  9: 0001 0011 0010 0110 0100 1100 1000 1001
  10: 0001 0101 0111 0110 1110 1010 1000 1001
  11: 00001 00010 00100 01000 10000
  12: 00011 00110 01100 11000 10001
  13: 00001 00011 00010 00110 00100 01100 01000 11000 10000 10001
  14: 00011 00111 00110 01110 01100 11100 11000 11001 10001 10011

The position is a 64-bit fixed-point accumulator whose bit 28 is the step bit; it
starts at half a step, so steps happen half way between whole positions. counts
(and rawcounts) are the accumulator shifted right by 28 bits; position-fb is the
accumulator less the half step, divided by 2^28 and by position-scale.
make-pulses moves the per-period increment toward its target by at most one
acceleration step, adds it to the accumulator and emits a step whenever the step
bit changes. update-freq turns the command into that target under maxvel and
maxaccel (velocity mode: velocity-cmd clamped to maxvel and ramped at maxaccel;
position mode: a move to position-cmd under both limits).

Direction changes: while the timer started by the last step (steplen + dirhold for
type 0, steplen + dirdelay for the others) runs, a change of direction holds the
accumulator. Once it has run out the direction flips; type 0 then sets dir (TRUE =
negative) and holds the accumulator for dirsetup more before the first step the
new way. So a step the other way comes at least steplen + dirhold + dirsetup
(type 0) or steplen + dirdelay (other types) after the last step, and dir changes
at least dirhold after the end of the last pulse and dirsetup before the next.
stepspace only lowers the highest step rate. steplen, stepspace (types 0 and 1)
and dirdelay are at least one make-pulses period; dirsetup and dirhold may be 0.""";
;;
#define STEPGEN_MAX_CHAN 16
#define STEPGEN_MAX_CYCLE 10
#define STEPGEN_PICKOFF 28
#define STEPGEN_ONE (1LL << STEPGEN_PICKOFF)
#define STEPGEN_HALF (1LL << (STEPGEN_PICKOFF - 1))
#define STEPGEN_DEFAULT_BASE_NS 50000
#define STEPGEN_DEFAULT_SERVO_NS 1000000

static int step_type[STEPGEN_MAX_CHAN] = { [0 ... STEPGEN_MAX_CHAN - 1] = -1 };
RTAPI_MP_ARRAY_INT(step_type, STEPGEN_MAX_CHAN, "stepping types for up to 16 channels");
static char *ctrl_type[STEPGEN_MAX_CHAN];
RTAPI_MP_ARRAY_STRING(ctrl_type, STEPGEN_MAX_CHAN, "control type (p or v) of each channel");
static int user_step_type[STEPGEN_MAX_CYCLE] = { [0 ... STEPGEN_MAX_CYCLE - 1] = -1 };
RTAPI_MP_ARRAY_INT(user_step_type, STEPGEN_MAX_CYCLE, "phase patterns of step type 15");

/* Phase patterns (bit 0 = phase A) of step types 2..14, one state per entry. */
static const unsigned char stepgen_cycle[13][STEPGEN_MAX_CYCLE] = {
    {1, 3, 2, 0},
    {1, 2, 4},
    {1, 3, 2, 6, 4, 5},
    {1, 2, 4, 8},
    {3, 6, 12, 9},
    {1, 7, 14, 8},
    {5, 6, 10, 9},
    {1, 3, 2, 6, 4, 12, 8, 9},
    {1, 5, 7, 6, 14, 10, 8, 9},
    {1, 2, 4, 8, 16},
    {3, 6, 12, 24, 17},
    {1, 3, 2, 6, 4, 12, 8, 24, 16, 17},
    {3, 7, 6, 14, 12, 28, 24, 25, 17, 19},
};
/* Number of states per cycle and number of phase outputs of step types 2..14. */
static const unsigned char stepgen_cycle_len[13] = {4, 3, 6, 4, 4, 4, 4, 8, 8, 5, 5, 10, 10};
static const unsigned char stepgen_phases[13] = {2, 3, 3, 4, 4, 4, 4, 4, 4, 5, 5, 5, 5};
static unsigned char user_cycle[STEPGEN_MAX_CYCLE];
static int user_cycle_len, user_phases;

/* Timing shared by all channels. make-pulses records its period in base_ns; until
   it has run, update-freq works with a 50 us base period (so its first call rounds
   the timing params and scales the increment for 50 us, as the reference does). */
static long base_ns, base_ns_used, servo_ns_used;
static double per_hz, per_hz_s, servo_s, servo_rate;

/* Put the shared timing back to its load-time defaults. */
static void stepgen_timing_init(void)
{
    base_ns = base_ns_used = STEPGEN_DEFAULT_BASE_NS;
    servo_ns_used = STEPGEN_DEFAULT_SERVO_NS;
    per_hz = STEPGEN_ONE * (STEPGEN_DEFAULT_BASE_NS * 0.000000001);
    per_hz_s = per_hz * (STEPGEN_DEFAULT_BASE_NS * 0.000000001);
    servo_s = STEPGEN_DEFAULT_SERVO_NS * 0.000000001;
    servo_rate = 1.0 / servo_s;
}

/* Recompute the scale factors when the make-pulses or servo period changed. */
static void stepgen_update_scales(long servo_period)
{
    if (base_ns != base_ns_used) {
        double base_s = base_ns * 0.000000001;
        base_ns_used = base_ns;
        per_hz = STEPGEN_ONE * base_s;
        per_hz_s = per_hz * base_s;
    }
    if (servo_period != servo_ns_used) {
        servo_ns_used = servo_period;
        servo_s = servo_period * 0.000000001;
        servo_rate = 1.0 / servo_s;
    }
}

/* Round a timing parameter (raised to `min_ns` first) up to whole make-pulses
   periods, store it back and return it. */
static long stepgen_round(hal_u32_t *ns, hal_u32_t min_ns)
{
    unsigned long long n = *ns < min_ns ? min_ns : *ns;
    if (n) n = ((n - 1) / (unsigned long long)base_ns + 1) * (unsigned long long)base_ns;
    *ns = (hal_u32_t)n;
    return (long)*ns;
}

/* Pattern of state `s` for the channel's step type (2..15). */
static unsigned stepgen_pattern(int type, int s)
{
    return type == 15 ? user_cycle[s] : stepgen_cycle[type - 2][s];
}

/* Number of states in one cycle of step type 2..15. */
static int stepgen_cycle_length(int type)
{
    return type == 15 ? user_cycle_len : stepgen_cycle_len[type - 2];
}

/* Direction hold time of the channel: dirhold (type 0) or dirdelay (others), in ns. */
static long stepgen_hold_ns(struct __comp_state *__comp_inst)
{
    return (personality & 0xff) == 0 ? (long)dirhold : (long)dirdelay;
}

/* Round the timing params; returns the highest step rate (steps/s) they allow. */
static double stepgen_timing_limit(struct __comp_state *__comp_inst)
{
    int type = personality & 0xff;
    long min_period = stepgen_round(&steplen, 1);
    if (type <= 1) min_period += stepgen_round(&stepspace, 1);
    if (type == 0) {
        stepgen_round(&dirsetup, 0);
        stepgen_round(&dirhold, 0);
    } else {
        stepgen_round(&dirdelay, 1);
    }
    return 1.0 / (min_period * 0.000000001);
}

/* A step rate as an int for messages, saturated at INT_MAX. */
static int stepgen_int(double v)
{
    return v < 2147483647.0 ? (int)v : 2147483647;
}

/* Apply maxvel to the timing limit (correcting a too high maxvel); returns steps/s. */
static double stepgen_vel_limit(struct __comp_state *__comp_inst, int chan, double fmax,
                                double scale)
{
    double want;
    if (!(maxvel > 0.0)) {
        maxvel = 0.0;
        return fmax;
    }
    want = maxvel * fabs(scale);
    if (want <= fmax) return want;
    if (!warned) {
        rtapi_print_msg(RTAPI_MSG_ERR, "STEPGEN: Channel %d: The requested maximum velocity of "
                        "%d steps/sec is too high.\n", chan, stepgen_int(want));
        rtapi_print_msg(RTAPI_MSG_ERR, "STEPGEN: The maximum number of steps possible is %d "
                        "steps per second\n", stepgen_int(fmax));
        warned = 1;
    }
    maxvel = fmax / fabs(scale);
    return fmax;
}

/* Apply maxaccel: the hard limit is full speed within one servo period; returns steps/s^2. */
static double stepgen_acc_limit(struct __comp_state *__comp_inst, double fmax, double scale)
{
    double amax = fmax * servo_rate;
    if (!(maxaccel > 0.0)) {
        maxaccel = 0.0;
        return amax;
    }
    if (maxaccel * fabs(scale) > amax) {
        maxaccel = amax / fabs(scale);
        return amax;
    }
    return maxaccel * fabs(scale);
}

/* Clamp v to [lo, hi]. */
static double stepgen_clamp(double v, double lo, double hi)
{
    if (v > hi) return hi;
    if (v < lo) return lo;
    return v;
}

/* Position mode: velocity for the next servo period that steers toward the command.
   It estimates where the output ends up once it has matched the command velocity at
   full acceleration, compares that with where the command will be (allowing for the
   1.5 period lag of the pulse chain) and ramps the way that shrinks the error. */
static double stepgen_plan(double cmd, double cmd_vel, double pos, double vel, double amax)
{
    double ac = cmd_vel > vel ? amax : -amax;
    double t_match = (cmd_vel - vel) / ac;
    double out_end = pos + (cmd_vel + vel) * 0.5 * t_match;
    double cmd_end = cmd + cmd_vel * (t_match - 1.5 * servo_s);
    double err = out_end - cmd_end;
    double flip_dp;
    if (t_match < servo_s) {
        if (fabs(err) < 0.0001) return cmd_vel;
        return stepgen_clamp(cmd_vel - 0.5 * err * servo_rate, vel - amax * servo_s,
                             vel + amax * servo_s);
    }
    flip_dp = -2.0 * ac * servo_s * t_match;
    if (fabs(err + flip_dp * 2.0) < fabs(err)) ac = -ac;
    return vel + ac * servo_s;
}

/* Valid position scale of the channel: a (near) zero, infinite or NaN scale is reset to 1. */
static double stepgen_scale(struct __comp_state *__comp_inst)
{
    if (!(fabs(position_scale) >= 1e-20) || isinf(position_scale)) position_scale = 1.0;
    return position_scale;
}

/* Servo-rate part of one channel: choose the step rate for the next period. */
static void stepgen_freq_one(struct __comp_state *__comp_inst, int chan)
{
    double scale = stepgen_scale(__comp_inst), fmax, amax, nv;
    fmax = stepgen_timing_limit(__comp_inst);
    if (!enable) {
        if (!(personality & 0x100)) old_pos_cmd = position_cmd * scale;
        freq = frequency = 0;
        addval = target_addval = 0;
        return;
    }
    fmax = stepgen_vel_limit(__comp_inst, chan, fmax, scale);
    amax = stepgen_acc_limit(__comp_inst, fmax, scale);
    if (personality & 0x100) {
        double dv = amax * servo_s;
        nv = stepgen_clamp(velocity_cmd * scale, -fmax, fmax);
        nv = stepgen_clamp(nv, freq - dv, freq + dv);
    } else {
        double cmd = position_cmd * scale;
        double cmd_vel = (cmd - old_pos_cmd) * servo_rate;
        double pos = (accum - STEPGEN_HALF) * (1.0 / STEPGEN_ONE);
        old_pos_cmd = cmd;
        nv = isfinite(cmd_vel) ? stepgen_plan(cmd, cmd_vel, pos, freq, amax) : NAN;
        nv = stepgen_clamp(nv, -fmax, fmax);
    }
    if (nv != nv)  /* a NaN or infinite command: ramp down to a stop */
        nv = stepgen_clamp(0.0, freq - amax * servo_s, freq + amax * servo_s);
    freq = frequency = nv;
    target_addval = (long long)(nv * per_hz);
    deltalim = (long long)(amax * per_hz_s);
}

/* Count a timer down by one make-pulses period, stopping at 0. */
static void stepgen_count_down(long *timer_ns)
{
    if (*timer_ns > 0) *timer_ns = *timer_ns > base_ns ? *timer_ns - base_ns : 0;
}

/* Move addval toward its target by at most deltalim per period. */
static void stepgen_ramp(struct __comp_state *__comp_inst)
{
    if (deltalim == 0) addval = target_addval;
    else if (target_addval > addval + deltalim) addval += deltalim;
    else if (target_addval < addval - deltalim) addval -= deltalim;
    else addval = target_addval;
}

/* Follow a change of the sign of addval: the direction flips only once the hold
   time after the last step has passed (type 0 then sets dir and waits dirsetup).
   Returns TRUE when the accumulator may advance in this period. */
static int stepgen_direction(struct __comp_state *__comp_inst)
{
    int want = addval > 0 ? 1 : addval < 0 ? -1 : curr_dir;
    if (want != curr_dir) {
        if (dir_ok_ns > 0) return 0;
        curr_dir = want;
        if ((personality & 0xff) == 0) {
            dir = want < 0;
            setup_ns = dirsetup;
        }
    }
    return setup_ns == 0;
}

/* Emit one step in the current direction and restart the timing constraints. */
static void stepgen_step(struct __comp_state *__comp_inst)
{
    int type = personality & 0xff;
    pulse_ns = steplen;
    dir_ok_ns = pulse_ns + stepgen_hold_ns(__comp_inst);
    if (type == 0) step = 1;
    else if (type == 1 && curr_dir > 0) up = 1;
    else if (type == 1) down = 1;
    else if (curr_dir > 0) state = state + 1 < stepgen_cycle_length(type) ? state + 1 : 0;
    else state = state > 0 ? state - 1 : stepgen_cycle_length(type) - 1;
}

/* Drive the phase outputs of types 2..15 from the current state. */
static void stepgen_phase_outputs(struct __comp_state *__comp_inst)
{
    int type = personality & 0xff;
    unsigned bits;
    if (type <= 1) return;
    bits = stepgen_pattern(type, state);
    phase_A = bits & 1;
    phase_B = (bits >> 1) & 1;
    if (phase_C_ptr) phase_C = (bits >> 2) & 1;
    if (phase_D_ptr) phase_D = (bits >> 3) & 1;
    if (phase_E_ptr) phase_E = (bits >> 4) & 1;
}

/* Base-rate part of one channel: ramp, advance the accumulator and emit steps. */
static void stepgen_pulses_one(struct __comp_state *__comp_inst)
{
    int step_now = 0;
    stepgen_count_down(&pulse_ns);
    stepgen_count_down(&dir_ok_ns);
    stepgen_count_down(&setup_ns);
    if (enable) stepgen_ramp(__comp_inst);
    if (enable && stepgen_direction(__comp_inst)) {
        long long before = accum;
        accum += addval;
        step_now = ((before ^ accum) >> STEPGEN_PICKOFF) & 1;
        rawcounts = (hal_s32_t)(accum >> STEPGEN_PICKOFF);
    }
    if (pulse_ns == 0 && step_ptr) step = 0;
    if (pulse_ns == 0 && up_ptr) up = down = 0;
    if (step_now) stepgen_step(__comp_inst);
    stepgen_phase_outputs(__comp_inst);
}

/* Publish counts and position of one channel. */
static void stepgen_capture_one(struct __comp_state *__comp_inst)
{
    long long a = accum;
    counts = (hal_s32_t)(a >> STEPGEN_PICKOFF);
    position_fb = (double)(a - STEPGEN_HALF) * ((1.0 / STEPGEN_ONE) / stepgen_scale(__comp_inst));
}

/* Funct stepgen.update-freq: all channels. */
static void stepgen_update_freq(void *arg, long period)
{
    int chan = 0;
    (void)arg;
    stepgen_update_scales(period);
    FOR_ALL_INSTS() stepgen_freq_one(__comp_inst, chan++);
}

/* Funct stepgen.make-pulses: all channels. */
static void stepgen_make_pulses(void *arg, long period)
{
    (void)arg;
    base_ns = period;
    FOR_ALL_INSTS() stepgen_pulses_one(__comp_inst);
}

/* Funct stepgen.capture-position: all channels. */
static void stepgen_capture_position(void *arg, long period)
{
    (void)arg;
    (void)period;
    FOR_ALL_INSTS() stepgen_capture_one(__comp_inst);
}

/* Check user_step_type and build the type 15 cycle; returns 0 or -EINVAL. */
static int stepgen_user_cycle(void)
{
    int i, bits = 0;
    for (i = 0; i < STEPGEN_MAX_CYCLE && user_step_type[i] != -1; i++) {
        if (user_step_type[i] < 0 || user_step_type[i] > 31) {
            rtapi_print_msg(RTAPI_MSG_ERR, "STEPGEN: ERROR: user_step_type entry %d (%d) must be "
                            "a pattern of at most 5 phases (0..31)\n", i, user_step_type[i]);
            return -EINVAL;
        }
        user_cycle[i] = user_step_type[i];
        bits |= user_step_type[i];
    }
    user_cycle_len = i;
    if (i < 2) {
        rtapi_print_msg(RTAPI_MSG_ERR, "STEPGEN: ERROR: step type 15 needs user_step_type= with "
                        "2 to %d patterns\n", STEPGEN_MAX_CYCLE);
        return -EINVAL;
    }
    for (user_phases = 2; user_phases < 5 && (bits >> user_phases); user_phases++)
        ;
    return 0;
}

/* Personality of channel i from step_type and ctrl_type, or -1 after an error. */
static int stepgen_personality(int i)
{
    int v = 0, t = step_type[i], phases = 0;
    if (t < 0 || t > 15) {
        rtapi_print_msg(RTAPI_MSG_ERR, "STEPGEN: ERROR: bad stepping type '%d', axis %d\n", t, i);
        return -1;
    }
    if (t == 15 && !user_cycle_len && stepgen_user_cycle() < 0) return -1;
    if (t >= 2) phases = t == 15 ? user_phases : stepgen_phases[t - 2];
    if (ctrl_type[i] && (ctrl_type[i][0] == 'v' || ctrl_type[i][0] == 'V')) v = 0x100;
    else if (ctrl_type[i] && ctrl_type[i][0] && ctrl_type[i][0] != 'p' && ctrl_type[i][0] != 'P') {
        rtapi_print_msg(RTAPI_MSG_ERR, "STEPGEN: ERROR: bad control type '%s' for axis %d "
                        "(must be 'p' or 'v')\n", ctrl_type[i], i);
        return -1;
    }
    return t | v | phases << 12;
}

/* Export the three functs shared by all channels. */
static int stepgen_export_functs(void)
{
    int r = hal_export_funct("stepgen.make-pulses", stepgen_make_pulses, 0, 0, 0, comp_id);
    if (r == 0) r = hal_export_funct("stepgen.update-freq", stepgen_update_freq, 0, 1, 0, comp_id);
    if (r == 0) r = hal_export_funct("stepgen.capture-position", stepgen_capture_position, 0, 1, 0,
                                     comp_id);
    return r;
}

/* Create the configured channels. */
int rtapi_app_main(void)
{
    int i, n = 0, r = 0, pers[STEPGEN_MAX_CHAN];
    char buf[HAL_NAME_LEN + 1];
    while (n < STEPGEN_MAX_CHAN && step_type[n] != -1) n++;
    if (n == 0) {
        rtapi_print_msg(RTAPI_MSG_ERR, "STEPGEN: ERROR: no channels configured\n");
        return -EINVAL;
    }
    for (i = 0; i < n; i++) {
        pers[i] = stepgen_personality(i);
        if (pers[i] < 0) return -EINVAL;
    }
    stepgen_timing_init();
    comp_id = hal_init("stepgen");
    if (comp_id < 0) return comp_id;
    for (i = 0; i < n && r == 0; i++) {
        rtapi_snprintf(buf, sizeof(buf), "stepgen.%d", i);
        r = export(buf, i, pers[i]);
    }
    if (r == 0) r = stepgen_export_functs();
    if (r) {
        hal_exit(comp_id);
        return r;
    }
    hal_ready(comp_id);
    return 0;
}

/* Remove the component. */
void rtapi_app_exit(void)
{
    hal_exit(comp_id);
}
