component encoder_ratio "Electronic gear: count two quadrature encoders and output the slave's error against the scaled master";
description """
Two functs serve every channel.  \\fBencoder-ratio.sample\\fR (no floating point;
run it at least twice as fast as the highest edge rate) decodes both encoders
x4: a change of one input is one edge, forward is 00, 10, 11, 01 (A leads B), a
change of both inputs at once counts nothing.  While \\fBenable\\fR is TRUE each
master edge moves the raw error by master-teeth x slave-ppr; each slave edge
always moves it by slave-teeth x master-ppr, the other way.
\\fBencoder-ratio.update\\fR (floating point) sets \\fBerror\\fR = raw /
(master-ppr x slave-ppr x slave-teeth) in slave revolutions (ppr counts edges,
four per line); the gear settings it uses take effect one update later.
""";
pin in bit master_A "Master encoder phase A";
pin in bit master_B "Master encoder phase B";
pin in bit slave_A "Slave encoder phase A";
pin in bit slave_B "Slave encoder phase B";
pin in bit enable "While FALSE, master edges are ignored (the slave keeps counting)";
pin io u32 master_ppr "Master edges per revolution (4 x lines)";
pin io u32 slave_ppr "Slave edges per revolution (4 x lines)";
pin io u32 master_teeth "Teeth on the master side of the ratio";
pin io u32 slave_teeth "Teeth on the slave side of the ratio";
pin out float error "Slave position error in slave revolutions";
variable int master_state;
variable int slave_state;
variable long long raw_error;
variable long long master_increment;
variable long long slave_increment;
variable double output_scale = 1.0;
option rtapi_app no;
include "comp_args.h";
license "GPL";
author "OpenEMC";
;;
#define ER_MAX_CHAN 8
static int num_chan = 0;
RTAPI_MP_INT(num_chan, "number of channels (0: one)");
static char *names[ER_MAX_CHAN];
RTAPI_MP_ARRAY_STRING(names, ER_MAX_CHAN, "names of the channels");

/* Edges between two quadrature states (A in bit 1, B in bit 0): +1 forward, -1 back, 0 none or both changed. */
static int er_step(int from, int to)
{
    static const signed char table[16] = { 0, -1, 1, 0, 1, 0, 0, -1, -1, 0, 0, 1, 0, 1, -1, 0 };
    return table[(from << 2) | to];
}

/* Fast part of one channel: decode both encoders and move the raw error. */
static void er_sample_one(struct __comp_state *__comp_inst)
{
    int m = (master_A ? 2 : 0) | (master_B ? 1 : 0), s = (slave_A ? 2 : 0) | (slave_B ? 1 : 0);
    if (enable)
        raw_error -= er_step(master_state, m) * master_increment;
    raw_error += er_step(slave_state, s) * slave_increment;
    master_state = m;
    slave_state = s;
}

/* Slow part of one channel: scale the error, then take the gear settings for the next call. */
static void er_update_one(struct __comp_state *__comp_inst)
{
    if (output_scale > 0)
        error = raw_error / output_scale;
    master_increment = (hal_u32_t)(master_teeth * slave_ppr);
    slave_increment = (hal_u32_t)(slave_teeth * master_ppr);
    output_scale = (hal_u32_t)(master_ppr * slave_ppr * slave_teeth);
}

/* Funct encoder-ratio.sample. */
static void er_sample(void *arg, long period)
{
    (void)arg;
    (void)period;
    FOR_ALL_INSTS() er_sample_one(__comp_inst);
}

/* Funct encoder-ratio.update. */
static void er_update(void *arg, long period)
{
    (void)arg;
    (void)period;
    FOR_ALL_INSTS() er_update_one(__comp_inst);
}

/* Create the channels (num_chan= or names=, one by default) and the shared functs. */
int rtapi_app_main(void)
{
    static const comp_chan_spec_t spec = { "ENCODER_RATIO", "encoder-ratio", ER_MAX_CHAN, 1 };
    int i, r = 0, n = comp_chan_count(&spec, num_chan, names);
    char buf[HAL_NAME_LEN + 1];
    if (n < 0)
        return n;
    comp_id = hal_init("encoder_ratio");
    if (comp_id < 0) return comp_id;
    for (i = 0; i < n && r == 0; i++) {
        comp_chan_name(&spec, names, i, buf, sizeof(buf));
        r = export(buf, i);
    }
    if (r == 0) r = hal_export_funct("encoder-ratio.sample", er_sample, 0, 0, 0, comp_id);
    if (r == 0) r = hal_export_funct("encoder-ratio.update", er_update, 0, 1, 0, comp_id);
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
