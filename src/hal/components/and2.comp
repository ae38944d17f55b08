component and2 "Two-input AND gate";
pin in bit in0;
pin in bit in1;
pin out bit out "out is TRUE when in0 and in1 are both TRUE";
function _ "Compute out from in0 and in1";
license "GPL";
author "OpenEMC";
;;
out = in0 && in1;
