component safety_latch "Latch an error when a value leaves its allowed range";
pin in float error-value "Monitored value";
pin in bit reset "A rising edge clears the latched error once the value is back in range";
pin out bit ok "TRUE while no error is latched";
pin out bit error "TRUE while an error is latched";
pin out bit threshold "TRUE while error-value is outside min-value..max-value (not latched)";
param rw float min-value = 0 "Lowest allowed value";
param rw float max-value = 0 "Highest allowed value";
variable int latched;
variable int old_reset;
function _ "Check the value and update the latch";
license "GPL";
author "OpenEMC";
description """
Whenever error-value is below min-value or above max-value, threshold is TRUE
and the error is latched: error becomes TRUE and ok FALSE until a rising edge on
reset arrives while the value is inside the range.  A reset edge while the value
is still out of range is ignored.  The error starts cleared at load time.
""";
;;
int out_of_range = !(error_value >= min_value && error_value <= max_value);  /* NaN is out of range */
int edge = reset && !old_reset;
old_reset = reset;
if (out_of_range) latched = 1;
else if (edge) latched = 0;
threshold = out_of_range;
error = latched;
ok = !latched;
