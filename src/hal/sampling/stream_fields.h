/* stream_fields.h: typed HAL pins that mirror the fields of a sampler/streamer stream record. */
#ifndef STREAM_FIELDS_H
#define STREAM_FIELDS_H

#include "hal.h"

#define STREAM_FIELDS_MAX 21

/* Pointer to one pin's value, by HAL type. */
typedef union {
    void *any;
    hal_bit_t *b;
    hal_float_t *f;
    hal_s32_t *s;
    hal_u32_t *u;
    hal_s64_t *l;
    hal_u64_t *k;
} stream_field_ptr_t;

/* The pins of one channel; must live in HAL memory (hal_malloc). */
typedef struct {
    int count;
    hal_type_t types[STREAM_FIELDS_MAX];
    stream_field_ptr_t pins[STREAM_FIELDS_MAX];
} stream_fields_t;

/* Checks a cfg string; prints the stream error and returns -EINVAL when bad. */
int stream_fields_check_cfg(const char *cfg);

/* Copies cfg into out (lower case, at most STREAM_FIELDS_MAX letters + NUL). */
void stream_fields_normalize(const char *cfg, char *out);

/* Creates pins `<prefix>.pin.M` for every letter of a checked cfg string. */
int stream_fields_new_pins(stream_fields_t *fields, const char *cfg,
                           const char *prefix, hal_pin_dir_t dir, int comp_id);

/* Fills a record from the current pin values. */
void stream_fields_to_record(const stream_fields_t *fields, union hal_stream_data *rec);

/* Writes a record's values to the pins. */
void stream_fields_from_record(stream_fields_t *fields, const union hal_stream_data *rec);

#endif
