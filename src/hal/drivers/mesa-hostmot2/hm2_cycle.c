/* hm2_cycle.c: the board's functs (read-request, read, write, read_gpio, write_gpio) and recovery. */
#include "rtapi_errno.h"
#include "hm2.h"

/* Queue and send this cycle's TRAM reads; a failure is a hard error. */
static void request_reads(hm2_board_t *hm2, long period)
{
    hm2->llio->period_ns = period;
    hm2_raw_queue_read(hm2);
    if (hm2_tram_queue_reads(hm2) < 0)
        *hm2->llio->io_error = 1;
    hm2->read_requested = true;
}

/* read-request funct: send the reads early so several boards overlap their round trips. */
static void read_request_funct(void *arg, long period)
{
    hm2_board_t *hm2 = arg;
    if (*hm2->llio->io_error)
        return;
    request_reads(hm2, period);
}

/* Run every module's read processing, in LinuxCNC's order. */
static void process_reads(hm2_board_t *hm2, long period)
{
    hm2_watchdog_process_tram_read(hm2);
    hm2_ioport_gpio_process_tram_read(hm2);
    hm2_encoder_process_tram_read(hm2, period);
    hm2_stepgen_process_tram_read(hm2, period);
    hm2_bspi_process_tram_read(hm2);
    hm2_sserial_process_tram_read(hm2);
    hm2_dpll_process_tram_read(hm2, period);
    hm2_raw_process_read(hm2);
}

/* read funct: receive the reads (requesting them first if needed) and process them. */
static void read_funct(void *arg, long period)
{
    hm2_board_t *hm2 = arg;
    if (*hm2->llio->io_error)
        return;
    if (!hm2->read_requested)
        request_reads(hm2, period);
    hm2->read_requested = false;
    if (*hm2->llio->io_error)
        return;
    int r = hm2_tram_receive_reads(hm2);
    hm2->read_iter++;
    if (r == -EAGAIN) {
        hm2->needs_soft_reset = true;
        return;
    }
    if (r < 0) {
        HM2_ERR(hm2, "error finishing read! iter=%u\n", hm2->read_iter);
        *hm2->llio->io_error = 1;
        return;
    }
    process_reads(hm2, period);
}

/* Write every module's configuration registers (load, recovery after a bite or lost packet).
   Only clear_bite clears a watchdog bite: a lost packet must not re-enable outputs behind the
   user's back (the bite is reported and waits for has_bit FALSE). */
void hm2_force_write(hm2_board_t *hm2, bool clear_bite)
{
    if (hm2->llio->ops->set_force_enqueue)
        hm2->llio->ops->set_force_enqueue(hm2->llio, true);
    hm2_watchdog_force_write(hm2, clear_bite);
    hm2_ioport_force_write(hm2);
    hm2_encoder_force_write(hm2);
    hm2_stepgen_force_write(hm2);
    hm2_pwmgen_force_write(hm2);
    hm2_dpll_force_write(hm2);
    hm2->led.ever_written = false;
    if (hm2->llio->ops->set_force_enqueue)
        hm2->llio->ops->set_force_enqueue(hm2->llio, false);
}

/* First write: module outputs take their direction now (no glitches while loading). */
static void apply_start_directions(hm2_board_t *hm2)
{
    for (int io = 0; io < hm2->num_pins; io++)
        hm2->pin[io].direction = hm2->pin[io].direction_at_start;
    hm2->watchdog.enable = true;
    hm2->first_write_done = true;
}

/* Recovery after a bite (once has_bit is FALSE) or silently after a lost packet. */
static void recover_if_needed(hm2_board_t *hm2)
{
    if (hm2->needs_reset) {
        if (hm2->watchdog.num_instances && *hm2->watchdog.hal->has_bit)
            return;
        HM2_PRINT(hm2, "trying to recover from IO error or Watchdog bite\n");
        hm2_force_write(hm2, true);
        hm2->needs_reset = false;
        hm2->needs_soft_reset = false;
        if (*hm2->llio->io_error)
            HM2_PRINT(hm2, "error recovery failed\n");
        else
            HM2_PRINT(hm2, "error recover successful!\n");
        return;
    }
    if (hm2->needs_soft_reset) {
        hm2_force_write(hm2, false);
        hm2->needs_soft_reset = false;
    }
}

