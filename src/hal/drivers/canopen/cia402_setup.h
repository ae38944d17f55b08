/* cia402_setup.h: the list of NMT commands and SDO writes that bring one drive into cyclic
   synchronous position mode (built from its configuration; period values filled in at send). */
#ifndef CIA402_SETUP_H
#define CIA402_SETUP_H

#include "canopen_sdo.h"
#include "cia402_config.h"

#define CIA402_SETUP_FIXED 40
#define CIA402_SETUP_MAX (CIA402_SETUP_FIXED + CIA402_MAX_SDO)

/* What a step does. */
typedef enum {
    CIA402_STEP_PRE_OPERATIONAL = 0,  /* NMT enter pre-operational (PDO mapping may change) */
    CIA402_STEP_SDO,                  /* one expedited SDO download, answered by the drive */
    CIA402_STEP_START                 /* NMT start: the last step */
} cia402_step_kind_t;

/* Values that depend on the thread period. */
typedef enum {
    CIA402_VALUE_FIXED = 0,
    CIA402_VALUE_CYCLE_US,            /* 0x1006: period in microseconds */
    CIA402_VALUE_INTERP_DIGITS,       /* 0x60C2:01: period mantissa */
    CIA402_VALUE_INTERP_EXPONENT      /* 0x60C2:02: period exponent (seconds) */
} cia402_value_kind_t;

/* One step with what to say about it when the drive refuses it. */
typedef struct {
    cia402_step_kind_t kind;
    cia402_value_kind_t value_kind;
    co_sdo_write_t write;
    const char *what;                 /* e.g. "the RPDO1 mapping" or "the SDO line" */
    int line;                         /* configuration line that asked for it */
} cia402_step_t;

/* Fill steps[] for drive d; returns the count. */
int cia402_setup_build(const cia402_drive_cfg_t *d, cia402_step_t steps[CIA402_SETUP_MAX]);

/* The value a step writes for a thread period of period_ns. */
uint32_t cia402_setup_value(const cia402_step_t *step, long period_ns);

#endif
