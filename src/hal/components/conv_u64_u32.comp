component conv_u64_u32 "Convert a value from u64 to u32";
pin in u64 in;
pin out u32 out;
pin out bit out_of_range "TRUE when in is outside the range of u32";
param rw bit clamp "When TRUE, out saturates at the limits of u32; else it is a C cast";
function _;
license "GPL";
author "OpenEMC";
;;
uint64_t v = in;
if (clamp) {
    if (v > 4294967295LL) {
        out = 4294967295LL;
        out_of_range = 1;
    } else {
        out = (uint32_t)v;
        out_of_range = 0;
    }
} else {
    uint32_t o = (uint32_t)v;
    out = o;
    out_of_range = (uint64_t)o != v;
}
