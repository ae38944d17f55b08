// halui_knobs.cc: halui's override knobs (feed, rapid, max velocity, spindle N) read from their pins and sent as NML commands.
#include "halui.hh"

namespace {

// The knob's input pins this cycle.
OverrideInput read_knob(const OverridePins &p)
{
    OverrideInput in;
    in.count_enable = **p.count_enable;
    in.counts = **p.counts;
    in.direct_value = **p.direct_value;
    in.scale = **p.scale;
    in.increase = **p.increase;
    in.decrease = **p.decrease;
    in.reset = p.reset ? **p.reset : false;
    return in;
}

// One knob: when its inputs ask for a new value, build the message and send it.
template <class Make>
void knob(const OverridePins &p, OverrideKnob &k, double current, const OverrideLimits &lim,
          double now_s, Make make)
{
    double target;
    if (override_update(k, read_knob(p), current, lim, now_s, &target)) make(target);
}

// A knob's range; reset sets 1.0 where the knob has a reset pin.
OverrideLimits limits(double lo, double hi, bool has_reset)
{
    OverrideLimits l;
    l.min = lo;
    l.max = hi;
    l.has_reset = has_reset;
    l.reset_value = 1.0;
    return l;
}

} // namespace

// Serve the feed, rapid, max-velocity and spindle override knobs.
void halui_overrides(Halui &h, double now_s)
{
    const EMC_STAT &s = h.client.status();
    HaluiPins &p = h.pins;
    knob(p.feed_override, h.feed_knob, s.motion.traj.scale, limits(0, h.cfg.max_feed_override, true),
         now_s, [&](double v) {
             EMC_TRAJ_SET_SCALE m;
             m.scale = v;
             halui_send(h, m);
         });
    knob(p.rapid_override, h.rapid_knob, s.motion.traj.rapid_scale,
         limits(0, h.cfg.max_rapid_override, true), now_s, [&](double v) {
             EMC_TRAJ_SET_RAPID_SCALE m;
             m.scale = v;
             halui_send(h, m);
         });
    knob(p.max_velocity, h.maxvel_knob, s.motion.traj.maxVelocity, limits(0, h.cfg.max_velocity, false),
         now_s, [&](double v) {
             EMC_TRAJ_SET_MAX_VELOCITY m;
             m.velocity = v;
             halui_send(h, m);
         });
    for (int n = 0; n < h.cfg.spindles; n++) {
        knob(p.spindle[n].override, h.spindle_knob[n], s.motion.spindle[n].spindle_scale,
             limits(h.cfg.min_spindle_override, h.cfg.max_spindle_override, true), now_s, [&](double v) {
                 EMC_TRAJ_SET_SPINDLE_SCALE m;
                 m.spindle = n;
                 m.scale = v;
                 halui_send(h, m);
             });
    }
}
