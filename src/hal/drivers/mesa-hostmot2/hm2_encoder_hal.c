/* hm2_encoder_hal.c: HAL pins and params of one encoder instance, with LinuxCNC's names. */
#include "rtapi_errno.h"
#include "hm2.h"

typedef struct {
    const char *name;
    hal_pin_dir_t dir;
    size_t offset;            /* of the pointer in hm2_encoder_hal_t */
    bool probe_only;
} enc_pin_t;

#define PIN(n, d, f) {n, d, offsetof(hm2_encoder_hal_t, f), false}
#define PROBE_PIN(n, d, f) {n, d, offsetof(hm2_encoder_hal_t, f), true}

static const enc_pin_t s32_pins[] = {
    PIN("count", HAL_OUT, count), PIN("rawcounts", HAL_OUT, rawcounts),
    PIN("rawlatch", HAL_OUT, rawlatch), PIN("count-latched", HAL_OUT, count_latch),
};
static const enc_pin_t float_pins[] = {
    PIN("position", HAL_OUT, position), PIN("position-interpolated", HAL_OUT, position_interpolated),
    PIN("position-latched", HAL_OUT, position_latch), PIN("velocity", HAL_OUT, velocity),
    PIN("velocity-rpm", HAL_OUT, velocity_rpm),
};
static const enc_pin_t bit_pins[] = {
    PIN("reset", HAL_IN, reset), PIN("index-enable", HAL_IO, index_enable),
    PIN("no_clear_on_index", HAL_IN, no_clear_on_index),
    PROBE_PIN("probe-enable", HAL_IN, probe_enable), PROBE_PIN("probe-invert", HAL_IN, probe_invert),
    PIN("quad-error", HAL_OUT, quad_error), PIN("quad-error-enable", HAL_IN, quad_error_enable),
    PIN("input-a", HAL_OUT, input_a), PIN("input-b", HAL_OUT, input_b),
    PIN("input-index", HAL_OUT, input_idx),
};

/* Pins of one kind from a table. */
static int export_pins(hm2_board_t *hm2, int i, hm2_encoder_hal_t *h, const enc_pin_t *t, int n,
                       hal_type_t type)
{
    const char *b = hm2->llio->name;
    char name[HAL_NAME_LEN + 1];
    for (int k = 0; k < n; k++) {
        if (t[k].probe_only && !hm2->encoder.has_probe)
            continue;
        rtapi_snprintf(name, sizeof(name), "%s.encoder.%02d.%s", b, i, t[k].name);
        int r = hal_pin_new(name, type, t[k].dir, (void **)((char *)h + t[k].offset), hm2->llio->comp_id);
        if (r < 0)
            return r;
    }
    return 0;
}

/* Params with their defaults (filter TRUE, scale 1, vel-timeout 0.5 s). */
static int export_params(hm2_board_t *hm2, int i, hm2_encoder_hal_t *h)
{
    const char *b = hm2->llio->name;
    int id = hm2->llio->comp_id;
    int r = hal_param_float_newf(HAL_RW, &h->scale, id, "%s.encoder.%02d.scale", b, i);
    if (r == 0)
        r = hal_param_bit_newf(HAL_RW, &h->index_invert, id, "%s.encoder.%02d.index-invert", b, i);
    if (r == 0)
        r = hal_param_bit_newf(HAL_RW, &h->index_mask, id, "%s.encoder.%02d.index-mask", b, i);
    if (r == 0)
        r = hal_param_bit_newf(HAL_RW, &h->index_mask_invert, id, "%s.encoder.%02d.index-mask-invert", b, i);
    if (r == 0)
        r = hal_param_bit_newf(HAL_RW, &h->counter_mode, id, "%s.encoder.%02d.counter-mode", b, i);
    if (r == 0)
        r = hal_param_bit_newf(HAL_RW, &h->filter, id, "%s.encoder.%02d.filter", b, i);
    if (r == 0)
        r = hal_param_float_newf(HAL_RW, &h->vel_timeout, id, "%s.encoder.%02d.vel-timeout", b, i);
    h->scale = 1.0;
    h->filter = 1;
    h->vel_timeout = 0.5;
    return r;
}

/* Every HAL object of encoder i. */
int hm2_encoder_export_instance(hm2_board_t *hm2, int i)
{
    hm2_encoder_hal_t *h = hal_malloc(sizeof(*h));
    if (!h)
        return -ENOMEM;
    hm2->encoder.instance[i].hal = h;
    int r = export_pins(hm2, i, h, s32_pins, sizeof(s32_pins) / sizeof(s32_pins[0]), HAL_S32);
    if (r == 0)
        r = export_pins(hm2, i, h, float_pins, sizeof(float_pins) / sizeof(float_pins[0]), HAL_FLOAT);
    if (r == 0)
        r = export_pins(hm2, i, h, bit_pins, sizeof(bit_pins) / sizeof(bit_pins[0]), HAL_BIT);
    if (r == 0)
        r = export_params(hm2, i, h);
    return r;
}

/* True when some module descriptor has this tag. */
bool hm2_md_has_gtag(hm2_board_t *hm2, int gtag)
{
    for (int i = 0; i < hm2->num_mds; i++)
        if (hm2->md[i].gtag == gtag)
            return true;
    return false;
}
