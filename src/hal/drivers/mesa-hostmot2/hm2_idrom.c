/* hm2_idrom.c: read and check the HostMot2 header, IDROM, pin descriptors and module descriptors. */
#include <stdlib.h>
#include <string.h>
#include "rtapi_errno.h"
#include "hm2.h"

/* Little-endian u32 from a byte buffer. */
static uint32_t le32(const uint8_t *p)
{
    return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
}

/* Check the cookie and the "HOSTMOT2" name, then read the IDROM offset. */
static int read_header(hm2_board_t *hm2)
{
    uint8_t buf[HM2_CONFIGNAME_LEN];
    uint32_t word;
    if (hm2_read(hm2, HM2_ADDR_IOCOOKIE, buf, 4) < 0) {
        HM2_ERR(hm2, "error reading HM2 cookie\n");
        return -EIO;
    }
    word = le32(buf);
    if (word != HM2_IOCOOKIE) {
        HM2_ERR(hm2, "invalid cookie, got 0x%08X, expected 0x%08X\n", word, HM2_IOCOOKIE);
        HM2_ERR(hm2, "FPGA failed to initialize, or unexpected firmware?\n");
        return -EINVAL;
    }
    if (hm2_read(hm2, HM2_ADDR_CONFIGNAME, buf, HM2_CONFIGNAME_LEN) < 0) {
        HM2_ERR(hm2, "error reading HM2 config name\n");
        return -EIO;
    }
    if (memcmp(buf, HM2_CONFIGNAME, HM2_CONFIGNAME_LEN) != 0) {
        char shown[HM2_CONFIGNAME_LEN + 1];
        for (int i = 0; i < HM2_CONFIGNAME_LEN; i++)
            shown[i] = (buf[i] >= 0x20 && buf[i] < 0x7f) ? (char)buf[i] : '?';
        shown[HM2_CONFIGNAME_LEN] = '\0';
        HM2_ERR(hm2, "invalid config name, got '%s', expected '%s'\n", shown, HM2_CONFIGNAME);
        return -EINVAL;
    }
    if (hm2_read(hm2, HM2_ADDR_IDROM_OFFSET, buf, 4) < 0) {
        HM2_ERR(hm2, "error reading IDROM offset\n");
        return -EIO;
    }
    hm2->idrom_offset = le32(buf) & 0xFFFF;
    return 0;
}

/* Decode the 16 IDROM words. */
static void decode_idrom(hm2_idrom_t *id, const uint8_t *b)
{
    id->idrom_type = le32(b + 0x00);
    id->offset_to_modules = le32(b + 0x04);
    id->offset_to_pin_desc = le32(b + 0x08);
    memcpy(id->board_name, b + 0x0C, 8);
    id->fpga_size = le32(b + 0x14);
    id->fpga_pins = le32(b + 0x18);
    id->io_ports = le32(b + 0x1C);
    id->io_width = le32(b + 0x20);
    id->port_width = le32(b + 0x24);
    id->clock_low = le32(b + 0x28);
    id->clock_high = le32(b + 0x2C);
    id->instance_stride_0 = le32(b + 0x30);
    id->instance_stride_1 = le32(b + 0x34);
    id->register_stride_0 = le32(b + 0x38);
    id->register_stride_1 = le32(b + 0x3C);
}

