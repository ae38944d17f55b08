component conv_bit_s64 "Convert a value from bit to s64";
pin in bit in;
pin out s64 out;
function _;
license "GPL";
author "OpenEMC";
;;
out = (int64_t)in;
