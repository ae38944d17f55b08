/* busy_rt.c: realtime test module whose funct busy-waits spin_ns, so a short thread overruns forever. */
#include "rtapi.h"
#include "rtapi_app.h"
#include "hal.h"

MODULE_LICENSE("GPL");

static long spin_ns = 20000;
RTAPI_MP_LONG(spin_ns, "time each call of busy.spin takes (ns)");

static int comp_id;

/* Burn spin_ns of CPU time. */
static void spin_funct(void *arg, long period)
{
    long long end = rtapi_get_time() + spin_ns;
    (void)arg;
    (void)period;
    while (rtapi_get_time() < end)
        ;
}

/* Register component busy_rt with funct busy.spin. */
int rtapi_app_main(void)
{
    comp_id = hal_init("busy_rt");
    if (comp_id < 0)
        return comp_id;
    if (hal_export_funct("busy.spin", spin_funct, NULL, 0, 0, comp_id) < 0) {
        hal_exit(comp_id);
        return -1;
    }
    hal_ready(comp_id);
    return 0;
}

/* Remove the component. */
void rtapi_app_exit(void)
{
    hal_exit(comp_id);
}
