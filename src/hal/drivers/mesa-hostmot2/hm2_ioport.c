/* hm2_ioport.c: the IOPort module: GPIO data, direction, open drain and invert registers. */
#include <stdlib.h>
#include "rtapi_errno.h"
#include "hm2.h"

/* Port and bit of an IO. */
#define PORT_OF(hm2, io) ((io) / (int)(hm2)->idrom.port_width)
#define BIT_OF(hm2, io) (1u << ((io) % (int)(hm2)->idrom.port_width))

/* Check the IOPort descriptor, register its TRAM regions and allocate its register images. */
int hm2_ioport_parse_md(hm2_board_t *hm2, int md_index)
{
    const hm2_md_t *md = &hm2->md[md_index];
    hm2_ioport_t *io = &hm2->ioport;
    if (!hm2_md_is_consistent_or_complain(hm2, md_index, 0, 5, 4, 0x1F))
        return -EINVAL;
    if (md->instances != hm2->idrom.io_ports) {
        HM2_ERR(hm2, "IDROM IOPorts is %d but MD IOPort NumInstances is %d, inconsistent "
                "firmware, aborting driver load\n", (int)hm2->idrom.io_ports, md->instances);
        return -EINVAL;
    }
    io->num_instances = md->instances;
    io->clock_freq = md->clock_freq;
    io->data_addr = md->base_address;
    io->ddr_addr = md->base_address + 1 * md->register_stride;
    io->alt_source_addr = md->base_address + 2 * md->register_stride;
    io->open_drain_addr = md->base_address + 3 * md->register_stride;
    io->output_invert_addr = md->base_address + 4 * md->register_stride;
    int n = io->num_instances;
    uint32_t **arrays[] = {&io->ddr, &io->alt_source, &io->open_drain, &io->output_invert,
                           &io->written_ddr, &io->written_open_drain, &io->written_output_invert};
    for (size_t i = 0; i < sizeof(arrays) / sizeof(arrays[0]); i++) {
        *arrays[i] = calloc(n, sizeof(uint32_t));
        if (!*arrays[i]) {
            HM2_ERR(hm2, "out of memory for the IOPort registers\n");
            return -ENOMEM;
        }
    }
    int r = hm2_register_tram_read_region(hm2, io->data_addr, n * 4, &io->data_read);
    if (r == 0)
        r = hm2_register_tram_write_region(hm2, io->data_addr, n * 4, &io->data_write);
    return r < 0 ? r : n;
}

/* Count IOs before `io` with the same module, unit and secondary pin (and in all). */
static int same_function_index(hm2_board_t *hm2, int io, int *total)
{
    const hm2_pin_t *p = &hm2->pin[io];
    int before = 0;
    *total = 0;
    for (int i = 0; i < hm2->num_pins; i++) {
        const hm2_pin_t *q = &hm2->pin[i];
        if (q->gtag == p->gtag && q->sec_tag == p->sec_tag && q->sec_unit == p->sec_unit &&
            q->sec_pin == p->sec_pin) {
            if (i < io)
                before++;
            (*total)++;
        }
    }
    return before;
}

/* Aliases B.<module>.NN[.k].<suffix>.{invert_output,is_opendrain} for a module output. */
static int alias_module_output(hm2_board_t *hm2, int io)
{
    const hm2_pin_t *p = &hm2->pin[io];
    const char *b = hm2->llio->name;
    const char *module = hm2_gtag_hal_name(p->sec_tag);
    char buf[32], unit[24], param[HAL_NAME_LEN + 1], alias[HAL_NAME_LEN + 1];
    int total, k = same_function_index(hm2, io, &total);
    if (!module)
        return 0;
    const char *suffix = hm2_pin_alias_name(p->sec_tag, p->sec_pin, buf, sizeof(buf));
    if (p->sec_unit & HM2_UNIT_GLOBAL_FLAG)
        unit[0] = '\0';
    else
        rtapi_snprintf(unit, sizeof(unit), ".%02d", p->sec_unit);
    const char *items[] = {"invert_output", "is_opendrain"};
    for (int i = 0; i < 2; i++) {
        rtapi_snprintf(param, sizeof(param), "%s.gpio.%03d.%s", b, io, items[i]);
        if (total > 1)
            rtapi_snprintf(alias, sizeof(alias), "%s.%s%s.%d.%s.%s", b, module, unit, k, suffix, items[i]);
        else
            rtapi_snprintf(alias, sizeof(alias), "%s.%s%s.%s.%s", b, module, unit, suffix, items[i]);
        int r = hal_param_alias(param, alias);
        if (r < 0) {
            HM2_ERR(hm2, "error aliasing %s to %s\n", param, alias);
            return r;
        }
    }
    return 0;
}

