component counter "Count rising edges of a single input (an encoder in counter mode)";
pin in bit phase_A "Count input: every rising edge adds one";
pin in bit phase_Z "Index input";
pin in bit reset "While TRUE, counts and position are held at zero";
pin io bit index_enable "When TRUE, the next index pulse zeroes counts and clears this pin";
pin out s32 rawcounts "Counts without reset or index corrections";
pin out s32 counts "Counts since the last reset or index";
pin out float position "counts / position-scale";
pin out float velocity "Velocity in position units per second";
pin io float position_scale = 1.0 "Counts per position unit";
variable int raw;
variable int offset;
variable int old_a;
variable int old_z;
variable int index_seen;
variable int old_raw;
option rtapi_app no;
license "GPL";
author "OpenEMC";
description """Load with num_chan=N (at most 8, default 1). Functs counter.update-counters and
counter.capture-position serve all channels.""";
;;
#define CNT_MAX_CHAN 8
static int num_chan = 1;
RTAPI_MP_INT(num_chan, "number of channels");

/* a - b on the wrapping 32-bit count circle (no signed overflow). */
static int cnt_diff(int a, int b)
{
    return (int)((unsigned)a - (unsigned)b);
}

/* Fast part of one channel: count edges and handle the index. */
static void cnt_count_one(struct __comp_state *__comp_inst)
{
    int a = phase_A, z = phase_Z;
    if (a && !old_a) raw = cnt_diff(raw, -1);  /* wraps like the 32-bit counter */
    old_a = a;
    if (z && !old_z && index_enable) {
        offset = raw;
        index_seen = 1;
    }
    old_z = z;
}

/* Servo part of one channel. */
static void cnt_capture_one(struct __comp_state *__comp_inst, long period)
{
    double scale = position_scale;
    if (scale > -1e-20 && scale < 1e-20) { scale = 1.0; position_scale = 1.0; }
    if (index_seen) { index_enable = 0; index_seen = 0; }
    if (reset) offset = raw;
    rawcounts = raw;
    counts = cnt_diff(raw, offset);
    position = cnt_diff(raw, offset) / scale;
    velocity = cnt_diff(raw, old_raw) / scale / (period * 1e-9);
    old_raw = raw;
}

/* Funct counter.update-counters. */
static void cnt_update_counters(void *arg, long period)
{
    (void)arg;
    (void)period;
    FOR_ALL_INSTS() cnt_count_one(__comp_inst);
}

/* Funct counter.capture-position. */
static void cnt_capture_position(void *arg, long period)
{
    (void)arg;
    FOR_ALL_INSTS() cnt_capture_one(__comp_inst, period);
}

/* Create the channels and the two shared functs. */
int rtapi_app_main(void)
{
    int i, r = 0;
    char buf[HAL_NAME_LEN + 1];
    if (num_chan < 1 || num_chan > CNT_MAX_CHAN) {
        rtapi_print_msg(RTAPI_MSG_ERR, "COUNTER: ERROR: invalid num_chan: %d\n", num_chan);
        return -EINVAL;
    }
    comp_id = hal_init("counter");
    if (comp_id < 0) return comp_id;
    for (i = 0; i < num_chan && r == 0; i++) {
        rtapi_snprintf(buf, sizeof(buf), "counter.%d", i);
        r = export(buf, i);
    }
    if (r == 0) r = hal_export_funct("counter.update-counters", cnt_update_counters, 0, 0, 0, comp_id);
    if (r == 0) r = hal_export_funct("counter.capture-position", cnt_capture_position, 0, 1, 0, comp_id);
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
