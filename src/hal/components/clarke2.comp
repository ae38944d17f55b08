component clarke2 "Two-input Clarke transform (three-phase to two-axis, assuming a + b + c = 0)";
pin in float a "Phase A";
pin in float b "Phase B";
pin out float x "a";
pin out float y "(a + 2b) / sqrt(3)";
function _;
license "GPL";
author "OpenEMC";
;;
#define CLARKE_1_SQRT3 0.577350269189626
#define CLARKE_2_SQRT3 1.154700538379250
(void)period;
x = a;
y = a * CLARKE_1_SQRT3 + b * CLARKE_2_SQRT3;
