component conv_float_s64 "Convert a value from float to s64";
pin in float in;
pin out s64 out;
pin out bit out_of_range "TRUE when in is outside the range of s64";
param rw bit clamp "When TRUE, out saturates at the limits of s64; else it is a C cast";
function _;
license "GPL";
author "OpenEMC";
;;
double v = in;
int inside = v >= -9223372036854775808.0 && v < 9223372036854775808.0;  /* FALSE for NaN too: every comparison fails */
if (inside) {
    out = (int64_t)v;
    out_of_range = clamp ? 0 : (double)(int64_t)v != v;
} else if (clamp) {
    out = v >= 9223372036854775808.0 ? 9223372036854775807LL : (-9223372036854775807LL - 1);
    out_of_range = 1;
} else {
    out = (-9223372036854775807LL - 1);  /* what x86 gives for an unrepresentable value */
    out_of_range = 1;
}
