component conv_bit_float "Convert a value from bit to float";
pin in bit in;
pin out float out;
function _;
license "GPL";
author "OpenEMC";
;;
out = (double)in;
