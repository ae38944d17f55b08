component limit3 "Follow an input within position, velocity and acceleration limits";
description """
Each period the output moves toward a goal: the input (when it can be followed),
or \\fBmin\\fR/\\fBmax\\fR when following the input would overshoot them.  The
output never exceeds \\fBmaxv\\fR or \\fBmaxa\\fR, matches the input's velocity
when it locks on, and reaches the position limits without overshoot.
""";
pin in float in;
pin out float out "Follows in, within [min, max], |velocity| <= maxv and |acceleration| <= maxa";
pin in bit load "When TRUE, out jumps to the input clamped to [min, max]";
pin in float min_ = -1e20;
pin in float max_ = 1e20;
pin in float maxv = 1e20 "Velocity limit, units per second";
pin in float maxa = 1e7 "Acceleration limit, units per second squared";
pin in bit enable = 1 "When FALSE, out returns to zero within the limits";
pin in u32 smooth_steps = 2 "Periods over which the landing on the goal is smoothed; 0 disables smoothing";
variable double out_prev;
variable double in_prev;
function _;
include "limit3_math.h";
license "GPL";
author "OpenEMC";
;;
limit3_state_t st = { out, out_prev, in_prev };
limit3_limits_t lim = { min_, max_, maxv, maxa, smooth_steps };
limit3_step(&st, &lim, enable ? in : 0.0, load, fperiod);
out = st.pos;
out_prev = st.pos_prev;
in_prev = st.target_prev;
