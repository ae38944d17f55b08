component modmath "Modular position arithmetic: which way is shorter from actual to desired";
pin in s32 actual "Current position (for example of a tool changer carousel)";
pin in s32 desired "Wanted position";
pin out bit up "TRUE when the shorter way from actual to desired is upward";
pin out bit down "TRUE when the shorter way from actual to desired is downward";
pin out bit on_target "TRUE when actual equals desired";
pin out bit on_target_max "TRUE when on target at max-num";
pin out bit on_target_min "TRUE when on target at min-num";
param rw s32 min_num = 0 "Lowest position";
param rw s32 max_num = 15 "Highest position";
param rw bit wrap = TRUE "TRUE: max-num is followed by min-num (a ring); FALSE: a plain range";
function _;
license "GPL";
author "OpenEMC";
description """Positions run from min-num to max-num. With wrap TRUE they form a ring and
the direction is the shorter way round (a tie goes up); with wrap FALSE the direction
is simply the sign of desired - actual. Nothing is set while max-num < min-num.""";
;;
long long n = (long long)max_num - min_num + 1, d = (long long)desired - actual;
if (n <= 0) {
    up = 0;
    down = 0;
    on_target = 0;
    on_target_max = 0;
    on_target_min = 0;
    return;
}
if (wrap) {
    d = ((d % n) + n) % n;
    if (d * 2 > n) d -= n;
}
up = d > 0;
down = d < 0;
on_target = d == 0;
on_target_max = d == 0 && actual == max_num;
on_target_min = d == 0 && actual == min_num;
