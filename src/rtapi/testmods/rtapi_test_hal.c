/* rtapi_test_hal.c: stand-in for hal_lib in RTAPI tests: takes a component id like HAL does. */
#include "rtapi.h"
#include "rtapi_app.h"

static int module_id;

/* Take id 1 from the instance counter, as the real hal_lib does. */
int rtapi_app_main(void)
{
    module_id = rtapi_init("HAL_LIB");
    if (module_id < 0)
        return module_id;
    rtapi_print("rtapi_test_hal: id %d\n", module_id);
    return 0;
}

/* Give the id back. */
void rtapi_app_exit(void)
{
    rtapi_print("rtapi_test_hal: exit\n");
    rtapi_exit(module_id);
}
