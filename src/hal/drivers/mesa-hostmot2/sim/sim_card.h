/* sim_card.h: state of the simulated Mesa Ethernet card (register file, modules, physics, faults). */
#ifndef SIM_CARD_H
#define SIM_CARD_H

#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include "sim_remote.h"

#define SIM_MAX_PORTS 3
#define SIM_MAX_IO (SIM_MAX_PORTS * 32)
#define SIM_MAX_STEPGENS 10
#define SIM_MAX_ENCODERS 8
#define SIM_MAX_PWMGENS 4
#define SIM_MAX_LOOPS 8
#define SIM_ROM_BYTES 0x0800

/* Fixed module layout of every simulated board. */
#define SIM_WATCHDOG_BASE 0x0C00
#define SIM_LED_BASE 0x0200
#define SIM_IOPORT_BASE 0x1000
#define SIM_STEPGEN_BASE 0x2000
#define SIM_ENCODER_BASE 0x3000
#define SIM_PWMGEN_BASE 0x4000
#define SIM_UART_TX_BASE 0x6000
#define SIM_UART_RX_BASE 0x7000
#define SIM_UART_STRIDE 0x10
#define SIM_UART_FIFO 16
#define SIM_MAX_UARTS 2
#define SIM_REG_STRIDE 0x100
#define SIM_INST_STRIDE 4

/* What a simulated board has: name, geometry, modules, pin functions. */
typedef struct {
    const char *name;               /* LBP16 board name, e.g. "7I92" */
    const char *idrom_name;         /* IDROM board name (8 chars) */
    int ports, port_width;
    int stepgens, encoders, pwmgens, uarts;
    uint32_t clock_low, clock_high;
    int sserial_channels;           /* channels of its Smart Serial port (0 = none) */
    const uint32_t *pins;           /* pin descriptor of each IO (ports * port_width) */
    const char *variant;            /* --board name of a firmware variant, e.g. "7i92-7i77" */
} sim_board_t;

/* A source feeding an encoder input: a stepgen's step output or a PWM-driven motor. */
typedef struct {
    int kind;                       /* SIM_LOOP_STEPGEN or SIM_LOOP_MOTOR */
    int from, to;                   /* stepgen/pwmgen index -> encoder index */
    double gain;                    /* counts per step, or counts/s at full duty */
} sim_loop_t;

enum { SIM_LOOP_STEPGEN = 1, SIM_LOOP_MOTOR = 2 };

typedef struct {
    uint32_t rate, mode, dirsetup, dirhold, steplen, stepspace, table_len;
    int64_t acc;                    /* DDS accumulator, 2^-32 steps */
    int64_t emitted_steps;          /* steps that reached the step pin */
} sim_stepgen_t;

typedef struct {
    double position;                /* counts (continuous) */
    uint16_t last_event_ts;
    uint32_t control;               /* control bits (latch enables cleared on latch) */
    uint16_t latched;
    int index_every;                /* index pulse every N counts (0 = none) */
    bool quad_error;
} sim_encoder_t;

typedef struct {
    uint32_t value, mode;
} sim_pwmgen_t;

/* A UART whose TX is wired to its own RX (loopback). */
typedef struct {
    uint8_t fifo[SIM_UART_FIFO];
    int count;
    uint32_t tx_bitrate, rx_bitrate, tx_mode, rx_mode;
} sim_uart_t;

/* The whole card. */
typedef struct {
    const sim_board_t *board;
    uint8_t mac[6];
    uint8_t rom[SIM_ROM_BYTES];      /* cookie, name, IDROM, MDs, PDs */
    uint8_t scratch[64];             /* LBP16 space 4 */
    uint16_t status_words[16];       /* LBP16 space 6 */
    uint16_t space_addr[8];          /* per-space address pointer */

    uint32_t data_out[SIM_MAX_PORTS], ddr[SIM_MAX_PORTS], alt[SIM_MAX_PORTS];
    uint32_t open_drain[SIM_MAX_PORTS], invert[SIM_MAX_PORTS];
    uint8_t input_level[SIM_MAX_IO]; /* level outside drives on undriven pins (pull-up: 1) */

    uint32_t wd_timer;
    bool wd_bitten;
    long long wd_deadline_ns;

    sim_stepgen_t stepgen[SIM_MAX_STEPGENS];
    uint32_t stepgen_master_dds;
    sim_encoder_t encoder[SIM_MAX_ENCODERS];
    uint32_t enc_tsdiv, enc_filter;
    sim_pwmgen_t pwmgen[SIM_MAX_PWMGENS];
    uint32_t pwm_dds, pdm_dds, pwm_enable;
    uint32_t led;
    sim_uart_t uart[SIM_MAX_UARTS];
    sim_sserial_t sserial;

    sim_loop_t loops[SIM_MAX_LOOPS];
    int num_loops;

    long long start_ns, now_ns;
    double tick_frac;                /* fractional ClockLow ticks not yet applied */

    /* fault injection */
    int drop_replies, garble_replies, stale_replies;
    bool paused;
    long long reply_delay_ns;
    unsigned long rx_packets, tx_packets, dropped, writes;
} sim_card_t;

/* ---- boards (sim_boards.c) ---- */
const sim_board_t *sim_find_board(const char *name);
void sim_list_boards(FILE *out);
void sim_build_rom(sim_card_t *c);

/* ---- time and physics (sim_physics.c) ---- */
void sim_advance(sim_card_t *c, long long now_ns);
int sim_io_level(const sim_card_t *c, int io);
bool sim_module_pin_driven(const sim_card_t *c, int gtag, int unit, int sec_pin);
uint16_t sim_timestamp(const sim_card_t *c, long long t_ns);
double sim_pwm_duty(const sim_card_t *c, int i, int *bits);

/* ---- registers (sim_regs.c) ---- */
uint32_t sim_reg_read(sim_card_t *c, uint16_t addr);
void sim_reg_write(sim_card_t *c, uint16_t addr, uint32_t value);

/* ---- UART (sim_uart.c) ---- */
bool sim_uart_read(sim_card_t *c, uint16_t addr, uint32_t *value);
bool sim_uart_write(sim_card_t *c, uint16_t addr, uint32_t value);

/* ---- Smart Serial (sim_sserial.c) ---- */
bool sim_sserial_read(sim_card_t *c, uint16_t addr, uint32_t *value);
bool sim_sserial_write(sim_card_t *c, uint16_t addr, uint32_t value);

/* ---- Smart Serial control commands (sim_sserial_cmd.c) ---- */
int sim_sserial_command(sim_card_t *c, int argc, char **argv);

/* ---- LBP16 (sim_lbp16.c) ---- */
int sim_handle_datagram(sim_card_t *c, const uint8_t *in, int len, uint8_t *out, int cap);

/* ---- commands (sim_commands.c) ---- */
int sim_command(sim_card_t *c, char *line);

/* Emit one line on stdout (flushed). */
void sim_say(const char *fmt, ...) __attribute__((format(printf, 1, 2)));

#endif
