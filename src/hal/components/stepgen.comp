component stepgen "Software step pulse generator (position or velocity mode)";
pin in bit enable "Pulses are generated only while TRUE";
pin in float position_cmd if !(personality & 0x100) "Commanded position, in position units";
pin in float velocity_cmd if personality & 0x100 "Commanded velocity, in position units per second";
pin out s32 counts "Steps output so far";
pin out float position_fb "Position from the step accumulator, in position units";
pin out bit step if (personality & 0xff) == 0 "Step output (type 0)";
pin out bit dir if (personality & 0xff) == 0 "Direction output (type 0), TRUE for negative motion";
pin out bit up if (personality & 0xff) == 1 "Count-up output (type 1)";
pin out bit down if (personality & 0xff) == 1 "Count-down output (type 1)";
pin out bit phase_A if (personality & 0xff) == 2 "Quadrature phase A (type 2)";
pin out bit phase_B if (personality & 0xff) == 2 "Quadrature phase B (type 2)";
param rw float position_scale = 1.0 "Steps per position unit";
param rw float maxvel = 0.0 "Velocity limit in position units per second (0 = only the pulse timing limit)";
param rw float maxaccel = 0.0 "Acceleration limit in position units per second squared (0 = none)";
param r float frequency "Current step rate in steps per second";
param r s32 rawcounts "Steps output so far";
param rw u32 steplen = 1 "Step pulse length in ns, rounded up to whole make-pulses periods";
param rw u32 stepspace = 1 if (personality & 0xff) <= 1 "Minimum space between step pulses in ns";
param rw u32 dirsetup = 1 if (personality & 0xff) == 0 "Time from a direction change to the next step, in ns";
param rw u32 dirhold = 1 if (personality & 0xff) == 0 "Time from a step to a direction change, in ns";
param rw u32 dirdelay = 1 if (personality & 0xff) >= 1 "Time from a step to a step in the other direction, in ns";
variable long long accum;
variable long long addval;
variable double freq;
variable int len_left;
variable int space_left;
variable int setup_left;
variable int hold_left;
variable int out_dir = 1;
variable int pulse_on;
variable unsigned phase;
option rtapi_app no;
include <rtapi_math.h>;
license "GPL";
author "OpenEMC";
description """Load with step_type=T0,T1,... (one entry per channel, at most 16; type 0 step/dir,
1 up/down, 2 quadrature) and ctrl_type=p|v,... (default p).""";
;;
#define STEPGEN_MAX_CHAN 16
#define STEPGEN_ONE (4294967296.0)

static int step_type[STEPGEN_MAX_CHAN] = { [0 ... STEPGEN_MAX_CHAN - 1] = -1 };
RTAPI_MP_ARRAY_INT(step_type, STEPGEN_MAX_CHAN, "stepping types for up to 16 channels");
static char *ctrl_type[STEPGEN_MAX_CHAN];
RTAPI_MP_ARRAY_STRING(ctrl_type, STEPGEN_MAX_CHAN, "control type (p or v) of each channel");
static long base_period_ns;

/* Round a timing parameter up to whole base periods, store it back, return the count. */
static int stepgen_periods(hal_u32_t *ns)
{
    long n;
    if (base_period_ns <= 0) return 1;
    n = (*ns + base_period_ns - 1) / base_period_ns;
    if (n < 1) n = 1;
    *ns = n * base_period_ns;
    return (int)n;
}

/* Highest step rate the pulse timing allows, in steps per second. */
static double stepgen_max_freq(struct __comp_state *__comp_inst)
{
    int type = personality & 0xff, n;
    if (base_period_ns <= 0) return 0;
    if (type == 2) n = stepgen_periods(&steplen);
    else n = stepgen_periods(&steplen) + stepgen_periods(&stepspace);
    return 1e9 / ((double)n * base_period_ns);
}

/* New velocity (steps/s) that heads for target under the accel limit and can stop there. */
static double stepgen_seek(double p, double v, double target, double amax, double dt)
{
    double d = target - p, s = d >= 0 ? 1.0 : -1.0, rem, lim, lo, hi, nv;
    if (amax <= 0) return 2.0 * d / dt - v;
    rem = fabs(d) - s * v * dt / 2.0;
    if (rem < 0) rem = 0;
    lim = amax * (-dt / 2.0 + sqrt(dt * dt / 4.0 + 2.0 * rem / amax));
    nv = s * lim;
    lo = v - amax * dt;
    hi = v + amax * dt;
    if (nv < lo) nv = lo;
    if (nv > hi) nv = hi;
    return nv;
}

