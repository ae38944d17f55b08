// halui_override.hh: the counts/scale/direct-value/increase/decrease/reset logic shared by halui's override knobs (pure, no HAL).
#ifndef HALUI_OVERRIDE_HH
#define HALUI_OVERRIDE_HH

#include <cstdint>

// What the knob's input pins read this cycle.
struct OverrideInput {
    bool count_enable = true;
    int32_t counts = 0;
    bool direct_value = false;
    double scale = 0;
    bool increase = false;
    bool decrease = false;
    bool reset = false;
};

// Range of a knob and its reset value (has_reset false: no reset pin, e.g. max-velocity).
struct OverrideLimits {
    double min = 0;
    double max = 1;
    bool has_reset = true;
    double reset_value = 1.0;
};

// State a knob keeps between cycles.
struct OverrideKnob {
    int32_t last_counts = 0;
    bool last_increase = false;
    bool last_decrease = false;
    bool last_reset = false;
    double sent = 0;       // last value commanded
    double sent_at = -1;   // when (seconds), -1 never
};

// How long a commanded value counts as "current" before task's status shows it.
constexpr double OVERRIDE_SETTLE_S = 0.5;

// One cycle of a knob. `current` is the value in task's status, `now_s` the time. Counts
// move the value by (change in counts) * scale, or set it to counts * scale with
// direct-value; a rising edge of increase/decrease moves it by scale; reset sets
// reset_value. Counts are tracked even while count-enable is off, so enabling never
// jumps. Returns true with *target (clamped to the limits) when a value must be sent.
bool override_update(OverrideKnob &knob, const OverrideInput &in, double current,
                     const OverrideLimits &limits, double now_s, double *target);

#endif
