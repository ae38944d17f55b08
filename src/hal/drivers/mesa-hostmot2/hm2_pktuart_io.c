/* hm2_pktuart_io.c: PktUART frame transfer: queued sends, direct and queued reads, status getters. */
#include "rtapi_errno.h"
#include "hm2.h"
#include "hm2_serial_lookup.h"
#include "hostmot2-serial.h"

#define PKTUART_MAX_FRAMES 16
#define PKTUART_RX_ERRORS (HM2_PKTUART_RXMODE_OVERRUN | HM2_PKTUART_RXMODE_FALSESTART | \
                           HM2_PKTUART_RXMODE_RCFIFOERR)
#define PKTUART_RCR_ERRORS (HM2_PKTUART_RCR_PARITYERR | HM2_PKTUART_RCR_OVERRUN | \
                            HM2_PKTUART_RCR_FALSESTART)

/* Instance by name, logging the miss. */
static hm2_pktuart_instance_t *lookup(const char *name, hm2_board_t **hm2)
{
    hm2_pktuart_instance_t *in = hm2_find_pktuart(name, hm2);
    if (!in)
        rtapi_print_msg(RTAPI_MSG_ERR, "hm2: Can not find PktUART instance %s (error %d).\n",
                        name ? name : "(null)", -ENODEV);
    return in;
}

/* Queue the frames' bytes (little-endian words) and one count push per frame. */
int hm2_pktuart_send(const char *name, const unsigned char data[], rtapi_u8 *num_frames,
                     const rtapi_u16 frame_sizes[])
{
    hm2_board_t *hm2;
    hm2_pktuart_instance_t *in = lookup(name, &hm2);
    if (!in)
        return -ENODEV;
    if (!in->tx_configured) {
        HM2_ERR(hm2, "%s has not been configured.\n", name);
        return -EINVAL;
    }
    int frames = *num_frames > PKTUART_MAX_FRAMES ? PKTUART_MAX_FRAMES : *num_frames;
    int at = 0;
    for (int f = 0; f < frames; f++) {
        for (int k = 0; k < frame_sizes[f]; k += 4) {
            uint32_t w = 0;
            for (int b = 0; b < 4 && k + b < frame_sizes[f]; b++)
                w |= (uint32_t)data[at + k + b] << (8 * b);
            if (hm2_queue_write(hm2, in->tx_fifo_addr, &w, 4) < 0)
                return -EIO;
        }
        uint32_t size = frame_sizes[f];
        if (hm2_queue_write(hm2, in->tx_count_addr, &size, 4) < 0)
            return -EIO;
        at += frame_sizes[f];
    }
    *num_frames = (rtapi_u8)frames;
    return at;
}
EXPORT_SYMBOL(hm2_pktuart_send);

/* Read one frame's data words into data; returns its size or -EIO. */
static int read_frame(hm2_board_t *hm2, hm2_pktuart_instance_t *in, unsigned char *data, int max_len)
{
    uint32_t count;
    if (hm2_read(hm2, in->rx_count_addr, &count, 4) < 0 || (count & PKTUART_RCR_ERRORS))
        return -EIO;
    int size = (int)HM2_PKTUART_RCR_NBYTES_VAL(count);
    if (size > max_len)
        return -EIO;
    for (int k = 0; k < size; k += 4) {
        uint32_t w;
        if (hm2_read(hm2, in->rx_fifo_addr, &w, 4) < 0)
            return -EIO;
        for (int b = 0; b < 4 && k + b < size; b++)
            data[k + b] = (unsigned char)(w >> (8 * b));
    }
    return size;
}

