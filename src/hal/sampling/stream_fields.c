/* stream_fields.c: cfg parsing and pin<->record copying shared by sampler and streamer. */
#include "rtapi.h"
#include "hal.h"
#include "stream_fields.h"

/* Maps one cfg letter (any case) to a HAL type; 0 when unknown. */
static hal_type_t letter_type(char c)
{
    switch (c) {
    case 'f': case 'F': case 'r': case 'R': return HAL_FLOAT;
    case 'b': case 'B': return HAL_BIT;
    case 's': case 'S': return HAL_S32;
    case 'u': case 'U': return HAL_U32;
    case 'l': case 'L': return HAL_S64;
    case 'k': case 'K': return HAL_U64;
    default: return (hal_type_t)0;
    }
}

/* Validates letters and length of a cfg string, printing the stream errors. */
int stream_fields_check_cfg(const char *cfg)
{
    int n;
    for (n = 0; cfg[n] != '\0'; n++) {
        if (n >= STREAM_FIELDS_MAX) {
            rtapi_print_msg(RTAPI_MSG_ERR, "stream: ERROR: more than %d items\n",
                            STREAM_FIELDS_MAX);
            return -EINVAL;
        }
        if (letter_type(cfg[n]) == 0) {
            rtapi_print_msg(RTAPI_MSG_ERR,
                "stream: ERROR: unknown type '%c', must be R (F), B, U, S, L or K\n",
                cfg[n]);
            return -EINVAL;
        }
    }
    return 0;
}

/* Lower-cases a checked cfg string into out, mapping 'r' to 'f'. */
void stream_fields_normalize(const char *cfg, char *out)
{
    static const char letters[] = { 0, 'b', 'f', 's', 'u', 0, 'l', 'k' };
    int n;
    for (n = 0; cfg[n] != '\0' && n < STREAM_FIELDS_MAX; n++) {
        out[n] = letters[letter_type(cfg[n])];
    }
    out[n] = '\0';
}

/* Creates one pin per cfg letter, named `<prefix>.pin.<index>`. */
int stream_fields_new_pins(stream_fields_t *fields, const char *cfg,
                           const char *prefix, hal_pin_dir_t dir, int comp_id)
{
    char name[HAL_NAME_LEN + 1];
    int n, retval;

    fields->count = 0;
    for (n = 0; cfg[n] != '\0' && n < STREAM_FIELDS_MAX; n++) {
        fields->types[n] = letter_type(cfg[n]);
        rtapi_snprintf(name, sizeof(name), "%s.pin.%d", prefix, n);
        retval = hal_pin_new(name, fields->types[n], dir,
                             (void **)&fields->pins[n].any, comp_id);
        if (retval < 0) {
            return retval;
        }
        fields->count = n + 1;
    }
    return 0;
}

/* Copies every pin value into the matching record field. */
void stream_fields_to_record(const stream_fields_t *fields, union hal_stream_data *rec)
{
    int n;
    for (n = 0; n < fields->count; n++) {
        const stream_field_ptr_t p = fields->pins[n];
        switch (fields->types[n]) {
        case HAL_BIT: rec[n].b = *p.b; break;
        case HAL_FLOAT: rec[n].f = *p.f; break;
        case HAL_S32: rec[n].s = *p.s; break;
        case HAL_U32: rec[n].u = *p.u; break;
        case HAL_S64: rec[n].l = *p.l; break;
        case HAL_U64: rec[n].k = *p.k; break;
        default: break;
        }
    }
}

/* Copies every record field into the matching pin. */
void stream_fields_from_record(stream_fields_t *fields, const union hal_stream_data *rec)
{
    int n;
    for (n = 0; n < fields->count; n++) {
        stream_field_ptr_t p = fields->pins[n];
        switch (fields->types[n]) {
        case HAL_BIT: *p.b = rec[n].b; break;
        case HAL_FLOAT: *p.f = rec[n].f; break;
        case HAL_S32: *p.s = rec[n].s; break;
        case HAL_U32: *p.u = rec[n].u; break;
        case HAL_S64: *p.l = rec[n].l; break;
        case HAL_U64: *p.k = rec[n].k; break;
        default: break;
        }
    }
}
