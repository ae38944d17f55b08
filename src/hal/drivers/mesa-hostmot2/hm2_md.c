/* hm2_md.c: hand each module descriptor to its module: IOPort first, then table order. */
#include "rtapi_errno.h"
#include "hm2.h"

typedef int (*hm2_md_parser_t)(hm2_board_t *hm2, int md_index);

typedef struct {
    int gtag;
    hm2_md_parser_t parse;    /* NULL: known to HostMot2, not driven by this driver */
} md_dispatch_t;

static const md_dispatch_t dispatch[] = {
    {HM2_GTAG_WATCHDOG, hm2_watchdog_parse_md},
    {HM2_GTAG_ENCODER, hm2_encoder_parse_md},
    {HM2_GTAG_MUXED_ENCODER, hm2_encoder_parse_md},
    {HM2_GTAG_STEPGEN, hm2_stepgen_parse_md},
    {HM2_GTAG_PWMGEN, hm2_pwmgen_parse_md},
    {HM2_GTAG_LED, hm2_led_parse_md},
    {HM2_GTAG_DPLL, hm2_dpll_parse_md},
    {HM2_GTAG_UART_TX, hm2_uart_parse_md},
    {HM2_GTAG_UART_RX, hm2_uart_parse_md},
    {HM2_GTAG_PKTUART_TX, hm2_pktuart_parse_md},
    {HM2_GTAG_PKTUART_RX, hm2_pktuart_parse_md},
    {HM2_GTAG_BSPI, hm2_bspi_parse_md},
    {HM2_GTAG_SSI, NULL}, {HM2_GTAG_BISS, NULL}, {HM2_GTAG_FABS, NULL},
    {HM2_GTAG_TPPWM, NULL}, {HM2_GTAG_RESOLVER, NULL}, {HM2_GTAG_SMARTSERIAL, hm2_sserial_parse_md},
    {HM2_GTAG_SMARTSERIALB, hm2_sserial_parse_md}, {HM2_GTAG_INM, NULL}, {HM2_GTAG_INMUX, NULL},
    {HM2_GTAG_XY2MOD, NULL}, {HM2_GTAG_RCPWMGEN, NULL}, {HM2_GTAG_OUTM, NULL},
    {HM2_GTAG_ONESHOT, NULL}, {HM2_GTAG_PERIODM, NULL}, {HM2_GTAG_SSR, NULL},
};

/* True when the descriptor has exactly the expected shape. */
int hm2_md_is_consistent(hm2_board_t *hm2, int md_index, uint8_t version, uint8_t num_registers,
                         uint32_t instance_stride, uint32_t multiple_registers)
{
    const hm2_md_t *md = &hm2->md[md_index];
    return md->version == version && md->num_registers == num_registers &&
           md->instance_stride == instance_stride && md->multiple_registers == multiple_registers;
}

/* As hm2_md_is_consistent, printing what differs when it does not match. */
int hm2_md_is_consistent_or_complain(hm2_board_t *hm2, int md_index, uint8_t version,
                                     uint8_t num_registers, uint32_t instance_stride,
                                     uint32_t multiple_registers)
{
    const hm2_md_t *md = &hm2->md[md_index];
    if (hm2_md_is_consistent(hm2, md_index, version, num_registers, instance_stride,
                             multiple_registers))
        return 1;
    HM2_ERR(hm2, "inconsistent Module Descriptor for %s, not loading driver\n",
            hm2_gtag_name(md->gtag));
    HM2_ERR(hm2, "    Version = %d, expected %d\n", md->version, version);
    HM2_ERR(hm2, "    NumRegisters = %d, expected %d\n", md->num_registers, num_registers);
    HM2_ERR(hm2, "    InstanceStride = 0x%08X, expected 0x%08X\n", md->instance_stride, instance_stride);
    HM2_ERR(hm2, "    MultipleRegisters = 0x%08X, expected 0x%08X\n", md->multiple_registers,
            multiple_registers);
    return 0;
}

/* Instances to enable from a config count (-1 = all); more than exist is an error. */
int hm2_md_instances_to_use(hm2_board_t *hm2, int md_index, int wanted, const char *what)
{
    int available = hm2->md[md_index].instances;
    if (wanted > available) {
        HM2_ERR(hm2, "config.%s=%d, but only %d are available, not loading driver\n",
                what, wanted, available);
        return -EINVAL;
    }
    return wanted < 0 ? available : wanted;
}

/* The dispatch entry of a tag, or NULL for tags this driver does not know. */
static const md_dispatch_t *find_dispatch(int gtag)
{
    for (size_t i = 0; i < sizeof(dispatch) / sizeof(dispatch[0]); i++)
        if (dispatch[i].gtag == gtag)
            return &dispatch[i];
    return NULL;
}

/* Parse one descriptor (not IOPort); logs the outcome. */
static int parse_one(hm2_board_t *hm2, int i)
{
    const hm2_md_t *md = &hm2->md[i];
    const char *name = hm2_gtag_name(md->gtag);
    const md_dispatch_t *d = find_dispatch(md->gtag);
    if (md->gtag == HM2_GTAG_MUXED_ENCODER_SEL)
        return 0;
    if (!d) {
        char unknown[24];
        rtapi_snprintf(unknown, sizeof(unknown), "(unknown-gtag-%d)", md->gtag);
        HM2_WARN(hm2, "MD %d: %dx %s v%d: ignored\n", i, md->instances, name ? name : unknown,
                 md->version);
        return 0;
    }
    if (!d->parse) {
        HM2_ERR(hm2, "MD %d: %dx %s v%d: not driven by this hostmot2 driver, its pins stay GPIO\n",
                i, md->instances, name, md->version);
        return 0;
    }
    int r = d->parse(hm2, i);
    if (r < 0) {
        HM2_ERR(hm2, "failed to parse Module Descriptor %d\n", i);
        return r;
    }
    HM2_INFO(hm2, "MD %d: %dx %s v%d: accepted, using %d\n", i, md->instances, name, md->version, r);
    return 0;
}

/* Refuse firmware that lists a function twice. */
static int check_duplicates(hm2_board_t *hm2)
{
    for (int i = 0; i < hm2->num_mds; i++) {
        for (int j = 0; j < i; j++) {
            if (hm2->md[i].gtag == hm2->md[j].gtag) {
                const char *name = hm2_gtag_name(hm2->md[i].gtag);
                HM2_ERR(hm2, "found duplicate Module Descriptor for %s (inconsistent firmware), "
                        "not loading driver\n", name ? name : "unknown function");
                return -EINVAL;
            }
        }
    }
    return 0;
}

/* IOPort first (every other module needs its pins), then the rest in table order. */
int hm2_parse_module_descriptors(hm2_board_t *hm2)
{
    int r = check_duplicates(hm2);
    if (r < 0)
        return r;
    for (int i = 0; i < hm2->num_mds; i++) {
        if (hm2->md[i].gtag != HM2_GTAG_IOPORT)
            continue;
        r = hm2_ioport_parse_md(hm2, i);
        if (r < 0) {
            HM2_ERR(hm2, "failed to parse Module Descriptor %d\n", i);
            return r;
        }
        HM2_INFO(hm2, "MD %d: %dx IOPort v%d: accepted, using %d\n", i, hm2->md[i].instances,
                 hm2->md[i].version, r);
    }
    for (int i = 0; i < hm2->num_mds; i++) {
        if (hm2->md[i].gtag == HM2_GTAG_IOPORT)
            continue;
        r = parse_one(hm2, i);
        if (r < 0)
            return r;
    }
    return 0;
}
