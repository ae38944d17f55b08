/* parport_io.h: register access to one parallel port, through ppdev ioctls or raw port I/O. */
#ifndef PARPORT_IO_H
#define PARPORT_IO_H

#include <pthread.h>
#include <stdint.h>
#include "parport_cfg.h"

/* How the registers are reached. */
typedef enum {
    PP_IO_PPDEV = 0, /* ioctls on a claimed /dev/parportN */
    PP_IO_RAW        /* inb/outb on base..base+2 (ioperm) */
} pp_io_kind_t;

/* One open port. */
typedef struct {
    pp_io_kind_t kind;
    int fd;                   /* claimed ppdev device, or -1 */
    unsigned long base;       /* data register address (0 when unknown) */
    unsigned long base_hi;    /* ECP/EPP extended registers (0 when none) */
    char device[PP_DEVICE_LEN];
    pthread_t io_thread;      /* raw: the thread that was last given port access */
    int io_errno;             /* first failed register access (reported once), 0 = none */
    int io_reported;
} pp_io_t;

/* Find, claim and prepare the port described by cfg; returns 0 or a negative errno (reported). */
int pp_io_open(pp_io_t *io, const pp_port_cfg_t *cfg);

/* Release the port. */
void pp_io_close(pp_io_t *io);

/* Called at the start of every funct: gives this thread raw access if needed; 0 = usable. */
int pp_io_begin(pp_io_t *io);

uint8_t pp_io_read_data(pp_io_t *io);
uint8_t pp_io_read_status(pp_io_t *io);
uint8_t pp_io_read_control(pp_io_t *io);
void pp_io_write_data(pp_io_t *io, uint8_t value);
void pp_io_write_control(pp_io_t *io, uint8_t value);

#endif
