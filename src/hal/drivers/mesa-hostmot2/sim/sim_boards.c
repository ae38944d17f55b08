/* sim_boards.c: the simulated boards (7I92, 7I76E, 7I96): pinouts and the IDROM they present. */
#include <stdio.h>
#include <string.h>
#include <strings.h>
#include "sim_card.h"
#include "../hm2_gtag.h"

#define IDROM_OFFSET 0x400
#define MD_OFFSET 0x40
#define PD_OFFSET 0x200
#define GPIO 0x03000000u
/* Pin descriptor: IOPort primary, module tag, unit, secondary pin (0x80 = output). */
#define PD(tag, unit, pin) (GPIO | (uint32_t)(unit) << 16 | (uint32_t)(tag) << 8 | (uint32_t)(pin))
#define SG(u) PD(HM2_GTAG_STEPGEN, u, 0x81), PD(HM2_GTAG_STEPGEN, u, 0x82)
#define ENC(u) PD(HM2_GTAG_ENCODER, u, 1), PD(HM2_GTAG_ENCODER, u, 2), PD(HM2_GTAG_ENCODER, u, 3)
#define PWM(u) PD(HM2_GTAG_PWMGEN, u, 0x81), PD(HM2_GTAG_PWMGEN, u, 0x82), PD(HM2_GTAG_PWMGEN, u, 0x83)
#define UART(u) PD(HM2_GTAG_UART_TX, u, 0x81), PD(HM2_GTAG_UART_TX, u, 0x82), PD(HM2_GTAG_UART_RX, u, 1)
#define G4 GPIO, GPIO, GPIO, GPIO
#define G17 G4, G4, G4, G4, GPIO
/* Smart Serial channel n of port 0: rx (input n+1), tx (output 0x81+n), tx enable (0x91+n). */
#define SS(n) PD(HM2_GTAG_SMARTSERIAL, 0, 1 + (n)), PD(HM2_GTAG_SMARTSERIAL, 0, 0x81 + (n)), \
    PD(HM2_GTAG_SMARTSERIAL, 0, 0x91 + (n))

static const uint32_t pins_7i92[34] = {
    SG(0), SG(1), SG(2), SG(3), ENC(0), ENC(1), PWM(0), G17,
};
static const uint32_t pins_7i76e[51] = {
    SG(0), SG(1), SG(2), SG(3), SG(4), G4, GPIO, GPIO, GPIO, G17, ENC(0), PWM(0), G4, SS(0), SS(1), GPIO,
};
/* 7I92 with a 7I77 on P1: 3 encoders and the Smart Serial channels 0-1 on P2, 2 stepgens on P1. */
static const uint32_t pins_7i92_7i77[34] = {
    ENC(0), ENC(1), ENC(2), SS(0), SS(1), GPIO, GPIO, SG(0), SG(1), G4, G4, G4, GPIO,
};
static const uint32_t pins_7i96[51] = {
    SG(0), SG(1), SG(2), SG(3), SG(4), ENC(0), PWM(0), GPIO, G17, G4, G4, G4, GPIO, GPIO, UART(0),
};

static const sim_board_t boards[] = {
    {"7I92", "MESA7I92", 2, 17, 4, 2, 1, 0, 100000000, 200000000, 0, pins_7i92, NULL},
    {"7I76E-16", "MESA7I76", 3, 17, 5, 1, 1, 0, 100000000, 200000000, SIM_SSERIAL_CHANNELS, pins_7i76e, NULL},
    {"7I96", "MESA7I96", 3, 17, 5, 1, 1, 1, 100000000, 200000000, 0, pins_7i96, NULL},
    {"7I92", "MESA7I92", 2, 17, 2, 3, 1, 0, 100000000, 200000000, SIM_SSERIAL_CHANNELS, pins_7i92_7i77,
     "7i92-7i77"},
};

/* Board by name, case-insensitive ("7i92", "7i76e", "7i96", or a variant such as "7i92-7i77"). */
const sim_board_t *sim_find_board(const char *name)
{
    for (size_t i = 0; i < sizeof(boards) / sizeof(boards[0]); i++)
        if (boards[i].variant && !strcasecmp(boards[i].variant, name))
            return &boards[i];
    for (size_t i = 0; i < sizeof(boards) / sizeof(boards[0]); i++) {
        size_t n = strlen(name);
        if (boards[i].variant)
            continue;
        if (strncasecmp(boards[i].name, name, n) == 0 &&
            (boards[i].name[n] == '\0' || boards[i].name[n] == '-'))
            return &boards[i];
    }
    return NULL;
}

