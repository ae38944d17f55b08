/* hm2_gtag.h: HostMot2 general function tags, secondary pin codes and name lookups. */
#ifndef HM2_GTAG_H
#define HM2_GTAG_H

#include <stdbool.h>

enum {
    HM2_GTAG_NONE = 0,
    HM2_GTAG_WATCHDOG = 2,
    HM2_GTAG_IOPORT = 3,
    HM2_GTAG_ENCODER = 4,
    HM2_GTAG_STEPGEN = 5,
    HM2_GTAG_PWMGEN = 6,
    HM2_GTAG_SPI = 7,
    HM2_GTAG_SSI = 8,
    HM2_GTAG_UART_TX = 9,
    HM2_GTAG_UART_RX = 10,
    HM2_GTAG_TRAM = 11,
    HM2_GTAG_MUXED_ENCODER = 12,
    HM2_GTAG_MUXED_ENCODER_SEL = 13,
    HM2_GTAG_BSPI = 14,
    HM2_GTAG_TPPWM = 19,
    HM2_GTAG_BISS = 24,
    HM2_GTAG_FABS = 25,
    HM2_GTAG_DPLL = 26,
    HM2_GTAG_PKTUART_TX = 27,
    HM2_GTAG_PKTUART_RX = 28,
    HM2_GTAG_INMUX = 30,
    HM2_GTAG_INM = 35,
    HM2_GTAG_DPAINTER = 42,
    HM2_GTAG_XY2MOD = 43,
    HM2_GTAG_RCPWMGEN = 44,
    HM2_GTAG_OUTM = 45,
    HM2_GTAG_LED = 128,
    HM2_GTAG_RESOLVER = 192,
    HM2_GTAG_SMARTSERIAL = 193,
    HM2_GTAG_SSR = 195,
    HM2_GTAG_SMARTSERIALB = 198,
    HM2_GTAG_ONESHOT = 199,
    HM2_GTAG_PERIODM = 200,
};

/* Secondary pin byte: bit 7 = output of the module; secondary unit bit 7 = all instances. */
#define HM2_PIN_OUTPUT_FLAG 0x80
#define HM2_UNIT_GLOBAL_FLAG 0x80

/* General function name used in log lines ("StepGen"); NULL when the tag is unknown. */
const char *hm2_gtag_name(int gtag);
/* HAL name of a module ("stepgen"); NULL when it has none. */
const char *hm2_gtag_hal_name(int gtag);
/* Log name of a secondary pin ("Step"), or "unknown-pin-N" written into buf. */
const char *hm2_pin_log_name(int gtag, int sec_pin, char *buf, int len);
/* Alias suffix of a module output pin ("step"), or "unknown-pin-N" written into buf. */
const char *hm2_pin_alias_name(int gtag, int sec_pin, char *buf, int len);

#endif
