/* rtapi_test_leak.c: test module using every resource kind, for load/unload leak checks. */
#include "rtapi.h"
#include "rtapi_app.h"

#define LEAK_SHM_KEY 0x524c4b31
#define LEAK_SHM_BYTES (256 * 1024)

static char *label = "x";
RTAPI_MP_STRING(label, "string parameter (allocated per load)");
static char *names[4];
RTAPI_MP_ARRAY_STRING(names, 4, "string array parameter");

static int module_id, shm_id, task_id = -1;

/* Task body: just wait out periods. */
static void idle_task(void *arg)
{
    (void)arg;
    for (;;)
        rtapi_wait();
}

/* Take an id, a shared segment and a running task. */
int rtapi_app_main(void)
{
    void *mem;

    module_id = rtapi_init("rtapi_test_leak");
    if (module_id < 0)
        return module_id;
    shm_id = rtapi_shmem_new(LEAK_SHM_KEY, module_id, LEAK_SHM_BYTES);
    if (shm_id < 0 || rtapi_shmem_getptr(shm_id, &mem) < 0)
        return -ENOMEM;
    ((char *)mem)[0] = 1;
    task_id = rtapi_task_new(idle_task, NULL, rtapi_prio_lowest(), module_id, 0, 0);
    if (task_id < 0)
        return task_id;
    return rtapi_task_start(task_id, 1000000);
}

/* Give everything back. */
void rtapi_app_exit(void)
{
    rtapi_task_delete(task_id);
    rtapi_shmem_delete(shm_id, module_id);
    rtapi_exit(module_id);
}
