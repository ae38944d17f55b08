/* hostmot2-serial.h: hostmot2's serial API (UART, PktUART, buffered SPI) for components built with halcompile. */
#ifndef HOSTMOT2_SERIAL_H
#define HOSTMOT2_SERIAL_H

#include <stdbool.h>
#include <stdint.h>
#include "rtapi.h"

typedef uint8_t rtapi_u8;
typedef uint16_t rtapi_u16;
typedef uint32_t rtapi_u32;
typedef int32_t rtapi_s32;

RTAPI_BEGIN_DECLS

/* ---- PktUART transmit mode register ---- */
#define HM2_PKTUART_TXMODE_HASDATA_BIT 21        /* frame buffer has data (RO) */
#define HM2_PKTUART_TXMODE_IFSCALE_BIT 20        /* inter-frame delay x4 (WO, v3+) */
#define HM2_PKTUART_TXMODE_STOPBITS2_BIT 19      /* two stop bits (WO, v3+) */
#define HM2_PKTUART_TXMODE_PARITYODD_BIT 18      /* odd parity (WO) */
#define HM2_PKTUART_TXMODE_PARITYEN_BIT 17       /* parity enable (WO) */
#define HM2_PKTUART_TXMODE_NFRAMES_BIT 16        /* frames to send (RO, 5 bits) */
#define HM2_PKTUART_TXMODE_INTERFRAMEDLY_BIT 8   /* inter-frame delay in bit times (RW, 8 bits) */
#define HM2_PKTUART_TXMODE_TXBUSY_BIT 7          /* transmit active (RO) */
#define HM2_PKTUART_TXMODE_DRIVEEN_BIT 6         /* drive enable (RW) */
#define HM2_PKTUART_TXMODE_DRIVEAUTO_BIT 5       /* drive enable automatic (RW) */
#define HM2_PKTUART_TXMODE_SCFIFOERR_BIT 4       /* send count FIFO error (RO) */
#define HM2_PKTUART_TXMODE_DRIVEENDLY_BIT 0      /* drive enable delay, ClockLow periods (RW, 4 bits) */

#define HM2_PKTUART_TXMODE_HASDATA (1u << HM2_PKTUART_TXMODE_HASDATA_BIT)
#define HM2_PKTUART_TXMODE_IFSCALE (1u << HM2_PKTUART_TXMODE_IFSCALE_BIT)
#define HM2_PKTUART_TXMODE_STOPBITS2 (1u << HM2_PKTUART_TXMODE_STOPBITS2_BIT)
#define HM2_PKTUART_TXMODE_PARITYODD (1u << HM2_PKTUART_TXMODE_PARITYODD_BIT)
#define HM2_PKTUART_TXMODE_PARITYEN (1u << HM2_PKTUART_TXMODE_PARITYEN_BIT)
#define HM2_PKTUART_TXMODE_NFRAMES_MASK (0x1fu << HM2_PKTUART_TXMODE_NFRAMES_BIT)
#define HM2_PKTUART_TXMODE_INTERFRAMEDLY_MASK (0xffu << HM2_PKTUART_TXMODE_INTERFRAMEDLY_BIT)
#define HM2_PKTUART_TXMODE_TXBUSY (1u << HM2_PKTUART_TXMODE_TXBUSY_BIT)
#define HM2_PKTUART_TXMODE_DRIVEEN (1u << HM2_PKTUART_TXMODE_DRIVEEN_BIT)
#define HM2_PKTUART_TXMODE_DRIVEAUTO (1u << HM2_PKTUART_TXMODE_DRIVEAUTO_BIT)
#define HM2_PKTUART_TXMODE_SCFIFOERR (1u << HM2_PKTUART_TXMODE_SCFIFOERR_BIT)
#define HM2_PKTUART_TXMODE_DRIVEENDLY_MASK (0xfu << HM2_PKTUART_TXMODE_DRIVEENDLY_BIT)
#define HM2_PKTUART_TXMODE_MASK 0x003fffffu
#define HM2_PKTUART_TXMODE_NFRAMES_VAL(x) (((x) & HM2_PKTUART_TXMODE_NFRAMES_MASK) >> HM2_PKTUART_TXMODE_NFRAMES_BIT)
#define HM2_PKTUART_TXMODE_INTERFRAMEDLY_VAL(x) (((rtapi_u32)(x) << HM2_PKTUART_TXMODE_INTERFRAMEDLY_BIT) & HM2_PKTUART_TXMODE_INTERFRAMEDLY_MASK)
#define HM2_PKTUART_TXMODE_DRIVEENDLY_VAL(x) (((rtapi_u32)(x) << HM2_PKTUART_TXMODE_DRIVEENDLY_BIT) & HM2_PKTUART_TXMODE_DRIVEENDLY_MASK)

