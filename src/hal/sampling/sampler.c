/* sampler.c: realtime module that writes pin values into sampler streams for halsampler. */
#include "rtapi.h"
#include "rtapi_app.h"
#include "hal.h"
#include "stream_module.h"

MODULE_AUTHOR("OpenEMC");
MODULE_DESCRIPTION("Samples HAL pins into a stream read by halsampler");
MODULE_LICENSE("GPL");

#define MAX_SAMPLERS STREAM_MODULE_MAX_CHANS
#define SAMPLER_KEY_BASE 0x48534130

static char *cfg[MAX_SAMPLERS];
RTAPI_MP_ARRAY_STRING(cfg, MAX_SAMPLERS, "field types of each channel");
static int depth[MAX_SAMPLERS];
RTAPI_MP_ARRAY_INT(depth, MAX_SAMPLERS, "stream depth of each channel");

/* Per-channel pins, in HAL memory. */
typedef struct {
    hal_bit_t *full;
    hal_bit_t *enable;
    hal_s32_t *curr_depth;
    hal_s32_t *overruns;
    hal_s32_t *sample_num;
    stream_fields_t fields;
} sampler_chan_t;

static void sample(void *arg, long period);
static int new_status_pins(void *chan, const char *prefix, int comp_id);

/* The module's description and channel state, shared with stream_module.c. */
static stream_module_t mod = {
    .name = "sampler",
    .tag = "SAMPLER",
    .key_base = SAMPLER_KEY_BASE,
    .field_dir = HAL_IN,
    .chan_size = sizeof(sampler_chan_t),
    .fields_offset = offsetof(sampler_chan_t, fields),
    .new_status_pins = new_status_pins,
    .funct = sample,
    .cfg = cfg,
    .depth = depth,
};

/* Realtime function: one record per call while enabled. */
static void sample(void *arg, long period)
{
    int n = (int)(long)arg;
    sampler_chan_t *ch = mod.chans[n];
    union hal_stream_data rec[STREAM_FIELDS_MAX];

    (void)period;
    if (*ch->enable) {
        stream_fields_to_record(&ch->fields, rec);
        if (hal_stream_write(&mod.streams[n], rec) < 0) {
            (*ch->overruns)++;
            *ch->full = 1;
            *ch->curr_depth = depth[n];
            return;
        }
    }
    *ch->curr_depth = hal_stream_depth(&mod.streams[n]);
    *ch->full = !hal_stream_writable(&mod.streams[n]);
}

/* Creates the status pins `sampler.N.*` of one channel. */
static int new_status_pins(void *chan, const char *prefix, int comp_id)
{
    sampler_chan_t *ch = chan;
    int r = hal_pin_bit_newf(HAL_OUT, &ch->full, comp_id, "%s.full", prefix);
    if (r == 0) r = hal_pin_bit_newf(HAL_IN, &ch->enable, comp_id, "%s.enable", prefix);
    if (r == 0) r = hal_pin_s32_newf(HAL_OUT, &ch->curr_depth, comp_id, "%s.curr-depth", prefix);
    if (r == 0) r = hal_pin_s32_newf(HAL_IO, &ch->overruns, comp_id, "%s.overruns", prefix);
    if (r == 0) r = hal_pin_s32_newf(HAL_IO, &ch->sample_num, comp_id, "%s.sample-num", prefix);
    if (r == 0) *ch->enable = 1;
    return r;
}

/* Module entry: parses cfg/depth and creates every channel. */
int rtapi_app_main(void)
{
    return stream_module_init(&mod);
}

/* Module exit: destroys the streams and the component. */
void rtapi_app_exit(void)
{
    stream_module_exit(&mod);
}
