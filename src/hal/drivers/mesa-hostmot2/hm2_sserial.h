/* hm2_sserial.h: hostmot2's Smart Serial state: ports, channels, discovered remotes and records. */
#ifndef HM2_SSERIAL_H
#define HM2_SSERIAL_H

#include <stdbool.h>
#include <stdint.h>
#include "hal.h"
#include "hm2_sserial_proto.h"

#define HM2_SSERIAL_PORTS 4
#define HM2_SSERIAL_MAX_RECORDS 48
#define HM2_SSERIAL_MAX_MODES 8

/* HAL objects of one process-data or global record (all in HAL memory). */
typedef struct {
    hal_bit_t **bit, **bit_not;        /* BITS: one pin (and -not for inputs) per bit */
    hal_bit_t *bit_invert;             /* BITS outputs: -NN-invert params */
    hal_bit_t *boolean, *boolean_not;  /* BOOLEAN */
    hal_bit_t invert;                  /* BOOLEAN output: -invert */
    hal_float_t *value;                /* UNSIGNED/SIGNED/FLOAT */
    hal_float_t scalemax, maxlim, minlim;
    hal_u32_t *stream;                 /* STREAM */
    hal_s32_t *count, *rawcounts;      /* ENCODER */
    hal_float_t *position;
    hal_bit_t *index_enable, *reset;
    hal_float_t scale;
    hal_u32_t counts_per_rev;
    hal_u32_t param_u32;               /* globals */
    hal_s32_t param_s32;
    hal_float_t param_float;
} hm2_sserial_rec_hal_t;

/* One discovered record. */
typedef struct {
    uint8_t data_type, dir, bits;
    float parm_min, parm_max;
    uint16_t parm_addr;
    char name[SSLBP_REC_NAME_MAX];
    char unit[SSLBP_REC_NAME_MAX];
    int bit_offset;                    /* in its direction's process-data stream */
    hm2_sserial_rec_hal_t *hal;
    int64_t enc_count;                 /* ENCODER: extended count */
    uint32_t enc_prev_raw, enc_offset;
    bool enc_seeded;                   /* first reading taken as the starting point */
    uint32_t written_global;           /* globals: value last written to the remote */
} hm2_sserial_rec_t;

typedef struct {
    int index, kind;
    char name[SSLBP_REC_NAME_MAX];
} hm2_sserial_mode_t;

typedef struct {
    hal_bit_t *fault;                  /* this remote failed its last transfer or stopped the port */
    hal_u32_t *comm_state;             /* link << 8 | remote status byte of the last transfer */
} hm2_sserial_remote_hal_t;

/* One channel of a port and the remote on it. */
typedef struct {
    bool present;                      /* a remote answered and is in use */
    int mode;                          /* sserial_port_N digit */
    char name[HAL_NAME_LEN + 1];       /* <board>.<card>.<port>.<chan> */
    char card[5];                      /* "7i76" */
    uint32_t unit_number, protocol;
    hm2_sserial_rec_t *rec;            /* process data then globals */
    int num_pd, num_globals;
    hm2_sserial_mode_t modes[HM2_SSERIAL_MAX_MODES];
    int num_modes;
    int in_bits, out_bits;
    uint32_t cs_addr, iface_addr[SSLBP_MAX_INTERFACE_REGS];
    uint32_t *cs_read, *iface_read[SSLBP_MAX_INTERFACE_REGS];    /* TRAM */
    uint32_t *iface_write[SSLBP_MAX_INTERFACE_REGS];
    hm2_sserial_remote_hal_t *hal;
    bool error_reported;               /* first failed transfer reported */
} hm2_sserial_channel_t;

typedef struct {
    hal_bit_t *run;
    hal_u32_t *port_state, *port_state2, *port_state3, *fault_count;
    hal_s32_t *debug;
    hal_u32_t fault_inc, fault_dec, fault_lim;
} hm2_sserial_port_hal_t;

/* port_state values (LinuxCNC shows 0 with run FALSE, 3 in normal operation, 10 after errors). */
enum {
    HM2_SSERIAL_STOPPED = 0,           /* run FALSE: globals may be written */
    HM2_SSERIAL_STARTING = 1,
    HM2_SSERIAL_RUNNING = 3,
    HM2_SSERIAL_STOPPED_ON_ERRORS = 10,
};

typedef struct {
    int index;
    int num_channels;                  /* channels with pins on this board */
    uint32_t command_addr, data_addr;
    uint32_t *command_read, *data_read, *command_write;   /* TRAM */
    hm2_sserial_channel_t chan[SSLBP_MAX_CHANNELS];
    uint32_t active_mask;              /* channels with a remote in use */
    int state;
    bool doit_sent, prev_run, send_stop, stop_reported, restart_reported;
    uint32_t fault_count, cycles_since_reset, over_limit_times, doit_late;
    uint32_t last_failed;              /* channel mask of the last failed transfer */
    hm2_sserial_port_hal_t *hal;
} hm2_sserial_port_t;

typedef struct {
    int num_instances;
    int version, num_iface_regs;
    uint32_t base_address, register_stride, instance_stride;
    hm2_sserial_port_t port[HM2_SSERIAL_PORTS];
} hm2_sserial_t;

#endif
