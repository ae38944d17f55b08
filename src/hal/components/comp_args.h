/* comp_args.h: set-up shared by the hand-written configurable modules (typed pins, config specs). */
#ifndef COMP_ARGS_H
#define COMP_ARGS_H

#include "hal.h"

/* One pin value of any of the four type letters b f s u. */
typedef union {
    hal_bit_t b;
    hal_float_t f;
    hal_s32_t s;
    hal_u32_t u;
} comp_value_t;

/* Select inputs and sizes shared by the generic mux and demux: sel-int plus sel-bit-NN. */
typedef struct {
    hal_bit_t **sel_bit;
    hal_u32_t *sel_int;
    char in_type, out_type;
    int size, nsel;
} comp_select_t;

/* How a num_chan=/names= module counts and names its channels. */
typedef struct {
    const char *who;    /* message prefix, e.g. "ENCODER" */
    const char *prefix; /* instance prefix without names=, e.g. "encoder" gives encoder.0 */
    int max_chan;       /* capacity of the names= array and largest num_chan */
    int default_chan;   /* channels when neither argument is given (or num_chan=0) */
} comp_chan_spec_t;

/* One pin of a table-driven module: name suffix, type, direction, where its pointer lives
 * (offset in the instance struct) and the value it starts with. */
typedef struct {
    const char *suffix;
    hal_type_t type;
    hal_pin_dir_t dir;
    size_t offset;
    double start;
} comp_pin_def_t;

/* Creates the pins and funct of instance i; returns 0 or a negative errno. */
typedef int (*comp_make_fn)(int comp_id, int i);
/* Creates the pins and funct of instance i named prefix; returns 0 or a negative errno. */
typedef int (*comp_named_make_fn)(int comp_id, int i, const char *prefix);

/* Value of type letter t as a double. */
static inline double comp_value_read(const comp_value_t *v, char t)
{
    switch (t) {
    case 'b': return v->b ? 1.0 : 0.0;
    case 'f': return v->f;
    case 's': return v->s;
    default: return v->u;
    }
}

/* x truncated to a 64-bit integer: NaN gives 0, beyond the range saturates (no undefined cast). */
static inline long long comp_trunc_ll(double x)
{
    if (x != x) return 0;
    if (x >= 9223372036854775807.0) return 9223372036854775807LL;
    if (x <= -9223372036854775807.0) return -9223372036854775807LL - 1;
    return (long long)x;
}

/* Store a double into a value of type letter t: s32 saturates, u32 wraps like a C cast. */
static inline void comp_value_write(comp_value_t *v, char t, double x)
{
    switch (t) {
    case 'b': v->b = x != 0.0; break;
    case 'f': v->f = x; break;
    case 's': {
        long long n = comp_trunc_ll(x);
        v->s = n > 2147483647LL ? 2147483647 : n < -2147483648LL ? (-2147483647 - 1) : (hal_s32_t)n;
        break;
    }
    default: v->u = (hal_u32_t)comp_trunc_ll(x); break;
    }
}

/* Float to an integer range: NaN gives 0, outside [lo, hi] clamps, inside truncates toward zero. */
static inline double comp_float_to_range(double x, double lo, double hi)
{
    if (x != x) return 0.0;
    if (x < lo) return lo;
    if (x > hi) return hi;
    return x < 0 ? -__builtin_floor(-x) : __builtin_floor(x);
}

/* Copy src (type letter from) into dst (type letter to) with mux_generic's conversions. */
static inline void comp_value_convert(comp_value_t *dst, char to, const comp_value_t *src, char from)
{
    if (from == to) {
        *dst = *src;
        return;
    }
    switch (from) {
    case 'b':
        if (to == 'f') dst->f = src->b ? 1.0 : 0.0;
        else if (to == 's') dst->s = src->b ? 1 : 0;
        else dst->u = src->b ? 1 : 0;
        return;
    case 'f':
        if (to == 'b') dst->b = src->f > 2e-7 || src->f < -2e-7;
        else if (to == 's') dst->s = (hal_s32_t)comp_float_to_range(src->f, -2147483648.0, 2147483647.0);
        else dst->u = (hal_u32_t)comp_float_to_range(src->f, 0.0, 4294967295.0);
        return;
    case 's':
        if (to == 'b') dst->b = src->s != 0;
        else if (to == 'f') dst->f = src->s;
        else dst->u = src->s < 0 ? 0 : (hal_u32_t)src->s;
        return;
    default:
        if (to == 'b') dst->b = src->u != 0;
        else if (to == 'f') dst->f = src->u;
        else dst->s = src->u > 2147483647u ? 2147483647 : (hal_s32_t)src->u;
        return;
    }
}

/* Debounce of a selection (mux_generic, demux_generic): microseconds a new one has waited and
   the one in effect. */
typedef struct {
    hal_u32_t elapsed;
    hal_u32_t selected;
} comp_debounce_t;

/* True when sel takes effect this call: unchanged, or waited debounce_us (counted in period
   steps); a zero selection with suppress set changes nothing. */
static inline int comp_select_settle(comp_debounce_t *d, unsigned sel, int suppress,
                                     hal_u32_t debounce_us, long period)
{
    if (suppress && sel == 0)
        return 0;
    if (sel != d->selected && d->elapsed < debounce_us) {
        d->elapsed += (hal_u32_t)(period / 1000);
        return 0;
    }
    d->selected = sel;
    d->elapsed = 0;
    return 1;
}

/* Selected index: sel-int plus the weighted sel-bit pins. */
static inline unsigned comp_select_read(const comp_select_t *s)
{
    unsigned sel = *s->sel_int;
    for (int i = 0; i < s->nsel; i++)
        if (*s->sel_bit[i])
            sel += 1u << i;
    return sel;
}

const char *comp_type_word(char c);
int comp_sel_bits(int size);
long comp_spec_parse(const char *who, const char *spec, long max_size, char types[2]);
int comp_select_init(comp_select_t *s, const char *who, const char *spec, long max_size);
int comp_select_pins(comp_select_t *s, int comp_id, const char *prefix);
int comp_typed_pin(int comp_id, char t, hal_pin_dir_t dir, void **ptr, const char *name);
int comp_count_args(char *const args[], int max);
int comp_last_arg(char *const args[], int max);
int comp_name_check(const char *who, int index, const char *name);
int comp_names_count(const char *who, char *const names[], int max);
int comp_chan_count(const comp_chan_spec_t *spec, int num_chan, char *const names[]);
void comp_chan_name(const comp_chan_spec_t *spec, char *const names[], int i, char *buf, size_t len);
int comp_setup(const char *name, int count, comp_make_fn make);
int comp_pin_table(int comp_id, void *inst, const comp_pin_def_t *defs, int n, const char *prefix);
int comp_make_named(int comp_id, const char *prefix_base, int count, const char *names,
                    int default_count, comp_named_make_fn make);
int comp_setup_named(const char *comp, const char *prefix_base, int count, const char *names,
                     int default_count, comp_named_make_fn make);
void comp_teardown(void);

#endif
