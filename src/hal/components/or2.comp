component or2 "Two-input OR gate";
pin in bit in0;
pin in bit in1;
pin out bit out;
function _ "Compute out from in0 and in1";
license "GPL";
author "OpenEMC";
;;
out = in0 || in1;
