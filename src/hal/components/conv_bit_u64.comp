component conv_bit_u64 "Convert a value from bit to u64";
pin in bit in;
pin out u64 out;
function _;
license "GPL";
author "OpenEMC";
;;
out = (uint64_t)in;
