/* classicladder_rt.c: realtime ClassicLadder PLC: HAL pins, the shared data segment, the scan. */
#include "rtapi.h"
#include "rtapi_app.h"
#include "rtapi_string.h"
#include "rtapi_errno.h"
#include "hal.h"
#include "cl_data.h"
#include "cl_eval.h"

MODULE_LICENSE("GPL");
MODULE_AUTHOR("OpenEMC");
MODULE_DESCRIPTION("ClassicLadder soft PLC: realtime scan of a project loaded by classicladder");

static int numRungs = 100;
RTAPI_MP_INT(numRungs, "number of rungs");
static int numBits = 20;
RTAPI_MP_INT(numBits, "number of memory bits %B");
static int numWords = 20;
RTAPI_MP_INT(numWords, "number of memory words %W");
static int numTimers = 10;
RTAPI_MP_INT(numTimers, "number of timers %T");
static int numMonostables = 10;
RTAPI_MP_INT(numMonostables, "number of monostables %M");
static int numCounters = 10;
RTAPI_MP_INT(numCounters, "number of counters %C");
static int numPhysInputs = 15;
RTAPI_MP_INT(numPhysInputs, "number of bit input pins %I");
static int numPhysOutputs = 15;
RTAPI_MP_INT(numPhysOutputs, "number of bit output pins %Q");
static int numArithmExpr = 50;
RTAPI_MP_INT(numArithmExpr, "number of arithmetic expressions");
static int numSections = 10;
RTAPI_MP_INT(numSections, "number of sections");
static int numSymbols = 100;
RTAPI_MP_INT(numSymbols, "number of symbols");
static int numS32in = 10;
RTAPI_MP_INT(numS32in, "number of s32 input pins %IW");
static int numS32out = 10;
RTAPI_MP_INT(numS32out, "number of s32 output pins %QW");
static int numFloatIn = 10;
RTAPI_MP_INT(numFloatIn, "number of float input pins %IF");
static int numFloatOut = 10;
RTAPI_MP_INT(numFloatOut, "number of float output pins %QF");
static int numTimersIec = 10;
RTAPI_MP_INT(numTimersIec, "number of IEC timers %TM");
static int numErrorBits = 10;
RTAPI_MP_INT(numErrorBits, "number of error bits %E");

/* Module parameters with their limits, in CL_N_* order. */
static const struct {
    const char *name;
    int *value;
    int min, max;
} params[CL_N_SIZES] = {
    { "numRungs", &numRungs, 1, 10000 }, { "numBits", &numBits, 0, 100000 },
    { "numWords", &numWords, 0, 100000 }, { "numTimers", &numTimers, 0, 10000 },
    { "numMonostables", &numMonostables, 0, 10000 }, { "numCounters", &numCounters, 0, 10000 },
    { "numPhysInputs", &numPhysInputs, 0, 1000 }, { "numPhysOutputs", &numPhysOutputs, 0, 1000 },
    { "numArithmExpr", &numArithmExpr, 0, 10000 }, { "numSections", &numSections, 1, 1000 },
    { "numSymbols", &numSymbols, 0, 100000 }, { "numS32in", &numS32in, 0, 1000 },
    { "numS32out", &numS32out, 0, 1000 }, { "numFloatIn", &numFloatIn, 0, 1000 },
    { "numFloatOut", &numFloatOut, 0, 1000 }, { "numTimersIec", &numTimersIec, 0, 10000 },
    { "numErrorBits", &numErrorBits, 0, 10000 },
};

/* HAL side of the PLC: pin pointer arrays (in HAL memory) and the data segment. */
typedef struct {
    hal_bit_t **in, **out;
    hal_s32_t **s32in, **s32out;
    hal_float_t **floatin, **floatout;
    hal_bit_t *hide_gui, *plc_stopped;
    cl_mem_t mem;
} cl_rt_t;

static int comp_id = -1;
static int shm_id = -1;

/* Copy the input pins into the PLC's %I, %IW and %IF arrays. */
static void read_inputs(cl_rt_t *rt)
{
    cl_mem_t *m = &rt->mem;
    for (int i = 0; i < numPhysInputs; i++)
        m->phys_in[i] = *rt->in[i] != 0;
    for (int i = 0; i < numS32in; i++)
        m->s32_in[i] = *rt->s32in[i];
    for (int i = 0; i < numFloatIn; i++)
        m->float_in[i] = *rt->floatin[i];
}

/* Copy %Q, %QW and %QF to the output pins. */
static void write_outputs(cl_rt_t *rt)
{
    cl_mem_t *m = &rt->mem;
    for (int i = 0; i < numPhysOutputs; i++)
        *rt->out[i] = m->phys_out[i] != 0;
    for (int i = 0; i < numS32out; i++)
        *rt->s32out[i] = m->s32_out[i];
    for (int i = 0; i < numFloatOut; i++)
        *rt->floatout[i] = m->float_out[i];
}

