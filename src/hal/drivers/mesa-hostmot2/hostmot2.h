/* hostmot2.h: the versioned interface between hostmot2 and its low-level board drivers (llio). */
#ifndef HOSTMOT2_H
#define HOSTMOT2_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include "hal.h"

RTAPI_BEGIN_DECLS

/* Version of hm2_llio_ops_t; hm2_register refuses a driver built for another one. */
#define HM2_LLIO_OPS_VERSION 1
#define HM2_LLIO_MAX_CONNECTORS 8

typedef struct hm2_llio hm2_llio_t;

/* What a board driver does for hostmot2. Every call returns 0 or a negative errno
   (register access: -EAGAIN from receive_queued_reads = this cycle's data is lost,
   skip processing; other errors are hard). Queued calls may be NULL: hostmot2 then
   uses read/write region by region. */
typedef struct {
    int version;                                     /* HM2_LLIO_OPS_VERSION */
    int (*read)(hm2_llio_t *llio, uint32_t addr, void *buf, int size);
    int (*write)(hm2_llio_t *llio, uint32_t addr, const void *buf, int size);
    int (*queue_read)(hm2_llio_t *llio, uint32_t addr, void *buf, int size);
    int (*send_queued_reads)(hm2_llio_t *llio);
    int (*receive_queued_reads)(hm2_llio_t *llio);
    int (*queue_write)(hm2_llio_t *llio, uint32_t addr, const void *buf, int size);
    int (*send_queued_writes)(hm2_llio_t *llio);
    void (*set_force_enqueue)(hm2_llio_t *llio, bool on);
    int (*program_fpga)(hm2_llio_t *llio, const void *bits, size_t size);
    int (*reset)(hm2_llio_t *llio);
} hm2_llio_ops_t;

/* One board as its driver describes it. The driver fills the first block; hostmot2
   fills the second during hm2_register. */
struct hm2_llio {
    char name[HAL_NAME_LEN + 1];          /* board prefix, e.g. hm2_7i92.0 */
    int comp_id;                          /* HAL component owning every object */
    int num_ioport_connectors;            /* 1..8 */
    int pins_per_connector;
    const char *ioport_connector_name[HM2_LLIO_MAX_CONNECTORS];
    const char *const *io_connector_pin_names;  /* optional per-IO names, NULL entry = no line */
    int num_leds;
    const char *fpga_part_number;
    bool threadsafe;                      /* export read_gpio/write_gpio */
    bool split_read;                      /* export read-request */
    const hm2_llio_ops_t *ops;
    void *driver_data;

    hal_bit_t *io_error;                  /* the B.io_error param; set by the driver on a hard error */
    long period_ns;                       /* period of the thread running read-request/read */
    void *board;                          /* hostmot2's state, opaque to the driver */
};

/* Register a board: parse config, read the IDROM, export HAL objects. 0 or -errno. */
int hm2_register(hm2_llio_t *llio, const char *config);
/* Unregister a board: watchdog to 1 ns (outputs safe) and free hostmot2's state. */
void hm2_unregister(hm2_llio_t *llio);

RTAPI_END_DECLS

#endif
