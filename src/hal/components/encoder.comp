component encoder "Software quadrature encoder counter";
pin in bit phase_A "Quadrature input A (count input in counter mode)";
pin in bit phase_B "Quadrature input B (direction input in counter mode: TRUE counts down)";
pin in bit phase_Z "Index input";
pin in bit reset "While TRUE, counts and position are held at zero";
pin in bit latch_input "Edges of this input latch counts and position";
pin in bit latch_rising = TRUE "Latch on rising edges of latch-input";
pin in bit latch_falling = TRUE "Latch on falling edges of latch-input";
pin io bit index_enable "When TRUE, the next index pulse zeroes counts and clears this pin";
pin io bit x4_mode = TRUE "TRUE counts every edge; FALSE counts once per quadrature cycle";
pin io bit counter_mode = FALSE "TRUE: A is the count input and B the direction";
pin out s32 rawcounts "Counts without reset or index corrections";
pin out s32 counts "Counts since the last reset or index";
pin out s32 counts_latched "counts at the last latch edge";
pin out float position "counts / position-scale";
pin out float position_interpolated "position refined by the velocity between counts";
pin out float position_latched "position at the last latch edge";
pin out float velocity "Velocity in position units per second";
pin out float velocity_rpm "velocity * 60";
pin io float position_scale = 1.0 "Counts per position unit";
pin in float min_speed_estimate = 1.0 "Below this speed the velocity is reported as zero";
pin in s32 missing_teeth "Teeth missing from a tooth wheel used as index (0 = normal index)";
variable int raw;
variable int offset;
variable int state;
variable int old_z;
variable int old_latch;
variable int latched;
variable int latch_seen;
variable int index_seen;
variable int old_raw;
variable long long clock_ns;
variable long long edge_ns;
variable long long prev_edge_ns;
variable long long gap_ns;
variable int edge_dir;
option rtapi_app no;
include "comp_args.h";
include <rtapi_math.h>;
license "GPL";
author "OpenEMC";
description """Load with num_chan=N (at most 8, default 3) or names=a,b,... Functs
encoder.update-counters (fast, no floating point) and encoder.capture-position serve all channels.""";
;;
#define ENC_MAX_CHAN 8
static int num_chan = 0;
RTAPI_MP_INT(num_chan, "number of channels");
static char *names[ENC_MAX_CHAN];
RTAPI_MP_ARRAY_STRING(names, ENC_MAX_CHAN, "names of the channels");

/* a - b on the wrapping 32-bit count circle (no signed overflow). */
static int enc_diff(int a, int b)
{
    return (int)((unsigned)a - (unsigned)b);
}

/* Count change for a quadrature transition from state a to b (AB as 2 bits). */
static int enc_step(int a, int b, int x4)
{
    static const signed char table[16] = {
        0, -1, 1, 0,
        1, 0, 0, -1,
        -1, 0, 0, 1,
        0, 1, -1, 0 };
    int d = table[(a << 2) | b];
    if (x4 || d == 0) return d;
    if (a == 0 && b == 2) return 1;
    if (a == 2 && b == 0) return -1;
    return 0;
}

/* Missing-tooth index: a gap longer than 1.5 normal tooth periods per missing tooth. */
static int enc_gap_index(struct __comp_state *__comp_inst, long long dt)
{
    int teeth = missing_teeth;
    int hit = teeth > 0 && gap_ns > 0 && 2.0 * dt > (double)gap_ns * (2.0 * teeth + 1.0);
    gap_ns = dt;
    return hit;
}

/* Fast part of one channel: decode edges, index and latch. */
static void enc_count_one(struct __comp_state *__comp_inst, long period)
{
    int s = (phase_A ? 2 : 0) | (phase_B ? 1 : 0), z = phase_Z, l = latch_input, d;
    clock_ns += period;
    if (counter_mode) d = (s & 2) && !(state & 2) ? ((s & 1) ? -1 : 1) : 0;
    else d = enc_step(state, s, x4_mode);
    state = s;
    if (d) {
        int idx = enc_gap_index(__comp_inst, clock_ns - edge_ns);
        raw = enc_diff(raw, -d);  /* wraps like the 32-bit counter */
        prev_edge_ns = edge_ns;
        edge_ns = clock_ns;
        edge_dir = d;
        if (idx && index_enable) { offset = raw; index_seen = 1; }
    }
    if (z && !old_z && index_enable && missing_teeth <= 0) {
        offset = raw;
        index_seen = 1;
    }
    old_z = z;
    if ((l && !old_latch && latch_rising) || (!l && old_latch && latch_falling)) {
        latched = raw;
        latch_seen = 1;
    }
    old_latch = l;
}

/* Servo part of one channel: counts, position and velocity. */
static void enc_capture_one(struct __comp_state *__comp_inst, long period)
{
    double scale = position_scale, since, vel;
    int c;
    if (scale > -1e-20 && scale < 1e-20) { scale = 1.0; position_scale = 1.0; }
    if (index_seen) { index_enable = 0; index_seen = 0; }
    if (reset) offset = raw;
    c = enc_diff(raw, offset);
    rawcounts = raw;
    counts = c;
    position = c / scale;
    if (latch_seen) {
        counts_latched = enc_diff(latched, offset);
        position_latched = counts_latched / scale;
        latch_seen = 0;
    }
    since = (clock_ns - edge_ns) * 1e-9;
    if (raw != old_raw && edge_ns > prev_edge_ns && prev_edge_ns > 0) {
        vel = enc_diff(raw, old_raw) / scale / ((double)period * 1e-9);
        if (enc_diff(raw, old_raw) == edge_dir) vel = edge_dir / scale / ((edge_ns - prev_edge_ns) * 1e-9);
    } else if (raw != old_raw) {
        vel = enc_diff(raw, old_raw) / scale / ((double)period * 1e-9);
    } else {
        vel = velocity;
        if (since > 0 && fabs(1.0 / scale / since) < fabs(vel)) vel = edge_dir / fabs(scale) / since;
        if (fabs(vel) < min_speed_estimate) vel = 0;
    }
    old_raw = raw;
    velocity = vel;
    velocity_rpm = vel * 60.0;
    since = vel * since;
    if (fabs(since) > 1.0 / fabs(scale)) since = since > 0 ? 1.0 / fabs(scale) : -1.0 / fabs(scale);
    position_interpolated = c / scale + since;
}

/* Funct encoder.update-counters. */
static void enc_update_counters(void *arg, long period)
{
    (void)arg;
    FOR_ALL_INSTS() enc_count_one(__comp_inst, period);
}

/* Funct encoder.capture-position. */
static void enc_capture_position(void *arg, long period)
{
    (void)arg;
    FOR_ALL_INSTS() enc_capture_one(__comp_inst, period);
}

/* Create the channels and the two shared functs. */
int rtapi_app_main(void)
{
    static const comp_chan_spec_t spec = { "ENCODER", "encoder", ENC_MAX_CHAN, 3 };
    int i, r = 0, n = comp_chan_count(&spec, num_chan, names);
    char buf[HAL_NAME_LEN + 1];
    if (n < 0)
        return n;
    comp_id = hal_init("encoder");
    if (comp_id < 0) return comp_id;
    for (i = 0; i < n && r == 0; i++) {
        comp_chan_name(&spec, names, i, buf, sizeof(buf));
        r = export(buf, i);
    }
    if (r == 0) r = hal_export_funct("encoder.update-counters", enc_update_counters, 0, 0, 0, comp_id);
    if (r == 0) r = hal_export_funct("encoder.capture-position", enc_capture_position, 0, 1, 0, comp_id);
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
