/* sim_remote.c: the simulated 7I76 Smart Serial remote: its discovery records and tables of
   contents in remote memory, process-data exchange and its own output watchdog. */
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include "sim_remote.h"

#define REC_AREA 0x100
#define TOC_AREA 0x800
#define GLOBAL_AREA 0xC00
#define ALL_MODES 0x07
#define ANALOG_MODES 0x06
#define MPG_MODE 0x04
#define FIELD_VOLTS 36.3f

#define NV_GLOBALS                                                                              \
    {"swrevision", "none", SSLBP_TYPE_UNSIGNED, SSLBP_DIR_IN, 16, 0, 0, 0, true, 14},              \
    {"nvbaudrate", "none", SSLBP_TYPE_NONVOL_UNSIGNED, SSLBP_DIR_OUT, 8, 0, 11, 0, true, 9},       \
    {"nvunitnumber", "none", SSLBP_TYPE_NONVOL_UNSIGNED, SSLBP_DIR_OUT, 32, 0, 0, 0, true, 0},     \
    {"nvwatchdogtimeout", "ms", SSLBP_TYPE_NONVOL_UNSIGNED, SSLBP_DIR_OUT, 16, 0, 65535, 0, true, 50}

static const sim_record_def_t records_7i76[] = {
    {"output", "none", SSLBP_TYPE_BITS, SSLBP_DIR_OUT, 16, 0, 0, ALL_MODES, false, 0},
    {"spinout", "none", SSLBP_TYPE_UNSIGNED, SSLBP_DIR_OUT, 16, 0, 100, ALL_MODES, false, 0},
    {"spinena", "none", SSLBP_TYPE_BOOLEAN, SSLBP_DIR_OUT, 1, 0, 0, ALL_MODES, false, 0},
    {"spindir", "none", SSLBP_TYPE_BOOLEAN, SSLBP_DIR_OUT, 1, 0, 0, ALL_MODES, false, 0},
    {"input", "none", SSLBP_TYPE_BITS, SSLBP_DIR_IN, 32, 0, 0, ALL_MODES, false, 0},
    {"analogin0", "volt", SSLBP_TYPE_UNSIGNED, SSLBP_DIR_IN, 8, 0, FIELD_VOLTS, ANALOG_MODES, false, 0},
    {"analogin1", "volt", SSLBP_TYPE_UNSIGNED, SSLBP_DIR_IN, 8, 0, FIELD_VOLTS, ANALOG_MODES, false, 0},
    {"analogin2", "volt", SSLBP_TYPE_UNSIGNED, SSLBP_DIR_IN, 8, 0, FIELD_VOLTS, ANALOG_MODES, false, 0},
    {"analogin3", "volt", SSLBP_TYPE_UNSIGNED, SSLBP_DIR_IN, 8, 0, FIELD_VOLTS, ANALOG_MODES, false, 0},
    {"fieldvoltage", "volt", SSLBP_TYPE_UNSIGNED, SSLBP_DIR_IN, 8, 0, FIELD_VOLTS, MPG_MODE, false, 0},
    {"encoder0", "count", SSLBP_TYPE_ENCODER, SSLBP_DIR_IN, 8, 0, 1, MPG_MODE, false, 0},
    {"encoder1", "count", SSLBP_TYPE_ENCODER, SSLBP_DIR_IN, 8, 0, 1, MPG_MODE, false, 0},
    NV_GLOBALS,
};

/* 7I77 channel 0: field I/O (modes 0 input_output .. 3 io_encoder_analog_fieldvoltage). */
static const sim_record_def_t records_7i77_io[] = {
    {"output", "none", SSLBP_TYPE_BITS, SSLBP_DIR_OUT, 16, 0, 0, 0x0F, false, 0},
    {"input", "none", SSLBP_TYPE_BITS, SSLBP_DIR_IN, 32, 0, 0, 0x0F, false, 0},
    {"analogin0", "volt", SSLBP_TYPE_UNSIGNED, SSLBP_DIR_IN, 8, 0, FIELD_VOLTS, 0x0E, false, 0},
    {"analogin1", "volt", SSLBP_TYPE_UNSIGNED, SSLBP_DIR_IN, 8, 0, FIELD_VOLTS, 0x0E, false, 0},
    {"analogin2", "volt", SSLBP_TYPE_UNSIGNED, SSLBP_DIR_IN, 8, 0, FIELD_VOLTS, 0x0E, false, 0},
    {"analogin3", "volt", SSLBP_TYPE_UNSIGNED, SSLBP_DIR_IN, 8, 0, FIELD_VOLTS, 0x0E, false, 0},
    {"fieldvoltage", "volt", SSLBP_TYPE_UNSIGNED, SSLBP_DIR_IN, 8, 0, FIELD_VOLTS, 0x0C, false, 0},
    {"encoder0", "count", SSLBP_TYPE_ENCODER, SSLBP_DIR_IN, 8, 0, 1, 0x08, false, 0},
    {"encoder1", "count", SSLBP_TYPE_ENCODER, SSLBP_DIR_IN, 8, 0, 1, 0x08, false, 0},
    NV_GLOBALS,
};

