/* hal_test_many.c: realtime test module registering count= HAL components (many rtapi ids). */
#include "rtapi.h"
#include "rtapi_app.h"
#include "hal.h"

MODULE_LICENSE("GPL");

static int count = 1;
RTAPI_MP_INT(count, "number of extra components");

static int main_id;
static int *extra_ids;   /* in HAL memory: ids of hal_test_many.N */
static int made;

/* Pin hal_test_many.N.out (s32 OUT = N) on component id. */
static int add_pin(int id, int n)
{
    hal_s32_t **out = hal_malloc(sizeof *out);

    if (!out || hal_pin_s32_newf(HAL_OUT, out, id, "hal_test_many.%d.out", n) < 0)
        return -EINVAL;
    **out = n;
    return 0;
}

/* Remove every component made so far. */
static void remove_all(void)
{
    while (made > 0)
        hal_exit(extra_ids[--made]);
    hal_exit(main_id);
}

/* Register hal_test_many and `count` components hal_test_many.0 .. N-1. */
int rtapi_app_main(void)
{
    char name[HAL_NAME_LEN + 1];

    main_id = hal_init("hal_test_many");
    if (main_id < 0)
        return main_id;
    extra_ids = count > 0 ? hal_malloc(count * sizeof *extra_ids) : NULL;
    for (made = 0; made < count; made++) {
        int id;
        rtapi_snprintf(name, sizeof name, "hal_test_many.%d", made);
        id = extra_ids ? hal_init(name) : -ENOMEM;
        if (id < 0 || add_pin(id, made) < 0 || hal_ready(id) < 0) {
            rtapi_print_msg(RTAPI_MSG_ERR, "hal_test_many: component %d failed\n", made);
            if (id > 0)
                hal_exit(id);
            remove_all();
            return -EINVAL;
        }
        extra_ids[made] = id;
    }
    hal_ready(main_id);
    return 0;
}

/* Remove all components. */
void rtapi_app_exit(void)
{
    remove_all();
}
