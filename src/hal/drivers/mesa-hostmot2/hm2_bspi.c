/* hm2_bspi.c: buffered SPI module (GTag 14) and its API: channel set-up, TRAM frames, callbacks. */
#include <stdlib.h>
#include "rtapi_errno.h"
#include "hm2.h"
#include "hm2_serial_lookup.h"
#include "hostmot2-serial.h"

#define BSPI_NOECHO (1u << 31)
#define BSPI_NOCLEAR (1u << 30)
#define BSPI_SAMPLELATE (1u << 29)
#define BSPI_DELAY_DEFAULT 0x10u
#define BSPI_DELAY_MAX 0x1Fu

/* Parse the descriptor; instances are named hm2_<board>.<idx>.bspi.<n>. */
int hm2_bspi_parse_md(hm2_board_t *hm2, int md_index)
{
    const hm2_md_t *md = &hm2->md[md_index];
    hm2_bspi_t *s = &hm2->bspi;
    if (!hm2_md_is_consistent_or_complain(hm2, md_index, 0, 3, 0x40, 0x07))
        return -EINVAL;
    int n = hm2_md_instances_to_use(hm2, md_index, hm2->config.num_bspis, "num_bspis");
    if (n <= 0)
        return n;
    s->instance = calloc(n, sizeof(*s->instance));
    if (!s->instance)
        return -ENOMEM;
    s->num_instances = n;
    for (int i = 0; i < n; i++) {
        hm2_bspi_instance_t *in = &s->instance[i];
        uint32_t base = md->base_address + i * md->instance_stride;
        rtapi_snprintf(in->name, sizeof(in->name), "%s.bspi.%d", hm2->llio->name, i);
        in->clock_freq = md->clock_freq;
        in->base_address = base;
        in->register_stride = md->register_stride;
        in->instance_stride = md->instance_stride;
        in->count_addr = base + 2 * md->register_stride;
        for (int c = 0; c < HM2_BSPI_CHANNELS; c++) {
            in->addr[c] = base + 4 * c;
            in->cd_addr[c] = base + md->register_stride + 4 * c;
        }
        HM2_PRINT(hm2, "created Buffered SPI function %s.\n", in->name);
    }
    return n;
}

/* Release the instances. */
void hm2_bspi_cleanup(hm2_board_t *hm2)
{
    free(hm2->bspi.instance);
    hm2->bspi.instance = NULL;
    hm2->bspi.num_instances = 0;
}

/* Run the read callbacks after the TRAM read. */
void hm2_bspi_process_tram_read(hm2_board_t *hm2)
{
    for (int i = 0; i < hm2->bspi.num_instances; i++) {
        hm2_bspi_instance_t *in = &hm2->bspi.instance[i];
        if (in->read_function)
            in->read_function(in->read_subdata);
    }
}

/* Run the write callbacks before the TRAM write. */
void hm2_bspi_prepare_tram_write(hm2_board_t *hm2)
{
    for (int i = 0; i < hm2->bspi.num_instances; i++) {
        hm2_bspi_instance_t *in = &hm2->bspi.instance[i];
        if (in->write_function)
            in->write_function(in->write_subdata);
    }
}

/* Instance by name, logging the miss. */
static hm2_bspi_instance_t *lookup(const char *name, hm2_board_t **hm2)
{
    hm2_bspi_instance_t *in = hm2_find_bspi(name, hm2);
    if (!in)
        rtapi_print_msg(RTAPI_MSG_ERR, "hm2: Can not find BSPI instance %s.\n", name ? name : "(null)");
    return in;
}

/* Channel descriptor word from the set-up arguments (mhz already limited). */
static uint32_t channel_descriptor(const hm2_bspi_instance_t *in, int cs, int bits, double mhz,
                                   int delay, int cpol, int cpha, int noclear, int noecho, int samplelate)
{
    double clock_mhz = in->clock_freq / 1e6;
    uint32_t div = (uint32_t)(clock_mhz / (2.0 * mhz) - 1.0) & 0xFF;
    uint32_t delay_clocks = delay <= 0 ? BSPI_DELAY_DEFAULT : (uint32_t)(delay * clock_mhz / 1000.0);
    if (delay_clocks > BSPI_DELAY_MAX)
        delay_clocks = BSPI_DELAY_MAX;
    return (noecho ? BSPI_NOECHO : 0) | (noclear ? BSPI_NOCLEAR : 0) | (samplelate ? BSPI_SAMPLELATE : 0) |
           delay_clocks << 24 | ((uint32_t)cs & 0xF) << 16 | div << 8 | (cpha ? 1u << 7 : 0) |
           (cpol ? 1u << 6 : 0) | (((uint32_t)bits - 1) & 0x3F);
}

