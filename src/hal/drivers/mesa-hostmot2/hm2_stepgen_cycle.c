/* hm2_stepgen_cycle.c: per-cycle stepgen work: velocity -> rate register, accumulator -> feedback. */
#include "rtapi_math.h"
#include "hm2.h"
#include "hm2_stepgen.h"

/* maxvel/maxaccel sanity (messages once: the params are rewritten); returns the usable maxvel. */
static double checked_maxvel(hm2_board_t *hm2, int i, hm2_stepgen_hal_t *h)
{
    double len_ns = (double)h->steplen + (double)h->stepspace;
    if (len_ns < 1.0)
        len_ns = 1e9 / hm2->stepgen.clock_freq;
    double physical = (1e9 / len_ns) / fabs(h->position_scale);
    if (h->maxvel < 0) {
        HM2_ERR(hm2, "stepgen.%02d.maxvel < 0, setting to its absolute value\n", i);
        h->maxvel = -h->maxvel;
    }
    if (h->maxvel > physical) {
        HM2_ERR(hm2, "stepgen.%02d.maxvel is too big for current step timings & position-scale, "
                "clipping to max possible\n", i);
        h->maxvel = physical;
    }
    if (h->maxaccel < 0) {
        HM2_ERR(hm2, "stepgen.%02d.maxaccel < 0, setting to its absolute value\n", i);
        h->maxaccel = -h->maxaccel;
    }
    return h->maxvel == 0.0 ? physical : h->maxvel;
}

/* Velocity of instance i for this cycle (position or velocity mode), with debug pins. */
static double plan_velocity(hm2_board_t *hm2, int i, double period_s)
{
    hm2_stepgen_instance_t *in = &hm2->stepgen.instance[i];
    hm2_stepgen_hal_t *h = in->hal;
    double maxvel = checked_maxvel(hm2, i, h);
    double v;
    if (*h->control_type) {
        v = hm2_stepgen_velocity_velocity(*h->velocity_cmd, *h->velocity_fb, h->maxaccel, period_s);
        in->old_position_cmd = *h->position_cmd;
    } else {
        hm2_stepgen_debug_t dbg;
        *h->dbg_pos_minus_prev_cmd = *h->position_fb - in->old_position_cmd;
        v = hm2_stepgen_position_velocity(*h->position_cmd, in->old_position_cmd, *h->position_fb,
                                          *h->velocity_fb, h->maxaccel, period_s, &dbg);
        in->old_position_cmd = *h->position_cmd;
        *h->dbg_ff_vel = dbg.ff_vel;
        *h->dbg_vel_error = dbg.vel_error;
        *h->dbg_s_to_match = dbg.s_to_match;
        *h->dbg_err_at_match = dbg.err_at_match;
    }
    if (v > maxvel)
        v = maxvel;
    else if (v < -maxvel)
        v = -maxvel;
    return v;
}

/* Rate registers for this cycle; a disabled stepgen stands still and tracks its command. */
void hm2_stepgen_prepare_tram_write(hm2_board_t *hm2, long period_ns)
{
    hm2_stepgen_t *s = &hm2->stepgen;
    double period_s = period_ns > 0 ? period_ns * 1e-9 : 1e-3;
    for (int i = 0; i < s->num_instances; i++) {
        hm2_stepgen_instance_t *in = &s->instance[i];
        hm2_stepgen_hal_t *h = in->hal;
        if (!*h->enable) {
            s->step_rate_reg[i] = 0;
            *h->velocity_fb = 0.0;
            *h->dbg_step_rate = 0;
            in->old_position_cmd = *h->position_cmd;
            continue;
        }
        double v = plan_velocity(hm2, i, period_s);
        *h->velocity_fb = v;
        s->step_rate_reg[i] = hm2_stepgen_rate_register(v, h->position_scale, s->clock_freq);
        *h->dbg_step_rate = (int32_t)s->step_rate_reg[i];
    }
}

/* Scale may not be (nearly) zero: reset it to +-1 with a message. */
static double checked_scale(hm2_board_t *hm2, int i, hm2_stepgen_hal_t *h)
{
    if (fabs(h->position_scale) < 1e-6) {
        double s = h->position_scale < 0 ? -1.0 : 1.0;
        HM2_ERR(hm2, "stepgen %d position_scale is too close to 0, resetting to %.1f\n", i, s);
        h->position_scale = s;
    }
    return h->position_scale;
}

/* Index/probe latches of 0xC2 firmware; returns the part of delta to count after the latch. */
static int32_t process_latch(hm2_board_t *hm2, int i, int32_t delta, double scale)
{
    hm2_stepgen_t *s = &hm2->stepgen;
    hm2_stepgen_instance_t *in = &s->instance[i];
    hm2_stepgen_hal_t *h = in->hal;
    if (!s->has_index_probe)
        return delta;
    uint32_t mode = s->mode_reg[i];
    int32_t to_latch = (int32_t)((mode & 0xFFFFFF00u) - (in->prev_accumulator & 0xFFFFFF00u));
    if ((in->written_mode & HM2_STEPGEN_MODE_LATCH_ON_INDEX) && !(mode & HM2_STEPGEN_MODE_LATCH_ON_INDEX)) {
        *h->position_latch = (in->subcounts + to_latch) / 65536.0 / scale;
        in->subcounts = 0;
        *h->index_enable = 0;
        in->written_mode &= ~HM2_STEPGEN_MODE_LATCH_ON_INDEX;
        return delta - to_latch;
    }
    if ((in->written_mode & HM2_STEPGEN_MODE_LATCH_ON_PROBE) && !(mode & HM2_STEPGEN_MODE_LATCH_ON_PROBE)) {
        *h->position_latch = (in->subcounts + to_latch) / 65536.0 / scale;
        *h->probe_enable = 0;
        in->written_mode &= ~HM2_STEPGEN_MODE_LATCH_ON_PROBE;
    }
    return delta;
}

/* Feedback from the 16.16 accumulators (wraps folded exactly by 2^32). */
void hm2_stepgen_process_tram_read(hm2_board_t *hm2, long period_ns)
{
    hm2_stepgen_t *s = &hm2->stepgen;
    (void)period_ns;
    for (int i = 0; i < s->num_instances; i++) {
        hm2_stepgen_instance_t *in = &s->instance[i];
        hm2_stepgen_hal_t *h = in->hal;
        double scale = checked_scale(hm2, i, h);
        uint32_t acc = s->accumulator_reg[i];
        int32_t delta = (int32_t)(acc - in->prev_accumulator);
        delta = process_latch(hm2, i, delta, scale);
        in->prev_accumulator = acc;
        in->subcounts += delta;
        if (*h->position_reset)
            in->subcounts = 0;
        *h->counts = (int32_t)(in->subcounts >> 16);
        *h->position_fb = (double)in->subcounts / 65536.0 / scale;
    }
}
