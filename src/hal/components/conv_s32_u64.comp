component conv_s32_u64 "Convert a value from s32 to u64";
pin in s32 in;
pin out u64 out;
pin out bit out_of_range "TRUE when in is outside the range of u64";
param rw bit clamp "When TRUE, out saturates at the limits of u64; else it is a C cast";
function _;
license "GPL";
author "OpenEMC";
;;
int32_t v = in;
if (clamp) {
    if (v < 0LL) {
        out = 0LL;
        out_of_range = 1;
    } else {
        out = (uint64_t)v;
        out_of_range = 0;
    }
} else {
    uint64_t o = (uint64_t)v;
    out = o;
    out_of_range = (int32_t)o != v;
}
