/* nml_segment.c: creating, attaching and removing a buffer's SysV segment; its lock and futex. */
#include <errno.h>
#include <limits.h>
#include <linux/futex.h>
#include <signal.h>
#include <stdio.h>
#include <string.h>
#include <sys/ipc.h>
#include <sys/shm.h>
#include <sys/syscall.h>
#include <time.h>
#include <unistd.h>

#include "nml_shm.h"
#include "rtapi_instance.h"

/* Segment bytes for a B line: header plus data rounded up to the alignment. */
static size_t segment_bytes(const nml_buffer_cfg_t *b)
{
    size_t data = ((size_t)b->size + NML_ALIGN - 1) & ~(size_t)(NML_ALIGN - 1);
    return sizeof(nml_shm_t) + data;
}

/* True when a master pid still runs. */
static int pid_alive(int pid)
{
    return pid > 0 && (kill(pid, 0) == 0 || errno == EPERM);
}

/* Set up the header and the robust process-shared lock; publish the magic last. */
static int segment_init(nml_shm_t *shm, const nml_buffer_cfg_t *b, size_t bytes)
{
    pthread_mutexattr_t attr;
    int rc;

    __atomic_store_n(&shm->magic, 0, __ATOMIC_RELEASE);
    memset(shm, 0, bytes);
    shm->version = NML_SHM_VERSION;
    shm->header_size = sizeof(nml_shm_t);
    shm->data_size = (uint32_t)(bytes - sizeof(nml_shm_t));
    shm->flags = b->flags;
    shm->master_pid = getpid();
    snprintf(shm->name, sizeof shm->name, "%s", b->name);
    pthread_mutexattr_init(&attr);
    pthread_mutexattr_setpshared(&attr, PTHREAD_PROCESS_SHARED);
    pthread_mutexattr_setrobust(&attr, PTHREAD_MUTEX_ROBUST);
    rc = pthread_mutex_init(&shm->lock, &attr);
    pthread_mutexattr_destroy(&attr);
    if (rc)
        return -rc;
    __atomic_store_n(&shm->alive, 1, __ATOMIC_RELEASE);
    __atomic_store_n(&shm->magic, NML_SHM_MAGIC, __ATOMIC_RELEASE);
    return 0;
}

/* Check a mapped segment against the channel's B line: 0 or -EPROTO with err set. */
static int segment_check(const struct nml_channel *ch, size_t seg_size, char *err,
                         size_t errlen)
{
    const nml_shm_t *shm = ch->shm;

    if (seg_size < sizeof(nml_shm_t) ||
        __atomic_load_n(&shm->magic, __ATOMIC_ACQUIRE) != NML_SHM_MAGIC ||
        shm->version != NML_SHM_VERSION || shm->header_size != sizeof(nml_shm_t) ||
        seg_size < sizeof(nml_shm_t) + shm->data_size) {
        snprintf(err, errlen, "%s: key 0x%08x holds no OpenEMC NML buffer of this version",
                 ch->buffer.name, (unsigned)ch->key);
        return -EPROTO;
    }
    if (shm->data_size < ch->buffer.size || shm->flags != ch->buffer.flags ||
        strncmp(shm->name, ch->buffer.name, sizeof shm->name)) {
        snprintf(err, errlen,
                 "%s: key 0x%08x holds buffer '%.*s' (%u bytes, options 0x%x), "
                 "not the one of this .nml file",
                 ch->buffer.name, (unsigned)ch->key, (int)sizeof shm->name, shm->name,
                 shm->data_size, shm->flags);
        return -EPROTO;
    }
    return 0;
}

/* Map segment id; its size in *size. 0 or -errno. */
static int segment_map(struct nml_channel *ch, int id, size_t *size)
{
    struct shmid_ds ds;
    void *addr;

    if (shmctl(id, IPC_STAT, &ds) < 0)
        return -errno;
    addr = shmat(id, NULL, 0);
    if (addr == (void *)-1)
        return -errno;
    ch->shm = addr;
    ch->shmid = id;
    *size = ds.shm_segsz;
    return 0;
}

/* Unmap without removing. */
static void segment_unmap(struct nml_channel *ch)
{
    if (ch->shm)
        shmdt(ch->shm);
    ch->shm = NULL;
    ch->shmid = -1;
}

/* Attach as a non-master. */
static int segment_attach(struct nml_channel *ch, char *err, size_t errlen)
{
    size_t size;
    int id = shmget(ch->key, 0, 0600);
    int rc;

    if (id < 0) {
        rc = -errno;
        if (rc == -ENOENT)
            snprintf(err, errlen, "%s: buffer does not exist (key 0x%08x): no master "
                     "(linuxcncsvr) has created it", ch->buffer.name, (unsigned)ch->key);
        else
            snprintf(err, errlen, "%s: key 0x%08x: %s", ch->buffer.name, (unsigned)ch->key,
                     strerror(-rc));
        return rc;
    }
    if ((rc = segment_map(ch, id, &size)) < 0) {
        snprintf(err, errlen, "%s: cannot map key 0x%08x: %s", ch->buffer.name,
                 (unsigned)ch->key, strerror(-rc));
        return rc;
    }
    if ((rc = segment_check(ch, size, err, errlen)) < 0) {
        segment_unmap(ch);
        return rc;
    }
    return 0;
}

/* A master found an existing segment: refuse a live owner or a foreign segment, else
 * remove the stale one so a fresh one can be made. */