/* The HAL objects of one IO: in/in_not always; out and params by ownership. */
static int export_gpio(hm2_board_t *hm2, int io)
{
    hm2_pin_t *p = &hm2->pin[io];
    const char *b = hm2->llio->name;
    int id = hm2->llio->comp_id, r;
    p->hal = hal_malloc(sizeof(*p->hal));
    if (!p->hal)
        return -ENOMEM;
    r = hal_pin_bit_newf(HAL_OUT, &p->hal->in, id, "%s.gpio.%03d.in", b, io);
    if (r == 0)
        r = hal_pin_bit_newf(HAL_OUT, &p->hal->in_not, id, "%s.gpio.%03d.in_not", b, io);
    bool full = p->gtag == HM2_GTAG_IOPORT;
    bool module_out = !full && (p->sec_pin & HM2_PIN_OUTPUT_FLAG);
    if (r == 0 && full)
        r = hal_pin_bit_newf(HAL_IN, &p->hal->out, id, "%s.gpio.%03d.out", b, io);
    if (r == 0 && full)
        r = hal_param_bit_newf(HAL_RW, &p->hal->is_output, id, "%s.gpio.%03d.is_output", b, io);
    if (r == 0 && (full || module_out))
        r = hal_param_bit_newf(HAL_RW, &p->hal->is_opendrain, id, "%s.gpio.%03d.is_opendrain", b, io);
    if (r == 0 && (full || module_out))
        r = hal_param_bit_newf(HAL_RW, &p->hal->invert_output, id, "%s.gpio.%03d.invert_output", b, io);
    if (r == 0 && module_out)
        r = alias_module_output(hm2, io);
    return r;
}

/* Export the GPIO objects of every IO. */
int hm2_ioport_gpio_export_hal(hm2_board_t *hm2)
{
    for (int io = 0; io < hm2->num_pins; io++) {
        int r = export_gpio(hm2, io);
        if (r < 0) {
            HM2_ERR(hm2, "error adding GPIO %03d HAL objects, aborting\n", io);
            return r;
        }
    }
    return 0;
}

/* Pin states from the data registers (every IO, output or not). */
void hm2_ioport_gpio_process_tram_read(hm2_board_t *hm2)
{
    hm2_ioport_t *iop = &hm2->ioport;
    int n = iop->num_instances * (int)hm2->idrom.port_width;
    for (int io = 0; io < n && io < hm2->num_pins; io++) {
        bool bit = (iop->data_read[PORT_OF(hm2, io)] & BIT_OF(hm2, io)) != 0;
        *hm2->pin[io].hal->in = bit;
        *hm2->pin[io].hal->in_not = !bit;
    }
}

/* Data words: `out` of full GPIOs, 0 for module pins. */
void hm2_ioport_gpio_prepare_tram_write(hm2_board_t *hm2)
{
    hm2_ioport_t *iop = &hm2->ioport;
    for (int port = 0; port < iop->num_instances; port++)
        iop->data_write[port] = 0;
    int n = iop->num_instances * (int)hm2->idrom.port_width;
    for (int io = 0; io < n && io < hm2->num_pins; io++) {
        const hm2_pin_t *p = &hm2->pin[io];
        if (p->gtag == HM2_GTAG_IOPORT && *p->hal->out)
            iop->data_write[PORT_OF(hm2, io)] |= BIT_OF(hm2, io);
    }
}

/* Wanted DDR / open-drain / invert images from the pins and their params. */
static void compute_config(hm2_board_t *hm2)
{
    hm2_ioport_t *iop = &hm2->ioport;
    int n = iop->num_instances * (int)hm2->idrom.port_width;
    for (int port = 0; port < iop->num_instances; port++)
        iop->ddr[port] = iop->open_drain[port] = iop->output_invert[port] = 0;
    for (int io = 0; io < n && io < hm2->num_pins; io++) {
        hm2_pin_t *p = &hm2->pin[io];
        int port = PORT_OF(hm2, io);
        uint32_t bit = BIT_OF(hm2, io);
        if (p->gtag == HM2_GTAG_IOPORT && hm2->first_write_done)
            p->direction = p->hal->is_output ? HM2_PIN_DIR_OUT : HM2_PIN_DIR_IN;
        if (p->direction == HM2_PIN_DIR_OUT)
            iop->ddr[port] |= bit;
        bool has_params = p->gtag == HM2_GTAG_IOPORT || (p->sec_pin & HM2_PIN_OUTPUT_FLAG);
        if (has_params && p->hal->is_opendrain)
            iop->open_drain[port] |= bit;
        if (has_params && p->hal->invert_output)
            iop->output_invert[port] |= bit;
    }
}