/* ---- PktUART receive mode register ---- */
#define HM2_PKTUART_RXMODE_BADPOP_BIT 30         /* bad pop error (RO) */
#define HM2_PKTUART_RXMODE_FILTER_BIT 22         /* RX digital filter, ClockLow periods (RW, 8 bits) */
#define HM2_PKTUART_RXMODE_HASDATA_BIT 21        /* frame buffer has data (RO) */
#define HM2_PKTUART_RXMODE_IFSCALE_BIT 20        /* inter-frame delay x4 (WO, v3+) */
#define HM2_PKTUART_RXMODE_STOPBITS2_BIT 19      /* two stop bits (WO, v3+) */
#define HM2_PKTUART_RXMODE_PARITYODD_BIT 18      /* odd parity (WO) */
#define HM2_PKTUART_RXMODE_PARITYEN_BIT 17       /* parity enable (WO) */
#define HM2_PKTUART_RXMODE_NFRAMES_BIT 16        /* frames received (RO, 5 bits) */
#define HM2_PKTUART_RXMODE_INTERFRAMEDLY_BIT 8   /* inter-frame delay in bit times (RW, 8 bits) */
#define HM2_PKTUART_RXMODE_RXBUSY_BIT 7          /* receive active (RO) */
#define HM2_PKTUART_RXMODE_RXMASK_BIT 6          /* RX mask (RO) */
#define HM2_PKTUART_RXMODE_PARITYERR_BIT 5       /* parity error (RW) */
#define HM2_PKTUART_RXMODE_RCFIFOERR_BIT 4       /* receive count FIFO error (RW) */
#define HM2_PKTUART_RXMODE_RXEN_BIT 3            /* receive enable (RW) */
#define HM2_PKTUART_RXMODE_RXMASKEN_BIT 2        /* RX mask enable (RW) */
#define HM2_PKTUART_RXMODE_OVERRUN_BIT 1         /* overrun error, sticky */
#define HM2_PKTUART_RXMODE_FALSESTART_BIT 0      /* false start error, sticky */