/* 7I77 channel 1: six +-10 V servo outputs with their enables. */
static const sim_record_def_t records_7i77_analog[] = {
    {"analogout0", "volt", SSLBP_TYPE_SIGNED, SSLBP_DIR_OUT, 13, -10, 10, 0x01, false, 0},
    {"analogout1", "volt", SSLBP_TYPE_SIGNED, SSLBP_DIR_OUT, 13, -10, 10, 0x01, false, 0},
    {"analogout2", "volt", SSLBP_TYPE_SIGNED, SSLBP_DIR_OUT, 13, -10, 10, 0x01, false, 0},
    {"analogout3", "volt", SSLBP_TYPE_SIGNED, SSLBP_DIR_OUT, 13, -10, 10, 0x01, false, 0},
    {"analogout4", "volt", SSLBP_TYPE_SIGNED, SSLBP_DIR_OUT, 13, -10, 10, 0x01, false, 0},
    {"analogout5", "volt", SSLBP_TYPE_SIGNED, SSLBP_DIR_OUT, 13, -10, 10, 0x01, false, 0},
    {"analogena", "none", SSLBP_TYPE_BOOLEAN, SSLBP_DIR_OUT, 1, 0, 0, 0x01, false, 0},
    {"spinena", "none", SSLBP_TYPE_BOOLEAN, SSLBP_DIR_OUT, 1, 0, 0, 0x01, false, 0},
    NV_GLOBALS,
};

#define COUNT(a) ((int)(sizeof(a) / sizeof((a)[0])))

/* The remote types by their mesa-sim name; a 7I77 takes two channels (I/O, then analog). */
static const struct {
    const char *cli;
    sim_remote_type_t type;
} types[] = {
    {"7i76", {"7I76", "standard", {"io_spin", "io_ana_spin", "io_enc_ana_spin_fv"}, 3, records_7i76,
              COUNT(records_7i76), 50}},
    {"7i77", {"7I77", "standard", {"input_output", "io_analog", "io_analog_fieldvoltage",
                                   "io_encoder_analog_fieldvoltage"}, 4, records_7i77_io,
              COUNT(records_7i77_io), 50}},
    {"7i77-analog", {"7I77", "standard", {"analogout_enables"}, 1, records_7i77_analog,
                     COUNT(records_7i77_analog), 50}},
};

/* Remote type by mesa-sim name ("7i76", "7i77", "7i77-analog"), or NULL. */
const sim_remote_type_t *sim_remote_type(const char *name)
{
    for (size_t i = 0; i < sizeof(types) / sizeof(types[0]); i++)
        if (!strcasecmp(types[i].cli, name))
            return &types[i].type;
    return NULL;
}

/* Little-endian store into remote memory. */
static void mem_put(sim_remote_t *r, uint32_t addr, uint32_t v, int bytes)
{
    for (int i = 0; i < bytes && addr + i < SIM_REMOTE_MEM; i++)
        r->mem[addr + i] = (uint8_t)(v >> (8 * i));
}

/* A 0-terminated string into remote memory; returns the next free address. */
static uint32_t mem_string(sim_remote_t *r, uint32_t addr, const char *s)
{
    size_t n = strlen(s) + 1;
    memcpy(r->mem + addr, s, n);
    return addr + (uint32_t)n;
}

/* One process-data record; returns the next free address. */
static uint32_t put_record(sim_remote_t *r, uint32_t at, const sim_record_def_t *d, uint16_t parm_addr)
{
    uint32_t fmin, fmax;
    memcpy(&fmin, &d->min, 4);
    memcpy(&fmax, &d->max, 4);
    r->mem[at + SSLBP_PD_TYPE] = SSLBP_REC_PROCESS_DATA;
    r->mem[at + SSLBP_PD_BITS] = d->bits;
    r->mem[at + SSLBP_PD_DATA_TYPE] = d->data_type;
    r->mem[at + SSLBP_PD_DIR] = d->dir;
    mem_put(r, at + SSLBP_PD_MIN, fmin, 4);
    mem_put(r, at + SSLBP_PD_MAX, fmax, 4);
    mem_put(r, at + SSLBP_PD_ADDR, parm_addr, 2);
    return mem_string(r, mem_string(r, at + SSLBP_PD_STRINGS, d->unit), d->name);
}

/* One mode record; returns the next free address. */
static uint32_t put_mode(sim_remote_t *r, uint32_t at, int index, int kind, const char *name)
{
    r->mem[at] = SSLBP_REC_MODE;
    r->mem[at + SSLBP_MODE_INDEX] = (uint8_t)index;
    r->mem[at + SSLBP_MODE_KIND] = (uint8_t)kind;
    return mem_string(r, at + SSLBP_MODE_NAME, name);
}

