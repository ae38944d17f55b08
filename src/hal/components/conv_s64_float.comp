component conv_s64_float "Convert a value from s64 to float";
pin in s64 in;
pin out float out;
function _;
license "GPL";
author "OpenEMC";
;;
out = (double)in;
