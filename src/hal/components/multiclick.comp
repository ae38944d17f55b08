component multiclick "Detect single, double, triple and quadruple clicks of a button";
pin in bit in "The button input";
pin out bit single_click "Pulses when the first click is released";
pin out bit single_click_only "Pulses when exactly one click was seen";
pin out bit double_click "Pulses when the second click is released";
pin out bit double_click_only "Pulses when exactly two clicks were seen";
pin out bit triple_click "Pulses when the third click is released";
pin out bit triple_click_only "Pulses when exactly three clicks were seen";
pin out bit quadruple_click "Pulses when the fourth click is released";
pin out bit quadruple_click_only "Pulses when exactly four clicks were seen";
pin out s32 state "0 idle, 1/3/5/7 button down for click 1..4, 2/4/6/8 released after click 1..4, 9 held too long";
param rw bit invert_input "When TRUE, a FALSE input means pressed";
param rw u32 max_hold_ns = 250000000 "Longest press that still counts as a click";
param rw u32 max_space_ns = 250000000 "Longest release between clicks of one pattern";
param rw u32 output_hold_ns = 100000000 "How long each output pulse stays TRUE";
variable long long timer_ns;
variable long long pulse_ns[8] = -1;
variable int st;
function _;
license "GPL";
author "OpenEMC";
;;
int pressed = invert_input ? !in : in;
int i, fire = -1;
if (st == 0) {
    if (pressed) { st = 1; timer_ns = 0; }
} else if (st == 9) {
    if (!pressed) st = 0;
} else if (st & 1) {
    if (!pressed) {
        fire = st - 1;
        st = st == 7 ? 8 : st + 1;
        timer_ns = 0;
    } else {
        timer_ns += period;
        if (timer_ns > (long long)max_hold_ns) st = 9;
    }
} else {
    if (pressed) {
        st = st == 8 ? 9 : st + 1;
        timer_ns = 0;
    } else {
        timer_ns += period;
        if (timer_ns > (long long)max_space_ns) {
            fire = st - 1;
            st = 0;
        }
    }
}
for (i = 0; i < 8; i++) {
    if (i == fire) pulse_ns[i] = 0;
    else if (pulse_ns[i] >= 0) {
        pulse_ns[i] += period;
        if (pulse_ns[i] > (long long)output_hold_ns) pulse_ns[i] = -1;
    }
}
single_click = pulse_ns[0] >= 0;
single_click_only = pulse_ns[1] >= 0;
double_click = pulse_ns[2] >= 0;
double_click_only = pulse_ns[3] >= 0;
triple_click = pulse_ns[4] >= 0;
triple_click_only = pulse_ns[5] >= 0;
quadruple_click = pulse_ns[6] >= 0;
quadruple_click_only = pulse_ns[7] >= 0;
state = st;
