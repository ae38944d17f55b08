/* hm2_encoder.c: quadrature (and muxed) encoder module: counts, latches, velocity from timestamps. */
#include <stdlib.h>
#include "rtapi_errno.h"
#include "rtapi_math.h"
#include "hm2.h"
#include "hm2_encoder.h"

#define DEFAULT_SAMPLE_FREQUENCY 25000000u
#define DEFAULT_MUXED_SAMPLE_FREQUENCY 8000000u

/* Accept the encoder versions LinuxCNC accepts; old ones get the upgrade warning. */
static int check_md(hm2_board_t *hm2, int md_index, bool muxed)
{
    const hm2_md_t *md = &hm2->md[md_index];
    int v = md->version;
    bool known = muxed ? (v == 2 || v == 3 || v == 4 || v == 0x84)
                       : (v == 1 || v == 2 || v == 3 || v == 0x83);
    if (!known || !hm2_md_is_consistent(hm2, md_index, md->version, 5, 4, 0x03)) {
        hm2_md_is_consistent_or_complain(hm2, md_index, muxed ? 4 : 3, 5, 4, 0x03);
        return -EINVAL;
    }
    if ((!muxed && v == 1) || (muxed && v == 2)) {
        HM2_PRINT(hm2, "WARNING: this firmware has %s v%d!\n", muxed ? "Muxed Encoder" : "Encoder", v);
        HM2_PRINT(hm2, "WARNING: Index logic is buggy\n");
        HM2_PRINT(hm2, "WARNING: upgrade your firmware!\n");
    }
    return 0;
}

/* Register addresses and TRAM regions. */
static int setup_registers(hm2_board_t *hm2, const hm2_md_t *md)
{
    hm2_encoder_t *e = &hm2->encoder;
    int n = e->num_instances;
    e->counter_addr = md->base_address;
    e->latch_control_addr = md->base_address + 1 * md->register_stride;
    e->timestamp_div_addr = md->base_address + 2 * md->register_stride;
    e->timestamp_count_addr = md->base_address + 3 * md->register_stride;
    e->filter_rate_addr = md->base_address + 4 * md->register_stride;
    e->dpll_timer_addr = md->base_address + 5 * md->register_stride;
    int r = hm2_register_tram_read_region(hm2, e->timestamp_count_addr, 4, &e->timestamp_count_reg);
    if (r == 0)
        r = hm2_register_tram_read_region(hm2, e->counter_addr, n * 4, &e->counter_reg);
    if (r == 0)
        r = hm2_register_tram_read_region(hm2, e->latch_control_addr, n * 4, &e->latch_control_reg);
    return r;
}

/* Global objects: sample frequency, hires timestamps, skew (muxed v>3), timer (with a DPLL). */
static int export_globals(hm2_board_t *hm2)
{
    hm2_encoder_t *e = &hm2->encoder;
    const char *b = hm2->llio->name;
    int id = hm2->llio->comp_id, r;
    e->hal = hal_malloc(sizeof(*e->hal));
    if (!e->hal)
        return -ENOMEM;
    r = hal_pin_u32_newf(HAL_IN, &e->hal->sample_frequency, id, "%s.encoder.%ssample-frequency", b,
                         e->muxed ? "muxed-" : "");
    if (r == 0)
        r = hal_pin_bit_newf(HAL_IN, &e->hal->hires_timestamp, id, "%s.encoder.hires-timestamp", b);
    if (r == 0 && e->muxed && e->version > 3)
        r = hal_pin_u32_newf(HAL_IN, &e->hal->muxed_skew, id, "%s.encoder.muxed-skew", b);
    if (r == 0 && hm2_md_has_gtag(hm2, HM2_GTAG_DPLL))
        r = hal_pin_s32_newf(HAL_IN, &e->hal->timer_number, id, "%s.encoder.timer-number", b);
    if (r < 0)
        return r;
    *e->hal->sample_frequency = e->muxed ? DEFAULT_MUXED_SAMPLE_FREQUENCY : DEFAULT_SAMPLE_FREQUENCY;
    *e->hal->hires_timestamp = 0;
    if (e->hal->muxed_skew)
        *e->hal->muxed_skew = 0;
    if (e->hal->timer_number)
        *e->hal->timer_number = -1;
    return 0;
}