/* The names --board accepts. */
void sim_list_boards(FILE *out)
{
    for (size_t i = 0; i < sizeof(boards) / sizeof(boards[0]); i++) {
        if (boards[i].variant)
            fprintf(out, " %s", boards[i].variant);
        else
            fprintf(out, " %.*s", (int)strcspn(boards[i].name, "-"), boards[i].name);
    }
    fprintf(out, "\n");
}

/* Little-endian word into the ROM image. */
static void rom32(sim_card_t *c, uint32_t addr, uint32_t v)
{
    for (int i = 0; i < 4; i++)
        c->rom[addr + i] = (uint8_t)(v >> (8 * i));
}

/* One module descriptor (register stride selector 0 = 0x100; instance selector 0 = 4, 1 = the
   board's InstanceStride1: 0x10 for UART boards, 0x40 for Smart Serial boards). */
static void rom_md(sim_card_t *c, int index, int gtag, int version, int clock_tag, int instances,
                   uint32_t base, int regs, uint32_t multiple)
{
    uint32_t at = IDROM_OFFSET + MD_OFFSET + 12 * index;
    uint32_t inst_sel = (gtag == HM2_GTAG_UART_TX || gtag == HM2_GTAG_UART_RX ||
                        gtag == HM2_GTAG_SMARTSERIAL) ? 1 : 0;
    rom32(c, at, (uint32_t)gtag | (uint32_t)version << 8 | (uint32_t)clock_tag << 16 | (uint32_t)instances << 24);
    rom32(c, at + 4, base | (uint32_t)regs << 16 | inst_sel << 28);
    rom32(c, at + 8, multiple);
}

/* Cookie, name, IDROM header, module descriptors and pin descriptors. */
void sim_build_rom(sim_card_t *c)
{
    const sim_board_t *b = c->board;
    int io_width = b->ports * b->port_width, md = 0;
    memset(c->rom, 0, sizeof(c->rom));
    rom32(c, 0x100, 0x55AACAFE);
    memcpy(c->rom + 0x104, "HOSTMOT2", 8);
    rom32(c, 0x10C, IDROM_OFFSET);
    uint32_t header[16] = {3, MD_OFFSET, PD_OFFSET, 0, 0, 9, 144, (uint32_t)b->ports,
                           (uint32_t)io_width, (uint32_t)b->port_width, b->clock_low, b->clock_high,
                           SIM_INST_STRIDE, b->sserial_channels ? SSLBP_INSTANCE_STRIDE : SIM_UART_STRIDE,
                           SIM_REG_STRIDE, 4};
    for (int i = 0; i < 16; i++)
        rom32(c, IDROM_OFFSET + 4 * i, header[i]);
    memcpy(c->rom + IDROM_OFFSET + 0x0C, b->idrom_name, 8);
    rom_md(c, md++, HM2_GTAG_WATCHDOG, 0, 1, 1, SIM_WATCHDOG_BASE, 3, 0x00);
    rom_md(c, md++, HM2_GTAG_IOPORT, 0, 1, b->ports, SIM_IOPORT_BASE, 5, 0x1F);
    rom_md(c, md++, HM2_GTAG_STEPGEN, 2, 1, b->stepgens, SIM_STEPGEN_BASE, 10, 0x1FF);
    rom_md(c, md++, HM2_GTAG_ENCODER, 2, 1, b->encoders, SIM_ENCODER_BASE, 5, 0x03);
    rom_md(c, md++, HM2_GTAG_PWMGEN, 0, 2, b->pwmgens, SIM_PWMGEN_BASE, 5, 0x03);
    rom_md(c, md++, HM2_GTAG_LED, 0, 1, 1, SIM_LED_BASE, 1, 0x00);
    if (b->uarts) {
        rom_md(c, md++, HM2_GTAG_UART_TX, 0, 1, b->uarts, SIM_UART_TX_BASE, 4, 0x0F);
        rom_md(c, md++, HM2_GTAG_UART_RX, 0, 1, b->uarts, SIM_UART_RX_BASE, 4, 0x0F);
    }
    if (b->sserial_channels)
        rom_md(c, md++, HM2_GTAG_SMARTSERIAL, 0, 1, 1, SIM_SSERIAL_BASE, SSLBP_V0_REGISTERS,
               SSLBP_MULTIPLE_REGS);
    for (int i = 0; i < io_width; i++)
        rom32(c, IDROM_OFFSET + PD_OFFSET + 4 * i, b->pins[i]);
}
