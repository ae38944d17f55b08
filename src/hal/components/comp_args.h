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

/* Creates the pins and funct of instance i; returns 0 or a negative errno. */
typedef int (*comp_make_fn)(int comp_id, int i);

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

/* Store a double into a value of type letter t (C conversion). */
static inline void comp_value_write(comp_value_t *v, char t, double x)
{
    switch (t) {
    case 'b': v->b = x != 0.0; break;
    case 'f': v->f = x; break;
    case 's': v->s = (hal_s32_t)(long long)x; break;
    default: v->u = (hal_u32_t)(long long)x; break;
    }
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
long comp_spec_size(const char *spec, long max_size);
long comp_spec_parse(const char *who, const char *spec, long max_size, char types[2]);
int comp_select_init(comp_select_t *s, const char *who, const char *spec, long max_size);
int comp_select_pins(comp_select_t *s, int comp_id, const char *prefix);
int comp_typed_pin(int comp_id, char t, hal_pin_dir_t dir, void **ptr, const char *name);
int comp_count_args(char *const args[], int max);
int comp_setup(const char *name, int count, comp_make_fn make);
void comp_teardown(void);

#endif
