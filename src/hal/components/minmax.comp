component minmax "Track the minimum and maximum of a value";
pin in float in;
pin in bit reset "When TRUE, min and max are set to in";
pin out float max_;
pin out float min_;
function _;
license "GPL";
author "OpenEMC";
;;
double v = in;
if (reset) {
    max_ = v;
    min_ = v;
} else {
    if (v > max_) max_ = v;
    if (v < min_) min_ = v;
}
