/* comp_args.c: set-up shared by the hand-written configurable modules (typed pins, config specs). */
#include "rtapi.h"
#include "rtapi_errno.h"
#include "rtapi_string.h"
#include "comp_args.h"

static int comp_args_id;

/* HAL type word of a config type letter, or NULL if the letter is invalid. */
const char *comp_type_word(char c)
{
    switch (c) {
    case 'b': case 'B': return "bit";
    case 'f': case 'F': return "float";
    case 's': case 'S': return "s32";
    case 'u': case 'U': return "u32";
    default: return NULL;
    }
}

/* Number of select-bit pins: log2(size>>1)+1 when size>>1 is a power of two, else 0. */
int comp_sel_bits(int size)
{
    int half = size >> 1, n = 1;
    if (half < 1 || (half & (half - 1)))
        return 0;
    for (; half > 1; half >>= 1)
        n++;
    return n;
}

/* Size and type letters of a config string: digits and up to two type letters in any order
 * ("bb8", "8bb", "b8f"); one letter means the same output type. Logs and returns -EINVAL if bad. */
long comp_spec_parse(const char *who, const char *spec, long max_size, char types[2])
{
    long size = 0;
    int ntypes = 0;
    for (const char *p = spec; *p; p++) {
        if (*p >= '0' && *p <= '9') {
            size = size * 10 + (*p - '0');
            if (size > max_size)
                size = max_size;
        } else if (comp_type_word(*p)) {
            if (ntypes == 2) {
                rtapi_print_msg(RTAPI_MSG_ERR, "%s: too many type specifiers in fmt string\n", who);
                return -EINVAL;
            }
            types[ntypes++] = *p | 0x20;
        } else {
            rtapi_print_msg(RTAPI_MSG_ERR, "%s: invalid character in fmt string\n", who);
            return -EINVAL;
        }
    }
    if (size == 0) {
        rtapi_print_msg(RTAPI_MSG_ERR, "%s: No entry count given\n", who);
        return -EINVAL;
    }
    if (size == 1) {
        rtapi_print_msg(RTAPI_MSG_ERR, "%s: A one-element %s makes no sense\n", who,
                        strstr(who, "demux") ? "demux" : "mux");
        return -EINVAL;
    }
    if (ntypes == 0) {
        rtapi_print_msg(RTAPI_MSG_ERR, "%s: No type specifiers in fmt string\n", who);
        return -EINVAL;
    }
    if (ntypes == 1)
        types[1] = types[0];
    return size;
}

/* Fill s from a "TTN" spec and allocate its sel-bit pointers; logs bad specs. */
int comp_select_init(comp_select_t *s, const char *who, const char *spec, long max_size)
{
    char types[2];
    long size = comp_spec_parse(who, spec ? spec : "", max_size, types);
    if (size < 0) return (int)size;
    s->in_type = types[0];
    s->out_type = types[1];
    s->size = (int)size;
    s->nsel = comp_sel_bits(s->size);
    s->sel_bit = hal_malloc(sizeof(*s->sel_bit) * (s->nsel ? s->nsel : 1));
    return s->sel_bit ? 0 : -ENOMEM;
}

/* Create the <prefix>.sel-bit-NN and <prefix>.sel-int input pins of s. */
int comp_select_pins(comp_select_t *s, int comp_id, const char *prefix)
{
    int r = 0;
    for (int i = 0; i < s->nsel && r == 0; i++)
        r = hal_pin_bit_newf(HAL_IN, &s->sel_bit[i], comp_id, "%s.sel-bit-%02d", prefix, i);
    if (r == 0) r = hal_pin_u32_newf(HAL_IN, &s->sel_int, comp_id, "%s.sel-int", prefix);
    return r;
}

/* Create a pin of type letter t (lower case) through the generic API. */
int comp_typed_pin(int comp_id, char t, hal_pin_dir_t dir, void **ptr, const char *name)
{
    static const hal_type_t types[] = { ['b'] = HAL_BIT, ['f'] = HAL_FLOAT, ['s'] = HAL_S32,
                                        ['u'] = HAL_U32 };
    return hal_pin_new(name, types[(unsigned char)t], dir, ptr, comp_id);
}

/* Creates the pins listed in defs as <prefix><suffix>, storing each pointer in inst at its offset
 * and the pin's start value; returns 0 or the first HAL error. */
int comp_pin_table(int comp_id, void *inst, const comp_pin_def_t *defs, int n, const char *prefix)
{
    char name[HAL_NAME_LEN + 1];
    for (int i = 0; i < n; i++) {
        void **ptr = (void **)((char *)inst + defs[i].offset);
        rtapi_snprintf(name, sizeof(name), "%s%s", prefix, defs[i].suffix);
        int r = hal_pin_new(name, defs[i].type, defs[i].dir, ptr, comp_id);
        if (r)
            return r;
        switch (defs[i].type) {
        case HAL_BIT: *(hal_bit_t *)*ptr = defs[i].start != 0; break;
        case HAL_FLOAT: *(hal_float_t *)*ptr = defs[i].start; break;
        case HAL_S32: *(hal_s32_t *)*ptr = (hal_s32_t)defs[i].start; break;
        case HAL_U32: *(hal_u32_t *)*ptr = (hal_u32_t)defs[i].start; break;
        default: break;
        }
    }
    return 0;
}

/* Number of leading non-empty strings in a string-array module argument. */
int comp_count_args(char *const args[], int max)
{
    int n = 0;
    while (n < max && args[n] && args[n][0])
        n++;
    return n;
}

/* One past the last non-empty string of a string-array module argument (empty ones before it count). */
int comp_last_arg(char *const args[], int max)
{
    int n = max;
    while (n > 0 && !(args[n - 1] && args[n - 1][0]))
        n--;
    return n;
}

