/* sim_physics.c: time on the simulated card: stepgen DDS, encoder inputs, PWM motors, watchdog bites. */
#include <math.h>
#include <stddef.h>
#include "sim_card.h"
#include "../hm2_gtag.h"

#define WD_DISABLED 0x80000000u
#define ENC_LATCH_ON_INDEX (1u << 4)

/* Timestamp counter (16 bit) at time t: ClockLow / (TSDiv + 2). */
uint16_t sim_timestamp(const sim_card_t *c, long long t_ns)
{
    double rate = (double)c->board->clock_low / (c->enc_tsdiv + 2.0);
    return (uint16_t)((long long)((t_ns - c->start_ns) * 1e-9 * rate) & 0xFFFF);
}

/* IO carrying the module pin (tag, unit, secondary pin), or -1. */
static int find_pin(const sim_card_t *c, int gtag, int unit, int sec_pin)
{
    int n = c->board->ports * c->board->port_width;
    for (int io = 0; io < n; io++) {
        uint32_t pd = c->board->pins[io];
        if ((int)((pd >> 8) & 0xFF) == gtag && (int)((pd >> 16) & 0xFF) == unit && (int)(pd & 0xFF) == sec_pin)
            return io;
    }
    return -1;
}

/* The pin is an output driven by its module (DDR and alt source set, watchdog not bitten). */
bool sim_module_pin_driven(const sim_card_t *c, int gtag, int unit, int sec_pin)
{
    int io = find_pin(c, gtag, unit, sec_pin);
    if (io < 0 || c->wd_bitten)
        return false;
    int port = io / c->board->port_width;
    uint32_t bit = 1u << (io % c->board->port_width);
    return (c->ddr[port] & bit) && (c->alt[port] & bit);
}

/* Duty of pwmgen i in -1..1 from its value and mode registers. */
double sim_pwm_duty(const sim_card_t *c, int i, int *bits)
{
    const sim_pwmgen_t *p = &c->pwmgen[i];
    int b = ((p->mode >> 3) & 3) == 3 ? 12 : (int)(p->mode & 3) + 9;
    uint32_t mag = (p->value >> 16) & ((1u << b) - 1);
    double duty = mag / (double)(1u << b);
    if (bits)
        *bits = b;
    return (p->value & 0x80000000u) ? -duty : duty;
}

/* Level a module drives on one of its output pins. */
static int module_level(const sim_card_t *c, uint32_t pd)
{
    int gtag = (pd >> 8) & 0xFF, unit = (pd >> 16) & 0xFF, pin = pd & 0x7F;
    if (gtag == HM2_GTAG_STEPGEN && unit < SIM_MAX_STEPGENS)
        return pin == 2 ? ((int32_t)c->stepgen[unit].rate < 0) : 0;
    if (gtag == HM2_GTAG_PWMGEN && unit < SIM_MAX_PWMGENS) {
        double d = sim_pwm_duty(c, unit, NULL);
        if (pin == 1)
            return d != 0.0;
        if (pin == 2)
            return d < 0.0;
        return !(c->pwm_enable & (1u << unit));   /* /Enable is active low */
    }
    return 0;
}

/* Electrical level of an IO: driven output (with invert and open drain) or the outside level. */
int sim_io_level(const sim_card_t *c, int io)
{
    int port = io / c->board->port_width;
    uint32_t bit = 1u << (io % c->board->port_width);
    if (c->wd_bitten || !(c->ddr[port] & bit))
        return c->input_level[io];
    int v = (c->alt[port] & bit) ? module_level(c, c->board->pins[io]) : (c->data_out[port] & bit) != 0;
    if (c->invert[port] & bit)
        v = !v;
    if ((c->open_drain[port] & bit) && v)
        return c->input_level[io];
    return v;
}

