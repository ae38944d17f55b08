/* motion_client.c: libemcmotshm, the user-space side of the motion segment (task, motion-logger, tests). */
#include <errno.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/ipc.h>
#include <sys/shm.h>
#include <time.h>
#include <unistd.h>
#include "rtapi_instance.h"
#include "motion_client.h"

#define STATUS_READ_TRIES 100       /* quick retries before yielding to the writer */
#define STATUS_READ_WAIT_S 1.0      /* give up (EBUSY) after this long */
#define POLL_INTERVAL_NS 200000L

struct emcmot_client {
    emcmot_shm_t *shm;
    int shmid;
    int key;
    int producer;       /* holds header.producer_pid */
    int owner;          /* created the segment */
};

/* The SysV key of base_key in this instance. */
static int sysv_key(int base_key)
{
    return rtapi_instance_key(base_key > 0 ? base_key : EMCMOT_SHM_DEFAULT_KEY);
}

/* Seconds on the monotonic clock. */
static double now_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec + ts.tv_nsec * 1e-9;
}

/* Sleep one polling interval. */
static void poll_sleep(void)
{
    struct timespec ts = { 0, POLL_INTERVAL_NS };
    nanosleep(&ts, NULL);
}

/* Non-zero when pid names a running process. */
static int pid_alive(int pid)
{
    return pid > 0 && (kill(pid, 0) == 0 || errno != ESRCH);
}

/* Take the producer side: free, ours already, or held by a dead process. */
static int claim_producer(emcmot_client_t *c, char *why, size_t why_size)
{
    int32_t *slot = &c->shm->header.producer_pid;
    int32_t me = (int32_t)getpid();

    for (;;) {
        int32_t holder = __atomic_load_n(slot, __ATOMIC_ACQUIRE);
        if (holder == me)
            break;
        if (holder != 0 && pid_alive(holder)) {
            snprintf(why, why_size, "motion command ring already has a producer (pid %d)",
                     (int)holder);
            return -EBUSY;
        }
        if (__atomic_compare_exchange_n(slot, &holder, me, 0, __ATOMIC_ACQ_REL,
                                        __ATOMIC_ACQUIRE))
            break;
    }
    c->producer = 1;
    return 0;
}

/* Map shmid and check the header; 0 or a negative errno. */
static int map_segment(emcmot_client_t *c, char *why, size_t why_size)
{
    struct shmid_ds ds;
    void *mem;

    if (shmctl(c->shmid, IPC_STAT, &ds) < 0 || (mem = shmat(c->shmid, NULL, 0)) == (void *)-1) {
        int err = errno;
        snprintf(why, why_size, "motion shared memory (key 0x%08x): %s", (unsigned)c->key,
                 strerror(err));
        return -err;
    }
    c->shm = mem;
    if (c->owner)
        return 0;
    if (emcmot_shm_check(c->shm, ds.shm_segsz, why, why_size) < 0)
        return -EPROTO;
    if (__atomic_load_n(&c->shm->header.owner_state, __ATOMIC_ACQUIRE) != EMCMOT_OWNER_RUNNING) {
        snprintf(why, why_size, "motion shared memory (key 0x%08x) is left from a motion module "
                 "that has exited", (unsigned)c->key);
        return -ENOENT;
    }
    return 0;
}

/* Attach to an existing segment. */
int emcmot_attach(int base_key, int flags, emcmot_client_t **client, char *why, size_t why_size)
{
    emcmot_client_t *c = calloc(1, sizeof *c);
    int rc;

    *client = NULL;
    if (!c) {
        snprintf(why, why_size, "out of memory");
        return -ENOMEM;
    }
    if (rtapi_instance() < 0) {
        snprintf(why, why_size, "OPENEMC_INSTANCE is not an instance number 0..16777215");
        free(c);
        return -EINVAL;
    }
    c->key = sysv_key(base_key);
    c->shmid = shmget(c->key, 0, 0);
    if (c->shmid < 0) {
        rc = -errno;
        snprintf(why, why_size, "motion shared memory (key 0x%08x) not found: is motmod loaded? (%s)",
                 (unsigned)c->key, strerror(errno));
        free(c);
        return rc;
    }
    rc = map_segment(c, why, why_size);
    if (rc == 0 && (flags & EMCMOT_ATTACH_PRODUCER))
        rc = claim_producer(c, why, why_size);
    if (rc < 0) {
        emcmot_detach(c);
        return rc;
    }
    *client = c;
    return 0;
}

