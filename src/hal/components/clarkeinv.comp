component clarkeinv "Inverse Clarke transform (two-axis plus homopolar to three-phase), with rotation";
pin in float x "X axis";
pin in float y "Y axis";
pin in float h "Homopolar component";
pin in float theta "Rotation of x and y before the transform, revolutions";
pin out float a "Phase A";
pin out float b "Phase B";
pin out float c "Phase C";
function _;
include <rtapi_math.h>;
license "GPL";
author "OpenEMC";
;;
#define CLARKE_SQRT3_2 0.866025403784439
#define CLARKE_1_SQRT2 0.707106781186547
#define CLARKE_TWO_PI 6.283185308
double th = theta * CLARKE_TWO_PI, s = sin(th), co = cos(th);
double xr = x * co - y * s, yr = x * s + y * co;
(void)period;
a = xr + CLARKE_1_SQRT2 * h;
b = -0.5 * xr + CLARKE_SQRT3_2 * yr + CLARKE_1_SQRT2 * h;
c = -0.5 * xr - CLARKE_SQRT3_2 * yr + CLARKE_1_SQRT2 * h;