/* Direct read of up to *num_frames frames of at most *max_frame_length bytes each. */
int hm2_pktuart_read(const char *name, unsigned char data[], rtapi_u8 *num_frames,
                     rtapi_u16 *max_frame_length, rtapi_u16 frame_sizes[])
{
    hm2_board_t *hm2;
    hm2_pktuart_instance_t *in = lookup(name, &hm2);
    uint32_t mode;
    if (!in)
        return -ENODEV;
    if (!num_frames || !max_frame_length || !*max_frame_length)
        return -EINVAL;
    if (hm2_read(hm2, in->rx_mode_addr, &mode, 4) < 0 || (mode & PKTUART_RX_ERRORS))
        return -EIO;
    int available = (int)HM2_PKTUART_RXMODE_NFRAMES_VAL(mode);
    int capacity = *num_frames, total = 0, f = 0;
    for (; f < available && f < capacity; f++) {
        int size = read_frame(hm2, in, data + total, *max_frame_length);
        if (size < 0)
            return size;
        frame_sizes[f] = (rtapi_u16)size;
        total += size;
    }
    *num_frames = (rtapi_u8)f;
    return total;
}
EXPORT_SYMBOL(hm2_pktuart_read);

/* Queue one count-FIFO read per frame the last cycle's RX status shows; frames - 1. */
int hm2_pktuart_queue_get_frame_sizes(const char *name, rtapi_u32 fsizes[])
{
    hm2_board_t *hm2;
    hm2_pktuart_instance_t *in = lookup(name, &hm2);
    if (!in)
        return -ENODEV;
    int frames = in->rx_status_reg ? (int)HM2_PKTUART_RXMODE_NFRAMES_VAL(*in->rx_status_reg) : 0;
    for (int f = 0; f < frames; f++)
        if (hm2_queue_read(hm2, in->rx_count_addr, &fsizes[f], 4) < 0)
            return -EIO;
    return frames - 1;
}
EXPORT_SYMBOL(hm2_pktuart_queue_get_frame_sizes);

/* Queue (bytes+3)/4 data-FIFO reads; words - 1. */
int hm2_pktuart_queue_read_data(const char *name, rtapi_u32 *data, int bytes)
{
    hm2_board_t *hm2;
    hm2_pktuart_instance_t *in = lookup(name, &hm2);
    if (!in)
        return -ENODEV;
    int words = (bytes + 3) / 4;
    for (int k = 0; k < words; k++)
        if (hm2_queue_read(hm2, in->rx_fifo_addr, &data[k], 4) < 0)
            return -EIO;
    return words - 1;
}
EXPORT_SYMBOL(hm2_pktuart_queue_read_data);

/* Module clock in Hz. */
int hm2_pktuart_get_clock(const char *name)
{
    hm2_board_t *hm2;
    hm2_pktuart_instance_t *in = lookup(name, &hm2);
    return in ? (int)in->clock_freq : -ENODEV;
}
EXPORT_SYMBOL(hm2_pktuart_get_clock);

/* tx_version + 16 * rx_version. */
int hm2_pktuart_get_version(const char *name)
{
    hm2_board_t *hm2;
    hm2_pktuart_instance_t *in = lookup(name, &hm2);
    return in ? in->tx_version + 16 * in->rx_version : -ENODEV;
}
EXPORT_SYMBOL(hm2_pktuart_get_version);

/* Last cycle's RX mode/status register (0 for an unknown name). */
rtapi_u32 hm2_pktuart_get_rx_status(const char *name)
{
    hm2_board_t *hm2;
    hm2_pktuart_instance_t *in = hm2_find_pktuart(name, &hm2);
    return in && in->rx_status_reg ? *in->rx_status_reg : 0;
}
EXPORT_SYMBOL(hm2_pktuart_get_rx_status);

/* Last cycle's TX mode/status register (0 for an unknown name). */
rtapi_u32 hm2_pktuart_get_tx_status(const char *name)
{
    hm2_board_t *hm2;
    hm2_pktuart_instance_t *in = hm2_find_pktuart(name, &hm2);
    return in && in->tx_status_reg ? *in->tx_status_reg : 0;
}
EXPORT_SYMBOL(hm2_pktuart_get_tx_status);
