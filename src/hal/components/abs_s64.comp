component abs_s64 "Absolute value and sign of a s64";
pin in s64 in;
pin out s64 out "Absolute value of in";
pin out bit sign "TRUE when in is negative";
pin out bit is_positive "TRUE when in is above zero";
pin out bit is_negative "TRUE when in is below zero";
function _;
license "GPL";
author "OpenEMC";
;;
hal_s64_t v = in;
sign = v < 0;
out = v >= 0 ? v : (v == INT64_MIN ? INT64_MAX : -v);  /* the most negative value saturates */
is_positive = v > 0;
is_negative = v < 0;
