component conv_bit_s32 "Convert a value from bit to s32";
pin in bit in;
pin out s32 out;
function _;
license "GPL";
author "OpenEMC";
;;
out = (int32_t)in;
