component conv_u64_float "Convert a value from u64 to float";
pin in u64 in;
pin out float out;
function _;
license "GPL";
author "OpenEMC";
;;
out = (double)in;
