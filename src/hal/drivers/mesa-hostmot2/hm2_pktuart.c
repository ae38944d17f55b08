/* hm2_pktuart.c: the PktUART module (GTag 27/28): configuration, TRAM status and frame transfer API. */
#include <stdlib.h>
#include "rtapi_errno.h"
#include "hm2.h"
#include "hm2_serial_lookup.h"
#include "hostmot2-serial.h"

#define PKTUART_MAX_FRAMES 16
#define PKTUART_BITRATE_MAX 0xFFFFFFu

/* Parse the TX or RX descriptor; instances are named hm2_<board>.<idx>.pktuart.<n>. */
int hm2_pktuart_parse_md(hm2_board_t *hm2, int md_index)
{
    const hm2_md_t *md = &hm2->md[md_index];
    hm2_pktuart_t *p = &hm2->pktuart;
    if (md->version > 3 || !hm2_md_is_consistent_or_complain(hm2, md_index, md->version, 4, 4, 0x0F))
        return -EINVAL;
    int wanted = hm2->config.num_pktuarts;
    if (wanted > md->instances) {
        HM2_ERR(hm2, "config defines %d pktuarts, but only %d are available, not loading driver\n",
                wanted, md->instances);
        return -EINVAL;
    }
    int n = wanted < 0 ? md->instances : wanted;
    if (n == 0)
        return 0;
    if (!p->instance) {
        p->instance = calloc(n, sizeof(*p->instance));
        if (!p->instance)
            return -ENOMEM;
        p->num_instances = n;
        for (int i = 0; i < n; i++) {
            rtapi_snprintf(p->instance[i].name, sizeof(p->instance[i].name), "%s.pktuart.%d",
                           hm2->llio->name, i);
            HM2_PRINT(hm2, "created PktUART Interface function %s.\n", p->instance[i].name);
        }
    }
    for (int i = 0; i < p->num_instances && i < n; i++) {
        hm2_pktuart_instance_t *in = &p->instance[i];
        uint32_t base = md->base_address + i * md->instance_stride, rs = md->register_stride;
        int r;
        in->clock_freq = md->clock_freq;
        if (md->gtag == HM2_GTAG_PKTUART_TX) {
            in->tx_version = md->version;
            in->tx_fifo_addr = base; in->tx_count_addr = base + rs;
            in->tx_bitrate_addr = base + 2 * rs; in->tx_mode_addr = base + 3 * rs;
            r = hm2_register_tram_read_region(hm2, in->tx_mode_addr, 4, &in->tx_status_reg);
        } else {
            in->rx_version = md->version;
            in->rx_fifo_addr = base; in->rx_count_addr = base + rs;
            in->rx_bitrate_addr = base + 2 * rs; in->rx_mode_addr = base + 3 * rs;
            r = hm2_register_tram_read_region(hm2, in->rx_mode_addr, 4, &in->rx_status_reg);
        }
        if (r < 0)
            return r;
    }
    return n;
}

/* Release the instances. */
void hm2_pktuart_cleanup(hm2_board_t *hm2)
{
    free(hm2->pktuart.instance);
    hm2->pktuart.instance = NULL;
    hm2->pktuart.num_instances = 0;
}

/* Instance by name, logging the miss. */
static hm2_pktuart_instance_t *lookup(const char *name, hm2_board_t **hm2)
{
    hm2_pktuart_instance_t *in = hm2_find_pktuart(name, hm2);
    if (!in)
        rtapi_print_msg(RTAPI_MSG_ERR, "hm2: Can not find PktUART instance %s (error %d).\n",
                        name ? name : "(null)", -ENODEV);
    return in;
}

/* Bitrate register: v2+ baud*2^24/clock (1..0xFFFFFF), older baud*2^20/clock. */
static uint32_t bitrate_register(uint32_t clock, int version, uint32_t baud)
{
    double r = (double)baud * (version >= 2 ? 16777216.0 : 1048576.0) / clock;
    if (version >= 2 && r > PKTUART_BITRATE_MAX)
        r = PKTUART_BITRATE_MAX;
    if (version >= 2 && r < 1)
        r = 1;
    return (uint32_t)r;
}

/* Inter-frame delay field (and the x4 scale bit for long delays on v3+). */
static uint32_t ifdelay_bits(uint32_t ifdelay, int version)
{
    if (ifdelay > 255 && version >= 3)
        return HM2_PKTUART_TXMODE_IFSCALE | HM2_PKTUART_TXMODE_INTERFRAMEDLY_VAL(ifdelay / 4 > 255 ? 255 : ifdelay / 4);
    return HM2_PKTUART_TXMODE_INTERFRAMEDLY_VAL(ifdelay > 255 ? 255 : ifdelay);
}

