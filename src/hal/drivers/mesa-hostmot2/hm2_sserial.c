/* hm2_sserial.c: Smart Serial (GTag 193/198) set-up: ports, remote discovery through the SSLBP
   commands (name, unit, PTOC/GTOC records, modes), TRAM regions and the pins the channels take. */
#include <stdlib.h>
#include <string.h>
#include "rtapi_errno.h"
#include "hm2.h"

#define SSERIAL_POLL_LIMIT 2000        /* command-register polls before a set-up command times out */
#define SSERIAL_V0_MULTIPLE 0x3C
#define SSERIAL_B_REGISTERS 10
#define SSERIAL_B_MULTIPLE 0x3FC
#define SSERIAL_REC_HEADER 14

/* Address of register reg of a port (and channel, for the per-channel registers). */
static uint32_t reg_addr(const hm2_sserial_t *s, int reg, int port, int chan)
{
    return s->base_address + reg * s->register_stride + port * s->instance_stride + 4u * chan;
}

/* Write a set-up command, wait for the firmware to clear it, return the data register. */
static int port_command(hm2_board_t *hm2, int port, uint32_t cmd, uint32_t *data)
{
    hm2_sserial_t *s = &hm2->sserial;
    uint32_t addr = reg_addr(s, SSLBP_REG_COMMAND, port, 0), v = cmd;
    if (hm2_write(hm2, addr, &v, 4) < 0)
        return -EIO;
    for (int i = 0; i < SSERIAL_POLL_LIMIT; i++) {
        if (hm2_read(hm2, addr, &v, 4) < 0)
            return -EIO;
        if (v == 0)
            return data ? hm2_read(hm2, reg_addr(s, SSLBP_REG_DATA, port, 0), data, 4) : 0;
    }
    HM2_ERR(hm2, "Smart Serial port %d: command 0x%04X not done by the firmware (timeout)\n", port, cmd);
    return -ETIMEDOUT;
}

/* One 4-byte read of a remote's memory through its channel. */
static int remote_read32(hm2_board_t *hm2, int port, int chan, uint32_t addr, uint32_t *v)
{
    hm2_sserial_t *s = &hm2->sserial;
    uint32_t cs = SSLBP_CS_REMOTE_READ | (addr & SSLBP_CS_ADDR_MASK), data;
    if (hm2_write(hm2, reg_addr(s, SSLBP_REG_CS, port, chan), &cs, 4) < 0)
        return -EIO;
    int r = port_command(hm2, port, SSLBP_CMD_DOIT | 1u << chan, &data);
    if (r < 0)
        return r;
    if (data & (1u << chan)) {
        HM2_ERR(hm2, "Smart Serial port %d channel %d: remote read at 0x%04X failed\n", port, chan, addr);
        return -EIO;
    }
    return hm2_read(hm2, reg_addr(s, SSLBP_REG_INTERFACE0, port, chan), v, 4);
}

/* n bytes of remote memory from addr. */
static int remote_read_bytes(hm2_board_t *hm2, int port, int chan, uint32_t addr, uint8_t *buf, int n)
{
    for (int i = 0; i < n; i += 4) {
        uint32_t w;
        int r = remote_read32(hm2, port, chan, addr + i, &w);
        if (r < 0)
            return r;
        for (int k = 0; k < 4 && i + k < n; k++)
            buf[i + k] = (uint8_t)(w >> (8 * k));
    }
    return 0;
}

/* Copy a 0-terminated string out of a record buffer; returns the bytes it used. */
static int take_string(const uint8_t *p, int avail, char *out, int cap)
{
    int i = 0;
    for (; i < avail && p[i]; i++)
        if (i < cap - 1)
            out[i] = (char)p[i];
    out[i < cap - 1 ? i : cap - 1] = '\0';
    return i + 1;
}

