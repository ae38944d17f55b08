/* mb2hal.h: runtime state of mb2hal (shared links, transactions with their HAL pins). */
#ifndef MB2HAL_H
#define MB2HAL_H

#include <modbus.h>

#include "hal.h"
#include "mb2hal_config.h"

/* One connection; transactions with equal link settings share it. */
typedef struct {
    mb_link_cfg_t cfg;
    modbus_t *ctx;      /* NULL while disconnected */
    double retry_at;    /* monotonic seconds before which no reconnect is tried */
    double last_use;    /* monotonic time of the last serial request (SERIAL_DELAY_MS) */
    int down;           /* the last connect failed (report only the first failure) */
} mb_link_t;

/* HAL pins of one transaction (all in HAL memory); which arrays are used depends on code and VERSION. */
typedef struct {
    hal_u32_t *num_errors;
    hal_bit_t **bits;
    hal_bit_t **bits_inv;   /* VERSION 1.1 bit reads: the inverted value */
    hal_float_t **floats;
    hal_s32_t **ints;       /* register reads; VERSION 1.1 register writes (added to the float) */
} mb_pins_t;

/* One transaction at run time. */
typedef struct {
    const mb_tx_cfg_t *cfg;
    mb_link_t *link;
    mb_pins_t *pins;
    double next_at;     /* monotonic time of the next run (MAX_UPDATE_RATE) */
    int failing;        /* the last run failed */
} mb_tx_t;

/* Monotonic clock in seconds. */
double mb_now(void);
/* Sleeps seconds (returns early on a signal). */
void mb_sleep(double seconds);
/* Makes sure link is connected for tx; 0, 1 while a reconnect is not due, or -1 (reported). */
int mb_link_open(mb_link_t *link, const mb_tx_cfg_t *tx);
/* Drops the connection (after an I/O error); the next open reconnects. */
void mb_link_close(mb_link_t *link);
/* Index of the link matching cfg in links[0..*nlinks), adding it when new. */
int mb_link_find(mb_link_t *links, int *nlinks, const mb_link_cfg_t *cfg);
/* Creates the pins of transaction tx_num under module name, logging them at init_debug 3;
   0 or a negative HAL error. */
int mb_pins_create(mb_tx_t *tx, int comp_id, const char *module, int tx_num, int init_debug);
/* Runs one Modbus transaction; 0 on success, 1 when skipped (link waiting to reconnect),
   -1 on failure (num_errors counted). */
int mb_tx_run(mb_tx_t *tx);

#endif
