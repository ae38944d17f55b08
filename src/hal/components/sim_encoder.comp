component sim_encoder "Simulated quadrature encoder";
pin io u32 ppr = 100 "Pulses per revolution";
pin io float scale = 1.0 "Position units per revolution";
pin in float speed "Speed in position units per second";
pin out bit phase_A "Quadrature output A";
pin out bit phase_B "Quadrature output B";
pin out bit phase_Z "Index output, one pulse per revolution";
pin in s32 rawcounts "Edge count (readable for diagnostics)";
variable long long accum;
variable long long addval;
variable int state;
variable long long edges;
option rtapi_app no;
include "comp_args.h";
license "GPL";
author "OpenEMC";
description """Load with num_chan=N (at most 8, default 1) or names=a,b,... Funct
sim-encoder.make-pulses (fast) and sim-encoder.update-speed serve all channels.""";
;;
#define SIMENC_MAX_CHAN 8
#define SIMENC_ONE 4294967296.0
#define SIMENC_ONE_LL 4294967296LL
static int num_chan = 0;
RTAPI_MP_INT(num_chan, "number of channels");
static char *names[SIMENC_MAX_CHAN];
RTAPI_MP_ARRAY_STRING(names, SIMENC_MAX_CHAN, "names of the channels");
static long simenc_base_ns;

/* Fast part of one channel: advance the phase accumulator and drive A/B/Z. */
static void simenc_pulse_one(struct __comp_state *__comp_inst, long period)
{
    unsigned p = ppr ? ppr : 1;
    long long per_rev = 4LL * p;
    simenc_base_ns = period;
    accum += addval;  /* accum holds only the fraction of an edge, so it never overflows */
    if (accum >= SIMENC_ONE_LL) { accum -= SIMENC_ONE_LL; state = (state + 1) & 3; edges++; }
    else if (accum < 0) { accum += SIMENC_ONE_LL; state = (state + 3) & 3; edges--; }
    phase_A = state == 1 || state == 2;
    phase_B = state >= 2;
    phase_Z = ((edges % per_rev) + per_rev) % per_rev == 0;
    *rawcounts_ptr = (hal_s32_t)edges;
}

/* Servo part of one channel: convert speed to an accumulator increment. */
static void simenc_speed_one(struct __comp_state *__comp_inst)
{
    double sc = scale, rate;
    unsigned p = ppr;
    if (p == 0) { p = 1; ppr = 1; }
    if (sc > -1e-20 && sc < 1e-20) { sc = 1.0; scale = 1.0; }
    rate = speed / sc * 4.0 * p;
    if (simenc_base_ns <= 0) { addval = 0; return; }
    rate *= simenc_base_ns * 1e-9;
    if (rate != rate) rate = 0.0;  /* a NaN speed stops the encoder */
    if (rate > 0.5) rate = 0.5;
    if (rate < -0.5) rate = -0.5;
    addval = (long long)(rate * SIMENC_ONE);
}

/* Funct sim-encoder.make-pulses. */
static void simenc_make_pulses(void *arg, long period)
{
    (void)arg;
    FOR_ALL_INSTS() simenc_pulse_one(__comp_inst, period);
}

/* Funct sim-encoder.update-speed. */
static void simenc_update_speed(void *arg, long period)
{
    (void)arg;
    (void)period;
    FOR_ALL_INSTS() simenc_speed_one(__comp_inst);
}

/* Create the channels and the two shared functs. */
int rtapi_app_main(void)
{
    static const comp_chan_spec_t spec = { "SIM_ENCODER", "sim-encoder", SIMENC_MAX_CHAN, 1 };
    int i, r = 0, n = comp_chan_count(&spec, num_chan, names);
    char buf[HAL_NAME_LEN + 1];
    if (n < 0)
        return n;
    comp_id = hal_init("sim_encoder");
    if (comp_id < 0) return comp_id;
    for (i = 0; i < n && r == 0; i++) {
        comp_chan_name(&spec, names, i, buf, sizeof(buf));
        r = export(buf, i);
    }
    if (r == 0) r = hal_export_funct("sim-encoder.make-pulses", simenc_make_pulses, 0, 0, 0, comp_id);
    if (r == 0) r = hal_export_funct("sim-encoder.update-speed", simenc_update_speed, 0, 1, 0, comp_id);
    if (r) {
        hal_exit(comp_id);
        return r;
    }
    hal_ready(comp_id);
    return 0;
}

/* Remove the component. */
void rtapi_app_exit(void)
{
    hal_exit(comp_id);
}
