component blend "Weighted mix of two inputs";
pin in float in1;
pin in float in2;
pin in float select "0 gives in2, 1 gives in1";
pin out float out "in1 * select + in2 * (1 - select)";
param rw bit open "When TRUE, select is not clamped to 0..1";
function _;
license "GPL";
author "OpenEMC";
;;
double s = select;
if (!open) {
    if (s < 0) s = 0;
    if (s > 1) s = 1;
}
out = in1 * s + in2 * (1 - s);
