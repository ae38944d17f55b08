/* demux_generic.c: demultiplexers with configurable size and in/out types (config="bf8,us4"). */
#include "rtapi.h"
#include "rtapi_app.h"
#include "rtapi_string.h"
#include "rtapi_errno.h"
#include "hal.h"

MODULE_LICENSE("GPL");
MODULE_AUTHOR("OpenEMC");
MODULE_DESCRIPTION("Generic demultiplexer: config=TTN,... (type letters b f s u, size N)");

#define DEMUX_MAX 100
#define DEMUX_MAX_SIZE 1024

static char *config[DEMUX_MAX];
RTAPI_MP_ARRAY_STRING(config, DEMUX_MAX, "demux specs: in type, out type, size (e.g. bf8,us4)");

/* One pin value of any of the four supported types. */
typedef union {
    hal_bit_t b;
    hal_float_t f;
    hal_s32_t s;
    hal_u32_t u;
} demux_value_t;

/* State of one demultiplexer. */
typedef struct {
    hal_bit_t **sel_bit;
    hal_u32_t *sel_int;
    demux_value_t *in;
    demux_value_t **out;
    char in_type, out_type;
    int size, nsel;
} demux_t;

static int comp_id;

/* HAL type word of a config letter, or NULL if the letter is invalid. */
static const char *demux_type_word(char c)
{
    switch (c) {
    case 'b': case 'B': return "bit";
    case 'f': case 'F': return "float";
    case 's': case 'S': return "s32";
    case 'u': case 'U': return "u32";
    default: return NULL;
    }
}

/* Value of type t as a double. */
static double demux_read(const demux_value_t *v, char t)
{
    switch (t) {
    case 'b': return v->b ? 1.0 : 0.0;
    case 'f': return v->f;
    case 's': return v->s;
    default: return v->u;
    }
}

/* Store a double into a value of type t (C conversion). */
static void demux_write(demux_value_t *v, char t, double x)
{
    switch (t) {
    case 'b': v->b = x != 0.0; break;
    case 'f': v->f = x; break;
    case 's': v->s = (hal_s32_t)(long long)x; break;
    default: v->u = (hal_u32_t)(long long)x; break;
    }
}

/* Number of select-bit pins: log2(size>>1)+1 when size>>1 is a power of two, else 0. */
static int demux_sel_bits(int size)
{
    int half = size >> 1, n = 1;
    if (half < 1 || (half & (half - 1)))
        return 0;
    for (; half > 1; half >>= 1)
        n++;
    return n;
}

/* Funct of one demultiplexer: the selected output follows the input, the others are 0. */
static void demux_funct(void *arg, long period)
{
    demux_t *m = arg;
    unsigned sel = *m->sel_int;
    double x = demux_read(m->in, m->in_type);
    (void)period;
    for (int i = 0; i < m->nsel; i++)
        if (*m->sel_bit[i])
            sel += 1u << i;
    for (int i = 0; i < m->size; i++)
        demux_write(m->out[i], m->out_type, (unsigned)i == sel ? x : 0.0);
}

/* Create a typed pin through the generic API. */
static int demux_pin(char t, hal_pin_dir_t dir, void **ptr, const char *name)
{
    static const hal_type_t types[] = { ['b'] = HAL_BIT, ['f'] = HAL_FLOAT, ['s'] = HAL_S32,
                                        ['u'] = HAL_U32 };
    return hal_pin_new(name, types[(unsigned char)t], dir, ptr, comp_id);
}

/* Create the select pins, the input pin and the funct of demux n. */
static int demux_control(demux_t *m, int n)
{
    char name[HAL_NAME_LEN + 1];
    int r = 0;
    for (int i = 0; i < m->nsel && r == 0; i++)
        r = hal_pin_bit_newf(HAL_IN, &m->sel_bit[i], comp_id, "demux-gen.%02d.sel-bit-%02d", n, i);
    if (r == 0) r = hal_pin_u32_newf(HAL_IN, &m->sel_int, comp_id, "demux-gen.%02d.sel-int", n);
    if (r == 0) {
        rtapi_snprintf(name, sizeof(name), "demux-gen.%02d.in-%s", n, demux_type_word(m->in_type));
        r = demux_pin(m->in_type, HAL_IN, (void **)&m->in, name);
    }
    if (r == 0) {
        rtapi_snprintf(name, sizeof(name), "demux-gen.%02d", n);
        r = hal_export_funct(name, demux_funct, m, 1, 0, comp_id);
    }
    return r;
}

/* Decimal size after the two type letters, or -1 when malformed. */
static long demux_size(const char *spec)
{
    long v = 0;
    const char *p = spec + 2;
    if (!*p) return -1;
    for (; *p; p++) {
        if (*p < '0' || *p > '9' || v > DEMUX_MAX_SIZE) return -1;
        v = v * 10 + (*p - '0');
    }
    return v;
}

/* Create demux n from its config text. */
static int demux_make(const char *spec, int n)
{
    char name[HAL_NAME_LEN + 1];
    long size = spec[0] && spec[1] ? demux_size(spec) : -1;
    demux_t *m;
    int r;
    if (!demux_type_word(spec[0]) || !demux_type_word(spec[1]) || size < 1 ||
        size > DEMUX_MAX_SIZE) {
        rtapi_print_msg(RTAPI_MSG_ERR, "DEMUX_GENERIC: ERROR: bad config '%s' (want two of b f s u "
                        "and a size 1..%d)\n", spec, DEMUX_MAX_SIZE);
        return -EINVAL;
    }
    m = hal_malloc(sizeof(*m));
    if (!m) return -ENOMEM;
    memset(m, 0, sizeof(*m));
    m->in_type = spec[0] | 0x20;
    m->out_type = spec[1] | 0x20;
    m->size = (int)size;
    m->nsel = demux_sel_bits(m->size);
    m->sel_bit = hal_malloc(sizeof(*m->sel_bit) * (m->nsel ? m->nsel : 1));
    m->out = hal_malloc(sizeof(*m->out) * m->size);
    if (!m->sel_bit || !m->out) return -ENOMEM;
    r = demux_control(m, n);
    for (int i = 0; i < m->size && r == 0; i++) {
        rtapi_snprintf(name, sizeof(name), "demux-gen.%02d.out-%s-%02d", n,
                       demux_type_word(m->out_type), i);
        r = demux_pin(m->out_type, HAL_OUT, (void **)&m->out[i], name);
    }
    return r;
}

/* Create every configured demultiplexer. */
int rtapi_app_main(void)
{
    int n = 0, r = 0;
    while (n < DEMUX_MAX && config[n] && config[n][0]) n++;
    if (n == 0) {
        rtapi_print_msg(RTAPI_MSG_ERR,
                        "DEMUX_GENERIC: ERROR: no config given (e.g. config=\"bf8,us4\")\n");
        return -EINVAL;
    }
    comp_id = hal_init("demux_generic");
    if (comp_id < 0) return comp_id;
    for (int i = 0; i < n && r == 0; i++)
        r = demux_make(config[i], i);
    if (r) {
        hal_exit(comp_id);
        return r;
    }
    hal_ready(comp_id);
    return 0;
}

/* Remove the component. */
void rtapi_app_exit(void)
{
    hal_exit(comp_id);
}
