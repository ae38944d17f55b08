/* cia402_node.h: the driver's view of one CiA 402 drive: set-up, NMT and heartbeat supervision,
   PDO exchange, the drive state machine and latched faults. Pure logic: frames in, frames out. */
#ifndef CIA402_NODE_H
#define CIA402_NODE_H

#include <stdint.h>
#include "canopen.h"
#include "cia402_config.h"
#include "cia402_setup.h"
#include "cia402_state.h"

#define CIA402_LABEL_LEN 64
#define CIA402_MSG_LEN 320
#define CIA402_FRAMES_PER_CYCLE 2   /* at most one set-up frame or one RPDO1 per cycle, plus margin */

/* Why a drive is faulted (the fault-code pin). */
typedef enum {
    CIA402_FAULT_NONE = 0,
    CIA402_FAULT_HEARTBEAT = 1,        /* no heartbeat for HEARTBEAT_TIMEOUT_MS */
    CIA402_FAULT_EMCY = 2,             /* an emergency message (error-code pin) */
    CIA402_FAULT_DRIVE = 3,            /* statusword: Fault, Fault reaction or Quick stop */
    CIA402_FAULT_SETUP = 4,            /* a set-up write was refused or answered wrongly */
    CIA402_FAULT_NO_ANSWER = 5,        /* no SDO answer: node absent */
    CIA402_FAULT_REBOOTED = 6,         /* boot-up message while in use */
    CIA402_FAULT_NOT_OPERATIONAL = 7,  /* heartbeat reports a state other than operational */
    CIA402_FAULT_FEEDBACK = 8,         /* no TPDO1 for PDO_TIMEOUT_MS */
    CIA402_FAULT_COMMAND = 9,          /* position command not a finite number in range */
    CIA402_FAULT_ENABLE_TIMEOUT = 10   /* Operation enabled not reached in ENABLE_TIMEOUT_MS */
} cia402_fault_t;

/* Where the link to the drive stands. */
typedef enum {
    CIA402_LINK_CONFIGURE = 0,   /* running the set-up steps */
    CIA402_LINK_STARTING,        /* NMT start sent, waiting for operational */
    CIA402_LINK_RUNNING,         /* PDOs every cycle */
    CIA402_LINK_DOWN             /* after a link fault: waits for a reset (or a boot-up if absent) */
} cia402_link_t;

/* Message sink: is_error 0 = information. */
typedef void (*cia402_report_fn)(void *ctx, int is_error, const char *text);

/* The HAL inputs of one cycle. */
typedef struct {
    int enable;
    int fault_reset;
    double position_cmd;         /* machine units */
} cia402_command_t;

/* Everything the driver knows about one drive. */
typedef struct {
    const cia402_drive_cfg_t *cfg;
    const char *config_path;
    char label[CIA402_LABEL_LEN];
    cia402_report_fn report;
    void *report_ctx;
    cia402_step_t steps[CIA402_SETUP_MAX];
    int step_count;
    /* link */
    cia402_link_t link;
    int step;
    int sdo_pending;
    int sdo_answered;            /* the node answered at least one SDO since the last (re)start */
    int absent;                  /* DOWN because the node never answered */
    int was_running;
    long long sdo_sent_ns, link_since_ns, last_heartbeat_ns, last_tpdo1_ns, enable_since_ns;
    uint8_t nmt_state;
    /* feedback */
    uint16_t statusword;
    int have_status;
    int32_t position_raw;
    int64_t position_counts;
    int32_t velocity_raw;
    int16_t torque_raw;
    int have_tpdo2;
    /* faults */
    cia402_fault_t fault;
    uint16_t error_code;
    uint32_t bad_frames;
    unsigned bad_reported;       /* one bit per malformed-frame kind, reported once until reset */
    int send_fault_reset;
    int reset_grace;             /* TPDO1s to wait after a fault reset before judging the state */
    int enable_prev, reset_prev;
    /* last outputs */
    uint16_t controlword;
    int32_t target;
    char msg[CIA402_MSG_LEN];
} cia402_node_t;

/* Prepare a node for drive cfg (its set-up starts with the first transmit). */
void cia402_node_init(cia402_node_t *n, const cia402_drive_cfg_t *cfg, const char *config_path,
                      cia402_report_fn report, void *ctx);

/* Take one frame addressed from this node (EMCY, TPDO1/2, SDO answer, heartbeat). */
void cia402_node_receive(cia402_node_t *n, const co_frame_t *f, long long now_ns);

/* Supervise timeouts and the drive state after the frames of a cycle were received. */
void cia402_node_check(cia402_node_t *n, long long now_ns);

/* Apply this cycle's command; writes up to CIA402_FRAMES_PER_CYCLE frames to out, returns the count. */
int cia402_node_transmit(cia402_node_t *n, const cia402_command_t *cmd, long long now_ns, long period_ns,
                         co_frame_t *out);

/* The frames that leave the drive safe when the driver unloads: RPDO1 with Shutdown (when PDOs
   run; a SYNC must follow) into *rpdo, NMT enter pre-operational into *nmt. Returns 1 when *rpdo
   was written. */
int cia402_node_goodbye(cia402_node_t *n, co_frame_t *rpdo, co_frame_t *nmt);

/* TRUE while the drive follows the position command. */
int cia402_node_enabled(const cia402_node_t *n);

/* The drive state from the last statusword. */
cia402_state_t cia402_node_state(const cia402_node_t *n);

#endif
