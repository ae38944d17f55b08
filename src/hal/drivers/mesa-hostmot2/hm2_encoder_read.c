/* hm2_encoder_read.c: per-cycle encoder processing: count extension, index/probe latches, velocity. */
#include "hm2.h"

/* Extend a 16-bit latched count next to a 64-bit count. */
static int64_t extend_near(int64_t near, uint16_t low)
{
    return near + (int16_t)(uint16_t)(low - (uint16_t)(near & 0xFFFF));
}

/* Index and probe latches: the hardware clears the latch bit when the event happened. */
static void process_latches(hm2_board_t *hm2, hm2_encoder_instance_t *in, uint32_t ctl, int64_t before)
{
    hm2_encoder_hal_t *h = in->hal;
    int64_t latched = extend_near(before, (uint16_t)(ctl >> 16));
    if ((in->written_control & HM2_ENCODER_LATCH_ON_INDEX) && !(ctl & HM2_ENCODER_LATCH_ON_INDEX)) {
        if (!*h->no_clear_on_index)
            in->zero_offset = latched;
        in->latch64 = latched;
        *h->index_enable = 0;
        in->written_control &= ~HM2_ENCODER_LATCH_ON_INDEX;
    } else if (hm2->encoder.has_probe && (in->written_control & HM2_ENCODER_LATCH_ON_PROBE) &&
               !(ctl & HM2_ENCODER_LATCH_ON_PROBE)) {
        in->latch64 = latched;
        *h->probe_enable = 0;
        in->written_control &= ~HM2_ENCODER_LATCH_ON_PROBE;
    }
}

/* Quadrature error: reported once per error while enabled. */
static void process_quad_error(hm2_board_t *hm2, int i, uint32_t ctl)
{
    hm2_encoder_instance_t *in = &hm2->encoder.instance[i];
    if (!*in->hal->quad_error_enable) {
        *in->hal->quad_error = 0;
        return;
    }
    bool qe = (ctl & HM2_ENCODER_QUADRATURE_ERROR) != 0;
    if (qe && !in->quad_error_reported) {
        HM2_ERR(hm2, "Encoder %d: quadrature count error\n", i);
        in->quad_error_reported = true;
    }
    *in->hal->quad_error = qe;
}

/* Scale may not be zero: reset it with a message. */
static double checked_scale(hm2_board_t *hm2, int i, hm2_encoder_hal_t *h)
{
    if (h->scale == 0.0) {
        HM2_ERR(hm2, "encoder.%02d.scale == 0.0, bogus, setting to 1.0\n", i);
        h->scale = 1.0;
    }
    return h->scale;
}

/* One instance: counts, latches, reset, positions, velocity. */
static void process_instance(hm2_board_t *hm2, int i, int64_t now_ticks)
{
    hm2_encoder_t *e = &hm2->encoder;
    hm2_encoder_instance_t *in = &e->instance[i];
    hm2_encoder_hal_t *h = in->hal;
    uint32_t reg = e->counter_reg[i], ctl = e->latch_control_reg[i];
    uint16_t hw = (uint16_t)(reg & 0xFFFF);
    int16_t delta = (int16_t)(uint16_t)(hw - in->prev_hw_count);
    int64_t before = in->count64;
    in->prev_hw_count = hw;
    in->count64 += delta;
    *h->input_a = (ctl & HM2_ENCODER_INPUT_A) != 0;
    *h->input_b = (ctl & HM2_ENCODER_INPUT_B) != 0;
    *h->input_idx = (ctl & HM2_ENCODER_INPUT_INDEX) != 0;
    process_quad_error(hm2, i, ctl);
    process_latches(hm2, in, ctl, before);
    if (*h->reset) {
        in->zero_offset = in->count64;
        in->latch64 = in->count64;
    }
    double scale = checked_scale(hm2, i, h);
    *h->rawcounts = (int32_t)in->count64;
    *h->rawlatch = (int32_t)in->latch64;
    *h->count = (int32_t)(in->count64 - in->zero_offset);
    *h->count_latch = (int32_t)(in->latch64 - in->zero_offset);
    *h->position = (double)(in->count64 - in->zero_offset) / scale;
    *h->position_latch = (double)(in->latch64 - in->zero_offset) / scale;
    int64_t event = hm2_encoder_event_ticks(e->tsc_epoch, e->prev_tsc, (uint16_t)(reg >> 16));
    double offset;
    *h->velocity = hm2_encoder_velocity(&in->vel, *h->velocity, in->count64, delta != 0, event,
                                        now_ticks, e->seconds_per_tick, scale, h->vel_timeout, &offset);
    *h->velocity_rpm = *h->velocity * 60.0;
    *h->position_interpolated = *h->position + offset;
}

/* Per-cycle read: track the timestamp counter's rollovers, then every instance. */
void hm2_encoder_process_tram_read(hm2_board_t *hm2, long period_ns)
{
    hm2_encoder_t *e = &hm2->encoder;
    (void)period_ns;
    if (e->num_instances == 0)
        return;
    uint16_t tsc = (uint16_t)(*e->timestamp_count_reg & 0xFFFF);
    if (tsc < e->prev_tsc)
        e->tsc_epoch++;
    e->prev_tsc = tsc;
    int64_t now_ticks = (int64_t)e->tsc_epoch * 65536 + tsc;
    for (int i = 0; i < e->num_instances; i++)
        process_instance(hm2, i, now_ticks);
}
