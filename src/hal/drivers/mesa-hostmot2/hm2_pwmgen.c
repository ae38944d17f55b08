/* hm2_pwmgen.c: the PWMGen module: frequencies, output modes, and the per-cycle duty values. */
#include <stdlib.h>
#include "rtapi_errno.h"
#include "rtapi_math.h"
#include "hm2.h"
#include "hm2_pwmgen.h"

/* Versions 0 and 1 (1 adds dither); anything else is refused. */
static int check_md(hm2_board_t *hm2, int md_index)
{
    int v = hm2->md[md_index].version;
    if (v > 1) {
        HM2_ERR(hm2, "Unsupported PWM firmware version %d", v);
        return -EINVAL;
    }
    if (!hm2_md_is_consistent_or_complain(hm2, md_index, (uint8_t)v, 5, 4, 0x03))
        return -EINVAL;
    return 0;
}

/* Per-instance pins and params. */
static int export_instance(hm2_board_t *hm2, int i)
{
    const char *b = hm2->llio->name;
    int id = hm2->llio->comp_id;
    hm2_pwmgen_hal_t *h = hal_malloc(sizeof(*h));
    if (!h)
        return -ENOMEM;
    hm2->pwmgen.instance[i].hal = h;
    int r = hal_pin_float_newf(HAL_IN, &h->value, id, "%s.pwmgen.%02d.value", b, i);
    if (r == 0)
        r = hal_pin_bit_newf(HAL_IN, &h->enable, id, "%s.pwmgen.%02d.enable", b, i);
    if (r == 0)
        r = hal_param_float_newf(HAL_RW, &h->scale, id, "%s.pwmgen.%02d.scale", b, i);
    if (r == 0)
        r = hal_param_s32_newf(HAL_RW, &h->output_type, id, "%s.pwmgen.%02d.output-type", b, i);
    if (r == 0)
        r = hal_param_bit_newf(HAL_RW, &h->offset_mode, id, "%s.pwmgen.%02d.offset-mode", b, i);
    if (r == 0 && hm2->pwmgen.version >= 1)
        r = hal_param_bit_newf(HAL_RW, &h->dither, id, "%s.pwmgen.%02d.dither", b, i);
    h->scale = 1.0;
    h->output_type = HM2_PWMGEN_OUTPUT_TYPE_PWM;
    return r;
}

/* Parse the PWMGen descriptor; export the globals and every instance. */
int hm2_pwmgen_parse_md(hm2_board_t *hm2, int md_index)
{
    const hm2_md_t *md = &hm2->md[md_index];
    hm2_pwmgen_t *p = &hm2->pwmgen;
    if (check_md(hm2, md_index) < 0)
        return -EINVAL;
    int n = hm2_md_instances_to_use(hm2, md_index, hm2->config.num_pwmgens, "num_pwmgens");
    if (n <= 0)
        return n;
    p->num_instances = n;
    p->version = md->version;
    p->clock_freq = md->clock_freq;
    p->pwm_value_addr = md->base_address;
    p->pwm_mode_addr = md->base_address + 1 * md->register_stride;
    p->pwmgen_master_rate_dds_addr = md->base_address + 2 * md->register_stride;
    p->pdmgen_master_rate_dds_addr = md->base_address + 3 * md->register_stride;
    p->enable_addr = md->base_address + 4 * md->register_stride;
    p->instance = calloc(n, sizeof(*p->instance));
    p->hal = hal_malloc(sizeof(*p->hal));
    if (!p->instance || !p->hal)
        return -ENOMEM;
    int r = hm2_register_tram_write_region(hm2, p->pwm_value_addr, n * 4, &p->pwm_value_reg);
    if (r == 0)
        r = hal_param_u32_newf(HAL_RW, &p->hal->pwm_frequency, hm2->llio->comp_id,
                               "%s.pwmgen.pwm_frequency", hm2->llio->name);
    if (r == 0)
        r = hal_param_u32_newf(HAL_RW, &p->hal->pdm_frequency, hm2->llio->comp_id,
                               "%s.pwmgen.pdm_frequency", hm2->llio->name);
    p->hal->pwm_frequency = HM2_PWMGEN_DEFAULT_FREQUENCY;
    p->hal->pdm_frequency = HM2_PWMGEN_DEFAULT_FREQUENCY;
    for (int i = 0; r == 0 && i < n; i++)
        r = export_instance(hm2, i);
    if (r < 0) {
        HM2_ERR(hm2, "error adding pwmgen HAL objects, aborting\n");
        return r;
    }
    return n;
}

/* Invalid output types fall back to PWM/Dir with the list of valid ones. */
static void check_output_type(hm2_board_t *hm2, hm2_pwmgen_hal_t *h)
{
    if (h->output_type >= HM2_PWMGEN_OUTPUT_TYPE_PWM && h->output_type <= HM2_PWMGEN_OUTPUT_TYPE_DIR_PWM)
        return;
    HM2_ERR(hm2, "invalid pwmgen output_type %d requested\n", (int)h->output_type);
    HM2_ERR(hm2, "supported .output-type values are: 1 (PWM & Dir), 2 (Up & Down), 3 (PDM & Dir), "
            "and 4 (Dir & PWM)\n");
    HM2_ERR(hm2, "switching to 1 (PWM & Dir)\n");
    h->output_type = HM2_PWMGEN_OUTPUT_TYPE_PWM;
}

