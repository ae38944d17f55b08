component oneshot "One-shot pulse generator";
pin in bit in "Trigger input";
pin in bit reset "Ends the current pulse";
pin out bit out "TRUE while the pulse runs";
pin out bit out_not "Inverted out";
pin in float width = 0 "Pulse length in seconds";
pin out float time_left "Seconds left in the pulse";
param rw bit retriggerable = TRUE "A new trigger during a pulse restarts it";
param rw bit rising = TRUE "Trigger on rising edges";
param rw bit falling = FALSE "Trigger on falling edges";
variable int old_in;
variable double timer;
function _;
license "GPL";
author "OpenEMC";
;;
int v = in;
int trig = (rising && v && !old_in) || (falling && !v && old_in);
old_in = v;
if (reset) {
    timer = 0;
} else if (trig && (retriggerable || timer <= 0)) {
    timer = width == width ? width : 0;  /* a NaN width gives no pulse instead of a stuck timer */
} else if (timer > 0) {
    timer -= fperiod;
    if (timer < 0) timer = 0;
}
out = timer > 0;
out_not = !(timer > 0);
time_left = timer;