/* Print the IDROM header (debug_idrom, or after a PortWidth mismatch). */
void hm2_print_idrom(hm2_board_t *hm2)
{
    const hm2_idrom_t *id = &hm2->idrom;
    char name[9];
    for (int i = 0; i < 8; i++)
        name[i] = (id->board_name[i] >= 0x20 && id->board_name[i] < 0x7f) ? id->board_name[i] : '?';
    name[8] = '\0';
    HM2_PRINT(hm2, "IDRom:\n");
    HM2_PRINT(hm2, "    IDRom Type: 0x%08X\n", id->idrom_type);
    HM2_PRINT(hm2, "    Offset to Modules: 0x%08X\n", id->offset_to_modules);
    HM2_PRINT(hm2, "    Offset to Pin Description: 0x%08X\n", id->offset_to_pin_desc);
    HM2_PRINT(hm2, "    Board Name: %s\n", name);
    HM2_PRINT(hm2, "    FPGA Size: %u\n", id->fpga_size);
    HM2_PRINT(hm2, "    FPGA Pins: %u\n", id->fpga_pins);
    HM2_PRINT(hm2, "    Port Width: %u\n", id->port_width);
    HM2_PRINT(hm2, "    IO Ports: %u\n", id->io_ports);
    HM2_PRINT(hm2, "    IO Width: %u\n", id->io_width);
    HM2_PRINT(hm2, "    Clock Low: %d Hz (%d KHz, %d MHz)\n", (int)id->clock_low,
              (int)(id->clock_low / 1000), (int)(id->clock_low / 1000000));
    HM2_PRINT(hm2, "    Clock High: %d Hz (%d KHz, %d MHz)\n", (int)id->clock_high,
              (int)(id->clock_high / 1000), (int)(id->clock_high / 1000000));
    HM2_PRINT(hm2, "    Instance Stride 0: 0x%08X\n", id->instance_stride_0);
    HM2_PRINT(hm2, "    Instance Stride 1: 0x%08X\n", id->instance_stride_1);
    HM2_PRINT(hm2, "    Register Stride 0: 0x%08X\n", id->register_stride_0);
    HM2_PRINT(hm2, "    Register Stride 1: 0x%08X\n", id->register_stride_1);
}

/* The IDROM consistency checks, in the order LinuxCNC makes them. */
static int check_idrom(hm2_board_t *hm2)
{
    const hm2_idrom_t *id = &hm2->idrom;
    const hm2_llio_t *llio = hm2->llio;
    if (id->idrom_type != 2 && id->idrom_type != 3) {
        HM2_ERR(hm2, "invalid IDROM type %d, expected 2 or 3, aborting load\n", (int)id->idrom_type);
        return -EINVAL;
    }
    if (id->port_width != (uint32_t)llio->pins_per_connector) {
        HM2_ERR(hm2, "invalid IDROM PortWidth %d, this board has %d pins per connector, "
                "aborting load\n", (int)id->port_width, llio->pins_per_connector);
        hm2_print_idrom(hm2);
        return -EINVAL;
    }
    if (id->io_width != id->io_ports * id->port_width) {
        HM2_ERR(hm2, "IDROM IOWidth is %d, but IDROM IOPorts is %d and IDROM PortWidth is %d "
                "(inconsistent firmware), aborting driver load\n",
                (int)id->io_width, (int)id->io_ports, (int)id->port_width);
        return -EINVAL;
    }
    if (id->io_ports != (uint32_t)llio->num_ioport_connectors) {
        HM2_ERR(hm2, "IDROM IOPorts is %d but llio num_ioport_connectors is %d, driver and "
                "firmware are inconsistent, aborting driver load\n",
                (int)id->io_ports, llio->num_ioport_connectors);
        return -EINVAL;
    }
    if (id->io_width > HM2_MAX_PINS) {
        HM2_ERR(hm2, "IDROM IOWidth is %d but max is %d, aborting driver load\n",
                (int)id->io_width, HM2_MAX_PINS);
        return -EINVAL;
    }
    if (id->clock_low < HM2_MIN_CLOCK_HZ) {
        HM2_ERR(hm2, "IDROM ClockLow is %d, that's too low, aborting driver load\n",
                (int)id->clock_low);
        return -EINVAL;
    }
    if (id->clock_high < HM2_MIN_CLOCK_HZ) {
        HM2_ERR(hm2, "IDROM ClockHigh is %d, that's too low, aborting driver load\n",
                (int)id->clock_high);
        return -EINVAL;
    }
    return 0;
}

