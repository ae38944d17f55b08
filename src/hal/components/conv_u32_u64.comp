component conv_u32_u64 "Convert a value from u32 to u64";
pin in u32 in;
pin out u64 out;
function _;
license "GPL";
author "OpenEMC";
;;
out = (uint64_t)in;
