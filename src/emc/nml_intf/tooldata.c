/* tooldata.c: the instance-keyed tool-data segment: task publishes the table, UIs copy consistent snapshots. */
#include "tooldata.h"

#include <errno.h>
#include <pthread.h>
#include <sched.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/ipc.h>
#include <sys/shm.h>
#include <unistd.h>

#include "rtapi_instance.h"

#define TOOLDATA_MAGIC 0x544F4F4Cu /* "TOOL" */
#define TOOLDATA_VERSION 1u

/* The segment: a seqlock-protected table; writers also take the lock. */
typedef struct tooldata_shm {
    uint32_t magic;       /* (atomic) set last by the creator */
    uint32_t version;
    uint32_t max_entries;
    int32_t creator_pid;
    uint32_t seq;         /* (atomic) odd while the table changes */
    uint32_t count;       /* entries in use (index 0 = spindle) */
    uint64_t generation;  /* (atomic) bumped by every change */
    pthread_mutex_t lock; /* robust, process-shared: writers */
    tooldata_entry_t entries[TOOLDATA_MAX_ENTRIES];
} tooldata_shm_t;

struct tooldata {
    tooldata_shm_t *shm;
    int shmid;
    int creator;
};

/* An empty entry. */
tooldata_entry_t tooldata_empty_entry(void)
{
    tooldata_entry_t e;

    memset(&e, 0, sizeof e);
    e.toolno = -1;
    return e;
}

/* Map an id and check the header; 0 or -errno. */
static int td_map(struct tooldata *td, int id, int check)
{
    void *addr = shmat(id, NULL, 0);

    if (addr == (void *)-1)
        return -errno;
    td->shm = addr;
    td->shmid = id;
    if (check && (__atomic_load_n(&td->shm->magic, __ATOMIC_ACQUIRE) != TOOLDATA_MAGIC ||
                  td->shm->version != TOOLDATA_VERSION ||
                  td->shm->max_entries != TOOLDATA_MAX_ENTRIES)) {
        shmdt(addr);
        td->shm = NULL;
        return -EPROTO;
    }
    return 0;
}

/* Header and lock of a new segment; the magic is published last. */
static int td_init(tooldata_shm_t *shm)
{
    pthread_mutexattr_t attr;
    int rc, i;

    memset(shm, 0, sizeof *shm);
    shm->version = TOOLDATA_VERSION;
    shm->max_entries = TOOLDATA_MAX_ENTRIES;
    shm->creator_pid = getpid();
    for (i = 0; i < TOOLDATA_MAX_ENTRIES; i++)
        shm->entries[i] = tooldata_empty_entry();
    shm->count = 1; /* the spindle entry, empty */
    pthread_mutexattr_init(&attr);
    pthread_mutexattr_setpshared(&attr, PTHREAD_PROCESS_SHARED);
    pthread_mutexattr_setrobust(&attr, PTHREAD_MUTEX_ROBUST);
    rc = pthread_mutex_init(&shm->lock, &attr);
    pthread_mutexattr_destroy(&attr);
    if (rc)
        return -rc;
    __atomic_store_n(&shm->magic, TOOLDATA_MAGIC, __ATOMIC_RELEASE);
    return 0;
}

/* Remove a stale segment at key (creator gone) or refuse a live or foreign one. */
static int td_reclaim(int key, char *err, size_t errlen)
{
    struct tooldata probe = {NULL, -1, 0};
    int id = shmget(key, 0, 0600);
    int rc;

    if (id < 0)
        return 0;
    rc = td_map(&probe, id, 1);
    if (rc < 0) {
        snprintf(err, errlen, "tool data: key 0x%08x is used by another program", (unsigned)key);
        return -EEXIST;
    }
    if (kill(probe.shm->creator_pid, 0) == 0 || errno == EPERM) {
        snprintf(err, errlen, "tool data: segment (key 0x%08x) already exists, created by pid %d",
                 (unsigned)key, probe.shm->creator_pid);
        shmdt(probe.shm);
        return -EEXIST;
    }
    shmdt(probe.shm);
    shmctl(id, IPC_RMID, NULL);
    return 0;
}