#define HM2_PKTUART_RXMODE_BADPOP (1u << HM2_PKTUART_RXMODE_BADPOP_BIT)
#define HM2_PKTUART_RXMODE_FILTER_MASK (0xffu << HM2_PKTUART_RXMODE_FILTER_BIT)
#define HM2_PKTUART_RXMODE_HASDATA (1u << HM2_PKTUART_RXMODE_HASDATA_BIT)
#define HM2_PKTUART_RXMODE_IFSCALE (1u << HM2_PKTUART_RXMODE_IFSCALE_BIT)
#define HM2_PKTUART_RXMODE_STOPBITS2 (1u << HM2_PKTUART_RXMODE_STOPBITS2_BIT)
#define HM2_PKTUART_RXMODE_PARITYODD (1u << HM2_PKTUART_RXMODE_PARITYODD_BIT)
#define HM2_PKTUART_RXMODE_PARITYEN (1u << HM2_PKTUART_RXMODE_PARITYEN_BIT)
#define HM2_PKTUART_RXMODE_NFRAMES_MASK (0x1fu << HM2_PKTUART_RXMODE_NFRAMES_BIT)
#define HM2_PKTUART_RXMODE_INTERFRAMEDLY_MASK (0xffu << HM2_PKTUART_RXMODE_INTERFRAMEDLY_BIT)
#define HM2_PKTUART_RXMODE_RXBUSY (1u << HM2_PKTUART_RXMODE_RXBUSY_BIT)
#define HM2_PKTUART_RXMODE_RXMASK (1u << HM2_PKTUART_RXMODE_RXMASK_BIT)
#define HM2_PKTUART_RXMODE_PARITYERR (1u << HM2_PKTUART_RXMODE_PARITYERR_BIT)
#define HM2_PKTUART_RXMODE_RCFIFOERR (1u << HM2_PKTUART_RXMODE_RCFIFOERR_BIT)
#define HM2_PKTUART_RXMODE_RXEN (1u << HM2_PKTUART_RXMODE_RXEN_BIT)
#define HM2_PKTUART_RXMODE_RXMASKEN (1u << HM2_PKTUART_RXMODE_RXMASKEN_BIT)
#define HM2_PKTUART_RXMODE_OVERRUN (1u << HM2_PKTUART_RXMODE_OVERRUN_BIT)
#define HM2_PKTUART_RXMODE_FALSESTART (1u << HM2_PKTUART_RXMODE_FALSESTART_BIT)
#define HM2_PKTUART_RXMODE_MASK 0x7fffffffu
#define HM2_PKTUART_RXMODE_FILTER_VAL(x) (((rtapi_u32)(x) << HM2_PKTUART_RXMODE_FILTER_BIT) & HM2_PKTUART_RXMODE_FILTER_MASK)
#define HM2_PKTUART_RXMODE_NFRAMES_VAL(x) (((x) & HM2_PKTUART_RXMODE_NFRAMES_MASK) >> HM2_PKTUART_RXMODE_NFRAMES_BIT)
#define HM2_PKTUART_RXMODE_INTERFRAMEDLY_VAL(x) (((rtapi_u32)(x) << HM2_PKTUART_RXMODE_INTERFRAMEDLY_BIT) & HM2_PKTUART_RXMODE_INTERFRAMEDLY_MASK)

/* ---- PktUART receive count register (one per received frame) ---- */
#define HM2_PKTUART_RCR_MAXICHARBITS_BIT 24      /* max inter-character bit times (v3+, 8 bits) */
#define HM2_PKTUART_RCR_PARITYERR_BIT 16
#define HM2_PKTUART_RCR_OVERRUN_BIT 15
#define HM2_PKTUART_RCR_FALSESTART_BIT 14
#define HM2_PKTUART_RCR_NBYTES_BIT 0             /* frame size in bytes (10 bits) */
#define HM2_PKTUART_RCR_MAXICHARBITS_MASK (0xffu << HM2_PKTUART_RCR_MAXICHARBITS_BIT)
#define HM2_PKTUART_RCR_PARITYERR (1u << HM2_PKTUART_RCR_PARITYERR_BIT)
#define HM2_PKTUART_RCR_OVERRUN (1u << HM2_PKTUART_RCR_OVERRUN_BIT)
#define HM2_PKTUART_RCR_FALSESTART (1u << HM2_PKTUART_RCR_FALSESTART_BIT)
#define HM2_PKTUART_RCR_NBYTES_MASK (0x3ffu << HM2_PKTUART_RCR_NBYTES_BIT)
#define HM2_PKTUART_RCR_MASK 0xff01c3ffu
#define HM2_PKTUART_RCR_MAXICHARBITS_VAL(x) (((x) & HM2_PKTUART_RCR_MAXICHARBITS_MASK) >> HM2_PKTUART_RCR_MAXICHARBITS_BIT)
#define HM2_PKTUART_RCR_NBYTES_VAL(x) (((x) & HM2_PKTUART_RCR_NBYTES_MASK) >> HM2_PKTUART_RCR_NBYTES_BIT)

/* Written to a mode register: abort, empty the data and count FIFOs. */
#define HM2_PKTUART_CLEAR 0x80010000u

