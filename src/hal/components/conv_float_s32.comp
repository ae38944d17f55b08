component conv_float_s32 "Convert a value from float to s32";
pin in float in;
pin out s32 out;
pin out bit out_of_range "TRUE when in is outside the range of s32";
param rw bit clamp "When TRUE, out saturates at the limits of s32; else it is a C cast";
function _;
license "GPL";
author "OpenEMC";
;;
double v = in;
int inside = v >= -2147483648.0 && v < 2147483648.0;  /* FALSE for NaN too: every comparison fails */
if (inside) {
    out = (int32_t)v;
    out_of_range = clamp ? 0 : (double)(int32_t)v != v;
} else if (clamp) {
    out = v >= 2147483648.0 ? 2147483647LL : (-2147483648LL);
    out_of_range = 1;
} else {
    out = (-2147483648LL);  /* what x86 gives for an unrepresentable value */
    out_of_range = 1;
}
