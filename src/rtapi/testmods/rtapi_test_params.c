/* rtapi_test_params.c: test module declaring every parameter type; prints what it got. */
#include <stdio.h>
#include "rtapi.h"
#include "rtapi_app.h"

static int count = 7;
RTAPI_MP_INT(count, "an int");
static long big = -1;
RTAPI_MP_LONG(big, "a long");
static char *label = "default";
RTAPI_MP_STRING(label, "a string");
static int ints[4] = { 1, 2, 3, 4 };
RTAPI_MP_ARRAY_INT(ints, 4, "int array");
static long longs[3] = { 10, 20, 30 };
RTAPI_MP_ARRAY_LONG(longs, 3, "long array");
static char *names[3];
RTAPI_MP_ARRAY_STRING(names, 3, "string array");
static int fail;
RTAPI_MP_INT(fail, "rtapi_app_main returns -fail when non-zero");
MODULE_LICENSE("GPL");
MODULE_AUTHOR("OpenEMC");

static int module_id;

/* Print a string parameter, showing NULL as (null). */
static const char *show(const char *s)
{
    return s ? s : "(null)";
}

/* Report every parameter value, then fail if asked. */
int rtapi_app_main(void)
{
    if (fail)
        return -fail;
    module_id = rtapi_init("rtapi_test_params");
    rtapi_print("params: id=%d count=%d big=%ld label=%s\n", module_id, count, big,
                show(label));
    rtapi_print("params: ints=%d,%d,%d,%d longs=%ld,%ld,%ld names=%s,%s,%s\n",
                ints[0], ints[1], ints[2], ints[3], longs[0], longs[1], longs[2],
                show(names[0]), show(names[1]), show(names[2]));
    printf("params: plain printf from the module\n");
    return 0;
}

/* Release the id. */
void rtapi_app_exit(void)
{
    rtapi_exit(module_id);
}