/* Read the header and the IDROM and check them. */
int hm2_read_idrom(hm2_board_t *hm2)
{
    uint8_t buf[64];
    int r = read_header(hm2);
    if (r < 0)
        return r;
    if (hm2_read(hm2, hm2->idrom_offset, buf, sizeof(buf)) < 0) {
        HM2_ERR(hm2, "error reading IDROM\n");
        return -EIO;
    }
    decode_idrom(&hm2->idrom, buf);
    r = check_idrom(hm2);
    if (r < 0)
        return r;
    if (debug_idrom)
        hm2_print_idrom(hm2);
    return 0;
}

/* Print the pin descriptor table (debug_pin_descriptors). */
static void print_pin_descriptors(hm2_board_t *hm2)
{
    char buf[32];
    HM2_PRINT(hm2, "%d HM2 Pin Descriptors:\n", hm2->num_pins);
    for (int i = 0; i < hm2->num_pins; i++) {
        const hm2_pin_t *p = &hm2->pin[i];
        const char *prim = hm2_gtag_name(p->primary_tag);
        HM2_PRINT(hm2, "    pin %d:\n", i);
        HM2_PRINT(hm2, "        Primary Tag: 0x%02X (%s)\n", p->primary_tag, prim ? prim : "unknown");
        if (p->sec_tag == 0)
            continue;
        const char *sec = hm2_gtag_name(p->sec_tag);
        HM2_PRINT(hm2, "        Secondary Tag: 0x%02X (%s)\n", p->sec_tag, sec ? sec : "unknown");
        HM2_PRINT(hm2, "        Secondary Unit: 0x%02X\n", p->sec_unit);
        HM2_PRINT(hm2, "        Secondary Pin: 0x%02X (%s, %s)\n", p->sec_pin,
                  hm2_pin_log_name(p->sec_tag, p->sec_pin, buf, sizeof(buf)),
                  (p->sec_pin & HM2_PIN_OUTPUT_FLAG) ? "Output" : "Input");
    }
}

/* Read IOWidth pin descriptors; every primary tag must be IOPort. */
int hm2_read_pin_descriptors(hm2_board_t *hm2)
{
    uint32_t addr = hm2->idrom_offset + hm2->idrom.offset_to_pin_desc;
    hm2->num_pins = (int)hm2->idrom.io_width;
    hm2->pin = calloc(hm2->num_pins ? hm2->num_pins : 1, sizeof(hm2_pin_t));
    if (!hm2->pin) {
        HM2_ERR(hm2, "out of memory for %d pins\n", hm2->num_pins);
        return -ENOMEM;
    }
    for (int i = 0; i < hm2->num_pins; i++) {
        uint8_t b[4];
        hm2_pin_t *p = &hm2->pin[i];
        if (hm2_read(hm2, addr + 4 * i, b, 4) < 0) {
            HM2_ERR(hm2, "error reading Pin Descriptor %d (at 0x%04x)\n", i, addr + 4 * i);
            return -EIO;
        }
        p->sec_pin = b[0];
        p->sec_tag = b[1];
        p->sec_unit = b[2];
        p->primary_tag = b[3];
        if (p->primary_tag == 0) {
            HM2_ERR(hm2, "pin %d primary tag is 0 (end-of-list sentinel), expected %d pins!\n",
                    i, hm2->num_pins);
            return -EINVAL;
        }
        if (p->primary_tag != HM2_GTAG_IOPORT) {
            const char *name = hm2_gtag_name(p->primary_tag);
            HM2_ERR(hm2, "pin %d primary tag is %d (%s), not IOPort!\n", i, p->primary_tag,
                    name ? name : "unknown");
            return -EINVAL;
        }
        p->gtag = HM2_GTAG_IOPORT;
    }
    if (hm2_connector_pin_number(hm2, 0) < 0)
        HM2_ERR(hm2, "hm2_read_pin_descriptors: invalid port width %d\n", (int)hm2->idrom.port_width);
    if (debug_pin_descriptors)
        print_pin_descriptors(hm2);
    return 0;
}

