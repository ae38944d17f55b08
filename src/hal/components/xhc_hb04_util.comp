component xhc_hb04_util "Helper logic for the xhc-hb04 pendant: start/pause button, jog count filters, accel mux";
pin in bit start_or_pause "The pendant's start/pause button";
pin in bit is_paused "Connect to halui.program.is-paused";
pin in bit is_idle "Connect to halui.program.is-idle";
pin in bit is_running "Connect to halui.program.is-running";
pin out bit pause "Connect to halui.program.pause; TRUE while the button that paused a running program is held";
pin out bit resume "Connect to halui.program.resume; TRUE while the button that resumed a paused program is held";
pin out bit run "Connect to halui.program.run; TRUE while the button that started an idle program is held";
pin in s32 in#[4] "Raw jog counts of channel N";
pin in float scale#[4] = 1.0 "Multiplier applied to inN before filtering";
pin in float coef#[4] = 1.0 "Filter coefficient of channel N, 0 to 1 (1 = no filtering, smaller = slower)";
pin out s32 out#[4] "Filtered, scaled counts of channel N (rounded to the nearest integer)";
pin in bit jogenable_off "TRUE when the pendant's axis selector is in its OFF position";
pin in bit amux_enable#[4] "TRUE when channel N is the selected axis";
pin in float amux_in#[4] "Value offered for channel N (for example a jog acceleration fraction)";
pin out float amux_out "amux-inN of the lowest selected channel N; 0 when none is selected or the selector is OFF";
variable double acc[4];
variable int old_button;
function _ "Update the button logic, the four filters and the mux";
license "GPL";
author "OpenEMC";
description """Glue logic for configurations using the xhc-hb04 wireless pendant.

Start/pause button: on the rising edge of start-or-pause the program state
decides the action: a paused program is resumed (resume), else an idle program is
started (run), else a running program is paused (pause). The chosen output
stays TRUE until the button is released, so that a polling user interface such as halui
sees it; all three outputs are FALSE while the button is up.

Filters: four independent channels. Each period the channel's internal value moves
toward scaleN*inN by the fraction coefN (clamped to 0..1) of the remaining
distance, and outN is that value rounded to the nearest integer. With the default
coef 1.0 and scale 1.0, outN equals inN.

Accel mux: amux-out copies amux-inN of the lowest-numbered channel whose
amux-enableN is TRUE, or is 0 when none is selected or jogenable-off is TRUE.""";
;;
#define XHC_CHANNELS 4

/* Decide which halui request the button asks for, holding it while the button is down. */
static void button_logic(struct __comp_state *__comp_inst)
{
    int pressed = start_or_pause;
    if (!pressed) {
        pause = 0;
        resume = 0;
        run = 0;
    } else if (!old_button) {
        if (is_paused) resume = 1;
        else if (is_idle) run = 1;
        else if (is_running) pause = 1;
    }
    old_button = pressed;
}

/* Round to the nearest integer, halves away from zero, saturating at the s32 range. */
static int round_s32(double v)
{
    if (v != v) return 0;
    if (v >= 2147483647.0) return 2147483647;
    if (v <= -2147483648.0) return -2147483647 - 1;
    return (int)(v >= 0 ? v + 0.5 : v - 0.5);
}

/* Move each channel toward its scaled input by its coefficient and publish it. */
static void filters(struct __comp_state *__comp_inst)
{
    int i;
    for (i = 0; i < XHC_CHANNELS; i++) {
        double c = coef(i);
        if (c < 0.0) c = 0.0;
        if (c > 1.0) c = 1.0;
        double target = scale(i) * in(i);
        if (target - target == 0.0)  /* NaN or inf scale/input leaves the filter where it is */
            acc[i] += c * (target - acc[i]);
        out(i) = round_s32(acc[i]);
    }
}

/* Select the value of the lowest enabled channel. */
static void accel_mux(struct __comp_state *__comp_inst)
{
    int i;
    double v = 0.0;
    for (i = XHC_CHANNELS - 1; i >= 0; i--)
        if (amux_enable(i)) v = amux_in(i);
    amux_out = jogenable_off ? 0.0 : v;
}

/* One period: button, filters, mux. */
FUNCTION(_)
{
    button_logic(__comp_inst);
    filters(__comp_inst);
    accel_mux(__comp_inst);
}
