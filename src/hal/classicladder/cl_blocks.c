/* cl_blocks.c: timers, monostables, counters and IEC timers stepped by the scan period. */
#include "cl_blocks.h"

/* Whole time-base units elapsed after adding period_ns to *acc_ns. */
static int32_t ticks(int64_t *acc_ns, int32_t base_ms, long period_ns)
{
    int64_t base_ns = (int64_t)(base_ms > 0 ? base_ms : 1) * 1000000;
    int64_t n;

    *acc_ns += period_ns > 0 ? period_ns : 0;
    n = *acc_ns / base_ns;
    *acc_ns -= n * base_ns;
    return n > 1000000 ? 1000000 : (int32_t)n;
}

/* value + n (n >= 0) but no more than limit, without overflowing. */
static int32_t add_upto(int32_t value, int32_t n, int32_t limit)
{
    return (int64_t)limit - value <= n ? limit : value + n;
}

/* Classic timer: E low resets; while C is high it counts up to the preset. */
void cl_timer_step(cl_timer_t *t, int enable, int control, long period_ns)
{
    if (!enable) {
        t->value = t->done = t->running = 0;
        t->acc_ns = 0;
        return;
    }
    t->running = control && !t->done;
    if (!t->running)
        return;
    t->value = add_upto(t->value, ticks(&t->acc_ns, t->base_ms, period_ns), t->preset);
    if (t->value >= t->preset) {
        t->value = t->preset;
        t->done = 1;
        t->running = 0;
    }
}

/* Monostable: a rising input (when idle) loads the preset, which then counts down to 0. */
void cl_mono_step(cl_mono_t *mo, int input, long period_ns)
{
    int start = input && !mo->prev_in && !mo->running;

    mo->prev_in = input;
    if (start) {
        mo->value = mo->preset;
        mo->running = mo->preset > 0;
        mo->acc_ns = 0;
        return;
    }
    if (!mo->running)
        return;
    mo->value -= ticks(&mo->acc_ns, mo->base_ms, period_ns);
    if (mo->value <= 0) {
        mo->value = 0;
        mo->running = 0;
    }
}

/* Counter: reset, preset, then count on rising up/down edges wrapping 0..9999. */
void cl_counter_step(cl_counter_t *c, int reset, int preset, int up, int down)
{
    c->empty = c->full = 0;
    if (reset)
        c->value = 0;
    else if (preset)
        c->value = c->preset;
    if (up && !c->prev_up) {  /* compare before counting: a written value may be INT32_MAX */
        c->full = c->value >= CL_COUNTER_MAX;
        c->value = c->full ? 0 : c->value + 1;
    }
    if (down && !c->prev_down) {
        c->empty = c->value <= 0;
        c->value = c->empty ? CL_COUNTER_MAX : c->value - 1;
    }
    c->prev_up = up;
    c->prev_down = down;
    c->done = c->value == c->preset;
}

/* Count an IEC timer's elapsed value up to its preset; returns 1 once reached. */
static int iec_count(cl_timer_iec_t *t, long period_ns)
{
    if (t->value < t->preset)
        t->value = add_upto(t->value, ticks(&t->acc_ns, t->base_ms, period_ns), t->preset);
    if (t->value >= t->preset) {
        t->value = t->preset;
        return 1;
    }
    return 0;
}

/* IEC timer in mode TON (0), TOF (1) or TP (2). */
void cl_timer_iec_step(cl_timer_iec_t *t, int in, long period_ns)
{
    int rising = in && !t->prev_in;

    t->prev_in = in;
    if (t->mode == 0) {
        if (!in) {
            t->q = t->value = 0;
            t->acc_ns = 0;
            return;
        }
        t->q = iec_count(t, period_ns);
    } else if (t->mode == 1) {
        if (in) {
            t->q = 1;
            t->value = t->active = 0;
            t->acc_ns = 0;
            return;
        }
        if (t->q)
            t->q = !iec_count(t, period_ns);
    } else {
        if (rising && !t->active) {
            t->active = t->q = 1;
            t->value = 0;
            t->acc_ns = 0;
        } else if (t->active && iec_count(t, period_ns)) {
            t->q = 0;
        }
        if (!t->q && !in)
            t->active = t->value = 0;
    }
}
