/* kins_demo.c: the demonstration items of LinuxCNC's userkins template (fpin/fdemo, in/out echo). */
#include "rtapi.h"
#include "hal.h"
#include "kins_demo.h"

/* The echo pins (their pointers live in HAL memory, as HAL requires). */
typedef struct {
    hal_u32_t *in, *out;
} kins_demo_echo_t;

static kins_demo_echo_t *echo;
static int inverse_seen, warned;

/* Funct <prefix>.fdemo: announce itself once, then count its calls on fpin. */
static void kins_demo_funct(void *arg, long period)
{
    hal_s32_t *fpin = *(hal_s32_t **)arg;
    (void)period;
    if (*fpin == 0)
        rtapi_print_msg(RTAPI_MSG_INFO, "fdemo function added to thread\n");
    *fpin += 1;
}

/* Instance items <prefix>.fpin (s32 OUT) and funct <prefix>.fdemo. */
int kins_demo_instance(int comp_id, int i, const char *prefix)
{
    char name[HAL_NAME_LEN + 1];
    hal_s32_t **fpin = hal_malloc(sizeof(*fpin));
    (void)i;
    if (!fpin)
        return -ENOMEM;
    int r = hal_pin_s32_newf(HAL_OUT, fpin, comp_id, "%s.fpin", prefix);
    if (r)
        return r;
    rtapi_snprintf(name, sizeof(name), "%s.fdemo", prefix);
    return hal_export_funct(name, kins_demo_funct, fpin, 0, 0, comp_id);
}

/* Pins <module>.in (u32 IN) and <module>.out (u32 OUT). */
int kins_demo_echo_pins(int comp_id, const char *module)
{
    kins_demo_echo_t *e = hal_malloc(sizeof(*e));
    if (!e)
        return -ENOMEM;
    int r = hal_pin_u32_newf(HAL_IN, &e->in, comp_id, "%s.in", module);
    if (r == 0)
        r = hal_pin_u32_newf(HAL_OUT, &e->out, comp_id, "%s.out", module);
    if (r == 0)
        echo = e;
    return r;
}

/* Inverse side: copy in to out. */
void kins_demo_echo_inverse(void)
{
    inverse_seen = 1;
    if (echo)
        *echo->out = *echo->in;
}

/* Forward side: say once that in is not echoed while no inverse has run. */
void kins_demo_echo_forward(const char *module)
{
    if (echo && *echo->in && !inverse_seen && !warned) {
        rtapi_print_msg(RTAPI_MSG_INFO, "%s the 'in' pin not echoed until Inverse called\n", module);
        warned = 1;
    }
}
