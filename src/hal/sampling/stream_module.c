/* stream_module.c: component, stream and pin set-up shared by the sampler and streamer modules. */
#include "rtapi.h"
#include "hal.h"
#include "stream_module.h"

/* Creates channel n's stream; the stream is destroyed by stream_module_exit. */
static int create_stream(stream_module_t *mod, int n)
{
    char types[STREAM_FIELDS_MAX + 1];
    int retval;

    if (mod->depth[n] <= 0) {
        rtapi_print_msg(RTAPI_MSG_ERR,
            "%s: ERROR: channel %d: depth must be greater than 0\n", mod->tag, n);
        return -EINVAL;
    }
    stream_fields_normalize(mod->cfg[n], types);
    retval = hal_stream_create(&mod->streams[n], mod->comp_id, mod->key_base + n,
                               mod->depth[n], types);
    if (retval < 0) {
        rtapi_print_msg(RTAPI_MSG_ERR,
            "%s: ERROR: channel %d: could not create stream\n", mod->tag, n);
        return retval;
    }
    mod->stream_ok[n] = 1;
    return 0;
}

/* Sets up channel n: stream, channel struct, pins and function. */
static int init_channel(stream_module_t *mod, int n)
{
    char prefix[HAL_NAME_LEN + 1];
    stream_fields_t *fields;
    int retval = create_stream(mod, n);

    if (retval < 0) {
        return retval;
    }
    mod->chans[n] = hal_malloc(mod->chan_size);
    if (mod->chans[n] == NULL) {
        rtapi_print_msg(RTAPI_MSG_ERR, "%s: ERROR: hal_malloc() failed\n", mod->tag);
        return -ENOMEM;
    }
    fields = (stream_fields_t *)((char *)mod->chans[n] + mod->fields_offset);
    rtapi_snprintf(prefix, sizeof(prefix), "%s.%d", mod->name, n);
    retval = stream_fields_new_pins(fields, mod->cfg[n], prefix, mod->field_dir, mod->comp_id);
    if (retval == 0) retval = mod->new_status_pins(mod->chans[n], prefix, mod->comp_id);
    if (retval == 0) {
        retval = hal_export_funct(prefix, mod->funct, (void *)(long)n, 1, 0, mod->comp_id);
    }
    if (retval < 0) {
        rtapi_print_msg(RTAPI_MSG_ERR,
            "%s: ERROR: channel %d: could not export pins/function\n", mod->tag, n);
    }
    return retval;
}

/* Counts the channels given by cfg=, checking every cfg string. */
static int count_channels(const stream_module_t *mod)
{
    int n;
    for (n = 0; n < STREAM_MODULE_MAX_CHANS && mod->cfg[n] != NULL && mod->cfg[n][0] != '\0';
         n++) {
        if (stream_fields_check_cfg(mod->cfg[n]) < 0) {
            return -EINVAL;
        }
    }
    return n;
}

/* Checks cfg/depth, creates the component and every channel, then marks it ready. */
int stream_module_init(stream_module_t *mod)
{
    int n, retval, num_chans = count_channels(mod);

    if (num_chans < 0) {
        return num_chans;
    }
    if (num_chans == 0) {
        rtapi_print_msg(RTAPI_MSG_ERR, "%s: ERROR: no channels specified\n", mod->tag);
        return -EINVAL;
    }
    mod->comp_id = hal_init(mod->name);
    if (mod->comp_id < 0) {
        rtapi_print_msg(RTAPI_MSG_ERR, "%s: ERROR: hal_init() failed\n", mod->tag);
        return mod->comp_id;
    }
    for (n = 0; n < num_chans; n++) {
        retval = init_channel(mod, n);
        if (retval < 0) {
            stream_module_exit(mod);
            return retval;
        }
    }
    hal_ready(mod->comp_id);
    return 0;
}

/* Destroys the streams created so far and removes the component. */
void stream_module_exit(stream_module_t *mod)
{
    int n;
    for (n = 0; n < STREAM_MODULE_MAX_CHANS; n++) {
        if (mod->stream_ok[n]) {
            hal_stream_destroy(&mod->streams[n]);
            mod->stream_ok[n] = 0;
        }
    }
    hal_exit(mod->comp_id);
}