static int segment_reclaim(struct nml_channel *ch, int id, char *err, size_t errlen)
{
    size_t size;
    int rc = segment_map(ch, id, &size);

    if (rc < 0) {
        snprintf(err, errlen, "%s: key 0x%08x exists and cannot be mapped: %s",
                 ch->buffer.name, (unsigned)ch->key, strerror(-rc));
        return rc;
    }
    if (size < sizeof(nml_shm_t) ||
        __atomic_load_n(&ch->shm->magic, __ATOMIC_ACQUIRE) != NML_SHM_MAGIC) {
        snprintf(err, errlen, "%s: key 0x%08x is used by another program", ch->buffer.name,
                 (unsigned)ch->key);
        rc = -EEXIST;
    } else if (__atomic_load_n(&ch->shm->alive, __ATOMIC_ACQUIRE) &&
               pid_alive(ch->shm->master_pid)) {
        snprintf(err, errlen, "%s: buffer (key 0x%08x) already has a master, pid %d",
                 ch->buffer.name, (unsigned)ch->key, ch->shm->master_pid);
        rc = -EEXIST;
    } else {
        __atomic_store_n(&ch->shm->alive, 0, __ATOMIC_RELEASE);
        nml_notify(ch->shm);
        shmctl(id, IPC_RMID, NULL);
    }
    segment_unmap(ch);
    return rc;
}

/* Create (master): reclaim a stale segment of a dead master first. */
static int segment_create(struct nml_channel *ch, char *err, size_t errlen)
{
    size_t bytes = segment_bytes(&ch->buffer);
    size_t size;
    int id = shmget(ch->key, 0, 0600);
    int rc;

    if (id >= 0 && (rc = segment_reclaim(ch, id, err, errlen)) < 0)
        return rc;
    id = shmget(ch->key, bytes, IPC_CREAT | IPC_EXCL | 0600);
    if (id < 0 || (rc = segment_map(ch, id, &size)) < 0) {
        rc = id < 0 ? -errno : rc;
        snprintf(err, errlen, "%s: cannot create key 0x%08x (%zu bytes): %s", ch->buffer.name,
                 (unsigned)ch->key, bytes, strerror(-rc));
        if (id >= 0)
            shmctl(id, IPC_RMID, NULL);
        return rc;
    }
    if ((rc = segment_init(ch->shm, &ch->buffer, bytes)) < 0) {
        snprintf(err, errlen, "%s: cannot set up its lock: %s", ch->buffer.name,
                 strerror(-rc));
        shmctl(id, IPC_RMID, NULL);
        segment_unmap(ch);
        return rc;
    }
    ch->master = 1;
    return 0;
}

/* Create or attach the segment of a channel. */
int nml_segment_open(struct nml_channel *ch, char *err, size_t errlen)
{
    ch->shmid = -1;
    if (rtapi_instance() < 0) {
        snprintf(err, errlen, "%s: OPENEMC_INSTANCE is not an instance number 0..16777215", ch->buffer.name);
        return -EINVAL;
    }
    ch->key = nml_buffer_key(&ch->buffer);
    if (ch->process.master)
        return segment_create(ch, err, errlen);
    return segment_attach(ch, err, errlen);
}

/* Detach; the master marks the buffer dead, wakes sleepers and removes it. */
void nml_segment_close(struct nml_channel *ch)
{
    if (!ch->shm)
        return;
    if (ch->master && ch->shm->master_pid == getpid()) {
        __atomic_store_n(&ch->shm->alive, 0, __ATOMIC_RELEASE);
        nml_notify(ch->shm);
        shmctl(ch->shmid, IPC_RMID, NULL);
    }
    segment_unmap(ch);
}

/* Lock, recovering from an owner that died while holding it. */
void nml_lock(nml_shm_t *shm)
{
    if (pthread_mutex_lock(&shm->lock) == EOWNERDEAD)
        pthread_mutex_consistent(&shm->lock);
}

/* Unlock. */
void nml_unlock(nml_shm_t *shm)
{
    pthread_mutex_unlock(&shm->lock);
}

/* Bump the change word and wake sleepers, if any (no syscall otherwise). */
void nml_notify(nml_shm_t *shm)
{
    __atomic_add_fetch(&shm->change, 1, __ATOMIC_SEQ_CST);
    if (__atomic_load_n(&shm->waiters, __ATOMIC_SEQ_CST))
        syscall(SYS_futex, &shm->change, FUTEX_WAKE, INT_MAX, NULL, NULL, 0);
}

/* Sleep while the change word equals seen. */
int nml_futex_wait(nml_shm_t *shm, uint32_t seen, int64_t timeout_ns)
{
    struct timespec ts;
    long rc;
    int err;

    if (timeout_ns >= 0) {
        ts.tv_sec = timeout_ns / 1000000000;
        ts.tv_nsec = timeout_ns % 1000000000;
    }
    __atomic_add_fetch(&shm->waiters, 1, __ATOMIC_SEQ_CST);
    rc = syscall(SYS_futex, &shm->change, FUTEX_WAIT, seen, timeout_ns >= 0 ? &ts : NULL,
                 NULL, 0);
    err = errno;
    __atomic_sub_fetch(&shm->waiters, 1, __ATOMIC_SEQ_CST);
    if (rc == 0 || err == EAGAIN)
        return 0;
    return err == ETIMEDOUT ? -ETIMEDOUT : -EINTR;
}
