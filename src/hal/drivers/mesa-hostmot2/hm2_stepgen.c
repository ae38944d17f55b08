/* hm2_stepgen.c: the StepGen module: descriptor, timing and mode registers, set-up and debug. */
#include <stdlib.h>
#include "rtapi_errno.h"
#include "hm2.h"
#include "hm2_stepgen.h"

/* Versions 0, 1 (old), 2, 0x42 (swap) and 0xC2 (swap + index/probe). */
static int check_md(hm2_board_t *hm2, int md_index)
{
    int v = hm2->md[md_index].version;
    bool known = v == 0 || v == 1 || v == 2 || v == 0x42 || v == 0xC2;
    if (!known || !hm2_md_is_consistent(hm2, md_index, (uint8_t)v, 10, 4, 0x1FF)) {
        hm2_md_is_consistent_or_complain(hm2, md_index, 2, 10, 4, 0x1FF);
        return -EINVAL;
    }
    if (v < 2) {
        HM2_PRINT(hm2, "WARNING: this firmware has StepGen v%d!\n", v);
        HM2_PRINT(hm2, "WARNING: upgrade your firmware!\n");
    }
    return 0;
}

/* Register addresses and TRAM regions (rate written, accumulator read, mode read on 0xC2). */
static int setup_registers(hm2_board_t *hm2, const hm2_md_t *md)
{
    hm2_stepgen_t *s = &hm2->stepgen;
    uint32_t b = md->base_address, rs = md->register_stride;
    int n = s->num_instances;
    s->step_rate_addr = b;
    s->accumulator_addr = b + 1 * rs;
    s->mode_addr = b + 2 * rs;
    s->dir_setup_time_addr = b + 3 * rs;
    s->dir_hold_time_addr = b + 4 * rs;
    s->pulse_width_addr = b + 5 * rs;
    s->pulse_idle_width_addr = b + 6 * rs;
    s->table_sequence_data_addr = b + 7 * rs;
    s->table_sequence_length_addr = b + 8 * rs;
    s->master_dds_addr = b + 9 * rs;
    s->dpll_timer_addr = b + 10 * rs;
    int r = hm2_register_tram_read_region(hm2, s->accumulator_addr, n * 4, &s->accumulator_reg);
    if (r == 0 && s->has_index_probe)
        r = hm2_register_tram_read_region(hm2, s->mode_addr, n * 4, &s->mode_reg);
    if (r == 0)
        r = hm2_register_tram_write_region(hm2, s->step_rate_addr, n * 4, &s->step_rate_reg);
    return r;
}

/* Parse the StepGen descriptor and export every instance. */
int hm2_stepgen_parse_md(hm2_board_t *hm2, int md_index)
{
    const hm2_md_t *md = &hm2->md[md_index];
    hm2_stepgen_t *s = &hm2->stepgen;
    if (check_md(hm2, md_index) < 0)
        return -EINVAL;
    int n = hm2_md_instances_to_use(hm2, md_index, hm2->config.num_stepgens, "num_stepgens");
    if (n <= 0)
        return n;
    s->num_instances = n;
    s->version = md->version;
    s->has_swap = md->version == 0x42 || md->version == 0xC2;
    s->has_index_probe = md->version == 0xC2;
    s->clock_freq = md->clock_freq;
    s->dpll_present = hm2_md_has_gtag(hm2, HM2_GTAG_DPLL);
    s->instance = calloc(n, sizeof(*s->instance));
    if (!s->instance)
        return -ENOMEM;
    int r = setup_registers(hm2, md);
    for (int i = 0; r == 0 && i < n; i++)
        r = hm2_stepgen_export_instance(hm2, i);
    if (r == 0 && s->dpll_present) {
        s->timer_number = NULL;
        r = hal_pin_s32_newf(HAL_IN, &s->timer_number, hm2->llio->comp_id, "%s.stepgen.timer-number",
                             hm2->llio->name);
        if (r == 0)
            *s->timer_number = -1;
    }
    if (r < 0) {
        HM2_ERR(hm2, "error adding stepgen HAL objects, aborting\n");
        return r;
    }
    return n;
}