/* Queue the cycle writes: TRAM regions first, then changed configuration registers. */
static void queue_cycle_writes(hm2_board_t *hm2, long period)
{
    hm2_watchdog_prepare_tram_write(hm2);
    hm2_ioport_gpio_prepare_tram_write(hm2);
    hm2_pwmgen_prepare_tram_write(hm2);
    hm2_stepgen_prepare_tram_write(hm2, period);
    hm2_bspi_prepare_tram_write(hm2);
    hm2_sserial_prepare_tram_write(hm2);
    if (hm2_tram_queue_writes(hm2) < 0) {
        *hm2->llio->io_error = 1;
        return;
    }
    hm2_ioport_write(hm2);
    hm2_watchdog_write(hm2, period);
    hm2_pwmgen_write(hm2);
    hm2_stepgen_write(hm2);
    hm2_encoder_write(hm2);
    hm2_dpll_write(hm2, period);
    hm2_led_write(hm2);
    hm2_sserial_write(hm2);
    hm2_raw_write(hm2);
}

/* write funct: outputs, pet, config changes, recovery; one packet for a queuing driver. */
static void write_funct(void *arg, long period)
{
    hm2_board_t *hm2 = arg;
    if (*hm2->llio->io_error) {
        hm2->io_error_seen = true;
        return;
    }
    if (hm2->io_error_seen) {
        hm2->io_error_seen = false;
        hm2->needs_soft_reset = true;
    }
    if (!hm2->first_write_done)
        apply_start_directions(hm2);
    recover_if_needed(hm2);
    queue_cycle_writes(hm2, period);
    if (!*hm2->llio->io_error) {
        int r = hm2_tram_send_writes(hm2);
        if (r == -EAGAIN)
            hm2->needs_soft_reset = true;
        else if (r < 0)
            *hm2->llio->io_error = 1;
    }
    hm2->write_iter++;
}

/* read_gpio funct (thread-safe boards): GPIO inputs now. */
static void read_gpio_funct(void *arg, long period)
{
    hm2_board_t *hm2 = arg;
    (void)period;
    if (*hm2->llio->io_error)
        return;
    hm2_ioport_gpio_read(hm2);
}

/* write_gpio funct (thread-safe boards): GPIO outputs and a watchdog pet now. */
static void write_gpio_funct(void *arg, long period)
{
    hm2_board_t *hm2 = arg;
    if (*hm2->llio->io_error)
        return;
    if (!hm2->first_write_done)
        return;
    hm2_ioport_gpio_write(hm2);
    hm2_watchdog_write(hm2, period);
    if (hm2->watchdog.num_instances) {
        uint32_t pet = 0x5A000000u;
        hm2_write(hm2, hm2->watchdog.reset_addr, &pet, 4);
    }
}

/* Export one funct named <board>.<what>. */
static int export_one(hm2_board_t *hm2, const char *what, void (*fn)(void *, long))
{
    char name[HAL_NAME_LEN + 1];
    rtapi_snprintf(name, sizeof(name), "%s.%s", hm2->llio->name, what);
    int r = hal_export_funct(name, fn, hm2, 1, 0, hm2->llio->comp_id);
    if (r < 0)
        HM2_ERR(hm2, "error %d exporting funct %s\n", r, name);
    return r;
}

/* The board's functs: read-request only for split-read drivers, GPIO ones for thread-safe ones. */
int hm2_export_functs(hm2_board_t *hm2)
{
    int r = 0;
    if (hm2->llio->split_read)
        r = export_one(hm2, "read-request", read_request_funct);
    if (r == 0)
        r = export_one(hm2, "read", read_funct);
    if (r == 0)
        r = export_one(hm2, "write", write_funct);
    if (r == 0 && hm2->llio->threadsafe)
        r = export_one(hm2, "read_gpio", read_gpio_funct);
    if (r == 0 && hm2->llio->threadsafe)
        r = export_one(hm2, "write_gpio", write_gpio_funct);
    return r;
}

/* debug_modules: every module's state. */
void hm2_print_modules(hm2_board_t *hm2)
{
    hm2_watchdog_print_module(hm2);
    hm2_ioport_print_module(hm2);
    hm2_encoder_print_module(hm2);
    hm2_stepgen_print_module(hm2);
    hm2_pwmgen_print_module(hm2);
    hm2_sserial_print_module(hm2);
}

/* Release every module's memory (HAL objects go with the driver's component). */
void hm2_cleanup_modules(hm2_board_t *hm2)
{
    hm2_ioport_cleanup(hm2);
    hm2_encoder_cleanup(hm2);
    hm2_stepgen_cleanup(hm2);
    hm2_pwmgen_cleanup(hm2);
    hm2_dpll_cleanup(hm2);
    hm2_uart_cleanup(hm2);
    hm2_pktuart_cleanup(hm2);
    hm2_bspi_cleanup(hm2);
    hm2_sserial_cleanup(hm2);
}
