component sim_home_switch "Simulated home switch with hysteresis";
pin in float cur_pos "Current joint position";
pin in float home_pos = 1.0 "Position at which the switch closes";
pin in float hysteresis = 0.1 "Distance past home_pos the joint must move back to open the switch";
pin out bit home_sw "Switch output";
pin io bit index_enable "Cleared index-delay-ms after the switch closes while TRUE";
pin in float index_delay_ms = 10 "Delay from switch closure to the simulated index pulse";
variable double since_ms;
function _;
license "GPL";
author "OpenEMC";
;;
double p = cur_pos, h = home_pos, hy = hysteresis;
int sw = home_sw;
if (h >= 0) sw = sw ? p > h - hy : p >= h;
else sw = sw ? p < h + hy : p <= h;
home_sw = sw;
if (sw && index_enable) {
    since_ms += fperiod * 1000.0;
    if (since_ms >= index_delay_ms) {
        index_enable = 0;
        since_ms = 0;
    }
} else {
    since_ms = 0;
}
