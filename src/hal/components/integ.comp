component integ "Integrator with gain and limits";
pin in float in;
pin in float gain = 1.0;
pin out float out "Integral of in * gain over time";
pin in bit reset "When TRUE, out is set to zero";
pin in float max_ = 1e20;
pin in float min_ = -1e20;
function _;
license "GPL";
author "OpenEMC";
;;
if (reset) {
    out = 0;
} else {
    double v = out + in * gain * fperiod;
    if (v > max_) v = max_;
    if (v < min_) v = min_;
    out = v;
}
