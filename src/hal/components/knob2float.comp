component knob2float "Turn encoder counts into a float value";
pin in s32 counts "Counts from an encoder";
pin in bit enable "Count changes are accumulated only while TRUE";
pin in float scale "Units per count";
pin out float out "The value, limited to [min-out, max-out]";
param rw float max_out = 1.0;
param rw float min_out = 0.0;
variable int old_counts;
variable int first = 1;
function _;
license "GPL";
author "OpenEMC";
;;
int c = counts;
if (first) {
    old_counts = c;
    first = 0;
}
if (enable) {
    double v = out + (double)(int)((unsigned)c - (unsigned)old_counts) * scale;  /* wrap-safe */
    if (v > max_out) v = max_out;
    if (v < min_out) v = min_out;
    if (v == v) out = v;  /* a NaN scale (or inf * 0) holds the output instead of poisoning it */
}
old_counts = c;
