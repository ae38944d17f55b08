component gray2bin "Convert a Gray code to a binary number";
pin in u32 in "Gray code";
pin out u32 out "Binary value of in";
function _;
license "GPL";
author "OpenEMC";
;;
hal_u32_t v = in, m = v >> 1;
while (m) {
    v ^= m;
    m >>= 1;
}
out = v;