/* Create a fresh segment. */
static int td_create(struct tooldata *td, int key, char *err, size_t errlen)
{
    int id, rc = td_reclaim(key, err, errlen);

    if (rc < 0)
        return rc;
    id = shmget(key, sizeof(tooldata_shm_t), IPC_CREAT | IPC_EXCL | 0600);
    if (id < 0 || (rc = td_map(td, id, 0)) < 0 || (rc = td_init(td->shm)) < 0) {
        rc = id < 0 ? -errno : rc;
        snprintf(err, errlen, "tool data: cannot create key 0x%08x: %s", (unsigned)key,
                 strerror(-rc));
        if (td->shm)
            shmdt(td->shm);
        if (id >= 0)
            shmctl(id, IPC_RMID, NULL);
        return rc;
    }
    td->creator = 1;
    return 0;
}

/* Attach to an existing segment. */
static int td_attach(struct tooldata *td, int key, char *err, size_t errlen)
{
    int id = shmget(key, 0, 0600);
    int rc;

    if (id < 0) {
        rc = -errno;
        snprintf(err, errlen, "tool data: segment (key 0x%08x) %s", (unsigned)key,
                 rc == -ENOENT ? "does not exist (no linuxcncsvr or task created it)"
                               : strerror(-rc));
        return rc;
    }
    rc = td_map(td, id, 1);
    if (rc < 0)
        snprintf(err, errlen, "tool data: key 0x%08x: %s", (unsigned)key,
                 rc == -EPROTO ? "not an OpenEMC tool-data segment of this version"
                               : strerror(-rc));
    return rc;
}

/* Open (attach or create). */
tooldata_t *tooldata_open(int create, char *err, size_t errlen)
{
    struct tooldata *td = calloc(1, sizeof *td);
    int key = rtapi_instance_key(TOOLDATA_BASE_KEY);
    int rc;

    if (!td) {
        snprintf(err, errlen, "tool data: out of memory");
        errno = ENOMEM;
        return NULL;
    }
    td->shmid = -1;
    if (rtapi_instance() < 0) {
        snprintf(err, errlen, "tool data: OPENEMC_INSTANCE is not an instance number 0..16777215");
        free(td);
        errno = EINVAL;
        return NULL;
    }
    rc = create ? td_create(td, key, err, errlen) : td_attach(td, key, err, errlen);
    if (rc < 0) {
        free(td);
        errno = -rc;
        return NULL;
    }
    return td;
}

/* Close; the creator removes the segment. */
void tooldata_close(tooldata_t *td)
{
    if (!td)
        return;
    if (td->creator && td->shm->creator_pid == getpid())
        shmctl(td->shmid, IPC_RMID, NULL);
    shmdt(td->shm);
    free(td);
}

/* Writer side of the seqlock: lock, make the sequence odd. */
static void write_begin(tooldata_shm_t *shm)
{
    uint32_t seq;

    if (pthread_mutex_lock(&shm->lock) == EOWNERDEAD)
        pthread_mutex_consistent(&shm->lock);
    seq = __atomic_load_n(&shm->seq, __ATOMIC_RELAXED);
    __atomic_store_n(&shm->seq, (seq | 1u), __ATOMIC_RELAXED);
    __atomic_thread_fence(__ATOMIC_RELEASE);
}

/* Make the sequence even again, bump the generation, unlock. */
static void write_end(tooldata_shm_t *shm)
{
    __atomic_add_fetch(&shm->generation, 1, __ATOMIC_RELAXED);
    __atomic_store_n(&shm->seq, __atomic_load_n(&shm->seq, __ATOMIC_RELAXED) + 1,
                     __ATOMIC_RELEASE);
    pthread_mutex_unlock(&shm->lock);
}

