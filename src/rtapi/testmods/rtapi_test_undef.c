/* rtapi_test_undef.c: test module using a symbol nobody defines (dlopen must fail). */
#include "rtapi.h"
#include "rtapi_app.h"

extern int rtapi_test_nowhere(void);

/* Calls the missing function. */
int rtapi_app_main(void)
{
    return rtapi_test_nowhere();
}

/* Nothing to tear down. */
void rtapi_app_exit(void)
{
}
