component tristate_float "Drive a float signal only while enabled";
pin in float in "Value driven onto out";
pin io float out "Driven with in while enable is TRUE";
pin in bit enable "When TRUE, out follows in";
function _;
license "GPL";
author "OpenEMC";
;;
if (enable) out = in;
