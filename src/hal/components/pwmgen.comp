component pwmgen "Software PWM/PDM generator";
pin in bit enable "Outputs are off while FALSE";
pin in float value "Commanded value";
pin io float scale = 1.0 "value / scale is the duty cycle before offset";
pin io float offset = 0.0 "Added to the duty cycle";
pin io float pwm_freq = 0.0 "PWM frequency in Hz; 0 selects PDM";
pin io float min_dc = 0.0 "Smallest duty cycle magnitude";
pin io float max_dc = 1.0 "Largest duty cycle magnitude";
pin io bit dither_pwm "Spread the fraction of a base period over several PWM cycles";
pin out float curr_dc "Duty cycle in use";
pin out bit pwm if personality <= 1 "PWM output (types 0 and 1)";
pin out bit dir if personality == 1 "Direction output (type 1), TRUE for negative values";
pin out bit up if personality == 2 "Output for positive values (type 2)";
pin out bit down if personality == 2 "Output for negative values (type 2)";
variable double duty;
variable double pdm_acc;
variable double dither_acc;
variable long cycle_pos;
variable long cycle_len;
variable long high_len;
option rtapi_app no;
include <rtapi_math.h>;
license "GPL";
author "OpenEMC";
description """Load with output_type=T0,T1,... (at most 8): 0 pwm only, 1 pwm and dir, 2 up/down.
Functs pwmgen.update (servo rate) and pwmgen.make-pulses (base rate).""";
;;
#define PWM_MAX_CHAN 8
#define PWM_MAX_CYCLE 2000000000L
static int output_type[PWM_MAX_CHAN] = { [0 ... PWM_MAX_CHAN - 1] = -1 };
RTAPI_MP_ARRAY_INT(output_type, PWM_MAX_CHAN, "output types of up to 8 channels");

/* Compute the signed duty cycle of one channel. */
static void pwm_update_one(struct __comp_state *__comp_inst)
{
    double sc = scale, d, mag;
    if (sc > -1e-20 && sc < 1e-20) { sc = 1.0; scale = 1.0; }
    d = value / sc + offset;
    if (d != d) d = 0.0;  /* a NaN command is treated as off */
    mag = fabs(d);
    if (mag > max_dc) mag = max_dc;
    if (mag < min_dc) mag = min_dc;
    if (personality == 0 && d < 0) mag = 0;
    if (!enable) mag = 0;
    duty = (d < 0 && mag > 0) ? -mag : mag;
    curr_dc = duty;
}

/* Drive the active output of one channel. */
static void pwm_drive(struct __comp_state *__comp_inst, int on)
{
    if (personality <= 1) pwm = on;
    if (personality == 1) dir = duty < 0;
    if (personality == 2) {
        up = on && duty > 0;
        down = on && duty < 0;
    }
}

/* Base periods in one PWM cycle, at least 1 and at most PWM_MAX_CYCLE. */
static long pwm_cycle_len(double freq, long period)
{
    double n = 1e9 / freq / period + 0.5;
    if (!(n < PWM_MAX_CYCLE)) return PWM_MAX_CYCLE;
    return n < 1.0 ? 1 : (long)n;
}

/* Length of the high part of the next PWM cycle, in base periods. */
static long pwm_high_len(struct __comp_state *__comp_inst, double mag)
{
    double exact = mag * cycle_len;
    long n = (long)exact;
    if (dither_pwm) {
        dither_acc += exact - n;
        if (dither_acc >= 1.0) { dither_acc -= 1.0; n++; }
    } else if (exact - n >= 0.5) {
        n++;
    }
    return n;
}

/* Base-rate output of one channel: PDM when pwm-freq is 0, else fixed-frequency PWM. */
static void pwm_pulse_one(struct __comp_state *__comp_inst, long period)
{
    double mag = fmin(fabs(duty), 1.0);
    if (!enable || !(mag > 0)) { pwm_drive(__comp_inst, 0); cycle_pos = 0; return; }
    if (!(pwm_freq > 0)) {
        pdm_acc += mag;
        if (pdm_acc >= 1.0) { pdm_acc -= 1.0; pwm_drive(__comp_inst, 1); }
        else pwm_drive(__comp_inst, 0);
        return;
    }
    if (cycle_pos == 0) {
        cycle_len = pwm_cycle_len(pwm_freq, period);
        high_len = pwm_high_len(__comp_inst, mag);
    }
    pwm_drive(__comp_inst, cycle_pos < high_len);
    if (++cycle_pos >= cycle_len) cycle_pos = 0;
}

/* Funct pwmgen.update. */
static void pwm_update(void *arg, long period)
{
    (void)arg;
    (void)period;
    FOR_ALL_INSTS() pwm_update_one(__comp_inst);
}

/* Funct pwmgen.make-pulses. */
static void pwm_make_pulses(void *arg, long period)
{
    (void)arg;
    FOR_ALL_INSTS() pwm_pulse_one(__comp_inst, period);
}

/* Create the configured channels. */
int rtapi_app_main(void)
{
    int i, n = 0, r = 0;
    char buf[HAL_NAME_LEN + 1];
    while (n < PWM_MAX_CHAN && output_type[n] != -1) n++;
    if (n == 0) {
        rtapi_print_msg(RTAPI_MSG_ERR, "PWMGEN: ERROR: no channels configured\n");
        return -EINVAL;
    }
    for (i = 0; i < n; i++) {
        if (output_type[i] < 0 || output_type[i] > 2) {
            rtapi_print_msg(RTAPI_MSG_ERR, "PWMGEN: ERROR: bad output type '%d', channel %d\n",
                            output_type[i], i);
            return -EINVAL;
        }
    }
    comp_id = hal_init("pwmgen");
    if (comp_id < 0) return comp_id;
    for (i = 0; i < n && r == 0; i++) {
        rtapi_snprintf(buf, sizeof(buf), "pwmgen.%d", i);
        r = export(buf, i, output_type[i]);
    }
    if (r == 0) r = hal_export_funct("pwmgen.make-pulses", pwm_make_pulses, 0, 0, 0, comp_id);
    if (r == 0) r = hal_export_funct("pwmgen.update", pwm_update, 0, 1, 0, comp_id);
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
