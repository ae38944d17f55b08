/* rtapi_test_noexit.c: test module without rtapi_app_exit (load must refuse it). */
#include "rtapi.h"
#include "rtapi_app.h"

/* Nothing to set up. */
int rtapi_app_main(void)
{
    return 0;
}
