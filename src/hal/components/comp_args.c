/* comp_args.c: set-up shared by the hand-written configurable modules (typed pins, config specs). */
#include "rtapi.h"
#include "rtapi_errno.h"
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

/* Decimal size after the two type letters of spec, or -1 when missing, malformed or too big. */
long comp_spec_size(const char *spec, long max_size)
{
    long v = 0;
    const char *p;
    if (!spec[0] || !spec[1] || !spec[2]) return -1;
    for (p = spec + 2; *p; p++) {
        if (*p < '0' || *p > '9' || v > max_size) return -1;
        v = v * 10 + (*p - '0');
    }
    return v;
}

/* Size of a "TTN" spec, its type letters in lower case in types[]; logs and returns -EINVAL if bad. */
long comp_spec_parse(const char *who, const char *spec, long max_size, char types[2])
{
    long size = comp_spec_size(spec, max_size);
    if (!comp_type_word(spec[0]) || !comp_type_word(spec[1]) || size < 1 || size > max_size) {
        rtapi_print_msg(RTAPI_MSG_ERR, "%s: ERROR: bad config '%s' (want two of b f s u "
                        "and a size 1..%d)\n", who, spec, (int)max_size);
        return -EINVAL;
    }
    types[0] = spec[0] | 0x20;
    types[1] = spec[1] | 0x20;
    return size;
}

/* Fill s from a "TTN" spec and allocate its sel-bit pointers; logs bad specs. */
int comp_select_init(comp_select_t *s, const char *who, const char *spec, long max_size)
{
    char types[2];
    long size = comp_spec_parse(who, spec, max_size, types);
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

/* Number of leading non-empty strings in a string-array module argument. */
int comp_count_args(char *const args[], int max)
{
    int n = 0;
    while (n < max && args[n] && args[n][0])
        n++;
    return n;
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

/* Remove the component made by comp_setup. */
void comp_teardown(void)
{
    hal_exit(comp_args_id);
}
