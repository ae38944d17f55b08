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
if (clamp) {
    if (v > 1.8446744073709552e+19) {
        out = 18446744073709551615ULL;
        out_of_range = 1;
    } else if (v < 0.0) {
        out = 0LL;
        out_of_range = 1;
    } else {
        out = (uint64_t)v;
        out_of_range = 0;
    }
} else {
    uint64_t o = (uint64_t)v;
    out = o;
    out_of_range = (double)o != v;
}
