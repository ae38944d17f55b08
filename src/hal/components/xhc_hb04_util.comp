component xhc_hb04_util "Helper logic for the xhc-hb04 pendant: start/pause button, jog count filters, divider";
pin in bit start_or_pause "The pendant's start/pause button";
pin in bit is_paused "Connect to halui.program.is-paused";
pin in bit is_idle "Connect to halui.program.is-idle";
pin in bit is_running "Connect to halui.program.is-running";
pin out bit pause "Connect to halui.program.pause";
pin out bit resume "Connect to halui.program.resume";
pin out bit run "Connect to halui.program.run";
pin in s32 in#[4] "Raw jog counts of channel N";
pin in float scale#[4] = 1.0 "Multiplier applied to the filtered value of channel N";
pin in float coef#[4] = 1.0 "Filter coefficient of channel N (|coefN|, at most 1; 1 = no filtering)";
pin out s32 out#[4] "Filtered, scaled counts of channel N";
pin in float divide_by_k_in "Dividend";
pin out float divide_by_k_out "divide-by-k-in / k (1e99 when k is 0)";
pin in float k = 1.0 "Divisor";
variable double value[4];
variable int old_button;
function _ "Update the divider, the four filters and the button logic";
include <rtapi_math.h>;
license "GPL";
author "OpenEMC";
description """Glue logic for configurations using the xhc-hb04 wireless pendant, as LinuxCNC's.

Divider: divide-by-k-out is divide-by-k-in / k, or 1e99 when k is 0.

Filters: four independent channels. Each period the channel's value moves toward
inN by the fraction |coefN| (at most 1) of the remaining distance, and outN is
value * scaleN rounded to the nearest integer, halves down. With the default
coef 1.0 and scale 1.0, outN equals inN.

Start/pause button: only when start-or-pause changes. Released: pause, run and
resume go FALSE. Pressed: a paused program asks resume, a running one pause, an
idle one run (one output TRUE, the others FALSE; if several status inputs are
TRUE the last of paused, running, idle wins); with no status input TRUE the
outputs keep their values.""";
;;
#define XHC_CHANNELS 4

/* The one output that is TRUE; the others go FALSE. */
static void button_set(struct __comp_state *__comp_inst, int p, int r, int u)
{
    pause = p;
    resume = r;
    run = u;
}

/* React to a change of the start/pause button. */
static void button_logic(struct __comp_state *__comp_inst)
{
    int pressed = start_or_pause;
    if (pressed == old_button)
        return;
    old_button = pressed;
    if (!pressed) {
        button_set(__comp_inst, 0, 0, 0);
        return;
    }
    if (is_paused) button_set(__comp_inst, 0, 1, 0);
    if (is_running) button_set(__comp_inst, 1, 0, 0);
    if (is_idle) button_set(__comp_inst, 0, 0, 1);
}

/* ceil(v - 0.5) (halves down), saturating at the s32 range; NaN gives 0. */
static int round_half_down_s32(double v)
{
    if (v != v) return 0;
    v = ceil(v - 0.5);
    if (v >= 2147483647.0) return 2147483647;
    if (v <= -2147483648.0) return -2147483647 - 1;
    return (int)v;
}

/* Move each channel toward its input by |coef| and publish it scaled. */
static void filters(struct __comp_state *__comp_inst)
{
    int i;
    for (i = 0; i < XHC_CHANNELS; i++) {
        double c = fabs(coef(i));
        if (c > 1.0) c = 1.0;
        double step = c * (in(i) - value[i]);
        if (step - step == 0.0)  /* a NaN coefficient leaves the value where it is */
            value[i] += step;
        out(i) = round_half_down_s32(value[i] * scale(i));
    }
}

FUNCTION(_)
{
    divide_by_k_out = k == 0.0 ? 1e99 : divide_by_k_in / k;
    filters(__comp_inst);
    button_logic(__comp_inst);
}
