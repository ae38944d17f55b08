// override_test.cc: unit test of halui's override knob logic (counts, direct value, steps, reset, count-enable, clamping, settling).
#include <cmath>
#include <cstdio>

#include "halui_override.hh"

namespace {

int failures = 0;

// One step of a knob; prints what was sent (or that nothing was).
void step(const char *what, OverrideKnob &k, const OverrideInput &in, double current,
          const OverrideLimits &lim, double now, bool want_send, double want)
{
    double target = -1;
    bool sent = override_update(k, in, current, lim, now, &target);
    bool ok = sent == want_send && (!sent || std::fabs(target - want) < 1e-12);
    printf("%s %-44s %s", ok ? "ok  " : "FAIL", what, sent ? "" : "nothing sent\n");
    if (sent) printf("%.4f\n", target);
    if (!ok) failures++;
}

OverrideLimits limits(double lo, double hi, bool reset)
{
    OverrideLimits l;
    l.min = lo;
    l.max = hi;
    l.has_reset = reset;
    return l;
}

void steps()
{
    OverrideKnob k;
    OverrideInput in;
    OverrideLimits lim = limits(0, 1.5, true);
    in.scale = 0.1;
    step("no change", k, in, 1.0, lim, 0, false, 0);
    in.increase = true;
    step("increase edge", k, in, 1.0, lim, 0, true, 1.1);
    step("increase held", k, in, 1.1, lim, 1, false, 0);
    in.increase = false;
    in.decrease = true;
    step("decrease edge (uses the sent 1.1)", k, in, 1.0, lim, 0.1, true, 1.0);
    in.decrease = false;
    in.reset = true;
    step("reset", k, in, 0.3, lim, 5, true, 1.0);
    in.reset = false;
    step("reset released", k, in, 1.0, lim, 6, false, 0);
}

void counts()
{
    OverrideKnob k;
    OverrideInput in;
    OverrideLimits lim = limits(0, 1.5, true);
    in.scale = 0.1;
    in.counts = 3;
    step("counts +3", k, in, 1.0, lim, 0, true, 1.3);
    in.counts = 10;
    step("counts +7 clamps to max", k, in, 1.3, lim, 1, true, 1.5);
    in.count_enable = false;
    in.counts = -20;
    step("counts while disabled", k, in, 1.5, lim, 2, false, 0);
    in.count_enable = true;
    in.counts = -21;
    step("enabled again: only the new count", k, in, 1.5, lim, 3, true, 1.4);
    in.counts = -100;
    step("clamps to min", k, in, 1.4, lim, 4, true, 0.0);
    in.direct_value = true;
    in.scale = 0.01;
    in.counts = 80;
    step("direct value", k, in, 0.0, lim, 5, true, 0.8);
    in.scale = 0.02;
    step("direct value: scale change alone", k, in, 0.8, lim, 6, false, 0);
}

void limits_and_reset()
{
    OverrideKnob k;
    OverrideInput in;
    OverrideLimits lim = limits(0.5, 1.2, false);
    in.scale = 0.5;
    in.reset = true;
    step("no reset pin (max velocity)", k, in, 1.0, lim, 0, false, 0);
    in.decrease = true;
    step("decrease clamps to min", k, in, 1.0, lim, 1, true, 0.5);
    in.decrease = false;
    in.scale = NAN;
    in.increase = true;
    step("a NaN scale sends nothing", k, in, 0.5, lim, 2, false, 0);
}

} // namespace

int main()
{
    steps();
    counts();
    limits_and_reset();
    printf("%d failures\n", failures);
    return failures ? 1 : 0;
}
