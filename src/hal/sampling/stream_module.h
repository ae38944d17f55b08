/* stream_module.h: channel set-up shared by the sampler and streamer realtime modules. */
#ifndef STREAM_MODULE_H
#define STREAM_MODULE_H

#include <stddef.h>
#include "hal.h"
#include "stream_fields.h"

#define STREAM_MODULE_MAX_CHANS 8

/* One sampler/streamer module: its description and its per-channel state. */
typedef struct {
    const char *name;            /* component name and pin prefix, e.g. "sampler" */
    const char *tag;             /* upper-case name used in error messages */
    int key_base;                /* stream key of channel 0 */
    hal_pin_dir_t field_dir;     /* direction of the `.pin.M` field pins */
    size_t chan_size;            /* bytes of one channel struct (hal_malloc'ed) */
    size_t fields_offset;        /* offset of the stream_fields_t in the channel struct */
    int (*new_status_pins)(void *chan, const char *prefix, int comp_id);
    void (*funct)(void *arg, long period);
    char **cfg;                  /* cfg= module parameter array */
    int *depth;                  /* depth= module parameter array */
    int comp_id;
    hal_stream_t streams[STREAM_MODULE_MAX_CHANS];
    int stream_ok[STREAM_MODULE_MAX_CHANS];
    void *chans[STREAM_MODULE_MAX_CHANS];
} stream_module_t;

/* Checks cfg/depth, creates the component and every channel; negative errno on failure. */
int stream_module_init(stream_module_t *mod);

/* Destroys the streams created so far and removes the component. */
void stream_module_exit(stream_module_t *mod);

#endif