/* Servo-rate part of one channel: choose the step rate for the next period. */
static void stepgen_freq_one(struct __comp_state *__comp_inst, long period)
{
    double dt = period * 1e-9, scale = position_scale, p, nv, fmax, vmax, amax;
    if (base_period_ns <= 0) base_period_ns = period;
    if (scale > -1e-20 && scale < 1e-20) scale = 1.0;
    fmax = stepgen_max_freq(__comp_inst);
    vmax = fabs(maxvel * scale);
    if (vmax <= 0 || vmax > fmax) vmax = fmax;
    amax = fabs(maxaccel * scale);
    if (!enable) {
        freq = 0;
        addval = 0;
        frequency = 0;
        return;
    }
    p = accum / STEPGEN_ONE;
    if (personality & 0x100) {
        double want = velocity_cmd * scale, dv = amax * dt;
        nv = want;
        if (amax > 0 && nv > freq + dv) nv = freq + dv;
        if (amax > 0 && nv < freq - dv) nv = freq - dv;
    } else {
        nv = stepgen_seek(p, freq, position_cmd * scale, amax, dt);
    }
    if (nv > vmax) nv = vmax;
    if (nv < -vmax) nv = -vmax;
    addval = (long long)((freq + nv) / 2.0 * (base_period_ns * 1e-9) * STEPGEN_ONE);
    freq = nv;
    frequency = nv;
}

/* Quadrature outputs for the current phase (type 2). */
static void stepgen_phase_out(struct __comp_state *__comp_inst)
{
    unsigned ph = phase & 3;
    phase_A = ph == 1 || ph == 2;
    phase_B = ph >= 2;
}

/* Start one step toward `want` (+1/-1) if the timing allows. */
static void stepgen_try_step(struct __comp_state *__comp_inst, int want)
{
    int type = personality & 0xff;
    if (pulse_on || space_left > 0) return;
    if (want != out_dir && type != 2) {
        if (hold_left > 0) return;
        out_dir = want;
        if (type == 0) dir = want < 0;
        setup_left = stepgen_periods(type == 0 ? &dirsetup : &dirdelay);
        return;
    }
    if (setup_left > 0) return;
    out_dir = want;
    rawcounts = rawcounts + want;
    len_left = stepgen_periods(&steplen);
    if (type == 2) {
        phase += want;
        stepgen_phase_out(__comp_inst);
        space_left = len_left;
        return;
    }
    pulse_on = 1;
    if (type == 0) step = 1;
    else if (want > 0) up = 1;
    else down = 1;
}

/* End a running step pulse when its length is over. */
static void stepgen_pulse_timers(struct __comp_state *__comp_inst)
{
    int type = personality & 0xff;
    if (space_left > 0) space_left--;
    if (setup_left > 0) setup_left--;
    if (hold_left > 0) hold_left--;
    if (!pulse_on) return;
    if (--len_left > 0) return;
    pulse_on = 0;
    if (type == 0) step = 0;
    else {
        up = 0;
        down = 0;
    }
    space_left = stepgen_periods(&stepspace);
    hold_left = type == 0 ? stepgen_periods(&dirhold) : 0;
}

/* Base-rate part of one channel: advance the accumulator and emit steps. */
static void stepgen_pulses_one(struct __comp_state *__comp_inst, long period)
{
    long long target;
    base_period_ns = period;
    if ((personality & 0xff) != 2) stepgen_pulse_timers(__comp_inst);
    else if (space_left > 0) space_left--;
    if (!enable) return;
    accum += addval;
    target = (accum + (1LL << 31)) >> 32;
    if (target > rawcounts) stepgen_try_step(__comp_inst, 1);
    else if (target < rawcounts) stepgen_try_step(__comp_inst, -1);
}

/* Publish counts and position of one channel. */
static void stepgen_capture_one(struct __comp_state *__comp_inst)
{
    double scale = position_scale;
    if (scale > -1e-20 && scale < 1e-20) scale = 1.0;
    counts = rawcounts;
    position_fb = accum / STEPGEN_ONE / scale;
}

/* Funct stepgen.update-freq: all channels. */
static void stepgen_update_freq(void *arg, long period)
{
    (void)arg;
    FOR_ALL_INSTS() stepgen_freq_one(__comp_inst, period);
}

/* Funct stepgen.make-pulses: all channels. */
static void stepgen_make_pulses(void *arg, long period)
{
    (void)arg;
    FOR_ALL_INSTS() stepgen_pulses_one(__comp_inst, period);
}

/* Funct stepgen.capture-position: all channels. */
static void stepgen_capture_position(void *arg, long period)
{
    (void)arg;
    (void)period;
    FOR_ALL_INSTS() stepgen_capture_one(__comp_inst);
}

/* Personality of channel i from step_type and ctrl_type, or -1 after an error. */
static int stepgen_personality(int i)
{
    int v = 0;
    if (step_type[i] < 0 || step_type[i] > 2) {
        rtapi_print_msg(RTAPI_MSG_ERR, "STEPGEN: ERROR: bad stepping type '%d', axis %d\n",
                        step_type[i], i);
        return -1;
    }
    if (ctrl_type[i] && ctrl_type[i][0]) {
        if ((ctrl_type[i][0] == 'v' || ctrl_type[i][0] == 'V') && !ctrl_type[i][1]) v = 0x100;
        else if ((ctrl_type[i][0] != 'p' && ctrl_type[i][0] != 'P') || ctrl_type[i][1]) {
            rtapi_print_msg(RTAPI_MSG_ERR, "STEPGEN: ERROR: bad control type '%s' for axis %d "
                            "(must be 'p' or 'v')\n", ctrl_type[i], i);
            return -1;
        }
    }
    return step_type[i] | v;
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
