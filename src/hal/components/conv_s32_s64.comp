component conv_s32_s64 "Convert a value from s32 to s64";
pin in s32 in;
pin out s64 out;
function _;
license "GPL";
author "OpenEMC";
;;
out = (int64_t)in;
