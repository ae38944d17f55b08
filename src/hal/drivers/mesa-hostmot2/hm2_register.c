/* hm2_register.c: hm2_register/hm2_unregister, the steps that turn a board driver's llio into HAL objects. */
#include <stdlib.h>
#include <string.h>
#include "rtapi_errno.h"
#include "hm2.h"
#include "hm2_firmware.h"

void hm2_board_list_add(hm2_board_t *hm2);
void hm2_board_list_remove(hm2_board_t *hm2);

/* Step 1: the llio's name, connectors and ops table must be usable. */
static int validate_llio(const hm2_llio_t *llio)
{
    if (!llio) {
        rtapi_print_msg(RTAPI_MSG_ERR, "hm2: NULL llio passed in\n");
        return -EINVAL;
    }
    size_t len = strnlen(llio->name, sizeof(llio->name));
    const char *why = len == 0 ? "zero length" : len == sizeof(llio->name) ? "not NULL terminated" : NULL;
    for (size_t i = 0; !why && i < len; i++)
        if (llio->name[i] < 0x21 || llio->name[i] > 0x7e)
            why = "contains non-printable character";
    if (why) {
        rtapi_print_msg(RTAPI_MSG_ERR, "hm2: invalid llio name passed in (%s)\n", why);
        return -EINVAL;
    }
    if (llio->num_ioport_connectors < 1 || llio->num_ioport_connectors > HM2_LLIO_MAX_CONNECTORS) {
        rtapi_print_msg(RTAPI_MSG_ERR, "hm2: llio reports invalid number of I/O connectors (%d)\n",
                        llio->num_ioport_connectors);
        return -EINVAL;
    }
    for (int i = 0; i < llio->num_ioport_connectors; i++) {
        if (!llio->ioport_connector_name[i]) {
            rtapi_print_msg(RTAPI_MSG_ERR, "hm2: llio ioport connector name %d is NULL\n", i);
            return -EINVAL;
        }
    }
    if (!llio->ops || llio->ops->version != HM2_LLIO_OPS_VERSION || !llio->ops->read ||
        !llio->ops->write) {
        rtapi_print_msg(RTAPI_MSG_ERR, "hm2: llio %s has ops table version %d, this hostmot2 needs "
                        "version %d with read and write, refusing it\n", llio->name,
                        llio->ops ? llio->ops->version : -1, HM2_LLIO_OPS_VERSION);
        return -EINVAL;
    }
    return 0;
}

/* Steps 2-5: config string, firmware, the io_error param, the greeting. */
static int setup_board(hm2_board_t *hm2, const char *config)
{
    char err[256];
    int r = hm2_config_parse(&hm2->config, config, err, sizeof(err));
    if (r < 0) {
        HM2_ERR(hm2, "%s\n", err);
        return r;
    }
    if (hm2->llio->ops->program_fpga) {
        if (!hm2->config.have_firmware)
            rtapi_print("hm2: no firmware specified in config modparam!  the board had better have "
                        "firmware configured already, or this won't work\n");
        else if ((r = hm2_load_firmware(hm2)) < 0)
            return r;
    }
    hm2->llio->io_error = hal_malloc(sizeof(hal_bit_t));
    if (!hm2->llio->io_error)
        return -ENOMEM;
    r = hal_param_bit_newf(HAL_RW, hm2->llio->io_error, hm2->llio->comp_id, "%s.io_error",
                           hm2->llio->name);
    if (r < 0) {
        HM2_ERR(hm2, "error adding param '%s.io_error', aborting\n", hm2->llio->name);
        return r;
    }
    *hm2->llio->io_error = 0;
    HM2_PRINT(hm2, "Low Level init %s\n", HM2_VERSION);
    return 0;
}

/* Steps 8-10: IDROM, descriptors, modules, TRAM, pins, GPIO objects, raw mode. */
static int discover_board(hm2_board_t *hm2)
{
    int r = hm2_read_idrom(hm2);
    if (r == 0)
        r = hm2_read_pin_descriptors(hm2);
    if (r == 0)
        r = hm2_read_module_descriptors(hm2);
    if (r == 0)
        r = hm2_parse_module_descriptors(hm2);
    if (r == 0)
        r = hm2_raw_setup(hm2);
    if (r == 0)
        r = hm2_allocate_tram_regions(hm2);
    if (r == 0)
        r = hm2_configure_pins(hm2);
    if (r == 0)
        r = hm2_ioport_gpio_export_hal(hm2);
    return r;
}

/* Step 11: configuration out, one full read to seed the modules, one write. */
static int initial_transfer(hm2_board_t *hm2)
{
    hm2_force_write(hm2, true);
    if (hm2_tram_queue_reads(hm2) < 0 || hm2_tram_receive_reads(hm2) < 0)
        *hm2->llio->io_error = 1;
    hm2_encoder_tram_init(hm2);
    hm2_stepgen_tram_init(hm2);
    hm2_ioport_gpio_process_tram_read(hm2);
    hm2_watchdog_prepare_tram_write(hm2);
    hm2_ioport_gpio_prepare_tram_write(hm2);
    hm2_pwmgen_prepare_tram_write(hm2);
    hm2_sserial_prepare_tram_write(hm2);
    if (hm2_tram_queue_writes(hm2) < 0 || hm2_tram_send_writes(hm2) < 0)
        *hm2->llio->io_error = 1;
    if (*hm2->llio->io_error) {
        HM2_ERR(hm2, "comm errors while initializing firmware!\n");
        return -EIO;
    }
    return 0;
}

/* Free hostmot2's memory of a board (its HAL objects belong to the driver's component). */
static void free_board(hm2_board_t *hm2)
{
    hm2_cleanup_modules(hm2);
    hm2_tram_free(hm2);
    free(hm2->pin);
    hm2->llio->board = NULL;
    free(hm2);
}

/* Register a board: every step in order; any failure aborts and frees everything. */
int hm2_register(hm2_llio_t *llio, const char *config)
{
    int r = validate_llio(llio);
    if (r < 0)
        return r;
    hm2_board_t *hm2 = calloc(1, sizeof(*hm2));
    if (!hm2) {
        rtapi_print_msg(RTAPI_MSG_ERR, "hm2: out of memory\n");
        return -ENOMEM;
    }
    hm2->llio = llio;
    llio->board = hm2;
    r = setup_board(hm2, config);
    if (r == 0)
        r = discover_board(hm2);
    if (r == 0)
        r = initial_transfer(hm2);
    if (r < 0) {
        free_board(hm2);
        return r;
    }
    hm2_print_pin_usage(hm2);
    if (debug_modules)
        hm2_print_modules(hm2);
    r = hm2_export_functs(hm2);
    if (r < 0) {
        free_board(hm2);
        return r;
    }
    hm2_board_list_add(hm2);
    HM2_PRINT(hm2, "registered\n");
    return 0;
}
EXPORT_SYMBOL(hm2_register);

/* Unregister: the watchdog bites at once (safe outputs), then hostmot2 forgets the board. */
void hm2_unregister(hm2_llio_t *llio)
{
    hm2_board_t *hm2 = llio ? llio->board : NULL;
    if (!hm2)
        return;
    hm2_watchdog_bite_now(hm2);
    HM2_PRINT(hm2, "unregistered\n");
    hm2_board_list_remove(hm2);
    free_board(hm2);
}
EXPORT_SYMBOL(hm2_unregister);
