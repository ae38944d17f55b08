component conv_float_u64 "Convert a value from float to u64";
pin in float in;
pin out u64 out;
pin out bit out_of_range "TRUE when in is outside the range of u64";
param rw bit clamp "When TRUE, out saturates at the limits of u64; else it is a C cast";
function _;
license "GPL";
author "OpenEMC";
;;
double v = in;
int inside = v >= 0.0 && v < 18446744073709551616.0;  /* FALSE for NaN too: every comparison fails */
if (inside) {
    out = (uint64_t)v;
    out_of_range = clamp ? 0 : (double)(uint64_t)v != v;
} else if (clamp) {
    out = v >= 18446744073709551616.0 ? 18446744073709551615ULL : 0LL;
    out_of_range = 1;
} else {
    out = (v < 0.0 && v > -9223372036854775808.0) ? (uint64_t)(int64_t)v : 0;  /* negative values wrap */
    out_of_range = 1;
}
