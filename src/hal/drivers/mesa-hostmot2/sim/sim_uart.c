/* sim_uart.c: the simulated card's UARTs: TX pushes of 1-4 bytes loop back into the RX FIFO. */
#include "sim_card.h"

/* Register, instance and byte count of a UART address; false when it is not a UART address. */
static bool decode(const sim_card_t *c, uint16_t addr, uint32_t base, int *reg, int *inst, int *bytes)
{
    if (!c->board->uarts || addr < base || addr >= base + 4 * SIM_REG_STRIDE)
        return false;
    *reg = (addr - base) / SIM_REG_STRIDE;
    int off = (addr - base) % SIM_REG_STRIDE;
    *inst = off / SIM_UART_STRIDE;
    *bytes = (off % SIM_UART_STRIDE) / 4 + 1;
    return *inst < c->board->uarts;
}

/* RX: data pops (1-4 bytes), FIFO count, bitrate, mode; TX: FIFO count, bitrate, mode. */
bool sim_uart_read(sim_card_t *c, uint16_t addr, uint32_t *value)
{
    int reg, inst, bytes;
    if (decode(c, addr, SIM_UART_TX_BASE, &reg, &inst, &bytes)) {
        sim_uart_t *u = &c->uart[inst];
        *value = reg == 2 ? u->tx_bitrate : reg == 3 ? u->tx_mode : 0;
        return true;
    }
    if (!decode(c, addr, SIM_UART_RX_BASE, &reg, &inst, &bytes))
        return false;
    sim_uart_t *u = &c->uart[inst];
    if (reg == 0) {
        uint32_t w = 0;
        int n = bytes < u->count ? bytes : u->count;
        for (int i = 0; i < n; i++)
            w |= (uint32_t)u->fifo[i] << (8 * i);
        for (int i = n; i < u->count; i++)
            u->fifo[i - n] = u->fifo[i];
        u->count -= n;
        *value = w;
    } else {
        *value = reg == 1 ? (uint32_t)u->count : reg == 2 ? u->rx_bitrate : u->rx_mode;
    }
    return true;
}

/* TX data pushes feed the RX FIFO (16 deep, excess dropped); 0 to a count register empties it. */
bool sim_uart_write(sim_card_t *c, uint16_t addr, uint32_t value)
{
    int reg, inst, bytes;
    bool tx = decode(c, addr, SIM_UART_TX_BASE, &reg, &inst, &bytes);
    if (!tx && !decode(c, addr, SIM_UART_RX_BASE, &reg, &inst, &bytes))
        return false;
    sim_uart_t *u = &c->uart[inst];
    if (reg == 0 && tx) {
        for (int i = 0; i < bytes && u->count < SIM_UART_FIFO; i++)
            u->fifo[u->count++] = (uint8_t)(value >> (8 * i));
    } else if (reg == 1) {
        u->count = 0;
    } else if (reg == 2) {
        *(tx ? &u->tx_bitrate : &u->rx_bitrate) = value;
    } else if (reg == 3) {
        *(tx ? &u->tx_mode : &u->rx_mode) = value;
    }
    return true;
}
