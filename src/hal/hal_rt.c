/* hal_rt.c: realtime-side start-up and shut-down of the HAL library inside rtapi_app. */
#include "hal_internal.h"

/* Attach/create HAL memory as the RT process; costs one id (id 1 on a fresh instance). */
int hal_rt_startup(void)
{
    int rc;

    if (hal_proc_is_rt)
        return 0;
    rc = hal_lib_attach();
    if (rc < 0)
        return rc;
    hal_proc_is_rt = 1;
    hal_clock_calibrate();
    return 0;
}

/* Stop and delete every thread, then detach (hal_lib's rtapi_app_exit). */
void hal_rt_shutdown(void)
{
    if (!hal_proc_is_rt || !hal_data)
        return;
    halpr_mutex_get();
    hal_data->threads_running = 0;
    while (hal_data->threads.list_ptr)
        halpr_thread_delete(SHMPTR(hal_data->threads.list_ptr));
    halpr_mutex_give();
    hal_shm_detach();
    rtapi_exit(hal_proc_lib_id);
    hal_proc_lib_id = 0;
    hal_proc_is_rt = 0;
}
