/* rtapi_ids.c: rtapi_init/rtapi_exit and the per-instance component-id counter (hal.md §4). */
#include <pthread.h>
#include <stdlib.h>
#include <string.h>
#include "rtapi.h"
#include "rtapi_instance.h"

#define COUNTER_BYTES 4096

static pthread_mutex_t ids_lock = PTHREAD_MUTEX_INITIALIZER;
static int counter_handle = -1;
static int *ids;          /* ids held by this process, 0 = free; grows on demand */
static int ids_size;
static int ids_used;

/* Attach the counter segment if not yet attached; 0 or -errno. */
static int counter_attach(void)
{
    if (counter_handle >= 0)
        return 0;
    counter_handle = rtapi_shmem_new(RTAPI_IDCOUNTER_KEY, 0, COUNTER_BYTES);
    return counter_handle < 0 ? counter_handle : 0;
}

/* Index of a free slot in ids[], growing the table up to RTAPI_MAX_MODULES; -ENOMEM when full. */
static int free_slot(void)
{
    int slot, size;
    int *grown;

    for (slot = 0; slot < ids_size && ids[slot] != 0; slot++)
        ;
    if (slot < ids_size)
        return slot;
    if (ids_size == RTAPI_MAX_MODULES)
        return -ENOMEM;
    size = ids_size ? ids_size * 2 : 64;
    if (size > RTAPI_MAX_MODULES)
        size = RTAPI_MAX_MODULES;
    grown = realloc(ids, size * sizeof *ids);
    if (!grown)
        return -ENOMEM;
    memset(grown + ids_size, 0, (size - ids_size) * sizeof *ids);
    ids = grown;
    ids_size = size;
    return slot;
}

/* Allocate the next id (starting at 1) from the counter shared by the instance. */
int rtapi_init(const char *modname)
{
    int *counter;
    int id, rc, slot;

    (void)modname;
    pthread_mutex_lock(&ids_lock);
    rc = counter_attach();
    slot = rc == 0 ? free_slot() : rc;
    if (slot < 0)
        rc = slot;
    if (rc == 0) {
        rtapi_shmem_getptr(counter_handle, (void **)&counter);
        id = __atomic_add_fetch(counter, 1, __ATOMIC_SEQ_CST);
        ids[slot] = id;
        ids_used++;
        rc = id;
    }
    pthread_mutex_unlock(&ids_lock);
    if (rc == -ENOMEM)
        rtapi_print_msg(RTAPI_MSG_ERR, "rtapi: init: more than %d modules in one process\n",
                        RTAPI_MAX_MODULES);
    return rc;
}

/* Release an id; the last one detaches the counter (removed once nobody uses it). */
int rtapi_exit(int module_id)
{
    int slot, rc = -EINVAL;

    pthread_mutex_lock(&ids_lock);
    for (slot = 0; slot < ids_size; slot++) {
        if (module_id > 0 && ids[slot] == module_id) {
            ids[slot] = 0;
            ids_used--;
            rc = 0;
            break;
        }
    }
    if (rc == 0 && ids_used == 0 && counter_handle >= 0) {
        rtapi_shmem_delete(counter_handle, 0);
        counter_handle = -1;
    }
    pthread_mutex_unlock(&ids_lock);
    return rc;
}
