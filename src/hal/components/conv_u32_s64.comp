component conv_u32_s64 "Convert a value from u32 to s64";
pin in u32 in;
pin out s64 out;
function _;
license "GPL";
author "OpenEMC";
;;
out = (int64_t)in;