/* ns param -> clocks; too large resets the param to the maximum with a message. */
static uint32_t timing_clocks(hm2_board_t *hm2, int i, hal_u32_t *param, const char *what)
{
    double clocks = (double)*param * hm2->stepgen.clock_freq / 1e9;
    if (clocks > HM2_STEPGEN_TIMING_MAX) {
        HM2_ERR(hm2, "stepgen %d has invalid %s, resetting to max\n", i, what);
        *param = (hal_u32_t)((double)HM2_STEPGEN_TIMING_MAX * 1e9 / hm2->stepgen.clock_freq);
        clocks = HM2_STEPGEN_TIMING_MAX;
    }
    return (uint32_t)clocks;
}

/* Write one timing register when its param changed (or always when forced). */
static void write_timing(hm2_board_t *hm2, int i, bool force)
{
    hm2_stepgen_instance_t *in = &hm2->stepgen.instance[i];
    hm2_stepgen_hal_t *h = in->hal;
    hal_u32_t *params[] = {&h->steplen, &h->stepspace, &h->dirsetup, &h->dirhold};
    uint32_t *written[] = {&in->written_steplen, &in->written_stepspace, &in->written_dirsetup,
                           &in->written_dirhold};
    const char *names[] = {"steplen", "stepspace", "dirsetup", "dirhold"};
    uint32_t addrs[] = {hm2->stepgen.pulse_width_addr, hm2->stepgen.pulse_idle_width_addr,
                        hm2->stepgen.dir_setup_time_addr, hm2->stepgen.dir_hold_time_addr};
    for (int k = 0; k < 4; k++) {
        if (!force && *params[k] == *written[k])
            continue;
        uint32_t clocks = timing_clocks(hm2, i, params[k], names[k]);
        hm2_queue_write(hm2, addrs[k] + 4 * i, &clocks, 4);
        *written[k] = *params[k];
    }
}

/* Mode bits from step_type, swap and the latch pins; validates the table depth. */
static uint32_t mode_word(hm2_board_t *hm2, int i)
{
    hm2_stepgen_hal_t *h = hm2->stepgen.instance[i].hal;
    if (h->step_type > HM2_STEPGEN_TABLE_MAX) {
        HM2_ERR(hm2, "the firmware only supports tables up to a depth of %d, you requested %u. "
                "Reverting to step type 0\n", HM2_STEPGEN_TABLE_MAX, (unsigned)h->step_type);
        h->step_type = 0;
    }
    uint32_t mode = h->step_type <= 2 ? h->step_type : HM2_STEPGEN_MODE_TABLE;
    if (hm2->stepgen.has_swap && h->swap_step_dir)
        mode |= HM2_STEPGEN_MODE_SWAP;
    if (hm2->stepgen.has_index_probe) {
        if (*h->index_enable)
            mode |= HM2_STEPGEN_MODE_LATCH_ON_INDEX;
        if (*h->index_invert)
            mode |= HM2_STEPGEN_MODE_INDEX_POLARITY;
        if (*h->probe_enable)
            mode |= HM2_STEPGEN_MODE_LATCH_ON_PROBE;
        if (*h->probe_invert)
            mode |= HM2_STEPGEN_MODE_PROBE_POLARITY;
    }
    return mode;
}

/* Table mode: the phase bytes, last phase first, then the length. */
static void write_table(hm2_board_t *hm2, int i)
{
    hm2_stepgen_t *s = &hm2->stepgen;
    hm2_stepgen_hal_t *h = s->instance[i].hal;
    for (int j = (int)h->step_type - 1; j >= 0; j--) {
        uint32_t byte = (h->table[j / 4] >> (8 * (j % 4))) & 0xFF;
        hm2_queue_write(hm2, s->table_sequence_data_addr + 4 * i, &byte, 4);
    }
    uint32_t len = h->step_type - 1;
    hm2_queue_write(hm2, s->table_sequence_length_addr + 4 * i, &len, 4);
}

