component timedelay "Delay changes of a bit signal";
pin in bit in;
pin out bit out "Follows in after in has differed from out for on-delay (rising) or off-delay (falling) seconds";
pin in float on_delay = 0.5 "Seconds before a TRUE input is passed on";
pin in float off_delay = 0.5 "Seconds before a FALSE input is passed on";
pin out float elapsed "Seconds in has differed from out";
function _;
license "GPL";
author "OpenEMC";
;;
int v = in;
if (v != out) {
    double e = elapsed + fperiod;
    if (e >= (v ? on_delay : off_delay)) {
        out = v;
        e = 0;
    }
    elapsed = e;
} else {
    elapsed = 0;
}
