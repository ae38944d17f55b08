component safety_latch "Integrating error latch: errors add harm, good periods heal, crossing a threshold raises the error";
pin in bit error_in "The monitored error condition";
pin in bit enable = TRUE "FALSE passes error-in straight through (count 0)";
pin in bit reset "A rising edge clears count and the error";
pin in bit latching = TRUE "TRUE keeps the error until a reset edge; FALSE clears it when count drops below threshold";
pin in s32 harm = 1 "Added to count each period error-in is TRUE";
pin in s32 heal = 1 "Taken from count each period error-in is FALSE";
pin in s32 threshold = 100 "count at or above this raises the error";
pin in s32 min = 0 "Lowest count";
pin in s32 max = 1000 "Highest count";
pin out s32 count "The integrated error";
pin out bit error_out "TRUE while the error is raised";
pin out bit ok_out = TRUE "NOT error-out";
variable int old_reset;
function _ "Integrate the error and update the latch";
license "GPL";
author "OpenEMC";
description """
Each period with enable TRUE, count grows by harm while error-in is TRUE and
shrinks by heal while it is FALSE, held within min..max (min applied first, then
max). When count reaches threshold, error-out goes TRUE and ok-out FALSE. With
latching FALSE they return as soon as count is below threshold again; with
latching TRUE only a rising edge of reset (which also sets count to 0) clears
them. With enable FALSE, error-out follows error-in, ok-out is its opposite and
count is 0. The arithmetic saturates at the s32 range.
""";
;;
/* count + delta held in the s32 range. */
static int latch_add(hal_s32_t c, long long delta)
{
    long long v = (long long)c + delta;
    if (v > 2147483647LL) return 2147483647;
    if (v < -2147483648LL) return -2147483647 - 1;
    return (hal_s32_t)v;
}

FUNCTION(_)
{
    int edge = reset && !old_reset;
    old_reset = reset;
    if (!enable) {
        error_out = error_in;
        ok_out = !error_in;
        count = 0;
        return;
    }
    if (edge) {
        count = 0;
        error_out = 0;
        ok_out = 1;
    }
    count = latch_add(count, error_in ? (long long)harm : -(long long)heal);
    if (count < min) count = min;
    if (count > max) count = max;
    if (count >= threshold) {
        error_out = 1;
        ok_out = 0;
    } else if (!latching) {
        error_out = 0;
        ok_out = 1;
    }
}
