/* cia402_config.h: the cia402 driver's configuration file: [CIA402] defaults and one
   [CIA402_DRIVE_<n>] section per drive, checked line by line. */
#ifndef CIA402_CONFIG_H
#define CIA402_CONFIG_H

#include <stdint.h>
#include "canopen_sdo.h"
#include "co_ini.h"

#define CIA402_MAX_DRIVES 32
#define CIA402_MAX_SDO 64
#define CIA402_IFNAME_LEN 16        /* IFNAMSIZ */
#define CIA402_PATH_LEN 256

/* An extra SDO write of a drive section (SDO = INDEX:SUB TYPE VALUE). */
typedef struct {
    co_sdo_write_t write;
    int line;
} cia402_sdo_item_t;

/* Settings of one drive (the [CIA402] values are its defaults). */
typedef struct {
    int number;                         /* n of [CIA402_DRIVE_n] */
    int section_line;
    int node_id;
    int node_line;
    char interface[CIA402_IFNAME_LEN];
    double position_scale;              /* drive counts per machine unit */
    int heartbeat_ms;                   /* producer time written to 0x1017 */
    int heartbeat_line;
    int heartbeat_timeout_ms;           /* no heartbeat for this long = fault */
    int pdo_timeout_ms;                 /* no position feedback for this long = fault */
    int sdo_timeout_ms;                 /* per set-up request */
    int enable_timeout_ms;              /* enable to Operation enabled */
    int velocity_feedback;              /* map 0x606C and 0x6077 into TPDO2 */
    int velocity_line;
    int sync_period_objects;            /* write 0x1006 and 0x60C2 from the thread period */
    int sync_line;
    cia402_sdo_item_t sdo[CIA402_MAX_SDO];
    int sdo_count;
} cia402_drive_cfg_t;

/* The whole file. */
typedef struct {
    char path[CIA402_PATH_LEN];
    uint16_t sync_cob_id;
    cia402_drive_cfg_t drives[CIA402_MAX_DRIVES];
    int drive_count;
} cia402_cfg_t;

/* Read and check path; returns 0, or -1 after reporting every problem as "path:line: ...". */
int cia402_cfg_load(cia402_cfg_t *cfg, const char *path, co_report_fn report, void *ctx);

#endif
