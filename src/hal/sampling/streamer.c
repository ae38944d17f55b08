/* streamer.c: realtime module that drives pins from streamer streams filled by halstreamer. */
#include "rtapi.h"
#include "rtapi_app.h"
#include "hal.h"
#include "stream_fields.h"

MODULE_AUTHOR("OpenEMC");
MODULE_DESCRIPTION("Drives HAL pins from a stream written by halstreamer");
MODULE_LICENSE("GPL");

#define MAX_STREAMERS 8
#define STREAMER_KEY_BASE 0x48535430

static char *cfg[MAX_STREAMERS];
RTAPI_MP_ARRAY_STRING(cfg, MAX_STREAMERS, "field types of each channel");
static int depth[MAX_STREAMERS];
RTAPI_MP_ARRAY_INT(depth, MAX_STREAMERS, "stream depth of each channel");

/* Clock modes of the clock-mode pin. */
enum { CLOCK_ALWAYS = 0, CLOCK_FALLING = 1, CLOCK_RISING = 2, CLOCK_BOTH = 3 };

/* Per-channel pins and state, in HAL memory. */
typedef struct {
    hal_bit_t *empty;
    hal_bit_t *enable;
    hal_s32_t *curr_depth;
    hal_s32_t *underruns;
    hal_bit_t *clock;
    hal_s32_t *clock_mode;
    int last_clock;
    stream_fields_t fields;
} streamer_chan_t;

static int comp_id;
static int num_chans;
static hal_stream_t streams[MAX_STREAMERS];
static int stream_ok[MAX_STREAMERS];
static streamer_chan_t *chans[MAX_STREAMERS];

/* Returns non-zero when this call should pop a record, per clock-mode. */
static int clocked(streamer_chan_t *ch)
{
    int now = *ch->clock ? 1 : 0;
    int prev = ch->last_clock;

    ch->last_clock = now;
    switch (*ch->clock_mode) {
    case CLOCK_FALLING: return prev && !now;
    case CLOCK_RISING: return !prev && now;
    case CLOCK_BOTH: return prev != now;
    default: return 1;
    }
}

/* Realtime function: report FIFO state, then pop one record when enabled and clocked. */
static void stream_out(void *arg, long period)
{
    int n = (int)(long)arg;
    streamer_chan_t *ch = chans[n];
    union hal_stream_data rec[STREAM_FIELDS_MAX];
    int fill = hal_stream_depth(&streams[n]);
    int pop;
    unsigned sampleno;

    (void)period;
    *ch->curr_depth = fill;
    *ch->empty = fill == 0;
    pop = clocked(ch);
    if (!*ch->enable || !pop) {
        return;
    }
    if (hal_stream_read(&streams[n], rec, &sampleno) < 0) {
        (*ch->underruns)++;
        return;
    }
    stream_fields_from_record(&ch->fields, rec);
}

/* Creates the status pins `streamer.N.*` of one channel. */
static int new_status_pins(streamer_chan_t *ch, const char *prefix)
{
    int r = hal_pin_bit_newf(HAL_OUT, &ch->empty, comp_id, "%s.empty", prefix);
    if (r == 0) r = hal_pin_bit_newf(HAL_IN, &ch->enable, comp_id, "%s.enable", prefix);
    if (r == 0) r = hal_pin_s32_newf(HAL_OUT, &ch->curr_depth, comp_id, "%s.curr-depth", prefix);
    if (r == 0) r = hal_pin_s32_newf(HAL_IO, &ch->underruns, comp_id, "%s.underruns", prefix);
    if (r == 0) r = hal_pin_bit_newf(HAL_IN, &ch->clock, comp_id, "%s.clock", prefix);
    if (r == 0) r = hal_pin_s32_newf(HAL_IN, &ch->clock_mode, comp_id, "%s.clock-mode", prefix);
    if (r == 0) {
        *ch->empty = 1;
        *ch->enable = 1;
        ch->last_clock = 0;
    }
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
            "STREAMER: ERROR: channel %d: depth must be greater than 0\n", n);
        return -EINVAL;
    }
    stream_fields_normalize(cfg[n], types);
    retval = hal_stream_create(&streams[n], comp_id, STREAMER_KEY_BASE + n, depth[n], types);
    if (retval < 0) {
        rtapi_print_msg(RTAPI_MSG_ERR,
            "STREAMER: ERROR: channel %d: could not create stream\n", n);
        return retval;
    }
    stream_ok[n] = 1;
    chans[n] = hal_malloc(sizeof(streamer_chan_t));
    if (chans[n] == NULL) {
        rtapi_print_msg(RTAPI_MSG_ERR, "STREAMER: ERROR: hal_malloc() failed\n");
        return -ENOMEM;
    }
    rtapi_snprintf(prefix, sizeof(prefix), "streamer.%d", n);
    retval = stream_fields_new_pins(&chans[n]->fields, cfg[n], prefix, HAL_OUT, comp_id);
    if (retval == 0) retval = new_status_pins(chans[n], prefix);
    if (retval == 0) retval = hal_export_funct(prefix, stream_out, (void *)(long)n, 1, 0, comp_id);
    if (retval < 0) {
        rtapi_print_msg(RTAPI_MSG_ERR,
            "STREAMER: ERROR: channel %d: could not export pins/function\n", n);
    }
    return retval;
}

/* Destroys the streams created so far and removes the component. */
static void cleanup(void)
{
    int n;
    for (n = 0; n < MAX_STREAMERS; n++) {
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
    for (n = 0; n < MAX_STREAMERS && cfg[n] != NULL && cfg[n][0] != '\0'; n++) {
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
        rtapi_print_msg(RTAPI_MSG_ERR, "STREAMER: ERROR: no channels specified\n");
        return -EINVAL;
    }
    comp_id = hal_init("streamer");
    if (comp_id < 0) {
        rtapi_print_msg(RTAPI_MSG_ERR, "STREAMER: ERROR: hal_init() failed\n");
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