/* Parity and stop bits share their positions between the TX and RX mode registers. */
static uint32_t framing_bits(uint32_t flags, int version)
{
    uint32_t m = 0;
    if (flags & HM2_PKTUART_CONFIG_PARITYEN)
        m |= HM2_PKTUART_TXMODE_PARITYEN;
    if (flags & HM2_PKTUART_CONFIG_PARITYODD)
        m |= HM2_PKTUART_TXMODE_PARITYODD;
    if ((flags & HM2_PKTUART_CONFIG_STOPBITS2) && version >= 3)
        m |= HM2_PKTUART_TXMODE_STOPBITS2;
    return m;
}

typedef int (*pkt_writer_t)(hm2_board_t *, uint32_t, const void *, int);

/* Configure one side; writes bitrate and mode when changed (or forced), flushes on request. */
static void config_side(hm2_board_t *hm2, hm2_pktuart_instance_t *in, const hm2_pktuart_config_t *c,
                        bool rx, pkt_writer_t writer)
{
    int version = rx ? in->rx_version : in->tx_version;
    uint32_t rate = bitrate_register(in->clock_freq, version, c->baudrate);
    uint32_t mode = ifdelay_bits(c->ifdelay, version) | framing_bits(c->flags, version);
    if (rx) {
        uint32_t filter_hz = c->filterrate ? c->filterrate : 2 * c->baudrate;
        uint32_t div = filter_hz ? in->clock_freq / filter_hz : 0xFFFF;
        rate |= ((div >> 8) & 0xFF) << 24;
        mode |= HM2_PKTUART_RXMODE_FILTER_VAL(div & 0xFF);
        mode |= (c->flags & HM2_PKTUART_CONFIG_RXEN) ? HM2_PKTUART_RXMODE_RXEN : 0;
        mode |= (c->flags & HM2_PKTUART_CONFIG_RXMASKEN) ? HM2_PKTUART_RXMODE_RXMASKEN : 0;
    } else {
        mode |= HM2_PKTUART_TXMODE_DRIVEENDLY_VAL(c->drivedelay > 15 ? 15 : c->drivedelay);
        mode |= (c->flags & HM2_PKTUART_CONFIG_DRIVEEN) ? HM2_PKTUART_TXMODE_DRIVEEN : 0;
        mode |= (c->flags & HM2_PKTUART_CONFIG_DRIVEAUTO) ? HM2_PKTUART_TXMODE_DRIVEAUTO : 0;
    }
    bool force = (c->flags & HM2_PKTUART_CONFIG_FORCECONFIG) || !(rx ? in->rx_configured : in->tx_configured);
    uint32_t *w_rate = rx ? &in->rx_bitrate : &in->tx_bitrate, *w_mode = rx ? &in->rx_mode : &in->tx_mode;
    uint32_t rate_addr = rx ? in->rx_bitrate_addr : in->tx_bitrate_addr;
    uint32_t mode_addr = rx ? in->rx_mode_addr : in->tx_mode_addr;
    if (force || rate != *w_rate)
        writer(hm2, rate_addr, &rate, 4);
    if (c->flags & HM2_PKTUART_CONFIG_FLUSH) {
        uint32_t clear = HM2_PKTUART_CLEAR;
        writer(hm2, mode_addr, &clear, 4);
    }
    if (force || mode != *w_mode || (c->flags & HM2_PKTUART_CONFIG_FLUSH))
        writer(hm2, mode_addr, &mode, 4);
    *w_rate = rate;
    *w_mode = mode;
    if (rx)
        in->rx_configured = true;
    else
        in->tx_configured = true;
}

/* Configure RX and/or TX (NULL leaves a side unchanged); queue != 0 sends with the next write. */
int hm2_pktuart_config(const char *name, const hm2_pktuart_config_t *rxcfg,
                       const hm2_pktuart_config_t *txcfg, int queue)
{
    hm2_board_t *hm2;
    hm2_pktuart_instance_t *in = lookup(name, &hm2);
    if (!in)
        return -ENODEV;
    pkt_writer_t writer = queue ? hm2_queue_write : hm2_write;
    if (rxcfg)
        config_side(hm2, in, rxcfg, true, writer);
    if (txcfg)
        config_side(hm2, in, txcfg, false, writer);
    return *hm2->llio->io_error ? -EIO : 0;
}
EXPORT_SYMBOL(hm2_pktuart_config);

