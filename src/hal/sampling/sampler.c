/* sampler.c: realtime module that writes pin values into sampler streams for halsampler. */
#include "rtapi.h"
#include "rtapi_app.h"
#include "hal.h"
#include "stream_fields.h"

MODULE_AUTHOR("OpenEMC");
MODULE_DESCRIPTION("Samples HAL pins into a stream read by halsampler");
MODULE_LICENSE("GPL");

#define MAX_SAMPLERS 8
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

static int comp_id;
static int num_chans;
static hal_stream_t streams[MAX_SAMPLERS];
static int stream_ok[MAX_SAMPLERS];
static sampler_chan_t *chans[MAX_SAMPLERS];

/* Realtime function: one record per call while enabled. */
static void sample(void *arg, long period)
{
    int n = (int)(long)arg;
    sampler_chan_t *ch = chans[n];
    union hal_stream_data rec[STREAM_FIELDS_MAX];

    (void)period;
    if (*ch->enable) {
        stream_fields_to_record(&ch->fields, rec);
        if (hal_stream_write(&streams[n], rec) < 0) {
            (*ch->overruns)++;
            *ch->full = 1;
            *ch->curr_depth = depth[n];
            return;
        }
    }
    *ch->curr_depth = hal_stream_depth(&streams[n]);
    *ch->full = !hal_stream_writable(&streams[n]);
}

/* Creates the status pins `sampler.N.*` of one channel. */
static int new_status_pins(sampler_chan_t *ch, const char *prefix)
{
    int r = hal_pin_bit_newf(HAL_OUT, &ch->full, comp_id, "%s.full", prefix);
    if (r == 0) r = hal_pin_bit_newf(HAL_IN, &ch->enable, comp_id, "%s.enable", prefix);
    if (r == 0) r = hal_pin_s32_newf(HAL_OUT, &ch->curr_depth, comp_id, "%s.curr-depth", prefix);
    if (r == 0) r = hal_pin_s32_newf(HAL_IO, &ch->overruns, comp_id, "%s.overruns", prefix);
    if (r == 0) r = hal_pin_s32_newf(HAL_IO, &ch->sample_num, comp_id, "%s.sample-num", prefix);
    if (r == 0) *ch->enable = 1;
    return r;
}

/* Sets up channel n: stream, pins and function. */
static int init_channel(int n)
{
    char prefix[HAL_NAME_LEN + 1];
    char types[STREAM_FIELDS_MAX + 1];
    int retval;

    if (depth[n] <= 0) {
        rtapi_print_msg(RTAPI_MSG_ERR,
            "SAMPLER: ERROR: channel %d: depth must be greater than 0\n", n);
        return -EINVAL;
    }
    stream_fields_normalize(cfg[n], types);
    retval = hal_stream_create(&streams[n], comp_id, SAMPLER_KEY_BASE + n, depth[n], types);
    if (retval < 0) {
        rtapi_print_msg(RTAPI_MSG_ERR,
            "SAMPLER: ERROR: channel %d: could not create stream\n", n);
        return retval;
    }
    stream_ok[n] = 1;
    chans[n] = hal_malloc(sizeof(sampler_chan_t));
    if (chans[n] == NULL) {
        rtapi_print_msg(RTAPI_MSG_ERR, "SAMPLER: ERROR: hal_malloc() failed\n");
        return -ENOMEM;
    }
    rtapi_snprintf(prefix, sizeof(prefix), "sampler.%d", n);
    retval = stream_fields_new_pins(&chans[n]->fields, cfg[n], prefix, HAL_IN, comp_id);
    if (retval == 0) retval = new_status_pins(chans[n], prefix);
    if (retval == 0) retval = hal_export_funct(prefix, sample, (void *)(long)n, 1, 0, comp_id);
    if (retval < 0) {
        rtapi_print_msg(RTAPI_MSG_ERR,
            "SAMPLER: ERROR: channel %d: could not export pins/function\n", n);
    }
    return retval;
}

/* Destroys the streams created so far and removes the component. */
static void cleanup(void)
{
    int n;
    for (n = 0; n < MAX_SAMPLERS; n++) {
        if (stream_ok[n]) {
            hal_stream_destroy(&streams[n]);
            stream_ok[n] = 0;
        }
    }
    hal_exit(comp_id);
}

/* Counts the channels given by cfg=, checking every cfg string. */
static int count_channels(void)
{
    int n;
    for (n = 0; n < MAX_SAMPLERS && cfg[n] != NULL && cfg[n][0] != '\0'; n++) {
        if (stream_fields_check_cfg(cfg[n]) < 0) {
            return -EINVAL;
        }
    }
    return n;
}

/* Module entry: parses cfg/depth and creates every channel. */
int rtapi_app_main(void)
{
    int n, retval;

    num_chans = count_channels();
    if (num_chans < 0) {
        return num_chans;
    }
    if (num_chans == 0) {
        rtapi_print_msg(RTAPI_MSG_ERR, "SAMPLER: ERROR: no channels specified\n");
        return -EINVAL;
    }
    comp_id = hal_init("sampler");
    if (comp_id < 0) {
        rtapi_print_msg(RTAPI_MSG_ERR, "SAMPLER: ERROR: hal_init() failed\n");
        return comp_id;
    }
    for (n = 0; n < num_chans; n++) {
        retval = init_channel(n);
        if (retval < 0) {
            cleanup();
            return retval;
        }
    }
    hal_ready(comp_id);
    return 0;
}

/* Module exit: destroys the streams and the component. */
void rtapi_app_exit(void)
{
    cleanup();
}
