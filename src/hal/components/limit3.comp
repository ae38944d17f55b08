component limit3 "Follow an input within position, velocity and acceleration limits";
pin in float in;
pin out float out "Follows in, clamped to [min, max], with |velocity| <= maxv and |acceleration| <= maxa";
pin in bit load "When TRUE, out jumps to the (clamped) input and the velocity is zeroed";
pin in float min_ = -1e20;
pin in float max_ = 1e20;
pin in float maxv = 1e20 "Velocity limit, units per second";
pin in float maxa = 1e7 "Acceleration limit, units per second squared";
pin in bit enable = 1 "When FALSE, out ramps to zero within the limits";
pin in u32 smooth_steps = 2 "Accepted for compatibility; the follower below is always smooth";
variable double pos;
variable double vel;
function _;
include <rtapi_math.h>;
license "GPL";
author "OpenEMC";
;;
double target = enable ? in : 0.0;
if (target != target) target = pos;  /* NaN input: brake and hold the current position */
double dv = maxa * fperiod, vmax = fabs(maxv);
double dist, lim, lo, hi, v;
if (target > max_) target = max_;
if (target < min_) target = min_;
if (load) {
    pos = target;
    vel = 0;
    out = pos;
    return;
}
if (!(dv > 0)) dv = 1e-12;  /* also a NaN maxa */
dist = target - pos;
lo = vel - dv;
hi = vel + dv;
if (fabs(dist / fperiod) <= dv && fabs(dist / fperiod) <= vmax &&
    dist / fperiod >= lo && dist / fperiod <= hi) {
    vel = dist / fperiod;
    pos = target;
} else {
    lim = (-dv + sqrt(dv * dv + 8.0 * dv * fabs(dist) / fperiod)) / 2.0;
    v = dist >= 0 ? (hi < lim ? hi : lim) : (lo > -lim ? lo : -lim);
    if (v < lo) v = lo;
    if (v > hi) v = hi;
    if (v > vmax) v = vmax > lo ? vmax : lo;
    if (v < -vmax) v = -vmax < hi ? -vmax : hi;
    vel = v;
    pos += v * fperiod;
}
out = pos;
