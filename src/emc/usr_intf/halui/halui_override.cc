// halui_override.cc: one cycle of an override knob (feed, rapid, spindle, max velocity): counts, direct value, steps, reset, clamping.
#include "halui_override.hh"

#include <cmath>

namespace {

// Clamp v into [lo, hi].
double clamp(double v, double lo, double hi)
{
    return v < lo ? lo : (v > hi ? hi : v);
}

} // namespace

// Apply this cycle's inputs on top of the value the knob believes is current.
bool override_update(OverrideKnob &knob, const OverrideInput &in, double current,
                     const OverrideLimits &limits, double now_s, double *target)
{
    bool recent = knob.sent_at >= 0 && now_s - knob.sent_at < OVERRIDE_SETTLE_S;
    double value = recent ? knob.sent : current;
    bool changed = false;

    if (in.counts != knob.last_counts && in.count_enable) {
        if (in.direct_value)
            value = in.counts * in.scale;
        else
            value += static_cast<double>(in.counts - knob.last_counts) * in.scale;
        changed = true;
    }
    if (in.increase && !knob.last_increase) {
        value += in.scale;
        changed = true;
    }
    if (in.decrease && !knob.last_decrease) {
        value -= in.scale;
        changed = true;
    }
    if (limits.has_reset && in.reset && !knob.last_reset) {
        value = limits.reset_value;
        changed = true;
    }
    knob.last_counts = in.counts;
    knob.last_increase = in.increase;
    knob.last_decrease = in.decrease;
    knob.last_reset = in.reset;
    if (!changed || !std::isfinite(value)) return false;
    *target = clamp(value, limits.min, limits.max);
    knob.sent = *target;
    knob.sent_at = now_s;
    return true;
}
