/* nml_latest.c: latest-value buffers (emcStatus): one message under a seqlock, copied by readers without blocking the writer. */
#include <errno.h>
#include <sched.h>
#include <string.h>
#include <time.h>

#include "nml_shm.h"

/* Spins before a reader yields, and how long it waits for a stalled writer. */
#define SPINS_BEFORE_YIELD 64
#define STALLED_WRITER_NS 200000000LL

/* Replace the message. Writers serialise on the lock; readers only watch `seq`. */
int nml_latest_write(struct nml_channel *ch, const void *msg, uint32_t size, int32_t *serial)
{
    nml_shm_t *shm = ch->shm;
    uint32_t seq;
    uint64_t count;

    if (size > shm->data_size)
        return -EMSGSIZE;
    nml_lock(shm);
    if ((shm->flags & NML_FLAG_CONFIRM_WRITE) && shm->msg_size &&
        !__atomic_load_n(&shm->was_read, __ATOMIC_ACQUIRE)) {
        nml_unlock(shm);
        return -EBUSY;
    }
    seq = __atomic_load_n(&shm->seq, __ATOMIC_RELAXED);
    if (seq & 1)
        seq++; /* a writer died mid-write: its data is overwritten now */
    __atomic_store_n(&shm->seq, seq + 1, __ATOMIC_RELAXED);
    __atomic_thread_fence(__ATOMIC_RELEASE);
    count = __atomic_load_n(&shm->write_count, __ATOMIC_RELAXED) + 1;
    memcpy(shm->data, msg, size);
    if (shm->flags & NML_FLAG_SERIAL)
        ((nml_msg_hdr_t *)shm->data)->serial_number = nml_serial_of(count);
    shm->msg_size = size;
    shm->msg_count = count;
    __atomic_store_n(&shm->was_read, 0, __ATOMIC_RELAXED);
    __atomic_store_n(&shm->seq, seq + 2, __ATOMIC_RELEASE);
    __atomic_store_n(&shm->write_count, count, __ATOMIC_RELEASE);
    nml_notify(shm);
    nml_unlock(shm);
    if (serial)
        *serial = nml_serial_of(count);
    return 0;
}

/* Monotonic nanoseconds. */
static int64_t now_ns(void)
{
    struct timespec ts;

    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (int64_t)ts.tv_sec * 1000000000LL + ts.tv_nsec;
}

/* Wait while a write is in progress; the even sequence, or -EIO for a writer that stopped
 * in the middle of a write. */
static int64_t stable_seq(nml_shm_t *shm)
{
    int64_t since = 0;
    uint32_t seq;
    int spins = 0;

    for (;;) {
        seq = __atomic_load_n(&shm->seq, __ATOMIC_ACQUIRE);
        if (!(seq & 1))
            return seq;
        if (++spins < SPINS_BEFORE_YIELD)
            continue;
        if (!since)
            since = now_ns();
        else if (now_ns() - since > STALLED_WRITER_NS)
            return -EIO;
        sched_yield();
    }
}

/* Copy the message as one consistent snapshot; mark it read when `mark`. */
int nml_latest_read(struct nml_channel *ch, void *buf, size_t cap, int mark)
{
    nml_shm_t *shm = ch->shm;
    uint32_t size;
    uint64_t count;
    int64_t seq;

    for (;;) {
        seq = stable_seq(shm);
        if (seq < 0)
            return (int)seq;
        size = shm->msg_size;
        count = shm->msg_count;
        if (size > shm->data_size)
            size = shm->data_size; /* torn read; the sequence check below retries */
        if (size <= cap)
            memcpy(buf, shm->data, size);
        __atomic_thread_fence(__ATOMIC_ACQUIRE);
        if (__atomic_load_n(&shm->seq, __ATOMIC_RELAXED) == (uint32_t)seq)
            break;
    }
    if (size > cap)
        return -EMSGSIZE;
    ch->last_read_count = count;
    if (mark && size)
        __atomic_store_n(&shm->was_read, 1, __ATOMIC_RELEASE);
    return (int)size;
}
