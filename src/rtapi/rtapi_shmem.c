/* rtapi_shmem.c: SysV shared memory per instance, reference-counted per process. */
#include <pthread.h>
#include <stdio.h>
#include <string.h>
#include <sys/ipc.h>
#include <sys/shm.h>
#include "rtapi.h"
#include "rtapi_instance.h"
#include "rtapi_internal.h"

typedef struct {
    int key;              /* instance key actually used */
    int shmid;
    unsigned long size;
    void *mem;
    int refs;             /* rtapi_shmem_new calls not yet deleted */
} shmem_slot_t;

static shmem_slot_t slots[RTAPI_MAX_SHMEMS];
static pthread_mutex_t shmem_lock = PTHREAD_MUTEX_INITIALIZER;

/* Slot already holding key, or -1. */
static int find_key(int key)
{
    for (int i = 0; i < RTAPI_MAX_SHMEMS; i++)
        if (slots[i].refs > 0 && slots[i].key == key)
            return i;
    return -1;
}

/* Create or attach the segment for key into a free slot; returns slot or -errno. */
static int attach_new(int key, unsigned long size)
{
    int slot, shmid;
    void *mem;

    for (slot = 0; slot < RTAPI_MAX_SHMEMS && slots[slot].refs > 0; slot++)
        ;
    if (slot == RTAPI_MAX_SHMEMS) {
        rtapi_print_msg(RTAPI_MSG_ERR, "rtapi: shmem_new: all %d slots in use\n",
                        RTAPI_MAX_SHMEMS);
        return -ENOMEM;
    }
    shmid = shmget(key, size, IPC_CREAT | 0600);
    if (shmid < 0) {
        int err = errno;
        rtapi_print_msg(RTAPI_MSG_ERR, "rtapi: shmem_new: shmget(key=0x%08x, size=%lu): %s\n",
                        (unsigned)key, size, strerror(err));
        return -err;
    }
    mem = shmat(shmid, NULL, 0);
    if (mem == (void *)-1) {
        int err = errno;
        rtapi_print_msg(RTAPI_MSG_ERR, "rtapi: shmem_new: shmat(key=0x%08x): %s\n",
                        (unsigned)key, strerror(err));
        return -err;
    }
    if (rtapi_rt_enabled())
        shmctl(shmid, SHM_LOCK, NULL);
    slots[slot] = (shmem_slot_t){ key, shmid, size, mem, 1 };
    return slot;
}

/* Map the segment of a base key (instance applied here); same key twice -> same handle. */
int rtapi_shmem_new(int key, int module_id, unsigned long int size)
{
    int ikey = rtapi_instance_key(key);
    int slot;

    (void)module_id;
    if (size == 0 || rtapi_instance() < 0)
        return -EINVAL;
    pthread_mutex_lock(&shmem_lock);
    slot = find_key(ikey);
    if (slot >= 0) {
        if (size > slots[slot].size)
            slot = -EINVAL;
        else
            slots[slot].refs++;
    } else {
        slot = attach_new(ikey, size);
    }
    pthread_mutex_unlock(&shmem_lock);
    return slot;
}

/* Drop one reference; detach on the last and remove the segment once unattached. */
int rtapi_shmem_delete(int shmem_id, int module_id)
{
    struct shmid_ds ds;
    shmem_slot_t *s;

    (void)module_id;
    if (shmem_id < 0 || shmem_id >= RTAPI_MAX_SHMEMS)
        return -EINVAL;
    pthread_mutex_lock(&shmem_lock);
    s = &slots[shmem_id];
    if (s->refs <= 0) {
        pthread_mutex_unlock(&shmem_lock);
        return -EINVAL;
    }
    if (--s->refs == 0) {
        shmdt(s->mem);
        if (shmctl(s->shmid, IPC_STAT, &ds) == 0 && ds.shm_nattch == 0)
            shmctl(s->shmid, IPC_RMID, NULL);
        memset(s, 0, sizeof *s);
    }
    pthread_mutex_unlock(&shmem_lock);
    return 0;
}

/* Address of a mapped segment. */
int rtapi_shmem_getptr(int shmem_id, void **ptr)
{
    if (shmem_id < 0 || shmem_id >= RTAPI_MAX_SHMEMS || slots[shmem_id].refs <= 0 || !ptr)
        return -EINVAL;
    *ptr = slots[shmem_id].mem;
    return 0;
}
