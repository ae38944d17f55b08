/* hm2_gtag.c: names of HostMot2 functions and of their secondary pins (log and HAL alias forms). */
#include "rtapi.h"
#include "hm2_gtag.h"

typedef struct {
    int gtag;
    const char *name;      /* general function name for log lines */
    const char *hal_name;  /* HAL module name, NULL when none */
} gtag_name_t;

static const gtag_name_t gtag_names[] = {
    {HM2_GTAG_WATCHDOG, "Watchdog", "watchdog"},
    {HM2_GTAG_IOPORT, "IOPort", "gpio"},
    {HM2_GTAG_ENCODER, "Encoder", "encoder"},
    {HM2_GTAG_STEPGEN, "StepGen", "stepgen"},
    {HM2_GTAG_PWMGEN, "PWMGen", "pwmgen"},
    {HM2_GTAG_SPI, "SPI", NULL},
    {HM2_GTAG_SSI, "SSI Encoder", "ssi"},
    {HM2_GTAG_UART_TX, "UART Transmit Channel", "uart"},
    {HM2_GTAG_UART_RX, "UART Receive Channel", "uart"},
    {HM2_GTAG_TRAM, "TranslationRAM", NULL},
    {HM2_GTAG_MUXED_ENCODER, "Muxed Encoder", "encoder"},
    {HM2_GTAG_MUXED_ENCODER_SEL, "Muxed Encoder Select", "encoder"},
    {HM2_GTAG_BSPI, "Buffered SPI Interface", "bspi"},
    {15, "DBSPI", NULL},
    {16, "DPainter", NULL},
    {17, "SPI Bus", NULL},
    {18, "WaveGen", NULL},
    {HM2_GTAG_TPPWM, "ThreePhasePWM", "3pwmgen"},
    {20, "BinOsc", NULL},
    {21, "DAQ FIFO", NULL},
    {22, "BinRead", NULL},
    {23, "BinWrite", NULL},
    {HM2_GTAG_BISS, "BiSS Encoder", "biss"},
    {HM2_GTAG_FABS, "Fanuc Abs Encoder", "fanuc"},
    {HM2_GTAG_DPLL, "Hostmot2 DPLL", "dpll"},
    {HM2_GTAG_PKTUART_TX, "PktUART Transmit Channel", "uart"},
    {HM2_GTAG_PKTUART_RX, "PktUART Receive Channel", "uart"},
    {HM2_GTAG_INMUX, "InMux Input Mux", "inmux"},
    {HM2_GTAG_INM, "InM Input Module", "inm"},
    {HM2_GTAG_DPAINTER, "Data Painter", NULL},
    {HM2_GTAG_XY2MOD, "xy2mod Galvo interface", "xy2mod"},
    {HM2_GTAG_RCPWMGEN, "RCPWMGen", "rcpwmgen"},
    {HM2_GTAG_OUTM, "OutM Output Module", "outm"},
    {64, "TPDrive", NULL},
    {HM2_GTAG_LED, "LED", "led"},
    {HM2_GTAG_RESOLVER, "Resolver", "resolver"},
    {HM2_GTAG_SMARTSERIAL, "Smart Serial Interface", "sserial"},
    {194, "Twiddler", NULL},
    {HM2_GTAG_SSR, "SSR", "ssr"},
    {HM2_GTAG_SMARTSERIALB, "Smart Serial Interface", "sserialb"},
    {HM2_GTAG_ONESHOT, "OneShot", "oneshot"},
    {HM2_GTAG_PERIODM, "PeriodM", "periodm"},
};

/* Secondary pin names of one module, indexed by the pin number (1-based). */
typedef struct {
    int gtag;
    int count;
    const char *const *log;
    const char *const *alias;
} pin_names_t;

static const char *const encoder_log[] = {"A", "B", "Index", "IndexMask", "Probe", "Shared Index"};
static const char *const encoder_alias[] = {"phase-A", "phase-B", "phase-Z", "phase-Z-mask",
                                            "probe-latch", "shared-Z"};
static const char *const muxsel_log[] = {"Mux Select 0", "Mux Select 1"};
static const char *const muxsel_alias[] = {"mux-select0", "mux-select1"};
static const char *const stepgen_log[] = {"Step", "Direction", "Table2Pin", "Table3Pin", "Table4Pin",
                                          "Table5Pin", "Table6Pin", "Table7Pin", "Index", "Probe"};
static const char *const stepgen_alias[] = {"step", "direction", "table2", "table3", "table4",
                                            "table5", "table6", "table7", "index", "probe"};
static const char *const pwmgen_log[] = {"Out0 (PWM or Up)", "Out1 (Dir or Down)", "Not-Enable"};
static const char *const pwmgen_alias[] = {"out0", "out1", "enable"};
static const char *const uart_tx_log[] = {"TX Data", "Drv Enable"};
static const char *const uart_tx_alias[] = {"tx", "tx-drv-en"};
static const char *const uart_rx_log[] = {"RX Data"};
static const char *const uart_rx_alias[] = {"rx"};
static const char *const bspi_log[] = {"/Frame", "Serial Out", "Clock", "Serial In",
                                       "CS0", "CS1", "CS2", "CS3"};
static const char *const bspi_alias[] = {"frame", "serial-out", "clock", "serial-in",
                                         "cs0", "cs1", "cs2", "cs3"};