/* Replace the whole table. */
int tooldata_publish(tooldata_t *td, const tooldata_entry_t *entries, int count)
{
    if (count < 1 || count > TOOLDATA_MAX_ENTRIES)
        return -EINVAL;
    write_begin(td->shm);
    memcpy(td->shm->entries, entries, (size_t)count * sizeof *entries);
    td->shm->count = (uint32_t)count;
    write_end(td->shm);
    return 0;
}

/* Set one entry; entries between the old end and idx become empty. */
int tooldata_put(tooldata_t *td, int idx, const tooldata_entry_t *entry)
{
    uint32_t i;

    if (idx < 0 || idx >= TOOLDATA_MAX_ENTRIES)
        return -EINVAL;
    write_begin(td->shm);
    for (i = td->shm->count; i < (uint32_t)idx; i++)
        td->shm->entries[i] = tooldata_empty_entry();
    td->shm->entries[idx] = *entry;
    if ((uint32_t)idx >= td->shm->count)
        td->shm->count = (uint32_t)idx + 1;
    write_end(td->shm);
    return 0;
}

/* Copy entries [first, first + n) (bounded by the table) as one snapshot; the count. */
static int read_snapshot(const tooldata_shm_t *shm, int first, tooldata_entry_t *out, int max,
                         uint64_t *generation)
{
    uint32_t seq, count;
    int n;

    for (;;) {
        seq = __atomic_load_n(&shm->seq, __ATOMIC_ACQUIRE);
        if (seq & 1) {
            sched_yield();
            continue;
        }
        count = shm->count;
        if (count > TOOLDATA_MAX_ENTRIES)
            count = TOOLDATA_MAX_ENTRIES;
        n = (int)count - first;
        n = n < 0 ? 0 : (n > max ? max : n);
        if (n > 0)
            memcpy(out, &shm->entries[first], (size_t)n * sizeof *out);
        if (generation)
            *generation = __atomic_load_n(&shm->generation, __ATOMIC_RELAXED);
        __atomic_thread_fence(__ATOMIC_ACQUIRE);
        if (__atomic_load_n(&shm->seq, __ATOMIC_RELAXED) == seq)
            return (int)count;
    }
}

/* Whole table. */
int tooldata_read(tooldata_t *td, tooldata_entry_t *out, int max, uint64_t *generation)
{
    return read_snapshot(td->shm, 0, out, max < 0 ? 0 : max, generation);
}

/* One entry by index. */
int tooldata_get(tooldata_t *td, int idx, tooldata_entry_t *out)
{
    if (idx < 0 || idx >= TOOLDATA_MAX_ENTRIES)
        return -ENOENT;
    return read_snapshot(td->shm, idx, out, 1, NULL) > idx ? 0 : -ENOENT;
}

/* Entry of a tool number (indexes 1..); its index or -ENOENT. */
int tooldata_find(tooldata_t *td, int toolno, tooldata_entry_t *out)
{
    tooldata_entry_t *table = malloc(TOOLDATA_MAX_ENTRIES * sizeof *table);
    int count, i, found = -ENOENT;

    if (!table)
        return -ENOMEM;
    count = tooldata_read(td, table, TOOLDATA_MAX_ENTRIES, NULL);
    for (i = 1; i < count && found < 0; i++) {
        if (table[i].toolno == toolno) {
            if (out)
                *out = table[i];
            found = i;
        }
    }
    free(table);
    return found;
}

/* Current generation. */
uint64_t tooldata_generation(const tooldata_t *td)
{
    return __atomic_load_n(&td->shm->generation, __ATOMIC_ACQUIRE);
}

/* Alive unless the segment was marked for removal (its creator closed it). */
int tooldata_alive(const tooldata_t *td)
{
    struct shmid_ds ds;

    if (shmctl(td->shmid, IPC_STAT, &ds) < 0)
        return 0;
    return (ds.shm_perm.mode & SHM_DEST) ? 0 : 1;
}
