component div2 "Quotient of two inputs";
pin in float in0 "Dividend";
pin in float in1 "Divisor";
pin out float out "out = in0 / in1";
param rw float deadband "When abs(in1) is below deadband, +/-deadband is used instead (minimum 1e-12)";
variable int warned;
function _;
license "GPL";
author "OpenEMC";
;;
double d = in1, db = deadband;
if (db < 1e-12) db = 1e-12;
if (d < db && d > -db) {
    if (!warned) {
        rtapi_print_msg(RTAPI_MSG_ERR, "div2: divisor magnitude below deadband, using deadband\n");
        warned = 1;
    }
    d = d < 0 ? -db : db;
}
out = in0 / d;
