component conv_s32_float "Convert a value from s32 to float";
pin in s32 in;
pin out float out;
function _;
license "GPL";
author "OpenEMC";
;;
out = (double)in;