/* Set up one channel and write all 16 descriptors. */
int hm2_bspi_setup_chan(char *name, int chan, int cs, int bits, double mhz, int delay, int cpol,
                        int cpha, int noclear, int noecho, int samplelate)
{
    hm2_board_t *hm2;
    hm2_bspi_instance_t *in = lookup(name, &hm2);
    if (!in)
        return -1;
    if (chan < 0 || chan >= HM2_BSPI_CHANNELS || cs < 0 || cs > 15 || bits < 1 || bits > 64 ||
        delay < 0 || delay > 1000000 || mhz <= 0) {
        HM2_ERR(hm2, "BSPI %s: invalid channel set-up (chan %d 0-15, cs %d 0-15, bits %d 1-64, "
                "delay %d 0-1000000 ns, %f MHz > 0)\n", name, chan, cs, bits, delay, mhz);
        return -1;
    }
    if (mhz > in->clock_freq / 2e6)
        mhz = in->clock_freq / 2e6;
    in->cd[chan] = channel_descriptor(in, cs, bits, mhz, delay, cpol, cpha, noclear, noecho, samplelate);
    in->conf_flag[chan] = true;
    for (int c = 0; c < HM2_BSPI_CHANNELS; c++)
        hm2_write(hm2, in->cd_addr[c], &in->cd[c], 4);
    return 0;
}
EXPORT_SYMBOL(hm2_bspi_setup_chan);

/* Direct write to a set-up channel's FIFO. */
int hm2_bspi_write_chan(char *name, int chan, rtapi_u32 val)
{
    hm2_board_t *hm2;
    hm2_bspi_instance_t *in = lookup(name, &hm2);
    if (!in || chan < 0 || chan >= HM2_BSPI_CHANNELS || !in->conf_flag[chan])
        return -1;
    return hm2_write(hm2, in->addr[chan], &val, 4) < 0 ? -1 : 0;
}
EXPORT_SYMBOL(hm2_bspi_write_chan);

/* Re-allocate the board's TRAM after frames were added. */
int hm2_allocate_bspi_tram(char *name)
{
    hm2_board_t *hm2;
    if (!lookup(name, &hm2))
        return -1;
    return hm2_allocate_tram_regions(hm2) < 0 ? -1 : 0;
}
EXPORT_SYMBOL(hm2_allocate_bspi_tram);

/* Callback run during every read. */
int hm2_bspi_set_read_function(char *name, int (*func)(void *subdata), void *subdata)
{
    hm2_board_t *hm2;
    hm2_bspi_instance_t *in = lookup(name, &hm2);
    if (!in || !func || !subdata)
        return -1;
    in->read_function = func;
    in->read_subdata = subdata;
    return 0;
}
EXPORT_SYMBOL(hm2_bspi_set_read_function);

/* Callback run during every write. */
int hm2_bspi_set_write_function(char *name, int (*func)(void *subdata), void *subdata)
{
    hm2_board_t *hm2;
    hm2_bspi_instance_t *in = lookup(name, &hm2);
    if (!in || !func || !subdata)
        return -1;
    in->write_function = func;
    in->write_subdata = subdata;
    return 0;
}
EXPORT_SYMBOL(hm2_bspi_set_write_function);

/* A TRAM write of the channel FIFO and, when it echoes, a read of the receive FIFO. */
int hm2_tram_add_bspi_frame(char *name, int chan, rtapi_u32 **wbuff, rtapi_u32 **rbuff)
{
    hm2_board_t *hm2;
    hm2_bspi_instance_t *in = lookup(name, &hm2);
    if (!in || chan < 0 || chan >= HM2_BSPI_CHANNELS || !in->conf_flag[chan] || !wbuff)
        return -1;
    bool echo = !(in->cd[chan] & BSPI_NOECHO);
    if (echo != (rbuff != NULL)) {
        HM2_ERR(hm2, "BSPI %s channel %d: a read buffer is needed exactly when the channel echoes\n",
                name, chan);
        return -1;
    }
    if (hm2_register_tram_write_region(hm2, in->addr[chan], 4, wbuff) < 0)
        return -1;
    if (echo && hm2_register_tram_read_region(hm2, in->addr[0], 4, rbuff) < 0)
        return -1;
    return 0;
}
EXPORT_SYMBOL(hm2_tram_add_bspi_frame);

/* Empty the FIFOs (write 0 to the count register). */
int hm2_bspi_clear_fifo(char *name)
{
    hm2_board_t *hm2;
    hm2_bspi_instance_t *in = lookup(name, &hm2);
    uint32_t zero = 0;
    if (!in)
        return -1;
    return hm2_write(hm2, in->count_addr, &zero, 4);
}
EXPORT_SYMBOL(hm2_bspi_clear_fifo);
