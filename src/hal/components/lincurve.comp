component lincurve "Piecewise-linear function of one input";
pin in float in "Input value";
pin out float out "Interpolated output";
pin io float out_io "Same value as out, on an IO pin";
param rw float x-val-##[16 : personality] "Breakpoint x values, in increasing order";
param rw float y-val-##[16 : personality] "Output at each breakpoint";
option default_personality 4;
function _;
license "GPL";
author "OpenEMC";
description "personality sets the number of breakpoints (2 to 16, default 4). Beyond the ends the output stays flat.";
;;
int i, n = personality;
double x = in, y;
if (n < 2) n = 2;
if (x <= x_val(0)) {
    y = y_val(0);
} else if (x >= x_val(n - 1)) {
    y = y_val(n - 1);
} else {
    for (i = 1; i < n - 1 && x >= x_val(i); i++) { }
    if (x_val(i) == x_val(i - 1)) y = y_val(i);
    else y = y_val(i - 1) + (x - x_val(i - 1)) * (y_val(i) - y_val(i - 1)) / (x_val(i) - x_val(i - 1));
}
out = y;
out_io = y;
