component pid "Proportional/integral/derivative controller with feed-forward and relay autotuning";
pin in float command "Commanded value";
pin in float command_deriv "Derivative of command; computed here while unlinked";
pin in float feedback "Actual value";
pin in float feedback_deriv "Derivative of feedback; computed here while unlinked";
pin in float Pgain = 1.0 "Proportional gain";
pin in float Igain "Integral gain";
pin in float Dgain "Derivative gain";
pin in float bias "Constant added to the output";
pin in float FF0 "Zeroth-order feed-forward (command)";
pin in float FF1 "First-order feed-forward (command velocity)";
pin in float FF2 "Second-order feed-forward (command acceleration)";
pin in float FF3 "Third-order feed-forward (command jerk)";
pin in float deadband "Errors smaller than this are ignored";
pin in float maxerror "Limit on the error (0 = none)";
pin in float maxerrorI "Limit on the error integral (0 = none)";
pin in float maxerrorD "Limit on the error derivative (0 = none)";
pin in float maxcmdD "Limit on the command derivative (0 = none)";
pin in float maxcmdDD "Limit on the command second derivative (0 = none)";
pin in float maxcmdDDD "Limit on the command third derivative (0 = none)";
pin in float maxoutput "Limit on the output magnitude (0 = none)";
pin in bit enable "When FALSE, output is zero and the integrator is cleared";
pin in bit index_enable "Connect to the encoder's index-enable so its reset does not cause a jump";
pin in bit error_previous_target = TRUE "Use the previous command to compute the error";
pin out float error "command - feedback as used by the loop";
pin out float output "Controller output";
pin out float saturated_s "Seconds the output has been saturated";
pin out bit saturated "TRUE while the output is at maxoutput";
pin out s32 saturated_count "Periods the output has been saturated";
pin in bit tune_mode "TRUE selects relay autotuning instead of PID control";
pin io bit tune_start "Set TRUE to start autotuning; cleared when done";
pin io u32 tune_type = 0 "0: tune P, I, D; 1: tune P, I, FF1";
pin io u32 tune_cycles = 50 "Relay cycles to average";
pin io float tune_effort = 0.5 "Relay output amplitude";
pin out float errorI if personality "Integral of the error";
pin out float errorD if personality "Derivative of the error";
pin out float commandD if personality "Command derivative";
pin out float commandDD if personality "Command second derivative";
pin out float commandDDD if personality "Command third derivative";
pin out float ultimate_gain if personality "Ultimate gain found by autotuning";
pin out float ultimate_period if personality "Ultimate period found by autotuning";
variable double prev_cmd;
variable double prev_fb;
variable double prev_err;
variable double cmd_d;
variable double cmd_dd;
variable double err_i;
variable double err_d;
variable double cmd_ddd;
variable int prev_ie;
variable void *cd_dummy;
variable void *fd_dummy;
variable double ku;
variable double tu;
variable int tune_state;
variable int tune_count;
variable double tune_time;
variable double tune_max;
variable double tune_min;
option rtapi_app no;
include "comp_args.h";
option post_export yes;
function do_pid_calcs "Run one controller step";
include <rtapi_math.h>;
license "GPL";
author "OpenEMC";
description """Load with num_chan=N (at most 16, default 3) or names=a,b,... and optionally debug=1
for the extra diagnostic pins. Instances are pid.N with funct pid.N.do-pid-calcs.""";
;;
#define PID_MAX_CHAN 16
static int num_chan = 0;
RTAPI_MP_INT(num_chan, "number of channels");
static int debug = 0;
RTAPI_MP_INT(debug, "1 adds the diagnostic pins");
static char *names[PID_MAX_CHAN];
RTAPI_MP_ARRAY_STRING(names, PID_MAX_CHAN, "names of the channels");

/* Remember the unlinked addresses of the derivative pins. */
POST_EXPORT()
{
    cd_dummy = (void *)command_deriv_ptr;
    fd_dummy = (void *)feedback_deriv_ptr;
    return 0;
}

/* Clamp v to +/-lim when lim is positive. */
static double pid_limit(double v, double lim)
{
    if (lim > 0 && v > lim) return lim;
    if (lim > 0 && v < -lim) return -lim;
    return v;
}

/* Derivative of the command and its higher orders, each clipped. */
static void pid_command_derivs(struct __comp_state *__comp_inst, double cmd, double dt, int fresh)
{
    double d, dd;
    if ((void *)command_deriv_ptr == cd_dummy) {
        d = fresh ? 0.0 : (cmd - prev_cmd) / dt;
        *command_deriv_ptr = d;
    } else {
        d = command_deriv;
    }
    d = pid_limit(d, maxcmdD);
    dd = pid_limit((d - cmd_d) / dt, maxcmdDD);
    cmd_ddd = pid_limit((dd - cmd_dd) / dt, maxcmdDDD);
    cmd_dd = dd;
    cmd_d = d;
}