/* Deprecated raw set-up: mode values as given (-1 = leave), clears on request. */
int hm2_pktuart_setup(const char *name, unsigned bitrate, rtapi_s32 tx_mode, rtapi_s32 rx_mode,
                      int txclear, int rxclear)
{
    hm2_board_t *hm2;
    hm2_pktuart_instance_t *in = lookup(name, &hm2);
    uint32_t clear = HM2_PKTUART_CLEAR;
    if (!in)
        return -ENODEV;
    uint32_t tx_rate = bitrate_register(in->clock_freq, in->tx_version, bitrate);
    uint32_t rx_rate = bitrate_register(in->clock_freq, in->rx_version, bitrate);
    hm2_write(hm2, in->tx_bitrate_addr, &tx_rate, 4);
    hm2_write(hm2, in->rx_bitrate_addr, &rx_rate, 4);
    if (txclear == 1)
        hm2_write(hm2, in->tx_mode_addr, &clear, 4);
    if (rxclear == 1)
        hm2_write(hm2, in->rx_mode_addr, &clear, 4);
    if (tx_mode >= 0) {
        uint32_t m = (uint32_t)tx_mode & HM2_PKTUART_TXMODE_MASK;
        hm2_write(hm2, in->tx_mode_addr, &m, 4);
        in->tx_mode = m;
        in->tx_configured = true;
    }
    if (rx_mode >= 0) {
        uint32_t m = (uint32_t)rx_mode & HM2_PKTUART_RXMODE_MASK;
        hm2_write(hm2, in->rx_mode_addr, &m, 4);
        in->rx_mode = m;
        in->rx_configured = true;
    }
    in->tx_bitrate = tx_rate;
    in->rx_bitrate = rx_rate;
    return 0;
}
EXPORT_SYMBOL(hm2_pktuart_setup);

/* Deprecated RX wrapper of hm2_pktuart_config (parity 1 odd, 2 even). */
int hm2_pktuart_setup_rx(const char *name, unsigned bitrate, unsigned filter_hz, unsigned parity,
                         int frame_delay, bool rx_enable, bool rx_mask)
{
    hm2_pktuart_config_t c = {0};
    c.baudrate = bitrate;
    c.filterrate = filter_hz;
    c.ifdelay = frame_delay > 0 ? (rtapi_u32)frame_delay : 0;
    c.flags = (parity ? HM2_PKTUART_CONFIG_PARITYEN : 0) | (parity == 1 ? HM2_PKTUART_CONFIG_PARITYODD : 0) |
              (rx_enable ? HM2_PKTUART_CONFIG_RXEN : 0) | (rx_mask ? HM2_PKTUART_CONFIG_RXMASKEN : 0);
    return hm2_pktuart_config(name, &c, NULL, 0);
}
EXPORT_SYMBOL(hm2_pktuart_setup_rx);

/* Deprecated TX wrapper of hm2_pktuart_config. */
int hm2_pktuart_setup_tx(const char *name, unsigned bitrate, unsigned parity, int frame_delay,
                         bool drive_enable, bool drive_auto, int enable_delay)
{
    hm2_pktuart_config_t c = {0};
    c.baudrate = bitrate;
    c.ifdelay = frame_delay > 0 ? (rtapi_u32)frame_delay : 0;
    c.drivedelay = enable_delay > 0 ? (rtapi_u32)enable_delay : 0;
    c.flags = (parity ? HM2_PKTUART_CONFIG_PARITYEN : 0) | (parity == 1 ? HM2_PKTUART_CONFIG_PARITYODD : 0) |
              (drive_enable ? HM2_PKTUART_CONFIG_DRIVEEN : 0) | (drive_auto ? HM2_PKTUART_CONFIG_DRIVEAUTO : 0);
    return hm2_pktuart_config(name, NULL, &c, 0);
}
EXPORT_SYMBOL(hm2_pktuart_setup_tx);

/* Clear both sides now. */
void hm2_pktuart_reset(const char *name)
{
    hm2_board_t *hm2;
    hm2_pktuart_instance_t *in = lookup(name, &hm2);
    uint32_t clear = HM2_PKTUART_CLEAR;
    if (!in)
        return;
    hm2_write(hm2, in->tx_mode_addr, &clear, 4);
    hm2_write(hm2, in->rx_mode_addr, &clear, 4);
}
EXPORT_SYMBOL(hm2_pktuart_reset);

/* Clear both sides with the next write packet. */
void hm2_pktuart_queue_reset(const char *name)
{
    hm2_board_t *hm2;
    hm2_pktuart_instance_t *in = lookup(name, &hm2);
    static const uint32_t clear = HM2_PKTUART_CLEAR;
    if (!in)
        return;
    hm2_queue_write(hm2, in->tx_mode_addr, &clear, 4);
    hm2_queue_write(hm2, in->rx_mode_addr, &clear, 4);
}
EXPORT_SYMBOL(hm2_pktuart_queue_reset);
