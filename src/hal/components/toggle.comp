component toggle "Push-on, push-off from a momentary button";
pin in bit in "Button input";
pin io bit out "Toggles on each debounced press";
param rw u32 debounce = 2 "Cycles the input must be held; outside 1..10000 it is reset to 2";
variable int held;
variable int pressed;
function _;
license "GPL";
author "OpenEMC";
;;
if (debounce < 1 || debounce > 10000) debounce = 2;
if (in) {
    if (held < (int)debounce) held++;
    if (held >= (int)debounce && !pressed) {
        pressed = 1;
        out = !out;
    }
} else {
    if (held > 0) held--;
    if (held == 0) pressed = 0;
}
