component conv_s32_u32 "Convert a value from s32 to u32";
pin in s32 in;
pin out u32 out;
pin out bit out_of_range "TRUE when in is outside the range of u32";
param rw bit clamp "When TRUE, out saturates at the limits of u32; else it is a C cast";
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
        out = (uint32_t)v;
        out_of_range = 0;
    }
} else {
    uint32_t o = (uint32_t)v;
    out = o;
    out_of_range = (int32_t)o != v;
}