/* Create (or take over an unattached stale) segment and initialise it as its owner. */
int emcmot_create(int base_key, const char *owner_name, emcmot_client_t **client,
                  char *why, size_t why_size)
{
    emcmot_client_t *c = calloc(1, sizeof *c);
    struct shmid_ds ds;
    int rc;

    *client = NULL;
    if (!c) {
        snprintf(why, why_size, "out of memory");
        return -ENOMEM;
    }
    c->key = sysv_key(base_key);
    c->owner = 1;
    c->shmid = shmget(c->key, sizeof(emcmot_shm_t), IPC_CREAT | 0600);
    if (c->shmid < 0 && errno == EINVAL) {
        int old = shmget(c->key, 0, 0);
        if (old >= 0 && shmctl(old, IPC_STAT, &ds) == 0 && ds.shm_nattch == 0)
            shmctl(old, IPC_RMID, NULL);
        c->shmid = shmget(c->key, sizeof(emcmot_shm_t), IPC_CREAT | 0600);
    }
    if (c->shmid < 0) {
        rc = -errno;
        snprintf(why, why_size, "motion shared memory (key 0x%08x): %s (in use by another motion module?)",
                 (unsigned)c->key, strerror(errno));
        free(c);
        return rc;
    }
    rc = map_segment(c, why, why_size);
    if (rc < 0) {
        free(c);
        return rc;
    }
    emcmot_shm_init(c->shm, owner_name, (int)getpid());
    *client = c;
    return 0;
}

/* Release the producer side, unmap and free; the owner retires and removes the segment. */
void emcmot_detach(emcmot_client_t *c)
{
    struct shmid_ds ds;

    if (!c)
        return;
    if (c->shm && c->producer) {
        int32_t me = (int32_t)getpid();
        __atomic_compare_exchange_n(&c->shm->header.producer_pid, &me, 0, 0,
                                    __ATOMIC_ACQ_REL, __ATOMIC_RELAXED);
    }
    if (c->shm && c->owner)
        emcmot_shm_retire(c->shm);
    int gone = c->shm && (c->owner ||
        __atomic_load_n(&c->shm->header.owner_state, __ATOMIC_ACQUIRE) == EMCMOT_OWNER_GONE);
    if (c->shm)
        shmdt(c->shm);
    if (gone && shmctl(c->shmid, IPC_STAT, &ds) == 0 && (c->owner || ds.shm_nattch == 0))
        shmctl(c->shmid, IPC_RMID, NULL);
    free(c);
}

/* Non-zero while the owner runs. */
int emcmot_owner_alive(emcmot_client_t *c)
{
    return __atomic_load_n(&c->shm->header.owner_state, __ATOMIC_ACQUIRE) == EMCMOT_OWNER_RUNNING;
}

/* Queue one command as the producer. */
long emcmot_push(emcmot_client_t *c, emcmot_command_t *cmd)
{
    if (!c->producer)
        return -EPERM;
    if (!emcmot_owner_alive(c))
        return -EPIPE;
    return emcmot_ring_push(c->shm, cmd);
}

/* A consistent status copy; a writer preempted mid-copy is waited for (sleeping), not spun on. */
int emcmot_read_status(emcmot_client_t *c, emcmot_status_t *out)
{
    double deadline = 0.0;
    struct timespec pause = { 0, 50000L };

    for (;;) {
        if (!emcmot_owner_alive(c))
            return -EPIPE;
        if (emcmot_status_read(c->shm, out, STATUS_READ_TRIES) == 0)
            return 0;
        if (deadline == 0.0)
            deadline = now_s() + STATUS_READ_WAIT_S;
        else if (now_s() > deadline)
            return -EBUSY;
        nanosleep(&pause, NULL);
    }
}

/* Oldest operator message. */
int emcmot_pop_error(emcmot_client_t *c, char *buf, size_t size, int *kind)
{
    return emcmot_error_pop(c->shm, kind, buf, size);
}

/* Commands waiting in the ring. */
unsigned emcmot_pending(emcmot_client_t *c)
{
    return emcmot_ring_count(c->shm);
}

/* The mapped segment. */
emcmot_shm_t *emcmot_client_shm(emcmot_client_t *c)
{
    return c->shm;
}

/* Poll the echo until serial shows up, until the absolute monotonic deadline. */
static int wait_until(emcmot_client_t *c, uint32_t serial, double deadline, int *result,
                      char *reason, size_t reason_size)
{
    static __thread emcmot_status_t status;

    for (;;) {
        int rc = emcmot_read_status(c, &status);
        if (rc == -EPIPE)
            return rc;
        if (rc == 0) {
            rc = emcmot_echo_lookup(&status.echo, serial, result, reason, reason_size);
            if (rc != 0)
                return rc < 0 ? rc : 0;
        }
        if (now_s() >= deadline)
            return -ETIMEDOUT;
        poll_sleep();
    }
}

/* Wait for the echo of serial. */
int emcmot_wait_serial(emcmot_client_t *c, uint32_t serial, double timeout_s, int *result,
                       char *reason, size_t reason_size)
{
    return wait_until(c, serial, now_s() + timeout_s, result, reason, reason_size);
}

/* Push (retrying while full) and wait for the echo. */
int emcmot_send(emcmot_client_t *c, emcmot_command_t *cmd, double timeout_s, int *result,
                char *reason, size_t reason_size)
{
    double deadline = now_s() + timeout_s;
    long serial;

    while ((serial = emcmot_push(c, cmd)) == -EAGAIN) {
        if (now_s() >= deadline)
            return -ETIMEDOUT;
        poll_sleep();
    }
    if (serial < 0)
        return (int)serial;
    return wait_until(c, (uint32_t)serial, deadline, result, reason, reason_size);
}