/* Funct classicladder.0.refresh: one PLC scan unless no project is loaded or one is loading. */
static void refresh(void *arg, long period)
{
    cl_rt_t *rt = arg;
    cl_header_t *h = rt->mem.hdr;

    h->in_scan = 1;
    __sync_synchronize();
    if (h->loading || !h->loaded) {
        h->in_scan = 0;
        *rt->plc_stopped = 1;
        return;
    }
    read_inputs(rt);
    cl_scan(&rt->mem, period);
    write_outputs(rt);
    h->scans++;
    *rt->plc_stopped = 0;
    __sync_synchronize();
    h->in_scan = 0;
}

/* Check every module parameter against its limits. */
static int check_params(int32_t sizes[CL_N_SIZES])
{
    for (int i = 0; i < CL_N_SIZES; i++) {
        int v = *params[i].value;
        if (v < params[i].min || v > params[i].max) {
            rtapi_print_msg(RTAPI_MSG_ERR, "CLASSICLADDER: ERROR: invalid %s=%d (must be %d..%d)\n",
                            params[i].name, v, params[i].min, params[i].max);
            return -EINVAL;
        }
        sizes[i] = v;
    }
    return 0;
}

/* Create count pins "classicladder.0.<stem>-NN" of one type into ptrs[]. */
static int make_pins(void ***ptrs, int count, hal_type_t type, hal_pin_dir_t dir, const char *stem)
{
    char name[HAL_NAME_LEN + 1];
    int r;

    *ptrs = hal_malloc(sizeof(void *) * (count > 0 ? count : 1));
    if (!*ptrs)
        return -ENOMEM;
    for (int i = 0; i < count; i++) {
        rtapi_snprintf(name, sizeof(name), "classicladder.0.%s-%02d", stem, i);
        r = hal_pin_new(name, type, dir, &(*ptrs)[i], comp_id);
        if (r != 0)
            return r;
    }
    return 0;
}

/* All pins of the PLC. */
static int export_pins(cl_rt_t *rt)
{
    int r = make_pins((void ***)&rt->in, numPhysInputs, HAL_BIT, HAL_IN, "in");
    if (r == 0) r = make_pins((void ***)&rt->out, numPhysOutputs, HAL_BIT, HAL_OUT, "out");
    if (r == 0) r = make_pins((void ***)&rt->s32in, numS32in, HAL_S32, HAL_IN, "s32in");
    if (r == 0) r = make_pins((void ***)&rt->s32out, numS32out, HAL_S32, HAL_OUT, "s32out");
    if (r == 0) r = make_pins((void ***)&rt->floatin, numFloatIn, HAL_FLOAT, HAL_IN, "floatin");
    if (r == 0)
        r = make_pins((void ***)&rt->floatout, numFloatOut, HAL_FLOAT, HAL_OUT, "floatout");
    if (r == 0) r = hal_pin_bit_new("classicladder.0.hide_gui", HAL_IN, &rt->hide_gui, comp_id);
    if (r == 0)
        r = hal_pin_bit_new("classicladder.0.plc-stopped", HAL_OUT, &rt->plc_stopped, comp_id);
    if (r == 0)
        *rt->plc_stopped = 1;
    return r;
}

/* Map and initialise the data segment shared with the classicladder loader. */
static int setup_segment(cl_rt_t *rt, const int32_t sizes[CL_N_SIZES])
{
    cl_header_t hdr;
    void *base;
    size_t total = cl_layout(&hdr, sizes);

    shm_id = rtapi_shmem_new(CL_SHM_KEY, comp_id, total);
    if (shm_id < 0) {
        rtapi_print_msg(RTAPI_MSG_ERR, "CLASSICLADDER: ERROR: cannot map %lu bytes of shared "
                        "memory (%d)\n", (unsigned long)total, shm_id);
        return shm_id;
    }
    rtapi_shmem_getptr(shm_id, &base);
    memset(base, 0, total);
    memcpy(base, &hdr, sizeof(hdr));
    cl_map(&rt->mem, base);
    cl_clear_program(&rt->mem);
    cl_clear_state(&rt->mem);
    __sync_synchronize();
    rt->mem.hdr->magic = CL_MAGIC;
    return 0;
}

/* Load: check parameters, create pins, data segment and the refresh funct. */
int rtapi_app_main(void)
{
    int32_t sizes[CL_N_SIZES];
    cl_rt_t *rt;
    int r = check_params(sizes);

    if (r < 0)
        return r;
    comp_id = hal_init("classicladder_rt");
    if (comp_id < 0)
        return comp_id;
    rt = hal_malloc(sizeof(*rt));
    r = rt ? export_pins(rt) : -ENOMEM;
    if (r == 0)
        r = setup_segment(rt, sizes);
    if (r == 0)
        r = hal_export_funct("classicladder.0.refresh", refresh, rt, 1, 0, comp_id);
    if (r == 0)
        return hal_ready(comp_id);
    if (shm_id >= 0)
        rtapi_shmem_delete(shm_id, comp_id);
    shm_id = -1;
    hal_exit(comp_id);
    return r;
}

/* Unload: invalidate and release the data segment, remove the component. */
void rtapi_app_exit(void)
{
    void *base;

    if (shm_id >= 0 && rtapi_shmem_getptr(shm_id, &base) == 0)
        ((cl_header_t *)base)->magic = 0;
    if (shm_id >= 0)
        rtapi_shmem_delete(shm_id, comp_id);
    shm_id = -1;
    hal_exit(comp_id);
}
