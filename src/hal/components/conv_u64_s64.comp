component conv_u64_s64 "Convert a value from u64 to s64";
pin in u64 in;
pin out s64 out;
pin out bit out_of_range "TRUE when in is outside the range of s64";
param rw bit clamp "When TRUE, out saturates at the limits of s64; else it is a C cast";
function _;
license "GPL";
author "OpenEMC";
;;
uint64_t v = in;
if (clamp) {
    if (v > 9223372036854775807LL) {
        out = 9223372036854775807LL;
        out_of_range = 1;
    } else {
        out = (int64_t)v;
        out_of_range = 0;
    }
} else {
    int64_t o = (int64_t)v;
    out = o;
    out_of_range = (uint64_t)o != v;
}