static const char *const dpll_log[] = {"Sync In Pin", "Ref Out Pin", "Timer 1 Pin", "Timer 2 Pin",
                                       "Timer 3 Pin", "Timer 4 Pin"};
static const char *const dpll_alias[] = {"sync-in", "ref-out", "timer1", "timer2",
                                         "timer3", "timer4"};
static const char *const abs_log[] = {"Clock", "Data", "Data Enable"};
static const char *const abs_alias[] = {"clock", "data", "data-enable"};

#define PIN_NAMES(tag, log, alias) {tag, (int)(sizeof(log) / sizeof(log[0])), log, alias}

static const pin_names_t pin_names[] = {
    PIN_NAMES(HM2_GTAG_ENCODER, encoder_log, encoder_alias),
    PIN_NAMES(HM2_GTAG_MUXED_ENCODER, encoder_log, encoder_alias),
    PIN_NAMES(HM2_GTAG_MUXED_ENCODER_SEL, muxsel_log, muxsel_alias),
    PIN_NAMES(HM2_GTAG_STEPGEN, stepgen_log, stepgen_alias),
    PIN_NAMES(HM2_GTAG_PWMGEN, pwmgen_log, pwmgen_alias),
    PIN_NAMES(HM2_GTAG_UART_TX, uart_tx_log, uart_tx_alias),
    PIN_NAMES(HM2_GTAG_PKTUART_TX, uart_tx_log, uart_tx_alias),
    PIN_NAMES(HM2_GTAG_UART_RX, uart_rx_log, uart_rx_alias),
    PIN_NAMES(HM2_GTAG_PKTUART_RX, uart_rx_log, uart_rx_alias),
    PIN_NAMES(HM2_GTAG_BSPI, bspi_log, bspi_alias),
    PIN_NAMES(HM2_GTAG_DPLL, dpll_log, dpll_alias),
    PIN_NAMES(HM2_GTAG_SSI, abs_log, abs_alias),
    PIN_NAMES(HM2_GTAG_BISS, abs_log, abs_alias),
    PIN_NAMES(HM2_GTAG_FABS, abs_log, abs_alias),
};

/* The name-table entry of a tag, or NULL. */
static const gtag_name_t *find_gtag(int gtag)
{
    for (size_t i = 0; i < sizeof(gtag_names) / sizeof(gtag_names[0]); i++)
        if (gtag_names[i].gtag == gtag)
            return &gtag_names[i];
    return NULL;
}

/* Log name of a function tag; unknown tags are reported once per lookup. */
const char *hm2_gtag_name(int gtag)
{
    const gtag_name_t *g = find_gtag(gtag);
    if (!g) {
        rtapi_print_msg(RTAPI_MSG_DBG, "hm2: Firmware contains unknown function (gtag-%d)\n", gtag);
        return NULL;
    }
    return g->name;
}

/* HAL name of a function tag, or NULL. */
const char *hm2_gtag_hal_name(int gtag)
{
    const gtag_name_t *g = find_gtag(gtag);
    return g ? g->hal_name : NULL;
}

/* Smart-serial pins are coded: outputs tx/txen/ntxen by range, inputs rx. */
static const char *sserial_pin_name(int sec_pin, char *buf, int len)
{
    int n = sec_pin & 0x7f;
    if (!(sec_pin & HM2_PIN_OUTPUT_FLAG))
        rtapi_snprintf(buf, len, "rx%d", n - 1);
    else if (n >= 0x21)
        rtapi_snprintf(buf, len, "ntxen%d", n - 0x21);
    else if (n >= 0x11)
        rtapi_snprintf(buf, len, "txen%d", n - 0x11);
    else
        rtapi_snprintf(buf, len, "tx%d", n - 1);
    return buf;
}

/* InM inputs: the first 8 double as MPG encoder phases. */
static const char *inm_pin_name(int sec_pin, char *buf, int len)
{
    int n = (sec_pin & 0x7f) - 1;
    if (n < 8)
        rtapi_snprintf(buf, len, "in%d,enc%c%d", n, (n & 1) ? 'b' : 'a', n / 2);
    else
        rtapi_snprintf(buf, len, "in%d", n);
    return buf;
}

/* Shared lookup for the log and alias forms. */
static const char *pin_name(int gtag, int sec_pin, char *buf, int len, bool alias)
{
    int n = sec_pin & 0x7f;
    if (gtag == HM2_GTAG_SMARTSERIAL || gtag == HM2_GTAG_SMARTSERIALB)
        return sserial_pin_name(sec_pin, buf, len);
    if (gtag == HM2_GTAG_INM || gtag == HM2_GTAG_INMUX)
        return inm_pin_name(sec_pin, buf, len);
    for (size_t i = 0; i < sizeof(pin_names) / sizeof(pin_names[0]); i++) {
        const pin_names_t *p = &pin_names[i];
        if (p->gtag == gtag && n >= 1 && n <= p->count)
            return alias ? p->alias[n - 1] : p->log[n - 1];
    }
    rtapi_snprintf(buf, len, "unknown-pin-%d", n);
    return buf;
}

/* Log form of a secondary pin name. */
const char *hm2_pin_log_name(int gtag, int sec_pin, char *buf, int len)
{
    return pin_name(gtag, sec_pin, buf, len, false);
}

/* Alias-suffix form of a secondary pin name. */
const char *hm2_pin_alias_name(int gtag, int sec_pin, char *buf, int len)
{
    return pin_name(gtag, sec_pin, buf, len, true);
}