/* Build the remote memory: records, one PTOC per software mode (modes first), the GTOC. */
void sim_remote_attach(sim_remote_t *r, const sim_remote_type_t *t, uint32_t unit)
{
    memset(r, 0, sizeof(*r));
    r->type = t;
    r->unit = unit;
    uint32_t at = REC_AREA, toc = TOC_AREA, global = GLOBAL_AREA;
    uint16_t mode_addr[5];
    mode_addr[0] = (uint16_t)at;
    at = put_mode(r, at, 0, SSLBP_MODE_HARDWARE, t->hw_mode);
    for (int m = 0; m < t->num_sw_modes; m++) {
        mode_addr[m + 1] = (uint16_t)at;
        at = put_mode(r, at, m, SSLBP_MODE_SOFTWARE, t->sw_modes[m]);
    }
    for (int i = 0; i < t->num_records; i++) {
        uint16_t parm = 0;
        if (t->records[i].global) {
            parm = (uint16_t)global;
            mem_put(r, global, t->records[i].initial, 4);
            global += 4;
        }
        r->rec_addr[i] = (uint16_t)at;
        at = put_record(r, at, &t->records[i], parm);
    }
    for (int m = 0; m < t->num_sw_modes; m++) {
        r->ptoc[m] = (uint16_t)toc;
        for (int k = 0; k <= t->num_sw_modes; k++, toc += 2)
            mem_put(r, toc, mode_addr[k], 2);
        for (int i = 0; i < t->num_records; i++)
            if (!t->records[i].global && (t->records[i].modes & (1u << m))) {
                mem_put(r, toc, r->rec_addr[i], 2);
                toc += 2;
            }
        toc += 2;
    }
    r->gtoc = (uint16_t)toc;
    for (int i = 0; i < t->num_records; i++)
        if (t->records[i].global) {
            mem_put(r, toc, r->rec_addr[i], 2);
            toc += 2;
        }
}

/* The remote drives its outputs only while running and fed within its watchdog time. */
bool sim_remote_outputs_enabled(const sim_remote_t *r, long long now_ns)
{
    if (!r->type || !r->started || !r->ever_transferred)
        return false;
    return now_ns - r->last_transfer_ns <= (long long)r->type->watchdog_ms * 1000000LL;
}

/* Record index by name, or -1; "input-05" names bit 5 of a BITS record (*bit = 5, else -1). */
int sim_remote_find(const sim_remote_t *r, const char *name, int *bit)
{
    *bit = -1;
    for (int i = 0; r->type && i < r->type->num_records; i++) {
        const char *n = r->type->records[i].name;
        size_t len = strlen(n);
        if (!strcmp(name, n))
            return i;
        if (!strncmp(name, n, len) && name[len] == '-' && r->type->records[i].data_type == SSLBP_TYPE_BITS) {
            *bit = (int)strtol(name + len + 1, NULL, 10);
            return *bit >= 0 && *bit < r->type->records[i].bits ? i : -1;
        }
    }
    return -1;
}

/* Bits [off, off+n) of a register array. */
static uint32_t field_get(const uint32_t *regs, int off, int n)
{
    uint32_t v = 0;
    for (int i = 0; i < n && i < 32; i++)
        v |= ((regs[(off + i) / 32] >> ((off + i) % 32)) & 1u) << i;
    return v;
}

/* Store n bits at off of a register array. */
static void field_put(uint32_t *regs, int off, int n, uint32_t v)
{
    for (int i = 0; i < n && i < 32; i++) {
        uint32_t bit = 1u << ((off + i) % 32);
        regs[(off + i) / 32] = ((v >> i) & 1u) ? regs[(off + i) / 32] | bit : regs[(off + i) / 32] & ~bit;
    }
}

/* One process-data transfer in the started mode: take the outputs, return the inputs. */
void sim_remote_exchange(sim_remote_t *r, const uint32_t *out, uint32_t *in, long long now_ns)
{
    int off_out = 0, off_in = 0;
    memset(in, 0, SSLBP_V0_INTERFACE_REGS * sizeof(uint32_t));
    for (int i = 0; i < r->type->num_records; i++) {
        const sim_record_def_t *d = &r->type->records[i];
        if (d->global || !(d->modes & (1u << r->mode)))
            continue;
        if (d->dir == SSLBP_DIR_OUT) {
            r->value[i] = field_get(out, off_out, d->bits);
            off_out += d->bits;
        } else {
            field_put(in, off_in, d->bits, r->value[i]);
            off_in += d->bits;
        }
    }
    r->last_transfer_ns = now_ns;
    r->ever_transferred = true;
}

/* Remote memory access (globals live there too). */
uint32_t sim_remote_read32(const sim_remote_t *r, uint32_t addr)
{
    uint32_t v = 0;
    for (int i = 0; i < 4 && addr + i < SIM_REMOTE_MEM; i++)
        v |= (uint32_t)r->mem[addr + i] << (8 * i);
    return v;
}

/* Write 4 bytes of remote memory (only the globals area is writable). */
void sim_remote_write32(sim_remote_t *r, uint32_t addr, uint32_t v)
{
    if (addr >= GLOBAL_AREA)
        mem_put(r, addr, v, 4);
}
