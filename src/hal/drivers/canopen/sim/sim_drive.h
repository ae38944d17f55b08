/* sim_drive.h: one simulated CiA 402 servo drive: NMT slave, SDO server, PDOs on SYNC, the drive
   state machine, a motor that follows the target position, heartbeat, EMCY and fault injection. */
#ifndef SIM_DRIVE_H
#define SIM_DRIVE_H

#include "../canopen.h"
#include "../cia402_state.h"
#include "sim_od.h"

/* Frame and log sinks of the program around the drive. */
typedef void (*sim_send_fn)(void *ctx, const co_frame_t *f);
typedef void (*sim_log_fn)(void *ctx, const char *text);

/* Malformed frames a test can ask for. */
typedef enum { SIM_BAD_TPDO1 = 0, SIM_BAD_HEARTBEAT, SIM_BAD_EMCY, SIM_BAD_SDO } sim_bad_kind_t;

/* One node. */
typedef struct {
    int node_id;
    sim_od_t od;
    uint8_t nmt;                     /* CO_STATE_* */
    cia402_state_t state;
    uint16_t previous_cw;
    double position;                 /* counts */
    double velocity;                 /* counts per second */
    double max_speed;                /* counts per second */
    uint16_t pending_emcy;           /* error code that keeps the drive in Fault until reset */
    int silent;                      /* cable cut: neither receives nor sends */
    int bad_sdo_next;                /* answer the next SDO request with a short frame */
    uint8_t rpdo_data[SIM_PDO_COUNT][8];
    int rpdo_len[SIM_PDO_COUNT];
    int rpdo_fresh[SIM_PDO_COUNT];
    unsigned sync_count;
    uint8_t guard_toggle;
    long long next_heartbeat_ns;
    sim_send_fn send;
    sim_log_fn log;
    void *ctx;
} sim_drive_t;

/* Set up node node_id (call sim_drive_boot to power it on). */
void sim_drive_init(sim_drive_t *d, int node_id, double max_speed, sim_send_fn send, sim_log_fn log, void *ctx);

/* Power on or reset: dictionary to power-on values, boot-up message, pre-operational. */
void sim_drive_boot(sim_drive_t *d, long long now_ns);

/* Take one frame from the bus. */
void sim_drive_receive(sim_drive_t *d, const co_frame_t *f, long long now_ns);

/* Time passes: heartbeat. */
void sim_drive_tick(sim_drive_t *d, long long now_ns);

/* Test hooks. */
void sim_drive_emcy(sim_drive_t *d, uint16_t code);
void sim_drive_set_nmt(sim_drive_t *d, uint8_t state);
void sim_drive_send_bad(sim_drive_t *d, sim_bad_kind_t kind);

/* The SDO server (sim_sdo.c): answer one request frame. */
void sim_sdo_request(sim_drive_t *d, const co_frame_t *f);

/* Format and log a line through d->log. */
void sim_logf(sim_drive_t *d, const char *fmt, ...) __attribute__((format(printf, 2, 3)));

#endif
