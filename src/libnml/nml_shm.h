/* nml_shm.h: private layout of one buffer's shared segment and the helpers libnml's files share. */
#ifndef NML_SHM_H
#define NML_SHM_H

#include <pthread.h>
#include <stdint.h>

#include "nml.h"

#define NML_SHM_MAGIC 0x4E4D4C53u /* "NMLS" */
#define NML_SHM_VERSION 1u
/* Queue records and the data area are aligned to this. */
#define NML_ALIGN 16u
/* Record size marking "continue at offset 0" in a queue. */
#define NML_RECORD_WRAP 0xFFFFFFFFu

/* Header of a queued record; the message follows. */
typedef struct nml_record {
    uint32_t size;        /* message bytes, or NML_RECORD_WRAP */
    uint32_t reserved;
    uint64_t write_count; /* write counter value of this message */
} nml_record_t;

/* One buffer segment: this header, then data_size bytes of data. Fields marked (atomic)
 * are only accessed with __atomic builtins; the rest change under `lock`. */
typedef struct nml_shm {
    uint32_t magic;       /* (atomic) NML_SHM_MAGIC once the master has set the segment up */
    uint32_t version;
    uint32_t header_size; /* sizeof(nml_shm_t) */
    uint32_t data_size;   /* bytes of data[] */
    uint32_t flags;       /* NML_FLAG_* of the B line */
    int32_t master_pid;
    uint32_t alive;       /* (atomic) 1 until the master removes the buffer */
    uint32_t reserved0;
    char name[NML_NAME_MAX];
    pthread_mutex_t lock; /* robust, process-shared: writers, and readers of queues */
    uint64_t write_count; /* (atomic) successful writes; the serial of the last one */
    uint32_t change;      /* (atomic) futex word: bumped by every write and queued read */
    uint32_t waiters;     /* (atomic) processes sleeping on `change` */
    /* latest-value buffers */
    uint32_t seq;         /* (atomic) seqlock: odd while a write is in progress */
    uint32_t msg_size;    /* bytes of the current message, 0 = never written */
    uint64_t msg_count;   /* write_count of the current message */
    uint32_t was_read;    /* (atomic) the current message has been read (confirm_write) */
    /* queues */
    uint32_t head;        /* offset of the oldest record */
    uint32_t tail;        /* offset of the next record */
    uint32_t count;       /* records queued */
    uint8_t pad[64];
    uint8_t data[] __attribute__((aligned(64)));
} nml_shm_t;

/* An open channel. */
struct nml_channel {
    nml_shm_t *shm;
    int shmid;
    int key;
    int master;           /* this channel created the segment and removes it */
    nml_buffer_cfg_t buffer;
    nml_process_cfg_t process;
    uint64_t last_read_count;
};

/* Segment of a channel: create (master) or attach. 0 or -errno with err filled. */
int nml_segment_open(struct nml_channel *ch, char *err, size_t errlen);
/* Detach; a master marks the buffer dead, wakes sleepers and removes it. */
void nml_segment_close(struct nml_channel *ch);

/* Lock the buffer (recovers the lock of a process that died holding it). */
void nml_lock(nml_shm_t *shm);
void nml_unlock(nml_shm_t *shm);
/* Bump the change counter and wake sleepers. */
void nml_notify(nml_shm_t *shm);
/* Sleep while change == seen: 0, -ETIMEDOUT, -EINTR. */
int nml_futex_wait(nml_shm_t *shm, uint32_t seen, int64_t timeout_ns);

/* Queue operations (lock held inside). */
int nml_queue_write(struct nml_channel *ch, const void *msg, uint32_t size, int32_t *serial);
int nml_queue_read(struct nml_channel *ch, void *buf, size_t cap, int remove);
/* Latest-value operations. */
int nml_latest_write(struct nml_channel *ch, const void *msg, uint32_t size, int32_t *serial);
int nml_latest_read(struct nml_channel *ch, void *buf, size_t cap, int mark);

/* The next write counter value, as stamped into a `serial` message. */
static inline int32_t nml_serial_of(uint64_t write_count)
{
    return (int32_t)(uint32_t)write_count;
}

#endif
