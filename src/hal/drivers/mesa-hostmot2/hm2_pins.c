/* hm2_pins.c: which module drives each IO pin, pin directions, and the pin usage log. */
#include "rtapi_errno.h"
#include "hm2.h"

/* DB25 order of a 17-pin port: IO bit -> connector pin. */
static const int db25_pin[17] = {1, 14, 2, 15, 3, 16, 4, 17, 5, 6, 7, 8, 9, 10, 11, 12, 13};

/* Connector pin number of IO io (1-based), or -1 for an unknown port width. */
int hm2_connector_pin_number(hm2_board_t *hm2, int io)
{
    int width = (int)hm2->idrom.port_width;
    switch (width) {
    case 24:
        return (io % 24) * 2 + 1;
    case 17:
        return db25_pin[io % 17];
    case 19: case 21: case 27: case 29: case 30: case 32:
        return io % width + 1;
    default:
        return -1;
    }
}

/* True when io is controlled by an IOPort register (else the error is logged). */
static bool ioport_has_pin(hm2_board_t *hm2, int io, const char *who)
{
    if (io < 0 || io >= hm2->ioport.num_instances * (int)hm2->idrom.port_width) {
        HM2_ERR(hm2, "%s: invalid pin number %d\n", who, io);
        return false;
    }
    return true;
}

/* Route io to its module (alt source) or to the IOPort data register. */
void hm2_set_pin_source(hm2_board_t *hm2, int io, int source_is_module)
{
    if (!ioport_has_pin(hm2, io, "hm2_set_pin_source"))
        return;
    int port = io / hm2->idrom.port_width, bit = io % hm2->idrom.port_width;
    if (source_is_module)
        hm2->ioport.alt_source[port] |= 1u << bit;
    else
        hm2->ioport.alt_source[port] &= ~(1u << bit);
}

/* Set a direction that applies from now on (and at start). */
void hm2_set_pin_direction_immediate(hm2_board_t *hm2, int io, int direction)
{
    if (!ioport_has_pin(hm2, io, "hm2_set_pin_direction_immediate"))
        return;
    hm2->pin[io].direction = direction;
    hm2->pin[io].direction_at_start = direction;
}

/* Set a direction that applies at the first write (outputs stay inputs until then). */
void hm2_set_pin_direction_at_start(hm2_board_t *hm2, int io, int direction)
{
    if (!ioport_has_pin(hm2, io, "hm2_set_pin_direction_at_start"))
        return;
    hm2->pin[io].direction_at_start = direction;
}

/* Hand io to module gtag; outputs take effect at once or at the first write. */
static void take_pin(hm2_board_t *hm2, int io, int gtag, bool at_start)
{
    hm2_pin_t *p = &hm2->pin[io];
    int dir = (p->sec_pin & HM2_PIN_OUTPUT_FLAG) ? HM2_PIN_DIR_OUT : HM2_PIN_DIR_IN;
    p->gtag = gtag;
    hm2_set_pin_source(hm2, io, 1);
    if (at_start)
        hm2_set_pin_direction_at_start(hm2, io, dir);
    else
        hm2_set_pin_direction_immediate(hm2, io, dir);
}

/* Give module gtag every pin of its first `units` instances (and global pins). */
static void allocate_module_pins(hm2_board_t *hm2, int gtag, int units, bool at_start)
{
    if (units <= 0)
        return;
    for (int io = 0; io < hm2->num_pins; io++) {
        const hm2_pin_t *p = &hm2->pin[io];
        if (p->sec_tag != gtag)
            continue;
        if ((p->sec_unit & HM2_UNIT_GLOBAL_FLAG) || p->sec_unit < units)
            take_pin(hm2, io, gtag, at_start);
    }
}

