component tp "IEC 61131-3 pulse timer: a rising edge of in gives a pulse of pt seconds";
description "Edges during the pulse do not restart it; et is reset one call after q drops. (Not the trajectory planner, which is tpmod.)";
pin in bit in "Trigger";
pin out bit q "Pulse output";
pin out float et "Elapsed time of the pulse, seconds";
param rw float pt "Pulse time, seconds";
variable int last_in;
function _;
license "GPL";
author "OpenEMC";
;;
if (pt < 0) {
    pt = 0;
    rtapi_print_msg(RTAPI_MSG_WARN, "tp: Pulse time must be positive, resetting to 0");
}
if (et < 0) {
    et = 0;
    rtapi_print_msg(RTAPI_MSG_WARN, "tp: Elapsed time rolled over, resetting to 0");
}
if ((in && !last_in) || q) {
    if (et < pt) {
        q = 1;
        et += fperiod;
    } else {
        q = 0;
    }
} else {
    et = 0;
    q = 0;
}
last_in = in;
