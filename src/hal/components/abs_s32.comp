component abs_s32 "Absolute value and sign of a s32";
pin in s32 in;
pin out s32 out "Absolute value of in";
pin out bit sign "TRUE when in is negative";
pin out bit is_positive "TRUE when in is above zero";
pin out bit is_negative "TRUE when in is below zero";
function _;
license "GPL";
author "OpenEMC";
;;
hal_s32_t v = in;
sign = v < 0;
out = v >= 0 ? v : (v == (-2147483647 - 1) ? 2147483647 : -v);  /* the most negative value saturates */
is_positive = v > 0;
is_negative = v < 0;