/* Queue the configuration registers that changed; DDR last. */
void hm2_ioport_write(hm2_board_t *hm2)
{
    hm2_ioport_t *iop = &hm2->ioport;
    compute_config(hm2);
    for (int port = 0; port < iop->num_instances; port++) {
        if (iop->open_drain[port] != iop->written_open_drain[port]) {
            hm2_queue_write(hm2, iop->open_drain_addr + 4 * port, &iop->open_drain[port], 4);
            iop->written_open_drain[port] = iop->open_drain[port];
        }
        if (iop->output_invert[port] != iop->written_output_invert[port]) {
            hm2_queue_write(hm2, iop->output_invert_addr + 4 * port, &iop->output_invert[port], 4);
            iop->written_output_invert[port] = iop->output_invert[port];
        }
    }
    for (int port = 0; port < iop->num_instances; port++) {
        if (iop->ddr[port] != iop->written_ddr[port]) {
            hm2_queue_write(hm2, iop->ddr_addr + 4 * port, &iop->ddr[port], 4);
            iop->written_ddr[port] = iop->ddr[port];
        }
    }
}

/* Write every configuration register: invert, open drain, alt source, DDR. */
void hm2_ioport_force_write(hm2_board_t *hm2)
{
    hm2_ioport_t *iop = &hm2->ioport;
    int n = iop->num_instances;
    if (n == 0)
        return;
    compute_config(hm2);
    hm2_write(hm2, iop->output_invert_addr, iop->output_invert, n * 4);
    hm2_write(hm2, iop->open_drain_addr, iop->open_drain, n * 4);
    hm2_write(hm2, iop->alt_source_addr, iop->alt_source, n * 4);
    hm2_write(hm2, iop->ddr_addr, iop->ddr, n * 4);
    for (int port = 0; port < n; port++) {
        iop->written_ddr[port] = iop->ddr[port];
        iop->written_open_drain[port] = iop->open_drain[port];
        iop->written_output_invert[port] = iop->output_invert[port];
    }
}

/* read_gpio funct: read the data registers now and update the inputs. */
void hm2_ioport_gpio_read(hm2_board_t *hm2)
{
    hm2_ioport_t *iop = &hm2->ioport;
    if (iop->num_instances == 0)
        return;
    if (hm2_read(hm2, iop->data_addr, iop->data_read, iop->num_instances * 4) < 0)
        return;
    int n = iop->num_instances * (int)hm2->idrom.port_width;
    for (int io = 0; io < n && io < hm2->num_pins; io++) {
        if (hm2->pin[io].direction != HM2_PIN_DIR_IN)
            continue;
        bool bit = (iop->data_read[PORT_OF(hm2, io)] & BIT_OF(hm2, io)) != 0;
        *hm2->pin[io].hal->in = bit;
        *hm2->pin[io].hal->in_not = !bit;
    }
}

/* write_gpio funct: changed config and the data registers, now. */
void hm2_ioport_gpio_write(hm2_board_t *hm2)
{
    hm2_ioport_t *iop = &hm2->ioport;
    if (iop->num_instances == 0)
        return;
    hm2_ioport_write(hm2);
    hm2_ioport_gpio_prepare_tram_write(hm2);
    hm2_write(hm2, iop->data_addr, iop->data_write, iop->num_instances * 4);
}

/* Free the register images. */
void hm2_ioport_cleanup(hm2_board_t *hm2)
{
    hm2_ioport_t *iop = &hm2->ioport;
    uint32_t *arrays[] = {iop->ddr, iop->alt_source, iop->open_drain, iop->output_invert,
                          iop->written_ddr, iop->written_open_drain, iop->written_output_invert};
    for (size_t i = 0; i < sizeof(arrays) / sizeof(arrays[0]); i++)
        free(arrays[i]);
}

/* debug_modules: the IOPort registers. */
void hm2_ioport_print_module(hm2_board_t *hm2)
{
    hm2_ioport_t *iop = &hm2->ioport;
    if (iop->num_instances == 0)
        return;
    HM2_PRINT(hm2, "IO Ports: %d\n", iop->num_instances);
    HM2_PRINT(hm2, "    clock_frequency: %d Hz\n", (int)iop->clock_freq);
    HM2_PRINT(hm2, "    data_addr: 0x%04X\n", iop->data_addr);
    HM2_PRINT(hm2, "    ddr_addr: 0x%04X\n", iop->ddr_addr);
    HM2_PRINT(hm2, "    alt_source_addr: 0x%04X\n", iop->alt_source_addr);
    HM2_PRINT(hm2, "    open_drain_addr: 0x%04X\n", iop->open_drain_addr);
    HM2_PRINT(hm2, "    output_invert_addr: 0x%04X\n", iop->output_invert_addr);
    for (int port = 0; port < iop->num_instances; port++)
        HM2_PRINT(hm2, "    port %d: ddr 0x%08X alt_source 0x%08X open_drain 0x%08X invert 0x%08X\n",
                  port, iop->ddr[port], iop->alt_source[port], iop->open_drain[port],
                  iop->output_invert[port]);
}
