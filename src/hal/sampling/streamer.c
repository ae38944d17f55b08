/* streamer.c: realtime module that drives pins from streamer streams filled by halstreamer. */
#include "rtapi.h"
#include "rtapi_app.h"
#include "hal.h"
#include "stream_module.h"

MODULE_AUTHOR("OpenEMC");
MODULE_DESCRIPTION("Drives HAL pins from a stream written by halstreamer");
MODULE_LICENSE("GPL");

#define MAX_STREAMERS STREAM_MODULE_MAX_CHANS
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

static void stream_out(void *arg, long period);
static int new_status_pins(void *chan, const char *prefix, int comp_id);

/* The module's description and channel state, shared with stream_module.c. */
static stream_module_t mod = {
    .name = "streamer",
    .tag = "STREAMER",
    .key_base = STREAMER_KEY_BASE,
    .field_dir = HAL_OUT,
    .chan_size = sizeof(streamer_chan_t),
    .fields_offset = offsetof(streamer_chan_t, fields),
    .new_status_pins = new_status_pins,
    .funct = stream_out,
    .cfg = cfg,
    .depth = depth,
};

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
    streamer_chan_t *ch = mod.chans[n];
    union hal_stream_data rec[STREAM_FIELDS_MAX];
    int fill = hal_stream_depth(&mod.streams[n]);
    int pop;
    unsigned sampleno;

    (void)period;
    *ch->curr_depth = fill;
    *ch->empty = fill == 0;
    pop = clocked(ch);
    if (!*ch->enable || !pop) {
        return;
    }
    if (hal_stream_read(&mod.streams[n], rec, &sampleno) < 0) {
        (*ch->underruns)++;
        return;
    }
    stream_fields_from_record(&ch->fields, rec);
}

/* Creates the status pins `streamer.N.*` of one channel. */
static int new_status_pins(void *chan, const char *prefix, int comp_id)
{
    streamer_chan_t *ch = chan;
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