/* Write the mode (and table) when anything it depends on changed. */
static void write_mode(hm2_board_t *hm2, int i)
{
    hm2_stepgen_instance_t *in = &hm2->stepgen.instance[i];
    uint32_t mode = mode_word(hm2, i);
    bool table_changed = false;
    for (int k = 0; k < 4; k++)
        table_changed |= in->hal->table[k] != in->written_table[k];
    if (in->mode_written && mode == in->written_mode && !table_changed &&
        in->hal->step_type == in->written_step_type)
        return;
    if ((mode & HM2_STEPGEN_MODE_TYPE_MASK) == HM2_STEPGEN_MODE_TABLE)
        write_table(hm2, i);
    hm2_queue_write(hm2, hm2->stepgen.mode_addr + 4 * i, &mode, 4);
    in->written_mode = mode;
    in->written_step_type = in->hal->step_type;
    for (int k = 0; k < 4; k++)
        in->written_table[k] = in->hal->table[k];
    in->mode_written = true;
}

/* DPLL timer select of the stepgens (only with a DPLL module). */
static void write_timer_select(hm2_board_t *hm2, bool force)
{
    hm2_stepgen_t *s = &hm2->stepgen;
    if (!s->timer_number)
        return;
    int32_t t = *s->timer_number;
    if (t < -1 || t > 4)
        t = -1;
    if (!force && t == s->written_timer_number)
        return;
    uint32_t v = t >= 0 ? ((uint32_t)t << 12) | 0x8000u : 0;
    hm2_queue_write(hm2, s->dpll_timer_addr, &v, 4);
    s->written_timer_number = t;
}

/* Queue changed timing, mode and timer registers (write funct). */
void hm2_stepgen_write(hm2_board_t *hm2)
{
    for (int i = 0; i < hm2->stepgen.num_instances; i++) {
        write_timing(hm2, i, false);
        write_mode(hm2, i);
    }
    if (hm2->stepgen.num_instances)
        write_timer_select(hm2, false);
}

/* Timing registers, the master DDS and the timer select (the mode is written by the cycle). */
void hm2_stepgen_force_write(hm2_board_t *hm2)
{
    hm2_stepgen_t *s = &hm2->stepgen;
    if (s->num_instances == 0)
        return;
    for (int i = 0; i < s->num_instances; i++)
        write_timing(hm2, i, true);
    uint32_t dds = HM2_STEPGEN_MASTER_DDS;
    hm2_write(hm2, s->master_dds_addr, &dds, 4);
    write_timer_select(hm2, true);
}

/* After the first read: positions start at zero where the accumulators are. */
void hm2_stepgen_tram_init(hm2_board_t *hm2)
{
    hm2_stepgen_t *s = &hm2->stepgen;
    for (int i = 0; i < s->num_instances; i++) {
        s->instance[i].prev_accumulator = s->accumulator_reg[i];
        s->instance[i].subcounts = 0;
        s->step_rate_reg[i] = 0;
    }
}

/* Release the instance table. */
void hm2_stepgen_cleanup(hm2_board_t *hm2)
{
    free(hm2->stepgen.instance);
    hm2->stepgen.instance = NULL;
}

/* debug_modules: the stepgen registers. */
void hm2_stepgen_print_module(hm2_board_t *hm2)
{
    hm2_stepgen_t *s = &hm2->stepgen;
    if (s->num_instances == 0)
        return;
    HM2_PRINT(hm2, "StepGen: %d\n", s->num_instances);
    HM2_PRINT(hm2, "    clock_frequency: %d Hz\n", (int)s->clock_freq);
    HM2_PRINT(hm2, "    version: %d\n", s->version);
    HM2_PRINT(hm2, "    step_rate_addr: 0x%04X\n", s->step_rate_addr);
    HM2_PRINT(hm2, "    accumulator_addr: 0x%04X\n", s->accumulator_addr);
    HM2_PRINT(hm2, "    mode_addr: 0x%04X\n", s->mode_addr);
    HM2_PRINT(hm2, "    master_dds_addr: 0x%04X\n", s->master_dds_addr);
    for (int i = 0; i < s->num_instances; i++)
        HM2_PRINT(hm2, "    instance %d: position-fb %f, step_type %u\n", i,
                  *s->instance[i].hal->position_fb, (unsigned)s->instance[i].hal->step_type);
}