/* Recompute the master DDS values from the frequency params (messages on clamping). */
static void compute_rates(hm2_board_t *hm2)
{
    hm2_pwmgen_t *p = &hm2->pwmgen;
    hm2_pwmgen_rate_t pwm = hm2_pwmgen_pwm_rate(p->clock_freq, p->hal->pwm_frequency);
    hm2_pwmgen_rate_t pdm = hm2_pwmgen_pdm_rate(p->clock_freq, p->hal->pdm_frequency);
    if (pwm.note == HM2_PWMGEN_RATE_TOO_LOW)
        HM2_ERR(hm2, "pwmgen.pwm_frequency %u is too low, setting to 1\n", (unsigned)p->hal->pwm_frequency);
    if (pwm.note == HM2_PWMGEN_RATE_TOO_HIGH)
        HM2_ERR(hm2, "max PWM frequency is %u Hz\n", (unsigned)pwm.frequency);
    if (pdm.note == HM2_PWMGEN_RATE_TOO_LOW)
        HM2_ERR(hm2, "min PDM frequency is %u Hz\n", (unsigned)pdm.frequency);
    if (pdm.note == HM2_PWMGEN_RATE_TOO_HIGH)
        HM2_ERR(hm2, "max PDM frequency is %u Hz\n", (unsigned)pdm.frequency);
    p->hal->pwm_frequency = pwm.frequency;
    p->hal->pdm_frequency = pdm.frequency;
    p->pwm_bits = pwm.bits;
    p->pwm_dds = pwm.dds;
    p->pdm_dds = pdm.dds;
}

/* Mode registers, master rates and the enable mask. */
static void write_config(hm2_board_t *hm2, int (*writer)(hm2_board_t *, uint32_t, const void *, int))
{
    hm2_pwmgen_t *p = &hm2->pwmgen;
    uint32_t enable = 0;
    compute_rates(hm2);
    for (int i = 0; i < p->num_instances; i++) {
        hm2_pwmgen_instance_t *in = &p->instance[i];
        check_output_type(hm2, in->hal);
        uint32_t mode = hm2_pwmgen_mode_word(in->hal->output_type, p->pwm_bits, in->hal->dither);
        writer(hm2, p->pwm_mode_addr + 4 * i, &mode, 4);
        if (*in->hal->enable)
            enable |= 1u << i;
        in->written_output_type = in->hal->output_type;
        in->written_offset_mode = in->hal->offset_mode;
        in->written_dither = in->hal->dither;
        in->written_enable = *in->hal->enable;
    }
    writer(hm2, p->pwmgen_master_rate_dds_addr, &p->pwm_dds, 4);
    writer(hm2, p->pdmgen_master_rate_dds_addr, &p->pdm_dds, 4);
    writer(hm2, p->enable_addr, &enable, 4);
    p->written_pwm_frequency = p->hal->pwm_frequency;
    p->written_pdm_frequency = p->hal->pdm_frequency;
    p->config_written = true;
}

/* Rewrite the configuration when a type, mode, dither, frequency or enable changed. */
void hm2_pwmgen_write(hm2_board_t *hm2)
{
    hm2_pwmgen_t *p = &hm2->pwmgen;
    if (p->num_instances == 0)
        return;
    bool changed = !p->config_written || p->hal->pwm_frequency != p->written_pwm_frequency ||
                   p->hal->pdm_frequency != p->written_pdm_frequency;
    for (int i = 0; i < p->num_instances && !changed; i++) {
        const hm2_pwmgen_instance_t *in = &p->instance[i];
        changed = in->hal->output_type != in->written_output_type ||
                  in->hal->offset_mode != in->written_offset_mode ||
                  in->hal->dither != in->written_dither || *in->hal->enable != in->written_enable;
    }
    if (changed)
        write_config(hm2, hm2_queue_write);
}

/* Write the whole configuration (load and recovery). */
void hm2_pwmgen_force_write(hm2_board_t *hm2)
{
    if (hm2->pwmgen.num_instances)
        write_config(hm2, hm2_write);
}

/* Duty registers from value/scale (0 while disabled). */
void hm2_pwmgen_prepare_tram_write(hm2_board_t *hm2)
{
    hm2_pwmgen_t *p = &hm2->pwmgen;
    for (int i = 0; i < p->num_instances; i++) {
        hm2_pwmgen_hal_t *h = p->instance[i].hal;
        double duty = *h->enable ? *h->value / h->scale : 0.0;
        int bits = h->output_type == HM2_PWMGEN_OUTPUT_TYPE_PDM ? 12 : (int)p->pwm_bits;
        p->pwm_value_reg[i] = hm2_pwmgen_value_register(duty, bits, h->offset_mode, h->dither);
    }
}

/* Release the instance table. */
void hm2_pwmgen_cleanup(hm2_board_t *hm2)
{
    free(hm2->pwmgen.instance);
    hm2->pwmgen.instance = NULL;
}

/* debug_modules: the pwmgen registers. */
void hm2_pwmgen_print_module(hm2_board_t *hm2)
{
    hm2_pwmgen_t *p = &hm2->pwmgen;
    if (p->num_instances == 0)
        return;
    HM2_PRINT(hm2, "PWMGen: %d\n", p->num_instances);
    HM2_PRINT(hm2, "    clock_frequency: %d Hz\n", (int)p->clock_freq);
    HM2_PRINT(hm2, "    pwm_value_addr: 0x%04X\n", p->pwm_value_addr);
    HM2_PRINT(hm2, "    pwm_mode_addr: 0x%04X\n", p->pwm_mode_addr);
    HM2_PRINT(hm2, "    pwmgen_master_rate_dds: 0x%08X (0x%04X)\n", p->pwm_dds, p->pwmgen_master_rate_dds_addr);
    HM2_PRINT(hm2, "    pdmgen_master_rate_dds: 0x%08X (0x%04X)\n", p->pdm_dds, p->pdmgen_master_rate_dds_addr);
    HM2_PRINT(hm2, "    enable_addr: 0x%04X\n", p->enable_addr);
}
