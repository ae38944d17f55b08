component clarke3 "Three-input Clarke transform (three-phase to two-axis plus homopolar)";
pin in float a "Phase A";
pin in float b "Phase B";
pin in float c "Phase C";
pin out float x "(2/3)a - (1/3)(b + c)";
pin out float y "(b - c) / sqrt(3)";
pin out float h "(sqrt(2)/3)(a + b + c), the homopolar component";
function _;
license "GPL";
author "OpenEMC";
;;
#define CLARKE_2_3 0.666666666666667
#define CLARKE_1_3 0.333333333333333
#define CLARKE_1_SQRT3 0.577350269189626
#define CLARKE_SQRT2_3 0.471404520791032
(void)period;
x = CLARKE_2_3 * a - CLARKE_1_3 * (b + c);
y = CLARKE_1_SQRT3 * (b - c);
h = CLARKE_SQRT2_3 * (a + b + c);
