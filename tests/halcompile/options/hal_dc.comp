component hal_dc "default_count and the hal_ prefix";
pin in bit in;
pin out bit out;
option default_count 3;
option period no;
function _;
license "GPL";
;;
out = !in;
