component charge_pump "Square wave for a charge-pump watchdog input";
pin out bit out "Toggles on every call";
pin out bit out_2 "Toggles on every second call";
pin out bit out_4 "Toggles on every fourth call";
pin in bit enable = TRUE "When FALSE, all outputs are FALSE";
variable unsigned phase;
option singleton yes;
function _;
license "GPL";
author "OpenEMC";
;;
if (!enable) {
    out = 0;
    out_2 = 0;
    out_4 = 0;
    phase = 0;
} else {
    phase = (phase + 1) & 7;
    out = phase & 1;
    out_2 = (phase >> 1) & 1;
    out_4 = (phase >> 2) & 1;
}