/* Every IO starts as a GPIO input; then each enabled module takes its pins. */
int hm2_configure_pins(hm2_board_t *hm2)
{
    for (int io = 0; io < hm2->num_pins; io++) {
        hm2->pin[io].gtag = HM2_GTAG_IOPORT;
        hm2_set_pin_source(hm2, io, 0);
        hm2_set_pin_direction_immediate(hm2, io, HM2_PIN_DIR_IN);
    }
    if (hm2->encoder.muxed) {
        allocate_module_pins(hm2, HM2_GTAG_MUXED_ENCODER, (hm2->encoder.num_instances + 1) / 2, true);
        allocate_module_pins(hm2, HM2_GTAG_MUXED_ENCODER_SEL, hm2->encoder.num_instances, true);
    } else {
        allocate_module_pins(hm2, HM2_GTAG_ENCODER, hm2->encoder.num_instances, true);
    }
    hm2_stepgen_allocate_pins(hm2);
    allocate_module_pins(hm2, HM2_GTAG_PWMGEN, hm2->pwmgen.num_instances, true);
    allocate_module_pins(hm2, HM2_GTAG_DPLL, hm2->dpll.num_instances, true);
    allocate_module_pins(hm2, HM2_GTAG_UART_TX, hm2->uart.num_instances, false);
    allocate_module_pins(hm2, HM2_GTAG_UART_RX, hm2->uart.num_instances, false);
    allocate_module_pins(hm2, HM2_GTAG_PKTUART_TX, hm2->pktuart.num_instances, false);
    allocate_module_pins(hm2, HM2_GTAG_PKTUART_RX, hm2->pktuart.num_instances, false);
    allocate_module_pins(hm2, HM2_GTAG_BSPI, hm2->bspi.num_instances, false);
    hm2_sserial_allocate_pins(hm2);
    return 0;
}

/* Stepgen outputs above stepgen_width stay GPIO; its inputs are always taken. */
void hm2_stepgen_allocate_pins(hm2_board_t *hm2)
{
    int units = hm2->stepgen.num_instances;
    for (int io = 0; io < hm2->num_pins && units > 0; io++) {
        const hm2_pin_t *p = &hm2->pin[io];
        if (p->sec_tag != HM2_GTAG_STEPGEN || p->sec_unit >= units)
            continue;
        if ((p->sec_pin & HM2_PIN_OUTPUT_FLAG) &&
            (p->sec_pin & 0x7F) > hm2->config.stepgen_width)
            continue;
        take_pin(hm2, io, HM2_GTAG_STEPGEN, true);
    }
}

/* "P2-01" from the connector table, or the llio's per-IO name (NULL = no line). */
static const char *pin_location(hm2_board_t *hm2, int io, char *buf, int len)
{
    const hm2_llio_t *llio = hm2->llio;
    if (llio->io_connector_pin_names)
        return llio->io_connector_pin_names[io];
    int width = (int)hm2->idrom.port_width;
    int conn = width ? io / width : 0;
    const char *cname = conn < llio->num_ioport_connectors ? llio->ioport_connector_name[conn] : "??";
    rtapi_snprintf(buf, len, "%s-%02d", cname, hm2_connector_pin_number(hm2, io));
    return buf;
}

/* The pin usage table printed after every registration. */
void hm2_print_pin_usage(hm2_board_t *hm2)
{
    char loc[32], pname[32];
    HM2_PRINT(hm2, "%d I/O Pins used:\n", hm2->num_pins);
    for (int io = 0; io < hm2->num_pins; io++) {
        const hm2_pin_t *p = &hm2->pin[io];
        const char *where = pin_location(hm2, io, loc, sizeof(loc));
        if (!where)
            continue;
        if (p->gtag == HM2_GTAG_IOPORT) {
            HM2_PRINT(hm2, "    IO Pin %03d (%s): IOPort\n", io, where);
            continue;
        }
        const char *fname = hm2_gtag_name(p->sec_tag);
        const char *dir = (p->sec_pin & HM2_PIN_OUTPUT_FLAG) ? "Output" : "Input";
        const char *shown = hm2_pin_log_name(p->sec_tag, p->sec_pin, pname, sizeof(pname));
        if (p->sec_unit & HM2_UNIT_GLOBAL_FLAG)
            HM2_PRINT(hm2, "    IO Pin %03d (%s): %s (all), pin %s (%s)\n", io, where, fname, shown, dir);
        else
            HM2_PRINT(hm2, "    IO Pin %03d (%s): %s #%d, pin %s (%s)\n", io, where, fname,
                      p->sec_unit, shown, dir);
    }
}
