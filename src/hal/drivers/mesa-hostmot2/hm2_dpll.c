/* hm2_dpll.c: the DPLL timer module (GTag 26): a reference locked to the servo thread, four timers. */
#include "rtapi_errno.h"
#include "rtapi_math.h"
#include "hm2.h"

#define DPLL_DEFAULT_TIMER_US 100.0
#define DPLL_DEFAULT_TIME_CONST 2000u
#define DPLL_DEFAULT_PLIMIT 0x400000u
#define DPLL_HOLD_WRITES 100
#define DPLL_DEFAULT_DDSIZE 32

/* Pins with their defaults. */
static int export_pins(hm2_board_t *hm2, hm2_dpll_hal_t *h)
{
    const char *b = hm2->llio->name;
    int id = hm2->llio->comp_id, r = 0;
    for (int t = 0; r == 0 && t < 4; t++)
        r = hal_pin_float_newf(HAL_IN, &h->time_us[t], id, "%s.dpll.%02d.timer-us", b, t + 1);
    if (r == 0)
        r = hal_pin_float_newf(HAL_IN, &h->base_freq, id, "%s.dpll.base-freq-khz", b);
    if (r == 0)
        r = hal_pin_float_newf(HAL_OUT, &h->phase_error, id, "%s.dpll.phase-error-us", b);
    if (r == 0)
        r = hal_pin_u32_newf(HAL_IN, &h->time_const, id, "%s.dpll.time-const", b);
    if (r == 0)
        r = hal_pin_u32_newf(HAL_IN, &h->plimit, id, "%s.dpll.plimit", b);
    if (r == 0)
        r = hal_pin_u32_newf(HAL_OUT, &h->ddsize, id, "%s.dpll.ddsize", b);
    if (r == 0)
        r = hal_pin_u32_newf(HAL_OUT, &h->prescale, id, "%s.dpll.prescale", b);
    if (r < 0)
        return r;
    for (int t = 0; t < 4; t++)
        *h->time_us[t] = DPLL_DEFAULT_TIMER_US;
    *h->base_freq = -1.0;
    *h->time_const = DPLL_DEFAULT_TIME_CONST;
    *h->plimit = DPLL_DEFAULT_PLIMIT;
    *h->prescale = 1;
    return 0;
}

/* Parse the DPLL descriptor (one instance at most; num_dplls=0 disables it). */
int hm2_dpll_parse_md(hm2_board_t *hm2, int md_index)
{
    const hm2_md_t *md = &hm2->md[md_index];
    hm2_dpll_t *d = &hm2->dpll;
    if (!hm2_md_is_consistent_or_complain(hm2, md_index, 0, 7, 4, 0x00))
        return -EINVAL;
    if (hm2->config.num_dplls == 0)
        return 0;
    if (hm2->config.num_dplls > md->instances)
        HM2_ERR(hm2, "There are only %d dplls on this board type, using %d\n", md->instances,
                md->instances);
    d->num_instances = 1;
    d->clock_freq = md->clock_freq;
    uint32_t b = md->base_address, rs = md->register_stride;
    d->base_rate_addr = b;
    d->phase_err_addr = b + rs;
    d->control_reg0_addr = b + 2 * rs;
    d->control_reg1_addr = b + 3 * rs;
    d->timer_12_addr = b + 4 * rs;
    d->timer_34_addr = b + 5 * rs;
    d->hm2_dpll_sync_addr = b + 6 * rs;
    int r = hm2_register_tram_read_region(hm2, d->hm2_dpll_sync_addr, 4, &d->hm2_dpll_sync_reg);
    if (r == 0)
        r = hm2_register_tram_read_region(hm2, d->control_reg1_addr, 4, &d->control_reg1_read);
    if (r < 0)
        return r;
    d->hal = hal_malloc(sizeof(*d->hal));
    if (!d->hal)
        return -ENOMEM;
    r = export_pins(hm2, d->hal);
    if (r < 0) {
        HM2_ERR(hm2, "error adding DPLL HAL objects, aborting\n");
        return r;
    }
    return 1;
}

/* Phase error (s32 of the period / 2^32) in us, and the DDS size read back. */
void hm2_dpll_process_tram_read(hm2_board_t *hm2, long period_ns)
{
    hm2_dpll_t *d = &hm2->dpll;
    if (d->num_instances == 0)
        return;
    *d->hal->phase_error = (int32_t)*d->hm2_dpll_sync_reg * (double)period_ns / 4294967296.0 / 1000.0;
    *d->hal->ddsize = *d->control_reg1_read & 0xFF;
}

/* Timer word: 16-bit fractions of the period before the reference, timer b high, a low. */
static uint32_t timer_word(double a_us, double b_us, double period_us)
{
    uint32_t lo = (uint32_t)(int32_t)(-a_us / period_us * 65536.0) & 0xFFFF;
    uint32_t hi = (uint32_t)(int32_t)(-b_us / period_us * 65536.0) & 0xFFFF;
    return hi << 16 | lo;
}

/* Write base rate, controls and timers when they change; hold the phase error for 100 writes. */
static void write_registers(hm2_board_t *hm2, long period_ns, bool force)
{
    hm2_dpll_t *d = &hm2->dpll;
    hm2_dpll_hal_t *h = d->hal;
    double period_us = period_ns > 0 ? period_ns / 1000.0 : 1000.0;
    if (*h->base_freq < 0)
        *h->base_freq = 1000.0 / period_us;
    int ddsize = (int)*h->ddsize ? (int)*h->ddsize : DPLL_DEFAULT_DDSIZE;
    double rate = *h->base_freq * 1000.0 * ldexp(1.0, ddsize) / d->clock_freq;
    uint32_t regs[5] = {
        rate >= 4294967295.0 ? 0xFFFFFFFFu : (uint32_t)rate,
        (*h->prescale & 0xFF) << 24 | (*h->plimit & 0xFFFFFF),
        *h->time_const << 16,
        timer_word(*h->time_us[0], *h->time_us[1], period_us),
        timer_word(*h->time_us[2], *h->time_us[3], period_us),
    };
    uint32_t *written[5] = {&d->written_base_rate, &d->written_control0, &d->written_control1,
                            &d->written_timer_12, &d->written_timer_34};
    uint32_t addrs[5] = {d->base_rate_addr, d->control_reg0_addr, d->control_reg1_addr,
                         d->timer_12_addr, d->timer_34_addr};
    for (int k = 0; k < 5; k++) {
        if (force || !d->written_once || regs[k] != *written[k])
            hm2_queue_write(hm2, addrs[k], &regs[k], 4);
        *written[k] = regs[k];
    }
    if (d->writes_done < DPLL_HOLD_WRITES) {
        uint32_t zero = 0;
        hm2_queue_write(hm2, d->phase_err_addr, &zero, 4);
        d->writes_done++;
    }
    d->written_once = true;
}

/* Changed registers (write funct). */
void hm2_dpll_write(hm2_board_t *hm2, long period_ns)
{
    if (hm2->dpll.num_instances)
        write_registers(hm2, period_ns, false);
}

/* Everything again on the next write (period unknown here). */
void hm2_dpll_force_write(hm2_board_t *hm2)
{
    hm2->dpll.written_once = false;
}

/* Nothing allocated outside HAL memory. */
void hm2_dpll_cleanup(hm2_board_t *hm2)
{
    hm2->dpll.num_instances = 0;
}
