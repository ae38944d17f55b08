component tristate_bit "Drive a bit signal only while enabled";
pin in bit in "Value driven onto out";
pin io bit out "Driven with in while enable is TRUE";
pin in bit enable "When TRUE, out follows in";
function _;
license "GPL";
author "OpenEMC";
;;
if (enable) out = in;