/* ---- PktUART configuration ---- */
typedef struct {
    rtapi_u32 baudrate;      /* RX and TX */
    rtapi_u32 filterrate;    /* RX: filter rate, 0 = twice the baud rate */
    rtapi_u32 drivedelay;    /* TX: drive enable delay (0..15 effective) */
    rtapi_u32 ifdelay;       /* inter-frame delay in bit times (0..255, v3+ up to 1020) */
    rtapi_u32 flags;         /* HM2_PKTUART_CONFIG_* */
    rtapi_u32 unused[3];
} hm2_pktuart_config_t;

#define HM2_PKTUART_CONFIG_DRIVEEN 0x0001u
#define HM2_PKTUART_CONFIG_DRIVEAUTO 0x0002u
#define HM2_PKTUART_CONFIG_RXEN 0x0010u
#define HM2_PKTUART_CONFIG_RXMASKEN 0x0020u
#define HM2_PKTUART_CONFIG_PARITYEN 0x0100u
#define HM2_PKTUART_CONFIG_PARITYODD 0x0200u
#define HM2_PKTUART_CONFIG_STOPBITS2 0x0400u
#define HM2_PKTUART_CONFIG_FLUSH 0x4000u
#define HM2_PKTUART_CONFIG_FORCECONFIG 0x8000u

/* PktUART (names: hm2_<board>.<idx>.pktuart.<n>). */
int hm2_pktuart_config(const char *name, const hm2_pktuart_config_t *rxcfg,
                       const hm2_pktuart_config_t *txcfg, int queue);
int hm2_pktuart_setup(const char *name, unsigned bitrate, rtapi_s32 tx_mode, rtapi_s32 rx_mode,
                      int txclear, int rxclear);
int hm2_pktuart_setup_rx(const char *name, unsigned bitrate, unsigned filter_hz, unsigned parity,
                         int frame_delay, bool rx_enable, bool rx_mask);
int hm2_pktuart_setup_tx(const char *name, unsigned bitrate, unsigned parity, int frame_delay,
                         bool drive_enable, bool drive_auto, int enable_delay);
void hm2_pktuart_reset(const char *name);
void hm2_pktuart_queue_reset(const char *name);
int hm2_pktuart_send(const char *name, const unsigned char data[], rtapi_u8 *num_frames,
                     const rtapi_u16 frame_sizes[]);
int hm2_pktuart_read(const char *name, unsigned char data[], rtapi_u8 *num_frames,
                     rtapi_u16 *max_frame_length, rtapi_u16 frame_sizes[]);
int hm2_pktuart_queue_get_frame_sizes(const char *name, rtapi_u32 fsizes[]);
int hm2_pktuart_queue_read_data(const char *name, rtapi_u32 *data, int bytes);
int hm2_pktuart_get_clock(const char *name);
int hm2_pktuart_get_version(const char *name);
rtapi_u32 hm2_pktuart_get_rx_status(const char *name);
rtapi_u32 hm2_pktuart_get_tx_status(const char *name);

/* UART (names: hm2_<board>.<idx>.uart.<n>). */
int hm2_uart_setup(char *name, int bitrate, rtapi_s32 tx_mode, rtapi_s32 rx_mode);
int hm2_uart_send(char *name, unsigned char data[], int count);
int hm2_uart_read(char *name, unsigned char data[]);

/* Buffered SPI (names: hm2_<board>.<idx>.bspi.<n>). */
int hm2_bspi_setup_chan(char *name, int chan, int cs, int bits, double mhz, int delay, int cpol,
                        int cpha, int noclear, int noecho, int samplelate);
int hm2_bspi_write_chan(char *name, int chan, rtapi_u32 val);
int hm2_allocate_bspi_tram(char *name);
int hm2_bspi_set_read_function(char *name, int (*func)(void *subdata), void *subdata);
int hm2_bspi_set_write_function(char *name, int (*func)(void *subdata), void *subdata);
int hm2_tram_add_bspi_frame(char *name, int chan, rtapi_u32 **wbuff, rtapi_u32 **rbuff);
int hm2_bspi_clear_fifo(char *name);

RTAPI_END_DECLS

#endif