/* Float stored little-endian in a record. */
static float record_float(const uint8_t *p)
{
    uint32_t u = (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
    float f;
    memcpy(&f, &u, sizeof(f));
    return f;
}

/* Read one record (process data or mode) and add it to the channel. */
static int read_record(hm2_board_t *hm2, int port, int chan, uint16_t addr, bool global)
{
    hm2_sserial_channel_t *ch = &hm2->sserial.port[port].chan[chan];
    uint8_t b[SSERIAL_REC_HEADER + 2 * SSLBP_REC_NAME_MAX];
    int r = remote_read_bytes(hm2, port, chan, addr, b, sizeof(b));
    if (r < 0)
        return r;
    if (b[SSLBP_PD_TYPE] == SSLBP_REC_MODE) {
        if (ch->num_modes >= HM2_SSERIAL_MAX_MODES)
            return 0;
        hm2_sserial_mode_t *m = &ch->modes[ch->num_modes++];
        m->index = b[SSLBP_MODE_INDEX];
        m->kind = b[SSLBP_MODE_KIND];
        take_string(b + SSLBP_MODE_NAME, sizeof(b) - SSLBP_MODE_NAME, m->name, sizeof(m->name));
        return 0;
    }
    if (b[SSLBP_PD_TYPE] != SSLBP_REC_PROCESS_DATA) {
        HM2_ERR(hm2, "Smart Serial port %d channel %d: unknown record type 0x%02X at 0x%04X\n",
                port, chan, b[SSLBP_PD_TYPE], addr);
        return -EINVAL;
    }
    if (ch->num_pd + ch->num_globals >= HM2_SSERIAL_MAX_RECORDS) {
        HM2_ERR(hm2, "Smart Serial port %d channel %d: more than %d records\n", port, chan,
                HM2_SSERIAL_MAX_RECORDS);
        return -EINVAL;
    }
    hm2_sserial_rec_t *rec = &ch->rec[ch->num_pd + ch->num_globals];
    rec->bits = b[SSLBP_PD_BITS];
    rec->data_type = b[SSLBP_PD_DATA_TYPE];
    rec->dir = b[SSLBP_PD_DIR];
    rec->parm_min = record_float(b + SSLBP_PD_MIN);
    rec->parm_max = record_float(b + SSLBP_PD_MAX);
    rec->parm_addr = (uint16_t)(b[SSLBP_PD_ADDR] | b[SSLBP_PD_ADDR + 1] << 8);
    int used = take_string(b + SSLBP_PD_STRINGS, sizeof(b) - SSLBP_PD_STRINGS, rec->unit, sizeof(rec->unit));
    take_string(b + SSLBP_PD_STRINGS + used, (int)sizeof(b) - SSLBP_PD_STRINGS - used, rec->name,
                sizeof(rec->name));
    if (global)
        ch->num_globals++;
    else
        ch->num_pd++;
    return 0;
}

/* Read a table of contents (0-terminated list of record addresses). */
static int read_toc(hm2_board_t *hm2, int port, int chan, uint16_t toc, bool global)
{
    for (int i = 0; toc && i < HM2_SSERIAL_MAX_RECORDS + HM2_SSERIAL_MAX_MODES; i++) {
        uint8_t a[2];
        int r = remote_read_bytes(hm2, port, chan, toc + 2u * i, a, 2);
        if (r < 0)
            return r;
        uint16_t addr = (uint16_t)(a[0] | a[1] << 8);
        if (addr == 0)
            return 0;
        if ((r = read_record(hm2, port, chan, addr, global)) < 0)
            return r;
    }
    return 0;
}

/* Process-data bit offsets per direction; refuse more than the interface registers hold. */
static int layout_process_data(hm2_board_t *hm2, int port, hm2_sserial_channel_t *ch)
{
    ch->in_bits = ch->out_bits = 0;
    for (int i = 0; i < ch->num_pd; i++) {
        hm2_sserial_rec_t *rec = &ch->rec[i];
        if (rec->dir == SSLBP_DIR_OUT) {
            rec->bit_offset = ch->out_bits;
            ch->out_bits += rec->bits;
        } else {
            rec->bit_offset = ch->in_bits;
            ch->in_bits += rec->bits;
        }
    }
    int max_bits = 32 * hm2->sserial.num_iface_regs;
    if (ch->in_bits > max_bits || ch->out_bits > max_bits) {
        HM2_ERR(hm2, "Data width, %i in / %i out bits, exceeds the supported number of smart-serial "
                "32-bit registers (%d)\n", ch->in_bits, ch->out_bits, hm2->sserial.num_iface_regs);
        return -EINVAL;
    }
    (void)port;
    return 0;
}

/* The requested mode must be one of the remote's software modes. */
static int check_mode(hm2_board_t *hm2, int port, int chan, hm2_sserial_channel_t *ch)
{
    char list[64] = "";
    int n = 0, len = 0;
    for (int i = 0; i < ch->num_modes; i++) {
        if (ch->modes[i].kind != SSLBP_MODE_SOFTWARE)
            continue;
        if (ch->modes[i].index == ch->mode)
            return 0;
        len += rtapi_snprintf(list + len, sizeof(list) - len, "%s%d", n++ ? ", " : "", ch->modes[i].index);
        if (len >= (int)sizeof(list))
            break;
    }
    if (n == 0)
        return 0;
    HM2_ERR(hm2, "sserial_port_%d: channel %d has a %s, which has no software mode %d (modes: %s)\n",
            port, chan, ch->card, ch->mode, list);
    return -EINVAL;
}

/* Read the remote's current value of every global (the params start from it). */
static int read_globals(hm2_board_t *hm2, int port, int chan, hm2_sserial_channel_t *ch)
{
    for (int i = ch->num_pd; i < ch->num_pd + ch->num_globals; i++) {
        uint32_t v;
        int r = remote_read32(hm2, port, chan, ch->rec[i].parm_addr, &v);
        if (r < 0)
            return r;
        if (ch->rec[i].bits < 32)
            v &= (1u << ch->rec[i].bits) - 1;
        ch->rec[i].written_global = v;
    }
    return 0;
}

/* Name a remote as LinuxCNC does: <board>.<card>.<port>.<chan> or hm2_<card>.<serial>. */
static void name_remote(hm2_board_t *hm2, int port, int chan, hm2_sserial_channel_t *ch, uint32_t name)
{
    for (int k = 0; k < 4; k++)
        ch->card[k] = (char)(name >> (8 * k));
    ch->card[4] = '\0';
    if (ch->card[1] >= 'A' && ch->card[1] <= 'Z')
        ch->card[1] = (char)(ch->card[1] - 'A' + 'a');
    if (use_serial_numbers)
        rtapi_snprintf(ch->name, sizeof(ch->name), "hm2_%s.%04x", ch->card, ch->unit_number & 0xFFFF);
    else
        rtapi_snprintf(ch->name, sizeof(ch->name), "%s.%s.%d.%d", hm2->llio->name, ch->card, port, chan);
}

/* Identify the remote on a channel that answered the set-up start and read its records. */
static int probe_channel(hm2_board_t *hm2, int port, int chan)
{
    hm2_sserial_t *s = &hm2->sserial;
    hm2_sserial_channel_t *ch = &s->port[port].chan[chan];
    uint32_t user0, user1, user2, cs;
    if (hm2_read(hm2, reg_addr(s, SSLBP_REG_INTERFACE0, port, chan), &user0, 4) < 0 ||
        hm2_read(hm2, reg_addr(s, SSLBP_REG_INTERFACE1, port, chan), &user1, 4) < 0 ||
        hm2_read(hm2, reg_addr(s, SSLBP_REG_INTERFACE2, port, chan), &user2, 4) < 0 ||
        hm2_read(hm2, reg_addr(s, SSLBP_REG_CS, port, chan), &cs, 4) < 0)
        return -EIO;
    if (user1 == 0)
        return 0;
    ch->unit_number = user0;
    ch->protocol = SSLBP_CS_PROTOCOL(cs);
    name_remote(hm2, port, chan, ch, user1);
    if ((user2 & 0xFFFF) == 0) {
        HM2_ERR(hm2, "Unsupported Device (%4s) found on sserial %d channel %d\n", ch->card, port, chan);
        return 0;
    }
    ch->rec = calloc(HM2_SSERIAL_MAX_RECORDS, sizeof(*ch->rec));
    if (!ch->rec)
        return -ENOMEM;
    int r = read_toc(hm2, port, chan, (uint16_t)(user2 & 0xFFFF), false);
    if (r == 0)
        r = read_toc(hm2, port, chan, (uint16_t)(user2 >> 16), true);
    if (r == 0)
        r = layout_process_data(hm2, port, ch);
    if (r == 0)
        r = check_mode(hm2, port, chan, ch);
    if (r == 0)
        r = read_globals(hm2, port, chan, ch);
    if (r < 0)
        return r;
    ch->present = true;
    HM2_INFO(hm2, "sserial port %d channel %d: %s unit 0x%08X protocol %u, %d/%d bits in/out\n",
             port, chan, ch->card, ch->unit_number, ch->protocol, ch->in_bits, ch->out_bits);
    return 0;
}

/* Channels of a port that have IO pins on this board (from the pin descriptors). */
static int count_channels(hm2_board_t *hm2, int gtag, int port)
{
    int n = 0;
    for (int io = 0; io < hm2->num_pins; io++) {
        const hm2_pin_t *p = &hm2->pin[io];
        int sec = p->sec_pin & 0x7F;
        if (p->sec_tag == gtag && p->sec_unit == port && !(p->sec_pin & HM2_PIN_OUTPUT_FLAG) &&
            sec >= 1 && sec <= SSLBP_MAX_CHANNELS && sec > n)
            n = sec;
    }
    return n;
}

/* Print the remote's modes as LinuxCNC does at load. */
static void print_modes(const hm2_sserial_channel_t *ch)
{
    for (int i = 0; i < ch->num_modes; i++)
        rtapi_print("Board %s %s Mode %d = %s\n", ch->name,
                    ch->modes[i].kind == SSLBP_MODE_HARDWARE ? "Hardware" : "Software",
                    ch->modes[i].index, ch->modes[i].name);
}

/* Write each enabled channel's mode to its CS register. */
static int write_modes(hm2_board_t *hm2, int port, uint32_t mask)
{
    for (int c = 0; c < SSLBP_MAX_CHANNELS; c++) {
        if (!(mask & (1u << c)))
            continue;
        uint32_t cs = (uint32_t)hm2->sserial.port[port].chan[c].mode << SSLBP_CS_MODE_SHIFT;
        if (hm2_write(hm2, reg_addr(&hm2->sserial, SSLBP_REG_CS, port, c), &cs, 4) < 0)
            return -EIO;
    }
    return 0;
}

/* Discover the remotes of one port and start the ones found in normal mode. */
static int setup_port(hm2_board_t *hm2, int gtag, int port)
{
    hm2_sserial_port_t *p = &hm2->sserial.port[port];
    uint32_t mask = 0, data;
    p->index = port;
    p->num_channels = count_channels(hm2, gtag, port);
    for (int c = 0; c < p->num_channels; c++) {
        char m = hm2->config.sserial_modes[port][c];
        p->chan[c].mode = m == 'x' ? -1 : m - '0';
        if (m != 'x')
            mask |= 1u << c;
    }
    int r = port_command(hm2, port, SSLBP_CMD_STOP_ALL, NULL);
    if (r == 0 && mask)
        r = write_modes(hm2, port, mask);
    if (r == 0 && mask)
        r = port_command(hm2, port, SSLBP_CMD_START_SETUP | mask, &data);
    for (int c = 0; r == 0 && c < p->num_channels; c++)
        if ((mask & (1u << c)) && !(data & (1u << c)))
            r = probe_channel(hm2, port, c);
    if (r == 0)
        r = port_command(hm2, port, SSLBP_CMD_STOP_ALL, NULL);
    for (int c = 0; c < p->num_channels; c++)
        if (p->chan[c].present)
            p->active_mask |= 1u << c;
    if (r < 0 || !p->active_mask)
        return r;
    if ((r = write_modes(hm2, port, p->active_mask)) < 0 ||
        (r = port_command(hm2, port, SSLBP_CMD_START_NORMAL | p->active_mask, &data)) < 0)
        return r;
    if (data & p->active_mask) {
        HM2_ERR(hm2, "Smart Serial port %d: channels 0x%02X failed to start\n", port, data & p->active_mask);
        return -EIO;
    }
    p->state = HM2_SSERIAL_RUNNING;
    for (int c = 0; c < p->num_channels; c++)
        if (p->chan[c].present)
            print_modes(&p->chan[c]);
    return 0;
}

/* Register the per-cycle TRAM regions of a port: command/data, and per remote CS + interfaces. */
static int register_tram(hm2_board_t *hm2, hm2_sserial_port_t *p)
{
    hm2_sserial_t *s = &hm2->sserial;
    int port = p->index;
    p->command_addr = reg_addr(s, SSLBP_REG_COMMAND, port, 0);
    p->data_addr = reg_addr(s, SSLBP_REG_DATA, port, 0);
    int r = hm2_register_tram_read_region(hm2, p->command_addr, 4, &p->command_read);
    r = r ? r : hm2_register_tram_read_region(hm2, p->data_addr, 4, &p->data_read);
    r = r ? r : hm2_register_tram_write_region(hm2, p->command_addr, 4, &p->command_write);
    for (int c = 0; r == 0 && c < p->num_channels; c++) {
        hm2_sserial_channel_t *ch = &p->chan[c];
        if (!ch->present)
            continue;
        ch->cs_addr = reg_addr(s, SSLBP_REG_CS, port, c);
        r = hm2_register_tram_read_region(hm2, ch->cs_addr, 4, &ch->cs_read);
        for (int i = 0; r == 0 && i < s->num_iface_regs; i++) {
            ch->iface_addr[i] = reg_addr(s, SSLBP_REG_INTERFACE0 + i, port, c);
            if (i * 32 < ch->in_bits)
                r = hm2_register_tram_read_region(hm2, ch->iface_addr[i], 4, &ch->iface_read[i]);
            if (r == 0 && i * 32 < ch->out_bits)
                r = hm2_register_tram_write_region(hm2, ch->iface_addr[i], 4, &ch->iface_write[i]);
        }
    }
    return r;
}

/* Check the descriptor shape and where the registers are. */
static int check_md(hm2_board_t *hm2, int md_index)
{
    hm2_md_t *md = &hm2->md[md_index];
    hm2_sserial_t *s = &hm2->sserial;
    if (md->gtag == HM2_GTAG_SMARTSERIAL && md->version < 1 && md->num_registers == 5) {
        HM2_ERR(hm2, "The bitfile contains Smart Serial modules for a firmware revision < rev22. "
                "This Driver now requires rev22 or newer firmwares\n");
        return -EINVAL;
    }
    bool b = md->gtag == HM2_GTAG_SMARTSERIALB;
    if (!hm2_md_is_consistent_or_complain(hm2, md_index, md->version,
                                          b ? SSERIAL_B_REGISTERS : SSLBP_V0_REGISTERS,
                                          SSLBP_INSTANCE_STRIDE, b ? SSERIAL_B_MULTIPLE : SSERIAL_V0_MULTIPLE))
        return -EINVAL;
    s->version = md->version;
    s->num_iface_regs = b ? SSLBP_MAX_INTERFACE_REGS : SSLBP_V0_INTERFACE_REGS;
    s->base_address = md->base_address;
    s->register_stride = md->register_stride;
    s->instance_stride = md->instance_stride;
    return 0;
}

/* Parse the Smart Serial descriptor: discover every enabled port's remotes, make their HAL objects. */
int hm2_sserial_parse_md(hm2_board_t *hm2, int md_index)
{
    hm2_md_t *md = &hm2->md[md_index];
    hm2_sserial_t *s = &hm2->sserial;
    int wanted = hm2->config.num_sserials, r;
    if (wanted > md->instances) {
        HM2_ERR(hm2, "num_sserials references %d instances, but only %d are available, not loading "
                "driver\n", wanted, md->instances);
        return -EINVAL;
    }
    if ((r = check_md(hm2, md_index)) < 0)
        return r;
    s->num_instances = wanted < 0 ? md->instances : wanted;
    if (s->num_instances > HM2_SSERIAL_PORTS)
        s->num_instances = HM2_SSERIAL_PORTS;
    if (s->num_instances == 0)
        return 0;
    if (sserial_baudrate != -1)
        HM2_PRINT(hm2, "sserial_baudrate=%d: this driver does not flash remotes; ignored\n",
                 sserial_baudrate);
    uint32_t version;
    if ((r = port_command(hm2, 0, SSLBP_CMD_READ_LOCAL | SSLBP_LOCAL_VERSION, &version)) < 0)
        return r;
    HM2_PRINT(hm2, "Smart Serial Firmware Version %i\n", (int)(version & 0xFF));
    for (int port = 0; port < s->num_instances; port++) {
        if ((r = setup_port(hm2, md->gtag, port)) < 0)
            return r;
        if (!s->port[port].active_mask) {
            HM2_INFO(hm2, "Smart Serial port %d: no remotes in use, no HAL objects\n", port);
            continue;
        }
        if ((r = hm2_sserial_export_port(hm2, &s->port[port])) < 0 ||
            (r = register_tram(hm2, &s->port[port])) < 0)
            return r;
    }
    return s->num_instances;
}

/* The rx/tx/txen pins of channels in use go to the module; the rest stay GPIO. */
void hm2_sserial_allocate_pins(hm2_board_t *hm2)
{
    hm2_sserial_t *s = &hm2->sserial;
    for (int io = 0; io < hm2->num_pins; io++) {
        hm2_pin_t *p = &hm2->pin[io];
        if ((p->sec_tag != HM2_GTAG_SMARTSERIAL && p->sec_tag != HM2_GTAG_SMARTSERIALB) ||
            p->sec_unit >= s->num_instances)
            continue;
        int chan = ((p->sec_pin & 0x7F) - 1) & 0x0F;
        if (!(s->port[p->sec_unit].active_mask & (1u << chan)))
            continue;
        p->gtag = p->sec_tag;
        hm2_set_pin_source(hm2, io, 1);
        hm2_set_pin_direction_immediate(hm2, io, (p->sec_pin & HM2_PIN_OUTPUT_FLAG) ? HM2_PIN_DIR_OUT
                                                                                   : HM2_PIN_DIR_IN);
    }
}

/* Release the record tables. */
void hm2_sserial_cleanup(hm2_board_t *hm2)
{
    for (int port = 0; port < HM2_SSERIAL_PORTS; port++)
        for (int c = 0; c < SSLBP_MAX_CHANNELS; c++) {
            free(hm2->sserial.port[port].chan[c].rec);
            hm2->sserial.port[port].chan[c].rec = NULL;
        }
}
