component encoder_ratio "Electronic gear: keep two quadrature encoders at a fixed ratio";
pin in bit master_A "Master encoder phase A";
pin in bit master_B "Master encoder phase B";
pin in bit slave_A "Slave encoder phase A";
pin in bit slave_B "Slave encoder phase B";
pin in bit enable "When FALSE, the error is held at zero and tracking restarts when enabled";
pin io u32 master_ppr "Master pulses per revolution";
pin io u32 slave_ppr "Slave pulses per revolution";
pin io u32 master_teeth "Master gear teeth";
pin io u32 slave_teeth "Slave gear teeth";
pin out float error "Slave position error in slave revolutions";
variable int mstate;
variable int sstate;
variable long long mcount;
variable long long scount;
option rtapi_app no;
license "GPL";
author "OpenEMC";
description """Load with num_chan=N (at most 8, default 1). Functs encoder-ratio.sample (fast)
and encoder-ratio.update serve all channels.""";
;;
#define ER_MAX_CHAN 8
static int num_chan = 1;
RTAPI_MP_INT(num_chan, "number of channels");

/* Count change of a quadrature transition (x4). */
static int er_step(int a, int b)
{
    static const signed char table[16] = { 0, -1, 1, 0, 1, 0, 0, -1, -1, 0, 0, 1, 0, 1, -1, 0 };
    return table[(a << 2) | b];
}

/* Fast part of one channel: count both encoders. */
static void er_sample_one(struct __comp_state *__comp_inst)
{
    int m = (master_A ? 2 : 0) | (master_B ? 1 : 0), s = (slave_A ? 2 : 0) | (slave_B ? 1 : 0);
    if (enable) {
        mcount += er_step(mstate, m);
        scount += er_step(sstate, s);
    } else {
        mcount = 0;
        scount = 0;
    }
    mstate = m;
    sstate = s;
}

/* Servo part of one channel: slave error in revolutions. */
static void er_update_one(struct __comp_state *__comp_inst)
{
    double mppr = master_ppr, sppr = slave_ppr, mt = master_teeth, st = slave_teeth;
    if (mppr <= 0 || sppr <= 0 || mt <= 0 || st <= 0 || !enable) {
        error = 0;
        return;
    }
    error = (mcount / (4.0 * mppr)) * (mt / st) - scount / (4.0 * sppr);
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

/* Create the channels and the shared functs. */
int rtapi_app_main(void)
{
    int i, r = 0;
    char buf[HAL_NAME_LEN + 1];
    if (num_chan < 1 || num_chan > ER_MAX_CHAN) {
        rtapi_print_msg(RTAPI_MSG_ERR, "ENCODER_RATIO: ERROR: invalid num_chan: %d\n", num_chan);
        return -EINVAL;
    }
    comp_id = hal_init("encoder_ratio");
    if (comp_id < 0) return comp_id;
    for (i = 0; i < num_chan && r == 0; i++) {
        rtapi_snprintf(buf, sizeof(buf), "encoder-ratio.%d", i);
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
