component conv_bit_u32 "Convert a value from bit to u32";
pin in bit in;
pin out u32 out;
function _;
license "GPL";
author "OpenEMC";
;;
out = (uint32_t)in;
