component edge "Detect rising and/or falling edges";
pin in bit in;
pin out bit out "Goes high on the selected edge and stays high for out-width-ns (at least one period)";
pin out bit out_invert "Opposite of out";
param rw bit both = FALSE "When TRUE, both edges are detected";
param rw bit in_edge = TRUE "FALSE: rising edge, TRUE: falling edge (when both is FALSE)";
param rw s32 out_width_ns = 0 "Pulse width in ns";
param r s32 time_left_ns "Time left in the current pulse";
param r bit last_in "Input value of the previous cycle";
variable int first = 1;
function _;
license "GPL";
author "OpenEMC";
;;
int now = in;
if (first) {
    first = 0;
    out = 0;
} else {
    int rise = now && !last_in, fall = !now && last_in;
    if ((both && (rise || fall)) || (!both && in_edge && fall) || (!both && !in_edge && rise)) {
        time_left_ns = out_width_ns;
        out = 1;
    } else if (time_left_ns > 0) {
        time_left_ns -= period;
        if (time_left_ns > 0) {
            out = 1;
        } else {
            time_left_ns = 0;
            out = 0;
        }
    } else {
        time_left_ns = 0;
        out = 0;
    }
}
last_in = now;
out_invert = !out;
