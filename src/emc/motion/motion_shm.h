/* motion_shm.h: the motion shared segment: header, command ring, seqlocked status, operator-message queue. */
#ifndef MOTION_SHM_H
#define MOTION_SHM_H

#include <stddef.h>
#include <stdint.h>
#include "motion_cmd.h"
#include "motion_status.h"

#ifdef __cplusplus
extern "C" {
#endif

/* [EMCMOT]SHMEM_KEY default; the instance is applied like HAL's key (rtapi_instance_key). */
#define EMCMOT_SHM_DEFAULT_KEY 100

#define EMCMOT_SHM_MAGIC 0x544F4D4Fu    /* "OMOT" */
/* Bump when the layout below or a command/status struct changes incompatibly. */
#define EMCMOT_SHM_VERSION 1u

#define EMCMOT_RING_CAPACITY 1024       /* commands; a power of two */
#define EMCMOT_ERROR_SLOTS 32           /* operator messages waiting for task */
#define EMCMOT_ERROR_LEN 1024           /* bytes per message, NUL included */

/* Owner life cycle (header.owner_state). */
#define EMCMOT_OWNER_STARTING 0u
#define EMCMOT_OWNER_RUNNING 1u
#define EMCMOT_OWNER_GONE 2u

/* Operator message kinds (what task forwards to emcError). */
#define EMCMOT_MSG_ERROR 0
#define EMCMOT_MSG_TEXT 1
#define EMCMOT_MSG_DISPLAY 2

#define EMCMOT_CACHE_LINE 64

/* Identifies the segment; readers refuse one whose magic, version or sizes differ. */
typedef struct emcmot_shm_header {
    uint32_t magic;             /* written last by the owner, after everything else is ready */
    uint32_t version;
    uint32_t size;              /* sizeof(emcmot_shm_t) */
    uint32_t command_size;      /* sizeof(emcmot_command_t) */
    uint32_t status_size;       /* sizeof(emcmot_status_t) */
    uint32_t ring_capacity;
    uint32_t error_slots;
    uint32_t error_len;
    uint32_t owner_state;       /* EMCMOT_OWNER_* */
    int32_t owner_pid;          /* process that owns the consumer side (rtapi_app, motion-logger) */
    char owner_name[32];        /* "motmod", "motion-logger" */
    int32_t producer_pid;       /* process holding the producer side, 0 none */
} emcmot_shm_header_t;

/* Single-producer/single-consumer command ring.  The producer owns head and
 * next_serial, the consumer owns tail; a full ring refuses (-EAGAIN). */
typedef struct emcmot_ring {
    uint32_t head __attribute__((aligned(EMCMOT_CACHE_LINE)));   /* next slot to fill */
    uint32_t next_serial;       /* serial the next pushed command gets (never 0) */
    uint32_t tail __attribute__((aligned(EMCMOT_CACHE_LINE)));   /* next slot to take */
    emcmot_command_t slot[EMCMOT_RING_CAPACITY] __attribute__((aligned(EMCMOT_CACHE_LINE)));
} emcmot_ring_t;

/* The status with its sequence counter: odd while the writer copies. */
typedef struct emcmot_status_buffer {
    uint32_t seq __attribute__((aligned(EMCMOT_CACHE_LINE)));
    emcmot_status_t status __attribute__((aligned(EMCMOT_CACHE_LINE)));
} emcmot_status_buffer_t;

/* One operator message; seq tells whose turn the slot is (bounded MPSC queue). */
typedef struct emcmot_error_slot {
    uint32_t seq;
    int32_t kind;               /* EMCMOT_MSG_* */
    char text[EMCMOT_ERROR_LEN];
} emcmot_error_slot_t;

/* Operator messages from realtime code to task; several writers, one reader. */
typedef struct emcmot_error_queue {
    uint32_t enqueue_pos __attribute__((aligned(EMCMOT_CACHE_LINE)));
    uint32_t dropped;           /* messages lost because the queue was full */
    uint32_t dequeue_pos __attribute__((aligned(EMCMOT_CACHE_LINE)));
    emcmot_error_slot_t slot[EMCMOT_ERROR_SLOTS];
} emcmot_error_queue_t;

/* The whole segment. */
typedef struct emcmot_shm {
    emcmot_shm_header_t header;
    emcmot_ring_t ring;
    emcmot_status_buffer_t status;
    emcmot_error_queue_t errors;
} emcmot_shm_t;

/* ---- both sides (realtime and user space) ---- */

/* Owner: clear the segment, fill the header and publish it (magic last), state RUNNING. */
void emcmot_shm_init(emcmot_shm_t *shm, const char *owner_name, int owner_pid);
/* Owner: mark the segment GONE before unmapping it. */
void emcmot_shm_retire(emcmot_shm_t *shm);
/* 0 when shm (mapped_size bytes) has our magic, version and sizes; else -EPROTO with why. */
int emcmot_shm_check(const emcmot_shm_t *shm, size_t mapped_size, char *why, size_t why_size);

/* Producer: copy *cmd into the ring with the next serial (also written to cmd->serial).
 * Returns the serial (> 0), or -EAGAIN when the ring is full (nothing queued). */
long emcmot_ring_push(emcmot_shm_t *shm, emcmot_command_t *cmd);
/* Consumer: copy the oldest command into *out without removing it; 1, or 0 when empty. */
int emcmot_ring_peek(emcmot_shm_t *shm, emcmot_command_t *out);
/* Consumer: drop the oldest command (after peek). */
void emcmot_ring_pop(emcmot_shm_t *shm);
/* Commands waiting in the ring. */
unsigned emcmot_ring_count(const emcmot_shm_t *shm);

/* Writer (one): publish *status; readers never block it. */
void emcmot_status_publish(emcmot_shm_t *shm, const emcmot_status_t *status);
/* Reader: a consistent copy into *out; 0, or -EBUSY after max_tries torn reads. */
int emcmot_status_read(const emcmot_shm_t *shm, emcmot_status_t *out, int max_tries);

/* Any writer: queue an operator message (truncated to EMCMOT_ERROR_LEN-1); 0, or -ENOSPC (counted in dropped). */
int emcmot_error_push(emcmot_shm_t *shm, int kind, const char *text);
/* Reader (one): take the oldest message; 1, or 0 when none. */
int emcmot_error_pop(emcmot_shm_t *shm, int *kind, char *buf, size_t size);

/* Result of serial according to an echo: 1 handled (*result, reason copied when rejected),
 * 0 not yet, -ENODATA handled but its result already left the rejection history. */
int emcmot_echo_lookup(const emcmot_echo_t *echo, uint32_t serial, int *result,
                       char *reason, size_t reason_size);

#ifdef __cplusplus
}
#endif

#endif
