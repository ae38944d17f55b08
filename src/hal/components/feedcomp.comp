component feedcomp "Scale a value by the ratio of the current velocity to the feed rate";
pin out float out "The input scaled by vel / feed (or the input itself when disabled)";
pin in float in "Value to scale, e.g. laser power at full feed rate";
pin in float vel "Current velocity, e.g. motion.current-vel";
param rw float feed "Reference feed rate the input applies to";
pin in bit enable "TRUE to scale the input; FALSE passes it through";
function _ "Compute the output";
license "GPL";
author "OpenEMC";
description """
Useful for laser or plasma power that must follow the actual tool speed: while
enable is TRUE, out = in * vel / feed, so the output falls as the machine
slows down in corners.  With enable FALSE, or a feed of zero, out = in.
""";
;;
if (enable && feed != 0.0) out = in * vel / feed;
else out = in;