/* Parse an Encoder or Muxed Encoder descriptor. */
int hm2_encoder_parse_md(hm2_board_t *hm2, int md_index)
{
    const hm2_md_t *md = &hm2->md[md_index];
    hm2_encoder_t *e = &hm2->encoder;
    bool muxed = md->gtag == HM2_GTAG_MUXED_ENCODER;
    if (e->num_instances) {
        HM2_ERR(hm2, "found duplicate Module Descriptor for %s (inconsistent firmware), "
                "not loading driver\n", hm2_gtag_name(md->gtag));
        return -EINVAL;
    }
    if (check_md(hm2, md_index, muxed) < 0)
        return -EINVAL;
    int n = hm2_md_instances_to_use(hm2, md_index, hm2->config.num_encoders, "num_encoders");
    if (n <= 0)
        return n;
    e->num_instances = n;
    e->muxed = muxed;
    e->version = md->version;
    e->has_probe = md->version == 0x83 || md->version == 0x84;
    e->clock_freq = md->clock_freq;
    e->instance = calloc(n, sizeof(*e->instance));
    if (!e->instance)
        return -ENOMEM;
    int r = setup_registers(hm2, md);
    if (r == 0)
        r = export_globals(hm2);
    for (int i = 0; r == 0 && i < n; i++)
        r = hm2_encoder_export_instance(hm2, i);
    if (r < 0) {
        HM2_ERR(hm2, "error adding encoder HAL objects, aborting\n");
        return r;
    }
    return n;
}

/* Control word of one instance from its pins and params. */
static uint32_t control_word(const hm2_encoder_t *e, const hm2_encoder_hal_t *h)
{
    uint32_t c = 0;
    if (*h->index_enable)
        c |= HM2_ENCODER_LATCH_ON_INDEX | HM2_ENCODER_INDEX_JUSTONCE;
    else if (e->has_probe && *h->probe_enable)
        c |= HM2_ENCODER_LATCH_ON_PROBE | HM2_ENCODER_INDEX_JUSTONCE;
    if (h->index_invert)
        c |= HM2_ENCODER_INDEX_POLARITY;
    if (h->index_mask)
        c |= HM2_ENCODER_INDEX_MASK;
    if (h->index_mask_invert)
        c |= HM2_ENCODER_INDEX_MASK_POLARITY;
    if (h->counter_mode)
        c |= HM2_ENCODER_COUNTER_MODE;
    if (h->filter)
        c |= HM2_ENCODER_FILTER;
    if (e->has_probe && *h->probe_invert)
        c |= HM2_ENCODER_PROBE_POLARITY;
    return c;
}

/* Timestamp divider and filter rate from the global pins; rewrite sample-frequency achieved. */
static void write_globals(hm2_board_t *hm2, bool force)
{
    hm2_encoder_t *e = &hm2->encoder;
    uint32_t freq = *e->hal->sample_frequency;
    bool hires = *e->hal->hires_timestamp;
    uint32_t skew = e->hal->muxed_skew ? *e->hal->muxed_skew : 0;
    if (!force && e->globals_written && freq == e->written_sample_frequency &&
        hires == e->written_hires && skew == e->written_skew)
        return;
    uint32_t tsdiv = hm2_encoder_timestamp_divider(e->clock_freq, hires);
    uint32_t rate = hm2_encoder_filter_rate(e->clock_freq, freq, &freq);
    if (e->muxed && e->version > 3)
        rate |= hm2_encoder_skew_bits(e->clock_freq, skew) << 28;
    *e->hal->sample_frequency = freq;
    e->seconds_per_tick = (tsdiv + 2.0) / e->clock_freq;
    hm2_write(hm2, e->timestamp_div_addr, &tsdiv, 4);
    hm2_write(hm2, e->filter_rate_addr, &rate, 4);
    e->written_sample_frequency = freq;
    e->written_hires = hires;
    e->written_skew = skew;
    e->globals_written = true;
}

/* DPLL timer select for the timestamps, when a DPLL exists. */
static void write_timer_select(hm2_board_t *hm2, bool force)
{
    hm2_encoder_t *e = &hm2->encoder;
    if (!e->hal->timer_number)
        return;
    int32_t t = *e->hal->timer_number;
    if (t < -1 || t > 4)
        t = -1;
    if (!force && t == e->written_timer_number)
        return;
    uint32_t v = t >= 0 ? ((uint32_t)t << 12) | 0x8000u : 0;
    hm2_write(hm2, e->dpll_timer_addr, &v, 4);
    e->written_timer_number = t;
}

