component conv_u64_bit "Convert a value from u64 to bit";
pin in u64 in;
pin out bit out;
pin out bit out_of_range "TRUE when in is outside the range of bit";
param rw bit clamp "When TRUE, out saturates at the limits of bit; else it is a C cast";
function _;
license "GPL";
author "OpenEMC";
;;
uint64_t v = in;
if (clamp) {
    if (v > 1LL) {
        out = 1;
        out_of_range = 1;
    } else {
        out = (hal_bit_t)v;
        out_of_range = 0;
    }
} else {
    hal_bit_t o = (hal_bit_t)v;
    out = o;
    out_of_range = (uint64_t)o != v;
}
