component conv_u32_float "Convert a value from u32 to float";
pin in u32 in;
pin out float out;
function _;
license "GPL";
author "OpenEMC";
;;
out = (double)in;
