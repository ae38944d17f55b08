component near "Tell whether two values are nearly equal";
pin in float in1;
pin in float in2;
pin out bit out "TRUE when in1 and in2 are near each other";
param rw float scale = 1 "Values are near when the larger is at most scale times the smaller (same sign)";
param rw float difference = 0 "Values are near when their difference is at most this";
function _;
include <rtapi_math.h>;
license "GPL";
author "OpenEMC";
;;
double a = in1, b = in2;
if (fabs(a - b) <= difference) {
    out = 1;
} else if (scale > 1 && ((a > 0 && b > 0) || (a < 0 && b < 0))) {
    a = fabs(a);
    b = fabs(b);
    out = b >= a / scale && b <= a * scale;
} else {
    out = 0;
}
