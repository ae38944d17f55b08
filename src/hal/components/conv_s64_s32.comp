component conv_s64_s32 "Convert a value from s64 to s32";
pin in s64 in;
pin out s32 out;
pin out bit out_of_range "TRUE when in is outside the range of s32";
param rw bit clamp "When TRUE, out saturates at the limits of s32; else it is a C cast";
function _;
license "GPL";
author "OpenEMC";
;;
int64_t v = in;
if (clamp) {
    if (v > 2147483647LL) {
        out = 2147483647LL;
        out_of_range = 1;
    } else if (v < (-2147483648LL)) {
        out = (-2147483648LL);
        out_of_range = 1;
    } else {
        out = (int32_t)v;
        out_of_range = 0;
    }
} else {
    int32_t o = (int32_t)v;
    out = o;
    out_of_range = (int64_t)o != v;
}
