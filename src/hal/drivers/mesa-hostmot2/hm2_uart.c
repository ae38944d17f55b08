/* hm2_uart.c: the UART module (GTag 9/10) and its serial API: setup, send, read. */
#include <stdlib.h>
#include "rtapi_errno.h"
#include "hm2.h"
#include "hm2_serial_lookup.h"
#include "hostmot2-serial.h"

#define UART_FIFO_BYTES 16
#define UART_RX_COUNT_MASK 0x1Fu

/* Parse the TX or RX descriptor; the instance (and its name) exists once either is seen. */
int hm2_uart_parse_md(hm2_board_t *hm2, int md_index)
{
    const hm2_md_t *md = &hm2->md[md_index];
    hm2_uart_t *u = &hm2->uart;
    if (!hm2_md_is_consistent_or_complain(hm2, md_index, 0, 4, 0x10, 0x0F))
        return -EINVAL;
    int wanted = hm2->config.num_uarts;
    if (wanted > md->instances) {
        HM2_ERR(hm2, "config defines %d uarts, but only %d are available, not loading driver\n",
                wanted, md->instances);
        return -EINVAL;
    }
    int n = wanted < 0 ? md->instances : wanted;
    if (n == 0)
        return 0;
    if (!u->instance) {
        u->instance = calloc(n, sizeof(*u->instance));
        if (!u->instance)
            return -ENOMEM;
        u->num_instances = n;
        for (int i = 0; i < n; i++) {
            rtapi_snprintf(u->instance[i].name, sizeof(u->instance[i].name), "%s.uart.%d",
                           hm2->llio->name, i);
            HM2_PRINT(hm2, "created UART Interface function %s.\n", u->instance[i].name);
        }
    }
    for (int i = 0; i < u->num_instances && i < n; i++) {
        hm2_uart_instance_t *in = &u->instance[i];
        uint32_t base = md->base_address + i * md->instance_stride, rs = md->register_stride;
        in->clock_freq = md->clock_freq;
        if (md->gtag == HM2_GTAG_UART_TX) {
            in->tx1_addr = base; in->tx2_addr = base + 4; in->tx3_addr = base + 8; in->tx4_addr = base + 12;
            in->tx_fifo_count_addr = base + rs;
            in->tx_bitrate_addr = base + 2 * rs;
            in->tx_mode_addr = base + 3 * rs;
        } else {
            in->rx1_addr = base; in->rx2_addr = base + 4; in->rx3_addr = base + 8; in->rx4_addr = base + 12;
            in->rx_fifo_count_addr = base + rs;
            in->rx_bitrate_addr = base + 2 * rs;
            in->rx_mode_addr = base + 3 * rs;
        }
    }
    return n;
}

/* Release the instances. */
void hm2_uart_cleanup(hm2_board_t *hm2)
{
    free(hm2->uart.instance);
    hm2->uart.instance = NULL;
    hm2->uart.num_instances = 0;
}

/* Bitrate register = bitrate * 2^20 / clock. */
static uint32_t uart_bitrate_register(uint32_t clock, int bitrate)
{
    return (uint32_t)((double)bitrate * 1048576.0 / clock);
}

/* Set the bitrate (when changed: clears RX mode and both FIFOs) and the mode registers. */
int hm2_uart_setup(char *name, int bitrate, rtapi_s32 tx_mode, rtapi_s32 rx_mode)
{
    hm2_board_t *hm2;
    hm2_uart_instance_t *in = hm2_find_uart(name, &hm2);
    if (!in) {
        rtapi_print_msg(RTAPI_MSG_ERR, "hm2: Can not find UART instance %s.\n", name ? name : "(null)");
        return -1;
    }
    uint32_t reg = uart_bitrate_register(in->clock_freq, bitrate), zero = 0;
    if (!in->configured || reg != in->bitrate) {
        hm2_write(hm2, in->rx_bitrate_addr, &reg, 4);
        hm2_write(hm2, in->tx_bitrate_addr, &reg, 4);
        hm2_write(hm2, in->rx_mode_addr, &zero, 4);
        hm2_write(hm2, in->rx_fifo_count_addr, &zero, 4);
        hm2_write(hm2, in->tx_fifo_count_addr, &zero, 4);
        in->bitrate = reg;
    }
    if (tx_mode >= 0) {
        uint32_t m = (uint32_t)tx_mode & 0x7F;
        hm2_write(hm2, in->tx_mode_addr, &m, 4);
    }
    if (rx_mode >= 0) {
        uint32_t m = (uint32_t)rx_mode & 0xFF;
        hm2_write(hm2, in->rx_mode_addr, &m, 4);
    }
    in->configured = true;
    return 0;
}
EXPORT_SYMBOL(hm2_uart_setup);

/* Little-endian word of n bytes. */
static uint32_t pack_bytes(const unsigned char *data, int n)
{
    uint32_t w = 0;
    for (int k = 0; k < n; k++)
        w |= (uint32_t)data[k] << (8 * k);
    return w;
}

/* Push count bytes: 4 at a time, the rest through the 1/2/3-byte address. Returns bytes sent. */
int hm2_uart_send(char *name, unsigned char data[], int count)
{
    hm2_board_t *hm2;
    hm2_uart_instance_t *in = hm2_find_uart(name, &hm2);
    if (!in) {
        rtapi_print_msg(RTAPI_MSG_ERR, "hm2: Can not find UART instance %s.\n", name ? name : "(null)");
        return -1;
    }
    if (!in->configured) {
        if (!in->warned_unconfigured)
            HM2_ERR(hm2, "The selected UART instance %s.\nHas not been configured.\n", name);
        in->warned_unconfigured = true;
        return -1;
    }
    int sent = 0;
    uint32_t addr[] = {0, in->tx1_addr, in->tx2_addr, in->tx3_addr, in->tx4_addr};
    while (sent < count) {
        int n = count - sent >= 4 ? 4 : count - sent;
        uint32_t w = pack_bytes(data + sent, n);
        if (hm2_write(hm2, addr[n], &w, 4) < 0)
            break;
        sent += n;
    }
    return sent;
}
EXPORT_SYMBOL(hm2_uart_send);

/* Read what the RX FIFO holds (at most 16 bytes) into data. Returns the byte count. */
int hm2_uart_read(char *name, unsigned char data[])
{
    hm2_board_t *hm2;
    hm2_uart_instance_t *in = hm2_find_uart(name, &hm2);
    if (!in) {
        rtapi_print_msg(RTAPI_MSG_ERR, "hm2: Can not find UART instance %s.\n", name ? name : "(null)");
        return -1;
    }
    uint32_t count_reg;
    if (hm2_read(hm2, in->rx_fifo_count_addr, &count_reg, 4) < 0)
        return -1;
    int count = (int)(count_reg & UART_RX_COUNT_MASK);
    if (count > UART_FIFO_BYTES)
        count = UART_FIFO_BYTES;
    uint32_t addr[] = {0, in->rx1_addr, in->rx2_addr, in->rx3_addr, in->rx4_addr};
    int got = 0;
    while (got < count) {
        int n = count - got >= 4 ? 4 : count - got;
        uint32_t w;
        if (hm2_read(hm2, addr[n], &w, 4) < 0)
            return -1;
        for (int k = 0; k < n; k++)
            data[got + k] = (unsigned char)(w >> (8 * k));
        got += n;
    }
    return got;
}
EXPORT_SYMBOL(hm2_uart_read);
