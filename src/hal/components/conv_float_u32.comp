component conv_float_u32 "Convert a value from float to u32";
pin in float in;
pin out u32 out;
pin out bit out_of_range "TRUE when in is outside the range of u32";
param rw bit clamp "When TRUE, out saturates at the limits of u32; else it is a C cast";
function _;
license "GPL";
author "OpenEMC";
;;
double v = in;
int inside = v >= 0.0 && v < 4294967296.0;  /* FALSE for NaN too: every comparison fails */
if (inside) {
    out = (uint32_t)v;
    out_of_range = clamp ? 0 : (double)(uint32_t)v != v;
} else if (clamp) {
    out = v >= 4294967296.0 ? 4294967295LL : 0LL;
    out_of_range = 1;
} else {
    out = (v < 0.0 && v > -9223372036854775808.0) ? (uint32_t)(int64_t)v : 0;  /* negative values wrap */
    out_of_range = 1;
}
