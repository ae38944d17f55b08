/* sim_regs.c: the simulated card's HostMot2 register file (space 0): ROM and module registers. */
#include <math.h>
#include <stddef.h>
#include "sim_card.h"

#define WD_DISABLED 0x80000000u
#define WD_PET_MAGIC 0x5Au
#define ENC_QUAD_ERROR (1u << 15)
#define ENC_WRITABLE 0x7FF8u

/* Decoded module register address. */
typedef struct {
    int reg, inst;
} sim_addr_t;

/* Split base + reg*0x100 + inst*4 for a module at base with `regs` registers. */
static bool decode(uint16_t addr, uint32_t base, int regs, sim_addr_t *a)
{
    if (addr < base || addr >= base + (uint32_t)regs * SIM_REG_STRIDE)
        return false;
    a->reg = (addr - base) / SIM_REG_STRIDE;
    a->inst = ((addr - base) % SIM_REG_STRIDE) / SIM_INST_STRIDE;
    return true;
}

/* Little-endian word of the ROM image. */
static uint32_t rom_word(const sim_card_t *c, uint16_t addr)
{
    if (addr + 4 > SIM_ROM_BYTES)
        return 0;
    const uint8_t *p = c->rom + addr;
    return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
}

/* Data register of a port: the level of every pin. */
static uint32_t port_levels(const sim_card_t *c, int port)
{
    uint32_t v = 0;
    for (int b = 0; b < c->board->port_width; b++)
        if (sim_io_level(c, port * c->board->port_width + b))
            v |= 1u << b;
    return v;
}

/* Encoder registers: count + timestamp, latch + control/status, globals. */
static uint32_t encoder_read(sim_card_t *c, sim_addr_t a)
{
    if (a.reg == 3)
        return sim_timestamp(c, c->now_ns);
    if (a.reg == 2)
        return c->enc_tsdiv;
    if (a.reg == 4)
        return c->enc_filter;
    if (a.inst >= c->board->encoders)
        return 0;
    const sim_encoder_t *e = &c->encoder[a.inst];
    uint32_t count = (uint32_t)(int64_t)floor(e->position);
    if (a.reg == 0)
        return (uint32_t)e->last_event_ts << 16 | (count & 0xFFFF);
    static const uint32_t phase[4] = {0, 1, 3, 2};   /* B:A per quadrature state */
    uint32_t status = phase[count & 3];
    if (e->index_every > 0 && (int64_t)floor(e->position) % e->index_every == 0)
        status |= 4;
    return (uint32_t)e->latched << 16 | (e->control & ENC_WRITABLE) | (e->quad_error ? ENC_QUAD_ERROR : 0) | status;
}

/* Stepgen registers. */
static uint32_t stepgen_read(sim_card_t *c, sim_addr_t a)
{
    if (a.reg == 9)
        return c->stepgen_master_dds;
    if (a.inst >= c->board->stepgens)
        return 0;
    const sim_stepgen_t *g = &c->stepgen[a.inst];
    uint32_t regs[9] = {g->rate, (uint32_t)(g->acc >> 16), g->mode, g->dirsetup, g->dirhold,
                        g->steplen, g->stepspace, 0, g->table_len};
    return a.reg < 9 ? regs[a.reg] : 0;
}

/* PWM registers. */
static uint32_t pwm_read(sim_card_t *c, sim_addr_t a)
{
    uint32_t global[3] = {c->pwm_dds, c->pdm_dds, c->pwm_enable};
    if (a.reg >= 2)
        return global[a.reg - 2];
    if (a.inst >= c->board->pwmgens)
        return 0;
    return a.reg == 0 ? c->pwmgen[a.inst].value : c->pwmgen[a.inst].mode;
}

/* IOPort registers. */
static uint32_t ioport_read(sim_card_t *c, sim_addr_t a)
{
    if (a.inst >= c->board->ports)
        return 0;
    uint32_t *regs[5] = {NULL, c->ddr, c->alt, c->open_drain, c->invert};
    return a.reg == 0 ? port_levels(c, a.inst) : regs[a.reg][a.inst];
}

/* Read one 32-bit register. */
uint32_t sim_reg_read(sim_card_t *c, uint16_t addr)
{
    sim_addr_t a;
    uint32_t v;
    if (addr == SIM_LED_BASE)
        return c->led;
    if (sim_uart_read(c, addr, &v) || sim_sserial_read(c, addr, &v))
        return v;
    if (addr < SIM_ROM_BYTES)
        return rom_word(c, addr);
    if (decode(addr, SIM_WATCHDOG_BASE, 3, &a) && a.inst == 0)
        return a.reg == 0 ? c->wd_timer : a.reg == 1 ? (uint32_t)c->wd_bitten : 0;
    if (decode(addr, SIM_IOPORT_BASE, 5, &a))
        return ioport_read(c, a);
    if (decode(addr, SIM_STEPGEN_BASE, 11, &a))
        return stepgen_read(c, a);
    if (decode(addr, SIM_ENCODER_BASE, 5, &a))
        return encoder_read(c, a);
    if (decode(addr, SIM_PWMGEN_BASE, 5, &a))
        return pwm_read(c, a);
    return 0;
}

