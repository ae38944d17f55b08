/* hal_test_ctor.c: realtime test module: a component with an instance constructor (newinst). */
#include <stdlib.h>
#include "rtapi.h"
#include "rtapi_app.h"
#include "hal.h"

MODULE_LICENSE("GPL");

static int comp_id, plain_id;

/* Constructor: pins <prefix>.value (s32 OUT, set from arg) and <prefix>.arg-count. */
static int make_instance(char *prefix, char *arg)
{
    hal_s32_t **value = hal_malloc(2 * sizeof *value);
    int words = 0, rc;

    if (!value)
        return -ENOMEM;
    rc = hal_pin_s32_newf(HAL_OUT, &value[0], comp_id, "%s.value", prefix);
    if (rc == 0)
        rc = hal_pin_s32_newf(HAL_OUT, &value[1], comp_id, "%s.arg-count", prefix);
    if (rc < 0)
        return rc;
    *value[0] = (hal_s32_t)strtol(arg, NULL, 0);
    for (const char *p = arg; *p; p++)
        if (*p != ' ' && (p == arg || p[-1] == ' '))
            words++;
    *value[1] = words;
    return 0;
}

/* Register hal_test_ctor (with constructor) and hal-test-plain (without). */
int rtapi_app_main(void)
{
    comp_id = hal_init("hal_test_ctor");
    if (comp_id < 0)
        return comp_id;
    plain_id = hal_init("hal-test-plain");
    if (plain_id < 0 || hal_set_constructor(comp_id, make_instance) < 0) {
        hal_exit(comp_id);
        return -EINVAL;
    }
    hal_ready(plain_id);
    hal_ready(comp_id);
    return 0;
}

/* Remove both components. */
void rtapi_app_exit(void)
{
    hal_exit(plain_id);
    hal_exit(comp_id);
}
