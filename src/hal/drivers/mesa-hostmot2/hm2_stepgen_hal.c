/* hm2_stepgen_hal.c: HAL pins and params of one stepgen instance, with LinuxCNC's names and defaults. */
#include <stddef.h>
#include "rtapi_errno.h"
#include "hm2.h"
#include "hm2_stepgen.h"

typedef struct {
    const char *name;
    hal_type_t type;
    hal_pin_dir_t dir;
    size_t offset;            /* of the pointer in hm2_stepgen_hal_t */
    bool latch_only;          /* only with index/probe firmware (0xC2) */
} sg_pin_t;

#define PIN(n, t, d, f, l) {n, t, d, offsetof(hm2_stepgen_hal_t, f), l}

static const sg_pin_t pins[] = {
    PIN("position-cmd", HAL_FLOAT, HAL_IN, position_cmd, false),
    PIN("velocity-cmd", HAL_FLOAT, HAL_IN, velocity_cmd, false),
    PIN("position-fb", HAL_FLOAT, HAL_OUT, position_fb, false),
    PIN("velocity-fb", HAL_FLOAT, HAL_OUT, velocity_fb, false),
    PIN("counts", HAL_S32, HAL_OUT, counts, false),
    PIN("enable", HAL_BIT, HAL_IN, enable, false),
    PIN("control-type", HAL_BIT, HAL_IN, control_type, false),
    PIN("position-reset", HAL_BIT, HAL_IN, position_reset, false),
    PIN("position-latch", HAL_FLOAT, HAL_OUT, position_latch, true),
    PIN("index-enable", HAL_BIT, HAL_IO, index_enable, true),
    PIN("probe-enable", HAL_BIT, HAL_IO, probe_enable, true),
    PIN("index-invert", HAL_BIT, HAL_IN, index_invert, true),
    PIN("probe-invert", HAL_BIT, HAL_IN, probe_invert, true),
    PIN("dbg_pos_minus_prev_cmd", HAL_FLOAT, HAL_OUT, dbg_pos_minus_prev_cmd, false),
    PIN("dbg_ff_vel", HAL_FLOAT, HAL_OUT, dbg_ff_vel, false),
    PIN("dbg_s_to_match", HAL_FLOAT, HAL_OUT, dbg_s_to_match, false),
    PIN("dbg_vel_error", HAL_FLOAT, HAL_OUT, dbg_vel_error, false),
    PIN("dbg_err_at_match", HAL_FLOAT, HAL_OUT, dbg_err_at_match, false),
    PIN("dbg_step_rate", HAL_S32, HAL_OUT, dbg_step_rate, false),
};

/* The pins of the table above. */
static int export_pins(hm2_board_t *hm2, int i, hm2_stepgen_hal_t *h)
{
    char name[HAL_NAME_LEN + 1];
    for (size_t k = 0; k < sizeof(pins) / sizeof(pins[0]); k++) {
        if (pins[k].latch_only && !hm2->stepgen.has_index_probe)
            continue;
        rtapi_snprintf(name, sizeof(name), "%s.stepgen.%02d.%s", hm2->llio->name, i, pins[k].name);
        int r = hal_pin_new(name, pins[k].type, pins[k].dir, (void **)((char *)h + pins[k].offset),
                            hm2->llio->comp_id);
        if (r < 0)
            return r;
    }
    return 0;
}

/* Timing params default to the hardware maximum (0x3FFF clocks) in ns. */
static int export_timing(hm2_board_t *hm2, int i, hm2_stepgen_hal_t *h)
{
    const char *b = hm2->llio->name;
    int id = hm2->llio->comp_id;
    hal_u32_t *params[] = {&h->steplen, &h->stepspace, &h->dirsetup, &h->dirhold};
    const char *names[] = {"steplen", "stepspace", "dirsetup", "dirhold"};
    hal_u32_t max_ns = (hal_u32_t)((double)HM2_STEPGEN_TIMING_MAX * 1e9 / hm2->stepgen.clock_freq);
    for (int k = 0; k < 4; k++) {
        int r = hal_param_u32_newf(HAL_RW, params[k], id, "%s.stepgen.%02d.%s", b, i, names[k]);
        if (r < 0)
            return r;
        *params[k] = max_ns;
    }
    return 0;
}

/* Scale, limits, step type, swap and the step table params. */
static int export_params(hm2_board_t *hm2, int i, hm2_stepgen_hal_t *h)
{
    const char *b = hm2->llio->name;
    int id = hm2->llio->comp_id;
    int r = hal_param_float_newf(HAL_RW, &h->position_scale, id, "%s.stepgen.%02d.position-scale", b, i);
    if (r == 0)
        r = hal_param_float_newf(HAL_RW, &h->maxvel, id, "%s.stepgen.%02d.maxvel", b, i);
    if (r == 0)
        r = hal_param_float_newf(HAL_RW, &h->maxaccel, id, "%s.stepgen.%02d.maxaccel", b, i);
    if (r == 0)
        r = export_timing(hm2, i, h);
    if (r == 0)
        r = hal_param_u32_newf(HAL_RW, &h->step_type, id, "%s.stepgen.%02d.step_type", b, i);
    if (r == 0 && hm2->stepgen.has_swap)
        r = hal_param_bit_newf(HAL_RW, &h->swap_step_dir, id, "%s.stepgen.%02d.swap_step_dir", b, i);
    for (int k = 0; r == 0 && k < 4 && hm2->stepgen.instance[i].table_width > 2; k++)
        r = hal_param_u32_newf(HAL_RW, &h->table[k], id, "%s.stepgen.%02d.table-data-%d", b, i, k);
    h->position_scale = 1.0;
    h->maxvel = 0.0;
    h->maxaccel = 1.0;
    return r;
}

/* Highest secondary pin byte of the instance's pins (bit 7 included, as LinuxCNC counts it). */
static int table_width(hm2_board_t *hm2, int i)
{
    int width = 0;
    for (int io = 0; io < hm2->num_pins; io++) {
        const hm2_pin_t *p = &hm2->pin[io];
        if (p->sec_tag == HM2_GTAG_STEPGEN && p->sec_unit == i && p->sec_pin > width)
            width = p->sec_pin;
    }
    return width;
}

/* Every HAL object of stepgen i. */
int hm2_stepgen_export_instance(hm2_board_t *hm2, int i)
{
    hm2_stepgen_hal_t *h = hal_malloc(sizeof(*h));
    if (!h)
        return -ENOMEM;
    hm2->stepgen.instance[i].hal = h;
    hm2->stepgen.instance[i].table_width = table_width(hm2, i);
    int r = export_pins(hm2, i, h);
    if (r == 0)
        r = export_params(hm2, i, h);
    return r;
}