/* Watchdog: timer (re)loads, status 0 clears a bite, 0x5A in the top byte of reset pets. */
static void watchdog_write(sim_card_t *c, int reg, uint32_t v)
{
    long long timeout = (long long)(((v & ~WD_DISABLED) + 1.0) * 1e9 / c->board->clock_low);
    if (reg == 0) {
        c->wd_timer = v;
        c->wd_deadline_ns = c->now_ns + timeout;
    } else if (reg == 1 && (v & 1) == 0 && c->wd_bitten) {
        c->wd_bitten = false;
        c->wd_deadline_ns = c->now_ns + (long long)((c->wd_timer + 1.0) * 1e9 / c->board->clock_low);
        sim_say("watchdog cleared");
    } else if (reg == 2 && (v >> 24) == WD_PET_MAGIC) {
        c->wd_deadline_ns = c->now_ns + (long long)(((c->wd_timer & ~WD_DISABLED) + 1.0) * 1e9 /
                                                    c->board->clock_low);
    }
}

/* Stepgen: rate, mode and timing registers (accumulator read-only). */
static void stepgen_write(sim_card_t *c, sim_addr_t a, uint32_t v)
{
    if (a.reg == 9) {
        c->stepgen_master_dds = v;
        return;
    }
    if (a.inst >= c->board->stepgens)
        return;
    sim_stepgen_t *g = &c->stepgen[a.inst];
    uint32_t *regs[9] = {&g->rate, NULL, &g->mode, &g->dirsetup, &g->dirhold, &g->steplen,
                         &g->stepspace, NULL, &g->table_len};
    if (a.reg < 9 && regs[a.reg])
        *regs[a.reg] = v;
}

/* Encoder: control (bit 15 clears the quadrature error) and the globals. */
static void encoder_write(sim_card_t *c, sim_addr_t a, uint32_t v)
{
    if (a.reg == 2)
        c->enc_tsdiv = v & 0xFFFF;
    else if (a.reg == 4)
        c->enc_filter = v;
    else if (a.reg == 1 && a.inst < c->board->encoders) {
        c->encoder[a.inst].control = v & ENC_WRITABLE;
        if (v & ENC_QUAD_ERROR)
            c->encoder[a.inst].quad_error = false;
    }
}

/* PWM: value and mode per instance, master rates and enables. */
static void pwm_write(sim_card_t *c, sim_addr_t a, uint32_t v)
{
    uint32_t *global[3] = {&c->pwm_dds, &c->pdm_dds, &c->pwm_enable};
    if (a.reg >= 2)
        *global[a.reg - 2] = v;
    else if (a.inst < c->board->pwmgens)
        *(a.reg == 0 ? &c->pwmgen[a.inst].value : &c->pwmgen[a.inst].mode) = v;
}

/* IOPort: output latch, DDR (ignored while bitten), alt source, open drain, invert. */
static void ioport_write(sim_card_t *c, sim_addr_t a, uint32_t v)
{
    if (a.inst >= c->board->ports)
        return;
    uint32_t *regs[5] = {c->data_out, c->ddr, c->alt, c->open_drain, c->invert};
    if (a.reg == 1 && c->wd_bitten)
        return;
    regs[a.reg][a.inst] = v;
}

/* Write one 32-bit register; writes to the ROM or unknown addresses are ignored. */
void sim_reg_write(sim_card_t *c, uint16_t addr, uint32_t v)
{
    sim_addr_t a;
    c->writes++;
    if (addr == SIM_LED_BASE)
        c->led = v;
    else if (sim_uart_write(c, addr, v) || sim_sserial_write(c, addr, v))
        return;
    else if (decode(addr, SIM_WATCHDOG_BASE, 3, &a) && a.inst == 0)
        watchdog_write(c, a.reg, v);
    else if (decode(addr, SIM_IOPORT_BASE, 5, &a))
        ioport_write(c, a, v);
    else if (decode(addr, SIM_STEPGEN_BASE, 11, &a))
        stepgen_write(c, a, v);
    else if (decode(addr, SIM_ENCODER_BASE, 5, &a))
        encoder_write(c, a, v);
    else if (decode(addr, SIM_PWMGEN_BASE, 5, &a))
        pwm_write(c, a, v);
}
