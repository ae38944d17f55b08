component constant "Drive a constant float value";
pin out float out "Always equal to value";
param rw float value;
function _;
license "GPL";
author "OpenEMC";
;;
out = value;
