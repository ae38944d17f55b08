/* sim_sserial.c: the simulated card's Smart Serial port (one SSLBP port, 2 channels): the
   command/data/CS/interface registers, set-up and normal starts, remote reads/writes, do-it. */
#include "sim_card.h"

#define REG_SPAN (SSLBP_V0_REGISTERS * SIM_REG_STRIDE)
#define CS_CMD(cs) ((cs) & 0xFF000000u)

/* Split an address of the module into register and channel; false when not ours. */
static bool decode(const sim_card_t *c, uint16_t addr, int *reg, int *chan)
{
    if (!c->board->sserial_channels || addr < SIM_SSERIAL_BASE || addr >= SIM_SSERIAL_BASE + REG_SPAN)
        return false;
    uint32_t off = addr - SIM_SSERIAL_BASE;
    *reg = (int)(off / SIM_REG_STRIDE);
    *chan = (int)((off % SIM_REG_STRIDE) / 4);
    return *chan < SSLBP_INSTANCE_STRIDE / 4;
}

/* The remote on a channel, if it can answer (connected, cable in). */
static sim_remote_t *answering(sim_card_t *c, int chan)
{
    sim_remote_t *r = chan < SIM_SSERIAL_CHANNELS ? &c->sserial.remote[chan] : NULL;
    return r && r->type && !r->unplugged ? r : NULL;
}

/* Set-up start: the remote reports unit, name and its tables of contents for the mode in CS. */
static bool start_setup(sim_card_t *c, int chan)
{
    sim_sserial_t *s = &c->sserial;
    sim_remote_t *r = answering(c, chan);
    if (!r)
        return false;
    int mode = (int)(s->cs_out[chan] >> SSLBP_CS_MODE_SHIFT);
    r->setup = true;
    r->started = false;
    r->mode = mode < r->type->num_sw_modes ? mode : 0;
    const char *n = r->type->name;
    s->iface_in[chan][0] = r->unit;
    s->iface_in[chan][1] = (uint32_t)n[0] | (uint32_t)n[1] << 8 | (uint32_t)n[2] << 16 | (uint32_t)n[3] << 24;
    s->iface_in[chan][2] = r->ptoc[r->mode] | (uint32_t)r->gtoc << 16;
    s->cs_in[chan] = 1u << 16;   /* protocol 1 */
    return true;
}

/* Normal start in the mode written to CS; a mode the remote lacks fails. */
static bool start_normal(sim_card_t *c, int chan)
{
    sim_remote_t *r = answering(c, chan);
    int mode = (int)(c->sserial.cs_out[chan] >> SSLBP_CS_MODE_SHIFT);
    if (!r || mode >= r->type->num_sw_modes)
        return false;
    r->mode = mode;
    r->setup = false;
    r->started = true;
    r->ever_transferred = false;
    return true;
}

/* One do-it on a channel: a remote memory access (CS command) or a process-data transfer. */
static bool doit(sim_card_t *c, int chan)
{
    sim_sserial_t *s = &c->sserial;
    sim_remote_t *r = answering(c, chan);
    uint32_t cs = s->cs_out[chan & (SIM_SSERIAL_CHANNELS - 1)];
    if (!r) {
        if (chan < SIM_SSERIAL_CHANNELS)
            s->cs_in[chan] = (uint32_t)SSLBP_LINK_TIMEOUT << 8 | 1u << 16;
        return false;
    }
    uint32_t addr = cs & SSLBP_CS_ADDR_MASK;
    if (CS_CMD(cs) == SSLBP_CS_REMOTE_READ) {
        s->iface_in[chan][0] = sim_remote_read32(r, addr);
    } else if (CS_CMD(cs) == SSLBP_CS_REMOTE_WRITE) {
        sim_remote_write32(r, addr, s->iface_out[chan][0]);
    } else if (r->started) {
        sim_remote_exchange(r, s->iface_out[chan], s->iface_in[chan], c->now_ns);
        s->doits++;
    } else {
        return false;
    }
    s->cs_in[chan] = 1u << 16 | r->status;
    return true;
}

/* Run a command written to the command register (done at once: it reads back 0, unless a
   busy fault leaves a do-it unfinished until the next command). */
static void command(sim_card_t *c, uint32_t cmd)
{
    sim_sserial_t *s = &c->sserial;
    uint32_t mask = cmd & SSLBP_CMD_MASK, failed = 0;
    bool (*per_channel)(sim_card_t *, int) = NULL;
    if ((cmd & SSLBP_CMD_IGNORED) || cmd == 0)
        return;
    s->pending = 0;
    if ((cmd & 0xF000u) == SSLBP_CMD_DOIT && s->busy_doits > 0) {
        s->busy_doits--;
        s->pending = cmd;
        return;
    }
    if ((cmd & 0xF000u) == SSLBP_CMD_READ_LOCAL && (cmd & 0xFFu) == SSLBP_LOCAL_VERSION) {
        s->data = SIM_SSERIAL_VERSION;
        return;
    }
    if ((cmd & 0xFF00u) == SSLBP_CMD_STOP_ALL) {
        for (int ch = 0; ch < SIM_SSERIAL_CHANNELS; ch++)
            s->remote[ch].started = s->remote[ch].setup = false;
        s->data = 0;
        return;
    }
    if ((cmd & 0xFF00u) == SSLBP_CMD_START_SETUP)
        per_channel = start_setup;
    else if ((cmd & 0xFF00u) == SSLBP_CMD_START_NORMAL)
        per_channel = start_normal;
    else if ((cmd & 0xF000u) == SSLBP_CMD_DOIT)
        per_channel = doit;
    for (int ch = 0; per_channel && ch < 8; ch++)
        if ((mask & (1u << ch)) && !(ch < c->board->sserial_channels && per_channel(c, ch)))
            failed |= 1u << ch;
    s->data = failed;
}

/* Register read; false when the address is not the Smart Serial module's. */
bool sim_sserial_read(sim_card_t *c, uint16_t addr, uint32_t *v)
{
    int reg, chan;
    if (!decode(c, addr, &reg, &chan))
        return false;
    sim_sserial_t *s = &c->sserial;
    bool ok = chan < SIM_SSERIAL_CHANNELS;
    switch (reg) {
    case SSLBP_REG_COMMAND: *v = chan == 0 ? s->pending : 0; break;
    case SSLBP_REG_DATA: *v = chan == 0 ? s->data : 0; break;
    case SSLBP_REG_CS: *v = ok ? s->cs_in[chan] : 0; break;
    default: *v = ok ? s->iface_in[chan][reg - SSLBP_REG_INTERFACE0] : 0; break;
    }
    return true;
}

/* Register write; false when the address is not the Smart Serial module's. */
bool sim_sserial_write(sim_card_t *c, uint16_t addr, uint32_t v)
{
    int reg, chan;
    if (!decode(c, addr, &reg, &chan))
        return false;
    sim_sserial_t *s = &c->sserial;
    bool ok = chan < SIM_SSERIAL_CHANNELS;
    if (reg == SSLBP_REG_COMMAND && chan == 0)
        command(c, v);
    else if (reg == SSLBP_REG_CS && ok)
        s->cs_out[chan] = v;
    else if (reg >= SSLBP_REG_INTERFACE0 && ok)
        s->iface_out[chan][reg - SSLBP_REG_INTERFACE0] = v;
    return true;
}
