component estop_latch "Software E-stop latch";
pin in bit ok_in = TRUE "External OK signal";
pin in bit fault_in "External fault signal";
pin in bit reset "A rising edge clears the latch when ok-in and no fault";
pin out bit ok_out = FALSE "TRUE when the system may run";
pin out bit fault_out = TRUE "TRUE while latched";
pin out bit watchdog "Toggles every cycle while ok-out is TRUE";
variable int old_reset;
function _;
license "GPL";
author "OpenEMC";
;;
int r = reset;
if (ok_in && !fault_in) {
    if (r && !old_reset) {
        ok_out = 1;
        fault_out = 0;
    }
    if (ok_out) watchdog = !watchdog;
} else {
    ok_out = 0;
    fault_out = 1;
}
old_reset = r;
