component offset "Add an offset to an input and subtract it from the feedback";
pin in float offset "The offset value";
pin in float in "The input value";
pin out float out "in + offset";
pin in float fb_in "The feedback value";
pin out float fb_out "fb-in - offset";
function update_output "Update out";
function update_feedback "Update fb-out";
license "GPL";
author "OpenEMC";
;;
/* out = in + offset. */
FUNCTION(update_output) { out = in + offset; }

/* fb-out = fb-in - offset. */
FUNCTION(update_feedback) { fb_out = fb_in - offset; }
