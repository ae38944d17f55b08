/* hm2.h: hostmot2's per-board state: IDROM, descriptors, pins, TRAM and the module states. */
#ifndef HM2_H
#define HM2_H

#include <stdbool.h>
#include <stdint.h>
#include "rtapi.h"
#include "hal.h"
#include "hostmot2.h"
#include "hm2_config.h"
#include "hm2_gtag.h"
#include "hm2_modules.h"
#include "hm2_sserial.h"

#define HM2_VERSION "0.15"

#define HM2_ADDR_IOCOOKIE 0x0100
#define HM2_ADDR_CONFIGNAME 0x0104
#define HM2_ADDR_IDROM_OFFSET 0x010C
#define HM2_IOCOOKIE 0x55AACAFEu
#define HM2_CONFIGNAME "HOSTMOT2"
#define HM2_CONFIGNAME_LEN 8
#define HM2_MAX_MODULE_DESCRIPTORS 48
#define HM2_MAX_PINS 1000
#define HM2_MIN_CLOCK_HZ 1000000u
#define HM2_MD_SIZE 12

/* Messages carry the board prefix: "hm2/<llio name>: ". */
#define HM2_PRINT(hm2, fmt, ...) rtapi_print("hm2/%s: " fmt, (hm2)->llio->name, ##__VA_ARGS__)
#define HM2_ERR(hm2, fmt, ...) \
    rtapi_print_msg(RTAPI_MSG_ERR, "hm2/%s: " fmt, (hm2)->llio->name, ##__VA_ARGS__)
#define HM2_WARN(hm2, fmt, ...) \
    rtapi_print_msg(RTAPI_MSG_WARN, "hm2/%s: " fmt, (hm2)->llio->name, ##__VA_ARGS__)
#define HM2_INFO(hm2, fmt, ...) \
    rtapi_print_msg(RTAPI_MSG_INFO, "hm2/%s: " fmt, (hm2)->llio->name, ##__VA_ARGS__)
#define HM2_DBG(hm2, fmt, ...) \
    rtapi_print_msg(RTAPI_MSG_DBG, "hm2/%s: " fmt, (hm2)->llio->name, ##__VA_ARGS__)

/* The IDROM header (16 words at the IDROM offset). */
typedef struct {
    uint32_t idrom_type, offset_to_modules, offset_to_pin_desc;
    char board_name[8];
    uint32_t fpga_size, fpga_pins, io_ports, io_width, port_width;
    uint32_t clock_low, clock_high;
    uint32_t instance_stride_0, instance_stride_1, register_stride_0, register_stride_1;
} hm2_idrom_t;

/* One module descriptor, with the strides and clock resolved. */
typedef struct {
    uint8_t gtag, version, clock_tag, instances;
    uint16_t base_address;
    uint8_t num_registers;
    uint32_t register_stride, instance_stride, multiple_registers;
    uint32_t clock_freq;
} hm2_md_t;

enum { HM2_PIN_DIR_IN = 0, HM2_PIN_DIR_OUT = 1 };

/* One IO pin: its descriptor and who drives it. */
typedef struct {
    uint8_t sec_pin, sec_tag, sec_unit, primary_tag;
    int gtag;                 /* owner: HM2_GTAG_IOPORT for a full GPIO */
    int direction;            /* as written to the DDR */
    int direction_at_start;   /* applied at the first write */
    hm2_gpio_hal_t *hal;
} hm2_pin_t;

/* A TRAM region: a block read or written every cycle. */
typedef struct {
    uint16_t addr;
    uint16_t size;            /* bytes */
    uint32_t **buffer;        /* set to the region's words once allocated */
} hm2_tram_region_t;

#define HM2_TRAM_MAX_REGIONS 256

typedef struct {
    hm2_tram_region_t read[HM2_TRAM_MAX_REGIONS], write[HM2_TRAM_MAX_REGIONS];
    int num_read, num_write;
    uint32_t *read_buf, *write_buf;
} hm2_tram_t;

/* Everything hostmot2 knows about one board. */
typedef struct hm2_board {
    hm2_llio_t *llio;
    hm2_config_t config;
    uint32_t idrom_offset;
    hm2_idrom_t idrom;
    hm2_md_t md[HM2_MAX_MODULE_DESCRIPTORS];
    int num_mds;
    hm2_pin_t *pin;
    int num_pins;
    hm2_tram_t *tram;

    hm2_ioport_t ioport;
    hm2_watchdog_t watchdog;
    hm2_encoder_t encoder;
    hm2_stepgen_t stepgen;
    hm2_pwmgen_t pwmgen;
    hm2_led_t led;
    hm2_dpll_t dpll;
    hm2_uart_t uart;
    hm2_pktuart_t pktuart;
    hm2_bspi_t bspi;
    hm2_raw_t raw;
    hm2_sserial_t sserial;

    bool read_requested;      /* read-request ran this cycle */
    bool first_write_done;
    bool needs_reset;         /* watchdog bit: wait for has_bit FALSE */
    bool needs_soft_reset;    /* lost packet: force-write at the next write */
    bool io_error_seen;       /* io_error was TRUE at the last write */
    unsigned read_iter, write_iter;
    struct hm2_board *next;
} hm2_board_t;

/* ---- hostmot2 module parameters (hm2_main.c) ---- */
extern int debug_idrom, debug_module_descriptors, debug_pin_descriptors;
extern int debug_modules, use_serial_numbers, sserial_baudrate;

/* ---- board list (hm2_main.c) ---- */
hm2_board_t *hm2_first_board(void);

/* ---- register access (hm2_access.c) ---- */
int hm2_read(hm2_board_t *hm2, uint32_t addr, void *buf, int size);
int hm2_write(hm2_board_t *hm2, uint32_t addr, const void *buf, int size);
int hm2_queue_write(hm2_board_t *hm2, uint32_t addr, const void *buf, int size);
int hm2_queue_read(hm2_board_t *hm2, uint32_t addr, void *buf, int size);

/* ---- TRAM (hm2_tram.c) ---- */
int hm2_register_tram_read_region(hm2_board_t *hm2, uint32_t addr, int size, uint32_t **buffer);
int hm2_register_tram_write_region(hm2_board_t *hm2, uint32_t addr, int size, uint32_t **buffer);
int hm2_allocate_tram_regions(hm2_board_t *hm2);
int hm2_tram_queue_reads(hm2_board_t *hm2);
int hm2_tram_receive_reads(hm2_board_t *hm2);
int hm2_tram_queue_writes(hm2_board_t *hm2);
int hm2_tram_send_writes(hm2_board_t *hm2);
void hm2_tram_free(hm2_board_t *hm2);

/* ---- IDROM and descriptors (hm2_idrom.c) ---- */
int hm2_read_idrom(hm2_board_t *hm2);
int hm2_read_pin_descriptors(hm2_board_t *hm2);
int hm2_read_module_descriptors(hm2_board_t *hm2);
void hm2_print_idrom(hm2_board_t *hm2);

/* ---- descriptor dispatch (hm2_md.c) ---- */
int hm2_parse_module_descriptors(hm2_board_t *hm2);
int hm2_md_is_consistent(hm2_board_t *hm2, int md_index, uint8_t version, uint8_t num_registers,
                         uint32_t instance_stride, uint32_t multiple_registers);
int hm2_md_is_consistent_or_complain(hm2_board_t *hm2, int md_index, uint8_t version,
                                     uint8_t num_registers, uint32_t instance_stride,
                                     uint32_t multiple_registers);
int hm2_md_instances_to_use(hm2_board_t *hm2, int md_index, int wanted, const char *what);

/* ---- pins (hm2_pins.c) ---- */
int hm2_configure_pins(hm2_board_t *hm2);
void hm2_print_pin_usage(hm2_board_t *hm2);
void hm2_set_pin_source(hm2_board_t *hm2, int pin_number, int source_is_module);
void hm2_set_pin_direction_immediate(hm2_board_t *hm2, int pin_number, int direction);
void hm2_set_pin_direction_at_start(hm2_board_t *hm2, int pin_number, int direction);
int hm2_connector_pin_number(hm2_board_t *hm2, int io);

/* ---- the cycle (hm2_cycle.c) ---- */
int hm2_export_functs(hm2_board_t *hm2);
void hm2_force_write(hm2_board_t *hm2, bool clear_bite);
void hm2_print_modules(hm2_board_t *hm2);
void hm2_cleanup_modules(hm2_board_t *hm2);

/* ---- Smart Serial (hm2_sserial*.c) ---- */
int hm2_sserial_parse_md(hm2_board_t *hm2, int md_index);
int hm2_sserial_export_port(hm2_board_t *hm2, hm2_sserial_port_t *p);
void hm2_sserial_allocate_pins(hm2_board_t *hm2);
void hm2_sserial_process_tram_read(hm2_board_t *hm2);
void hm2_sserial_prepare_tram_write(hm2_board_t *hm2);
void hm2_sserial_write(hm2_board_t *hm2);
void hm2_sserial_print_module(hm2_board_t *hm2);
void hm2_sserial_cleanup(hm2_board_t *hm2);
void hm2_sserial_pack_outputs(hm2_sserial_channel_t *ch);
void hm2_sserial_unpack_inputs(hm2_sserial_channel_t *ch);

#endif
