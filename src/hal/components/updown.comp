component updown "Count up or down on rising edges, with optional limits";
pin in bit countup "Each rising edge adds one";
pin in bit countdown "Each rising edge subtracts one";
pin in bit reset "When TRUE, count is set to zero";
pin out s32 count "The count";
param rw bit clamp "When TRUE, count stays within [min, max]";
param rw bit wrap "When TRUE, count wraps around between min and max";
param rw s32 max_ = 0x7FFFFFFF;
param rw s32 min_ = 0;
variable int oldup;
variable int olddown;
variable long long value;
function _;
license "GPL";
author "OpenEMC";
;;
int up = countup, down = countdown;
if (reset) {
    value = 0;
} else {
    if (up && !oldup) value++;
    if (down && !olddown) value--;
    if (wrap) {
        if (value > max_) value = min_;
        if (value < min_) value = max_;
    } else if (clamp) {
        if (value > max_) value = max_;
        if (value < min_) value = min_;
    }
}
oldup = up;
olddown = down;
count = (hal_s32_t)value;
