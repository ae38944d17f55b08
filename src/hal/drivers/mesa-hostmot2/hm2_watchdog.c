/* hm2_watchdog.c: the FPGA watchdog: armed at the first write, petted every write, bite detection. */
#include "rtapi_errno.h"
#include "hm2.h"

#define WATCHDOG_DISABLED 0x80000000u
#define WATCHDOG_TIMER_MAX 0x7FFFFFFFu
#define WATCHDOG_PET 0x5A000000u
#define WATCHDOG_STATUS_BITTEN 0x1u
#define WATCHDOG_DEFAULT_TIMEOUT_NS 5000000u

/* Check the descriptor, register status read / pet write, export has_bit and timeout_ns. */
int hm2_watchdog_parse_md(hm2_board_t *hm2, int md_index)
{
    const hm2_md_t *md = &hm2->md[md_index];
    hm2_watchdog_t *w = &hm2->watchdog;
    const char *b = hm2->llio->name;
    if (!hm2_md_is_consistent_or_complain(hm2, md_index, 0, 3, 4, 0x00))
        return -EINVAL;
    if (md->instances != 1)
        HM2_PRINT(hm2, "MD declares %d watchdogs!  only using the first one...\n", md->instances);
    w->num_instances = 1;
    w->clock_freq = md->clock_freq;
    w->timer_addr = md->base_address;
    w->status_addr = md->base_address + md->register_stride;
    w->reset_addr = md->base_address + 2 * md->register_stride;
    int r = hm2_register_tram_read_region(hm2, w->status_addr, 4, &w->status_reg);
    if (r == 0)
        r = hm2_register_tram_write_region(hm2, w->reset_addr, 4, &w->reset_reg);
    if (r < 0)
        return r;
    w->hal = hal_malloc(sizeof(*w->hal));
    if (!w->hal)
        return -ENOMEM;
    r = hal_pin_bit_newf(HAL_IO, &w->hal->has_bit, hm2->llio->comp_id, "%s.watchdog.has_bit", b);
    if (r == 0)
        r = hal_param_u32_newf(HAL_RW, &w->hal->timeout_ns, hm2->llio->comp_id,
                               "%s.watchdog.timeout_ns", b);
    if (r < 0) {
        HM2_ERR(hm2, "error adding watchdog HAL objects, aborting\n");
        return r;
    }
    *w->hal->has_bit = 0;
    w->hal->timeout_ns = WATCHDOG_DEFAULT_TIMEOUT_NS;
    w->enable = false;
    return 1;
}

/* Timer register for the current timeout; clamps (and rewrites) an out-of-range timeout. */
static uint32_t timer_value(hm2_board_t *hm2)
{
    hm2_watchdog_t *w = &hm2->watchdog;
    if (!w->enable)
        return WATCHDOG_DISABLED;
    double ticks = (double)w->hal->timeout_ns * w->clock_freq / 1e9 - 1.0;
    if (ticks < 0)
        ticks = 0;
    if (ticks >= (double)WATCHDOG_DISABLED) {
        ticks = WATCHDOG_TIMER_MAX;
        w->hal->timeout_ns = (hal_u32_t)((WATCHDOG_TIMER_MAX + 1.0) * 1e9 / w->clock_freq);
        HM2_ERR(hm2, "requested watchdog timeout is out of range, setting it to max: %u ns\n",
                (unsigned)w->hal->timeout_ns);
    }
    return (uint32_t)ticks;
}

/* Bite check: report once, mark the board for recovery. */
void hm2_watchdog_process_tram_read(hm2_board_t *hm2)
{
    hm2_watchdog_t *w = &hm2->watchdog;
    if (w->num_instances == 0 || hm2->needs_reset)
        return;
    if (*w->status_reg & WATCHDOG_STATUS_BITTEN) {
        HM2_ERR(hm2, "Watchdog has bit! (set the .has-bit pin to False to resume)\n");
        *w->hal->has_bit = 1;
        hm2->needs_reset = true;
    }
}

/* Every write pets the watchdog. */
void hm2_watchdog_prepare_tram_write(hm2_board_t *hm2)
{
    if (hm2->watchdog.num_instances == 0)
        return;
    *hm2->watchdog.reset_reg = WATCHDOG_PET;
}

/* Write the timer when the timeout or the enable changed; warn about short timeouts. */
void hm2_watchdog_write(hm2_board_t *hm2, long period_ns)
{
    hm2_watchdog_t *w = &hm2->watchdog;
    if (w->num_instances == 0)
        return;
    if (w->enable == w->written_enable && w->hal->timeout_ns == w->written_timeout_ns)
        return;
    uint32_t timer = timer_value(hm2);
    if (w->enable && period_ns > 0 && (double)w->hal->timeout_ns < 1.5 * period_ns)
        HM2_PRINT(hm2, "Watchdog timeout (%u ns) is dangerously short compared to hm2_write() "
                  "period (%ld ns)\n", (unsigned)w->hal->timeout_ns, period_ns);
    hm2_queue_write(hm2, w->timer_addr, &timer, 4);
    w->written_enable = w->enable;
    w->written_timeout_ns = w->hal->timeout_ns;
}

/* Timer and a pet; with clear_bite also the status, after which the outputs follow the modules. */
void hm2_watchdog_force_write(hm2_board_t *hm2, bool clear_bite)
{
    hm2_watchdog_t *w = &hm2->watchdog;
    if (w->num_instances == 0)
        return;
    uint32_t timer = timer_value(hm2), status = 0, pet = WATCHDOG_PET;
    hm2_write(hm2, w->timer_addr, &timer, 4);
    if (clear_bite)
        hm2_write(hm2, w->status_addr, &status, 4);
    hm2_write(hm2, w->reset_addr, &pet, 4);
    w->written_enable = w->enable;
    w->written_timeout_ns = w->hal->timeout_ns;
}

/* Make the watchdog bite at once (unregister): every output goes to its safe state. */
void hm2_watchdog_bite_now(hm2_board_t *hm2)
{
    hm2_watchdog_t *w = &hm2->watchdog;
    if (w->num_instances == 0)
        return;
    w->enable = true;
    w->hal->timeout_ns = 1;
    uint32_t timer = timer_value(hm2);
    hm2_write(hm2, w->timer_addr, &timer, 4);
}

/* debug_modules: the watchdog. */
void hm2_watchdog_print_module(hm2_board_t *hm2)
{
    hm2_watchdog_t *w = &hm2->watchdog;
    if (w->num_instances == 0)
        return;
    HM2_PRINT(hm2, "Watchdog: %d\n", w->num_instances);
    HM2_PRINT(hm2, "    clock_frequency: %d Hz\n", (int)w->clock_freq);
    HM2_PRINT(hm2, "    timer_addr: 0x%04X\n", w->timer_addr);
    HM2_PRINT(hm2, "    status_addr: 0x%04X\n", w->status_addr);
    HM2_PRINT(hm2, "    reset_addr: 0x%04X\n", w->reset_addr);
    HM2_PRINT(hm2, "    has_bit: %d\n", (int)*w->hal->has_bit);
    HM2_PRINT(hm2, "    timeout_ns: %u\n", (unsigned)w->hal->timeout_ns);
}
