component limit2 "Clamp a value to a range and limit its rate of change";
pin in float in;
pin out float out;
pin in bit load "When TRUE, out jumps to the (clamped) input";
pin in float min_ = -1e20;
pin in float max_ = 1e20;
pin in float maxv = 1e20 "Largest rate of change, units per second";
variable double old_out;
function _;
license "GPL";
author "OpenEMC";
;;
double v = in, step = maxv * fperiod;
if (v != v) v = old_out;  /* NaN input: hold the last output */
if (v > max_) v = max_;
if (v < min_) v = min_;
if (!load) {
    if (v > old_out + step) v = old_out + step;
    if (v < old_out - step) v = old_out - step;
}
old_out = v;
out = v;