/* Print one module descriptor (debug_module_descriptors). */
static void print_md(hm2_board_t *hm2, int i, uint32_t addr, const hm2_md_t *md)
{
    const char *name = hm2_gtag_name(md->gtag);
    HM2_PRINT(hm2, "Module Descriptor %d at 0x%04X:\n", i, addr);
    HM2_PRINT(hm2, "    General Function Tag: %d (%s)\n", md->gtag, name ? name : "unknown");
    HM2_PRINT(hm2, "    Version: %d\n", md->version);
    HM2_PRINT(hm2, "    Clock Tag: %d (%d.%03d MHz)\n", md->clock_tag,
              (int)(md->clock_freq / 1000000), (int)((md->clock_freq / 1000) % 1000));
    HM2_PRINT(hm2, "    Instances: %d\n", md->instances);
    HM2_PRINT(hm2, "    Base Address: 0x%04X\n", md->base_address);
    HM2_PRINT(hm2, "    -- Num Registers: %d\n", md->num_registers);
    HM2_PRINT(hm2, "    Register Stride: 0x%08X\n", md->register_stride);
    HM2_PRINT(hm2, "    -- Instance Stride: 0x%08X\n", md->instance_stride);
    HM2_PRINT(hm2, "    -- Multiple Registers: 0x%08X\n", md->multiple_registers);
}

/* Decode one descriptor's three words and resolve clock and strides. */
static int decode_md(hm2_board_t *hm2, int i, uint32_t addr, const uint8_t *b, hm2_md_t *md)
{
    const hm2_idrom_t *id = &hm2->idrom;
    uint32_t w1 = le32(b + 4);
    int rs = (w1 >> 24) & 0x0F, is = (w1 >> 28) & 0x0F;
    md->gtag = b[0];
    md->version = b[1];
    md->clock_tag = b[2];
    md->instances = b[3];
    md->base_address = (uint16_t)(w1 & 0xFFFF);
    md->num_registers = (uint8_t)((w1 >> 16) & 0xFF);
    md->multiple_registers = le32(b + 8);
    md->clock_freq = md->clock_tag == 1 ? id->clock_low : md->clock_tag == 2 ? id->clock_high : 0;
    md->register_stride = rs == 0 ? id->register_stride_0 : id->register_stride_1;
    md->instance_stride = is == 0 ? id->instance_stride_0 : id->instance_stride_1;
    if (debug_module_descriptors)
        print_md(hm2, i, addr, md);
    if (md->clock_tag != 1 && md->clock_tag != 2) {
        HM2_ERR(hm2, "Module Descriptor %d (at 0x%04x) has invalid ClockTag %d\n", i, addr, md->clock_tag);
        return -EINVAL;
    }
    if (rs > 1) {
        HM2_ERR(hm2, "Module Descriptor %d (at 0x%04x) has invalid RegisterStride %d\n", i, addr, rs);
        return -EINVAL;
    }
    if (is > 1) {
        HM2_ERR(hm2, "Module Descriptor %d (at 0x%04x) has invalid InstanceStride %d\n", i, addr, is);
        return -EINVAL;
    }
    return 0;
}

/* Read module descriptors until the first GTag 0 (at most 48). */
int hm2_read_module_descriptors(hm2_board_t *hm2)
{
    uint32_t addr = hm2->idrom_offset + hm2->idrom.offset_to_modules;
    hm2->num_mds = 0;
    for (int i = 0; i < HM2_MAX_MODULE_DESCRIPTORS; i++, addr += HM2_MD_SIZE) {
        uint8_t b[HM2_MD_SIZE];
        if (hm2_read(hm2, addr, b, HM2_MD_SIZE) < 0) {
            HM2_ERR(hm2, "error reading Module Descriptor %d (at 0x%04x)\n", i, addr);
            return -EIO;
        }
        if (b[0] == 0)
            break;
        int r = decode_md(hm2, i, addr, b, &hm2->md[i]);
        if (r < 0)
            return r;
        hm2->num_mds++;
    }
    return 0;
}