/* Queue changed control words and globals (write funct). */
void hm2_encoder_write(hm2_board_t *hm2)
{
    hm2_encoder_t *e = &hm2->encoder;
    if (e->num_instances == 0)
        return;
    for (int i = 0; i < e->num_instances; i++) {
        hm2_encoder_instance_t *in = &e->instance[i];
        uint32_t c = control_word(e, in->hal);
        bool clear_qe = *in->hal->quad_error_enable && !in->prev_quad_error_enable;
        in->prev_quad_error_enable = *in->hal->quad_error_enable;
        if (clear_qe) {
            c |= HM2_ENCODER_QUADRATURE_ERROR;
            in->quad_error_reported = false;
        }
        if (clear_qe || !in->control_written || c != in->written_control) {
            hm2_queue_write(hm2, e->latch_control_addr + 4 * i, &c, 4);
            in->written_control = c & ~HM2_ENCODER_QUADRATURE_ERROR;
            in->control_written = true;
        }
    }
    write_globals(hm2, false);
    write_timer_select(hm2, false);
}

/* Write every control word and the globals. */
void hm2_encoder_force_write(hm2_board_t *hm2)
{
    hm2_encoder_t *e = &hm2->encoder;
    if (e->num_instances == 0)
        return;
    for (int i = 0; i < e->num_instances; i++) {
        hm2_encoder_instance_t *in = &e->instance[i];
        uint32_t c = control_word(e, in->hal);
        hm2_write(hm2, e->latch_control_addr + 4 * i, &c, 4);
        in->written_control = c;
        in->control_written = true;
    }
    write_globals(hm2, true);
    write_timer_select(hm2, true);
}

/* After the first read: counts start where the hardware is, so count = 0. */
void hm2_encoder_tram_init(hm2_board_t *hm2)
{
    hm2_encoder_t *e = &hm2->encoder;
    for (int i = 0; i < e->num_instances; i++) {
        hm2_encoder_instance_t *in = &e->instance[i];
        in->prev_hw_count = (uint16_t)(e->counter_reg[i] & 0xFFFF);
        in->count64 = in->prev_hw_count;
        in->zero_offset = in->count64;
        in->vel.state = HM2_ENCODER_STOPPED;
        in->vel.prev_event_count = in->count64;
        in->latch64 = in->count64;
        *in->hal->rawcounts = (int32_t)in->count64;
    }
    if (e->num_instances)
        e->prev_tsc = (uint16_t)(*e->timestamp_count_reg & 0xFFFF);
}

/* Release the instance table. */
void hm2_encoder_cleanup(hm2_board_t *hm2)
{
    free(hm2->encoder.instance);
    hm2->encoder.instance = NULL;
}

/* debug_modules: the encoder registers. */
void hm2_encoder_print_module(hm2_board_t *hm2)
{
    hm2_encoder_t *e = &hm2->encoder;
    if (e->num_instances == 0)
        return;
    HM2_PRINT(hm2, "Encoders: %d\n", e->num_instances);
    HM2_PRINT(hm2, "    clock_frequency: %d Hz\n", (int)e->clock_freq);
    HM2_PRINT(hm2, "    version: %d\n", e->version);
    HM2_PRINT(hm2, "    counter_addr: 0x%04X\n", e->counter_addr);
    HM2_PRINT(hm2, "    latch_control_addr: 0x%04X\n", e->latch_control_addr);
    HM2_PRINT(hm2, "    timestamp_div_addr: 0x%04X\n", e->timestamp_div_addr);
    HM2_PRINT(hm2, "    timestamp_count_addr: 0x%04X\n", e->timestamp_count_addr);
    HM2_PRINT(hm2, "    filter_rate_addr: 0x%04X\n", e->filter_rate_addr);
    for (int i = 0; i < e->num_instances; i++)
        HM2_PRINT(hm2, "    instance %d: rawcounts %d, control 0x%08X\n", i,
                  (int)*e->instance[i].hal->rawcounts, e->instance[i].written_control);
}
