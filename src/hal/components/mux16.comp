component mux16 "Select one of sixteen float values by four select bits";
pin in bit use_graycode "TRUE: the select bits are a Gray code";
pin in bit suppress_no_input "TRUE: selection 0 keeps the previous output";
pin in float debounce_time "Seconds a new selection must be stable before it is used";
pin in bit sel#[4] "Select bits (sel0 is the least significant)";
pin out float out_f "The selected input";
pin out s32 out_s "The selected input, truncated to an integer";
pin in float in##[16] "Inputs";
param r float elapsed "Seconds the current selection has been stable";
param r s32 selected "The selection in use";
variable int pending;
function _;
license "GPL";
author "OpenEMC";
;;
int i, s = 0;
for (i = 3; i >= 0; i--) {
    int b = sel(i) ? 1 : 0;
    if (use_graycode) b ^= (s & 1);
    s = (s << 1) | b;
}
if (s != pending) {
    pending = s;
    elapsed = 0;
} else {
    elapsed += fperiod;
}
if (elapsed >= debounce_time) {
    selected = pending;
    if (!(suppress_no_input && pending == 0)) {
        out_f = in(pending);
        double v = in(pending);
        out_s = v >= 2147483647.0 ? 2147483647 : v <= -2147483648.0 ? (-2147483647 - 1) :
                v == v ? (hal_s32_t)v : 0;  /* saturate; NaN gives 0 */
    }
}