/* Stepgen DDS over ticks clocks; steps reaching the pin move the looped-back encoders. */
static void advance_stepgen(sim_card_t *c, int s, long long ticks)
{
    sim_stepgen_t *g = &c->stepgen[s];
    int64_t rate = (int32_t)g->rate;
    uint32_t period = g->steplen + g->stepspace;
    if (period > 0) {
        int64_t max = (int64_t)(4294967296.0 / period);
        rate = rate > max ? max : rate < -max ? -max : rate;
    }
    int64_t before = g->acc >> 32;
    g->acc += rate * ticks;
    int64_t steps = (g->acc >> 32) - before;
    if (steps == 0 || !sim_module_pin_driven(c, HM2_GTAG_STEPGEN, s, 0x81))
        return;
    g->emitted_steps += steps;
    for (int l = 0; l < c->num_loops; l++)
        if (c->loops[l].kind == SIM_LOOP_STEPGEN && c->loops[l].from == s)
            c->encoder[c->loops[l].to].position += steps * c->loops[l].gain;
}

/* PWM-driven motors: speed = duty * gain while the drive is enabled through its pin. */
static void advance_motors(sim_card_t *c, double dt_s)
{
    for (int l = 0; l < c->num_loops; l++) {
        const sim_loop_t *p = &c->loops[l];
        if (p->kind != SIM_LOOP_MOTOR || !(c->pwm_enable & (1u << p->from)) ||
            !sim_module_pin_driven(c, HM2_GTAG_PWMGEN, p->from, 0x83))
            continue;
        c->encoder[p->to].position += sim_pwm_duty(c, p->from, NULL) * p->gain * dt_s;
    }
}

/* Event timestamp and index latch of an encoder that moved from p0 to its position. */
static void encoder_events(sim_card_t *c, int e, double p0, long long t0, long long t1)
{
    sim_encoder_t *n = &c->encoder[e];
    double p1 = n->position;
    long long c0 = (long long)floor(p0), c1 = (long long)floor(p1);
    if (c0 == c1)
        return;
    double boundary = p1 > p0 ? (double)c1 : (double)c1 + 1.0;
    long long t = t0 + (long long)((boundary - p0) / (p1 - p0) * (t1 - t0));
    n->last_event_ts = sim_timestamp(c, t);
    if (n->index_every <= 0 || !(n->control & ENC_LATCH_ON_INDEX))
        return;
    long long lo = c0 < c1 ? c0 + 1 : c1, hi = c0 < c1 ? c1 : c0 - 1;
    long long m = (long long)floor((double)hi / n->index_every) * n->index_every;
    if (m >= lo) {
        n->latched = (uint16_t)(m & 0xFFFF);
        n->control &= ~ENC_LATCH_ON_INDEX;
    }
}

/* Watchdog: bite when not petted in time; every IO becomes an input. */
static void check_watchdog(sim_card_t *c)
{
    if (c->wd_bitten || (c->wd_timer & WD_DISABLED) || c->now_ns <= c->wd_deadline_ns)
        return;
    c->wd_bitten = true;
    for (int p = 0; p < SIM_MAX_PORTS; p++)
        c->ddr[p] = 0;
    sim_say("bite");
}

/* Bring the card to now_ns. */
void sim_advance(sim_card_t *c, long long now_ns)
{
    long long t0 = c->now_ns, dt = now_ns - t0;
    if (dt <= 0)
        return;
    double exact = dt * 1e-9 * c->board->clock_low + c->tick_frac;
    long long ticks = (long long)exact;
    double p0[SIM_MAX_ENCODERS];
    c->tick_frac = exact - ticks;
    for (int e = 0; e < c->board->encoders; e++)
        p0[e] = c->encoder[e].position;
    for (int s = 0; s < c->board->stepgens; s++)
        advance_stepgen(c, s, ticks);
    advance_motors(c, dt * 1e-9);
    for (int e = 0; e < c->board->encoders; e++)
        encoder_events(c, e, p0[e], t0, now_ns);
    c->now_ns = now_ns;
    check_watchdog(c);
}
