component comp "Two-input comparator with hysteresis";
pin in float in0 "Inverting input";
pin in float in1 "Non-inverting input";
pin out bit out "TRUE when in1 > in0 (with hysteresis)";
pin out bit equal "TRUE when in0 and in1 are within hyst/2";
param rw float hyst = 0.0 "Hysteresis band width";
function _;
license "GPL";
author "OpenEMC";
;;
double tmp = in1 - in0;
double half = hyst / 2.0;
if (half < 0.0) half = -half;
if (tmp < -half) {
    out = 0;
    equal = 0;
} else if (tmp > half) {
    out = 1;
    equal = 0;
} else {
    equal = 1;
}