/* Relay autotuning: drive +/-effort by the sign of the error and time the oscillation. */
static void pid_tune(struct __comp_state *__comp_inst, double e, double dt)
{
    double fb = feedback, eff = tune_effort;
    if (!tune_start) {
        tune_state = 0;
        output = bias;
        return;
    }
    if (tune_state == 0) {
        tune_state = e >= 0 ? 1 : 2;
        tune_count = 0;
        tune_time = 0;
        tune_max = fb;
        tune_min = fb;
    }
    tune_time += dt;
    if (fb > tune_max) tune_max = fb;
    if (fb < tune_min) tune_min = fb;
    if (tune_state == 1 && e < 0) tune_state = 2;
    else if (tune_state == 2 && e >= 0) {
        tune_state = 1;
        tune_count++;
    }
    output = bias + (tune_state == 1 ? eff : -eff);
    if (tune_count >= (int)tune_cycles && tune_count > 0 && tune_max > tune_min) {
        tu = tune_time / tune_count;
        ku = 4.0 * eff / (3.1415926535897932 * (tune_max - tune_min) / 2.0);
        *Pgain_ptr = (tune_type == 0 ? 0.6 : 0.45) * ku;
        *Igain_ptr = (tune_type == 0 ? 1.2 : 0.54) * ku / tu;
        if (tune_type == 0) *Dgain_ptr = 0.075 * ku * tu;
        tune_start = 0;
        tune_state = 0;
    }
}

/* Sum of the controller terms, with integrator anti-windup and output limit. */
static void pid_control(struct __comp_state *__comp_inst, double e, double cmd, double dt)
{
    double out;
    if (!(saturated && ((output > 0 && e > 0) || (output < 0 && e < 0)))) {
        err_i = pid_limit(err_i + e * dt, maxerrorI);
    }
    err_d = pid_limit((e - prev_err) / dt, maxerrorD);
    out = bias + Pgain * e + Igain * err_i + Dgain * err_d + FF0 * cmd + FF1 * cmd_d +
          FF2 * cmd_dd + FF3 * cmd_ddd;
    if (maxoutput > 0 && (out > maxoutput || out < -maxoutput)) {
        out = pid_limit(out, maxoutput);
        saturated = 1;
        saturated_s = saturated_s + dt;
        if (saturated_count < 2147483647) saturated_count = saturated_count + 1;
    } else {
        saturated = 0;
        saturated_s = 0;
        saturated_count = 0;
    }
    output = out;
}

/* Copy internal values to the debug pins. */
static void pid_debug_out(struct __comp_state *__comp_inst)
{
    if (!personality) return;
    errorI = err_i;
    errorD = err_d;
    commandD = cmd_d;
    commandDD = cmd_dd;
    commandDDD = cmd_ddd;
    ultimate_gain = ku;
    ultimate_period = tu;
}

/* One controller step: error, derivatives, then PID output or autotuning. */
FUNCTION(do_pid_calcs)
{
    double dt = fperiod, cmd = command, fb = feedback, e;
    int ie = index_enable, fresh = prev_ie && !ie;
    e = (error_previous_target && !fresh ? prev_cmd : cmd) - fb;
    error = e;
    e = pid_limit(e, maxerror);
    if (e > deadband) e -= deadband;
    else if (e < -deadband) e += deadband;
    else e = 0;
    pid_command_derivs(__comp_inst, cmd, dt, fresh);
    if ((void *)feedback_deriv_ptr == fd_dummy) *feedback_deriv_ptr = fresh ? 0.0 : (fb - prev_fb) / dt;
    if (!enable) {
        err_i = 0;
        err_d = 0;
        output = 0;
        saturated = 0;
    } else if (tune_mode) {
        pid_tune(__comp_inst, e, dt);
    } else {
        pid_control(__comp_inst, e, cmd, dt);
    }
    prev_err = e;
    prev_cmd = cmd;
    prev_fb = fb;
    prev_ie = ie;
    pid_debug_out(__comp_inst);
}

/* Create num_chan (or one per name) controllers. */
int rtapi_app_main(void)
{
    static const comp_chan_spec_t spec = { "PID", "pid", PID_MAX_CHAN, 3 };
    int i, r = 0, n = comp_chan_count(&spec, num_chan, names);
    char buf[HAL_NAME_LEN + 1];
    if (n < 0)
        return n;
    comp_id = hal_init("pid");
    if (comp_id < 0) return comp_id;
    for (i = 0; i < n && r == 0; i++) {
        comp_chan_name(&spec, names, i, buf, sizeof(buf));
        r = export(buf, i, debug ? 1 : 0);
    }
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
