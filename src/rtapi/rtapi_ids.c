/* rtapi_ids.c: rtapi_init/rtapi_exit and the per-instance component-id counter (hal.md §4). */
#include <pthread.h>
#include <string.h>
#include "rtapi.h"
#include "rtapi_instance.h"

#define COUNTER_BYTES 4096

static pthread_mutex_t ids_lock = PTHREAD_MUTEX_INITIALIZER;
static int counter_handle = -1;
static int ids[RTAPI_MAX_MODULES];
static int ids_used;

/* Attach the counter segment if not yet attached; 0 or -errno. */
static int counter_attach(void)
{
    if (counter_handle >= 0)
        return 0;
    counter_handle = rtapi_shmem_new(RTAPI_IDCOUNTER_KEY, 0, COUNTER_BYTES);
    return counter_handle < 0 ? counter_handle : 0;
}

/* Allocate the next id (starting at 1) from the counter shared by the instance. */
int rtapi_init(const char *modname)
{
    int *counter;
    int id, rc, slot;

    (void)modname;
    pthread_mutex_lock(&ids_lock);
    rc = counter_attach();
    for (slot = 0; slot < RTAPI_MAX_MODULES && ids[slot] != 0; slot++)
        ;
    if (rc == 0 && slot == RTAPI_MAX_MODULES)
        rc = -ENOMEM;
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
    for (slot = 0; slot < RTAPI_MAX_MODULES; slot++) {
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
