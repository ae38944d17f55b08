/* motion_client.h: user-space access to the motion segment (lib/libemcmotshm.so): attach, push, status, messages. */
#ifndef MOTION_CLIENT_H
#define MOTION_CLIENT_H

#include <stddef.h>
#include <stdint.h>
#include "motion_cmd.h"
#include "motion_status.h"
#include "motion_shm.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct emcmot_client emcmot_client_t;

/* emcmot_attach flags. */
#define EMCMOT_ATTACH_READER 0      /* status and messages only */
#define EMCMOT_ATTACH_PRODUCER 1    /* also the (single) command producer */

/* Attach to the segment of [EMCMOT]SHMEM_KEY base_key (<= 0: 100) in this process's
 * OPENEMC_INSTANCE.  0, or a negative errno with the reason in why:
 * -ENOENT no segment, or one left by an owner that exited (motion not loaded),
 * -EPROTO other version/size,
 * -EBUSY another live process already holds the producer side. */
int emcmot_attach(int base_key, int flags, emcmot_client_t **client, char *why, size_t why_size);
/* Release the producer side (if held), unmap, free; removes a segment whose owner is gone. */
void emcmot_detach(emcmot_client_t *client);

/* Queue *cmd (its serial is written back).  The serial (> 0), or -EAGAIN ring full
 * (nothing queued), -EPERM not attached as producer, -EPIPE the owner is gone. */
long emcmot_push(emcmot_client_t *client, emcmot_command_t *cmd);
/* A consistent copy of the status; 0, or -EBUSY (writer kept changing it), -EPIPE owner gone. */
int emcmot_read_status(emcmot_client_t *client, emcmot_status_t *out);
/* Oldest operator message into buf (kind = EMCMOT_MSG_*); 1, or 0 when none. */
int emcmot_pop_error(emcmot_client_t *client, char *buf, size_t size, int *kind);
/* Wait until motion has handled serial: 0 with *result (and the reason of a rejection),
 * -ETIMEDOUT, -EPIPE owner gone, -ENODATA handled but its result already dropped. */
int emcmot_wait_serial(emcmot_client_t *client, uint32_t serial, double timeout_s,
                       int *result, char *reason, size_t reason_size);
/* Push (retrying while the ring is full) and wait for the echo, within timeout_s in all.
 * 0 with *result, or the negative errno of emcmot_push/emcmot_wait_serial. */
int emcmot_send(emcmot_client_t *client, emcmot_command_t *cmd, double timeout_s,
                int *result, char *reason, size_t reason_size);
/* Non-zero while the owner (motmod or motion-logger) runs. */
int emcmot_owner_alive(emcmot_client_t *client);
/* Commands waiting in the ring. */
unsigned emcmot_pending(emcmot_client_t *client);
/* The mapped segment (for the owner side and tests). */
emcmot_shm_t *emcmot_client_shm(emcmot_client_t *client);

/* Owner side in user space (motion-logger): create and initialise the segment
 * (replacing an unattached stale one); detach with emcmot_detach. */
int emcmot_create(int base_key, const char *owner_name, emcmot_client_t **client,
                  char *why, size_t why_size);

#ifdef __cplusplus
}
#endif

#endif
