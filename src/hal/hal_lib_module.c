/* hal_lib_module.c: rtlib/hal_lib.so, loaded first by rtapi_app: sets up and tears down the RT side of HAL. */
#include "rtapi.h"
#include "rtapi_app.h"
#include "hal.h"
#include "hal_priv.h"

MODULE_LICENSE("GPL");
MODULE_DESCRIPTION("HAL library realtime side");

/* Create/attach HAL memory for the realtime process. */
int rtapi_app_main(void)
{
    return hal_rt_startup();
}

/* Delete all threads and detach. */
void rtapi_app_exit(void)
{
    hal_rt_shutdown();
}