/* Check one names= entry: not empty, no blanks or control characters; logs and returns -EINVAL. */
int comp_name_check(const char *who, int index, const char *name)
{
    if (!name || !name[0]) {
        rtapi_print_msg(RTAPI_MSG_ERR, "%s: ERROR: names[%d] is invalid (empty string)\n", who, index);
        return -EINVAL;
    }
    for (const char *p = name; *p; p++) {
        if ((unsigned char)*p <= ' ' || *p == 0x7f) {
            rtapi_print_msg(RTAPI_MSG_ERR, "%s: ERROR: names[%d] \"%s\" contains a blank or "
                            "control character\n", who, index, name);
            return -EINVAL;
        }
    }
    if (strlen(name) > HAL_NAME_LEN) {
        rtapi_print_msg(RTAPI_MSG_ERR, "%s: ERROR: names[%d] \"%s\" is too long (at most %d "
                        "characters)\n", who, index, name, HAL_NAME_LEN);
        return -EINVAL;
    }
    return 0;
}

/* Number of names= entries (an empty names= is none); an empty or bad entry gives -EINVAL. */
int comp_names_count(const char *who, char *const names[], int max)
{
    int n = max;
    while (n > 0 && !names[n - 1])
        n--;
    if (n == 1 && !names[0][0])
        return 0;
    for (int i = 0; i < n; i++)
        if (comp_name_check(who, i, names[i]) < 0)
            return -EINVAL;
    return n;
}

/* Channels of a num_chan=/names= module (num_chan 0 means not given); logs and returns -EINVAL. */
int comp_chan_count(const comp_chan_spec_t *spec, int num_chan, char *const names[])
{
    int n = comp_names_count(spec->who, names, spec->max_chan);
    if (n < 0)
        return n;
    if (num_chan && n) {
        rtapi_print_msg(RTAPI_MSG_ERR, "num_chan= and names= are mutually exclusive\n");
        return -EINVAL;
    }
    if (n)
        return n;
    if (num_chan == 0)
        return spec->default_chan;
    if (num_chan < 0 || num_chan > spec->max_chan) {
        rtapi_print_msg(RTAPI_MSG_ERR, "%s: ERROR: invalid number of channels: %d\n",
                        spec->who, num_chan);
        return -EINVAL;
    }
    return num_chan;
}

/* Prefix of channel i: its names= entry, else <prefix>.<i>. */
void comp_chan_name(const comp_chan_spec_t *spec, char *const names[], int i, char *buf, size_t len)
{
    if (names[0] && names[0][0])
        rtapi_snprintf(buf, len, "%s", names[i]);
    else
        rtapi_snprintf(buf, len, "%s.%d", spec->prefix, i);
}

/* hal_init the component, make instances 0..count-1, then hal_ready; exit HAL on failure. */
int comp_setup(const char *name, int count, comp_make_fn make)
{
    int r = 0;
    comp_args_id = hal_init(name);
    if (comp_args_id < 0) return comp_args_id;
    for (int i = 0; i < count && r == 0; i++)
        r = make(comp_args_id, i);
    if (r) {
        hal_exit(comp_args_id);
        return r;
    }
    hal_ready(comp_args_id);
    return 0;
}

/* Instances of a count=/names= module (halcompile's rules): each name, or count (default when 0)
 * prefixes <prefix_base>.<i>. Bad combinations and names are logged; returns 0 or -EINVAL. */
int comp_make_named(int comp_id, const char *prefix_base, int count, const char *names,
                    int default_count, comp_named_make_fn make)
{
    char buf[HAL_NAME_LEN + 1];
    int r = 0, i = 0;
    if (count && names && names[0]) {
        rtapi_print_msg(RTAPI_MSG_ERR, "%s: ERROR: count= and names= are mutually exclusive\n", prefix_base);
        return -EINVAL;
    }
    if (count < 0) {
        rtapi_print_msg(RTAPI_MSG_ERR, "%s: ERROR: count=%d: the count must not be negative\n", prefix_base,
                        count);
        return -EINVAL;
    }
    if (!names || !names[0]) {
        for (i = 0; i < (count ? count : default_count) && r == 0; i++) {
            rtapi_snprintf(buf, sizeof(buf), "%s.%d", prefix_base, i);
            r = make(comp_id, i, buf);
        }
        return r;
    }
    for (const char *p = names; r == 0; i++) {
        const char *end = strchr(p, ',');
        size_t len = end ? (size_t)(end - p) : strlen(p);
        if (len > HAL_NAME_LEN) {
            rtapi_print_msg(RTAPI_MSG_ERR, "%s: ERROR: names: \"%.*s\" too long\n", prefix_base, (int)len, p);
            return -EINVAL;
        }
        memcpy(buf, p, len);
        buf[len] = '\0';
        r = comp_name_check(prefix_base, i, buf);
        if (r == 0)
            r = make(comp_id, i, buf);
        if (!end)
            break;
        p = end + 1;
    }
    return r;
}

/* hal_init comp, make its count=/names= instances, then hal_ready; exit HAL on failure. */
int comp_setup_named(const char *comp, const char *prefix_base, int count, const char *names,
                     int default_count, comp_named_make_fn make)
{
    comp_args_id = hal_init(comp);
    if (comp_args_id < 0) return comp_args_id;
    int r = comp_make_named(comp_args_id, prefix_base, count, names, default_count, make);
    if (r) {
        hal_exit(comp_args_id);
        return r;
    }
    hal_ready(comp_args_id);
    return 0;
}

/* Remove the component made by comp_setup. */
void comp_teardown(void)
{
    hal_exit(comp_args_id);
}
