/* mux_generic.c: multiplexers with configurable size and in/out types (config="bb8,fu12"). */
#include "rtapi.h"
#include "rtapi_app.h"
#include "rtapi_string.h"
#include "rtapi_errno.h"
#include "hal.h"

MODULE_LICENSE("GPL");
MODULE_AUTHOR("OpenEMC");
MODULE_DESCRIPTION("Generic multiplexer: config=TTN,... with in/out type letters b f s u and size N");

#define MUXG_MAX_MUX 100
#define MUXG_MAX_SIZE 1024

static char *config[MUXG_MAX_MUX];
RTAPI_MP_ARRAY_STRING(config, MUXG_MAX_MUX, "mux specs: in type, out type, size (e.g. bb8,fu12)");

/* One value of any of the four supported types. */
typedef union {
    hal_bit_t b;
    hal_float_t f;
    hal_s32_t s;
    hal_u32_t u;
} muxg_value_t;

/* State of one multiplexer. */
typedef struct {
    hal_bit_t **sel_bit;
    hal_u32_t *sel_int;
    hal_bit_t *suppress;
    hal_u32_t *debounce_us;
    muxg_value_t **in;
    muxg_value_t *out;
    hal_u32_t elapsed;
    hal_u32_t selected;
    char in_type, out_type;
    int size, nsel;
    unsigned pending;
    long long stable_ns;
} muxg_t;

static int comp_id;

/* HAL type word of a config letter, or NULL if the letter is invalid. */
static const char *muxg_type_word(char c)
{
    switch (c) {
    case 'b': case 'B': return "bit";
    case 'f': case 'F': return "float";
    case 's': case 'S': return "s32";
    case 'u': case 'U': return "u32";
    default: return NULL;
    }
}

/* Read a value of type t as a double. */
static double muxg_read(const muxg_value_t *v, char t)
{
    switch (t) {
    case 'b': return v->b ? 1.0 : 0.0;
    case 'f': return v->f;
    case 's': return v->s;
    default: return v->u;
    }
}

/* Store a double into a value of type t (C conversion). */
static void muxg_write(muxg_value_t *v, char t, double x)
{
    switch (t) {
    case 'b': v->b = x != 0.0; break;
    case 'f': v->f = x; break;
    case 's': v->s = (hal_s32_t)(long long)x; break;
    default: v->u = (hal_u32_t)(long long)x; break;
    }
}

/* Number of select-bit pins: log2(size>>1)+1 when size>>1 is a power of two, else 0. */
static int muxg_sel_bits(int size)
{
    int half = size >> 1, n = 1;
    if (half < 1 || (half & (half - 1)))
        return 0;
    while (half > 1) {
        half >>= 1;
        n++;
    }
    return n;
}

/* Funct of one multiplexer: pick the (debounced) selection and copy it to out. */
static void muxg_funct(void *arg, long period)
{
    muxg_t *m = arg;
    unsigned sel = *m->sel_int;
    for (int i = 0; i < m->nsel; i++)
        if (*m->sel_bit[i])
            sel += 1u << i;
    if (sel != m->pending) {
        m->pending = sel;
        m->stable_ns = 0;
    } else {
        m->stable_ns += period;
    }
    m->elapsed = (hal_u32_t)(m->stable_ns / 1000);
    if (m->stable_ns / 1000 < (long long)*m->debounce_us)
        return;
    if ((int)sel >= m->size || (sel == 0 && *m->suppress))
        return;
    m->selected = sel;
    muxg_write(m->out, m->out_type, muxg_read(m->in[sel], m->in_type));
}

/* Create a typed pin through the generic API. */
static int muxg_pin(char t, hal_pin_dir_t dir, void **ptr, const char *name)
{
    static const hal_type_t types[] = { ['b'] = HAL_BIT, ['f'] = HAL_FLOAT, ['s'] = HAL_S32,
                                        ['u'] = HAL_U32 };
    return hal_pin_new(name, types[(unsigned char)t], dir, ptr, comp_id);
}

/* Create the select and control pins and params of mux n. */
static int muxg_control(muxg_t *m, int n)
{
    char name[HAL_NAME_LEN + 1];
    int r = 0;
    for (int i = 0; i < m->nsel && r == 0; i++)
        r = hal_pin_bit_newf(HAL_IN, &m->sel_bit[i], comp_id, "mux-gen.%02d.sel-bit-%02d", n, i);
    if (r == 0) r = hal_pin_u32_newf(HAL_IN, &m->sel_int, comp_id, "mux-gen.%02d.sel-int", n);
    if (r == 0) r = hal_pin_bit_newf(HAL_IN, &m->suppress, comp_id, "mux-gen.%02d.suppress-no-input", n);
    if (r == 0) r = hal_pin_u32_newf(HAL_IN, &m->debounce_us, comp_id, "mux-gen.%02d.debounce-us", n);
    if (r == 0) r = hal_param_u32_newf(HAL_RO, &m->elapsed, comp_id, "mux-gen.%02d.elapsed", n);
    if (r == 0) r = hal_param_u32_newf(HAL_RO, &m->selected, comp_id, "mux-gen.%02d.selected", n);
    if (r == 0) {
        rtapi_snprintf(name, sizeof(name), "mux-gen.%02d", n);
        r = hal_export_funct(name, muxg_funct, m, 1, 0, comp_id);
    }
    return r;
}

/* Decimal size after the two type letters, or -1 when malformed. */
static long muxg_size(const char *spec)
{
    long v = 0;
    const char *p = spec + 2;
    if (!*p) return -1;
    for (; *p; p++) {
        if (*p < '0' || *p > '9' || v > MUXG_MAX_SIZE) return -1;
        v = v * 10 + (*p - '0');
    }
    return v;
}

/* Create mux n from its config text. */
static int muxg_make(const char *spec, int n)
{
    char name[HAL_NAME_LEN + 1];
    long size = spec[0] && spec[1] ? muxg_size(spec) : -1;
    if (!muxg_type_word(spec[0]) || !muxg_type_word(spec[1]) || size < 1 || size > MUXG_MAX_SIZE) {
        rtapi_print_msg(RTAPI_MSG_ERR, "MUX_GENERIC: ERROR: bad config '%s' (want two of b f s u "
                        "and a size 1..%d)\n", spec, MUXG_MAX_SIZE);
        return -EINVAL;
    }
    muxg_t *m = hal_malloc(sizeof(*m));
    if (!m) return -ENOMEM;
    memset(m, 0, sizeof(*m));
    m->in_type = spec[0] | 0x20;
    m->out_type = spec[1] | 0x20;
    m->size = (int)size;
    m->nsel = muxg_sel_bits(m->size);
    m->sel_bit = hal_malloc(sizeof(*m->sel_bit) * (m->nsel ? m->nsel : 1));
    m->in = hal_malloc(sizeof(*m->in) * m->size);
    if (!m->sel_bit || !m->in) return -ENOMEM;
    int r = muxg_control(m, n);
    for (int i = 0; i < m->size && r == 0; i++) {
        rtapi_snprintf(name, sizeof(name), "mux-gen.%02d.in-%s-%02d", n, muxg_type_word(m->in_type), i);
        r = muxg_pin(m->in_type, HAL_IN, (void **)&m->in[i], name);
    }
    if (r == 0) {
        rtapi_snprintf(name, sizeof(name), "mux-gen.%02d.out-%s", n, muxg_type_word(m->out_type));
        r = muxg_pin(m->out_type, HAL_OUT, (void **)&m->out, name);
    }
    return r;
}

/* Create every configured multiplexer. */
int rtapi_app_main(void)
{
    int n = 0, r = 0;
    while (n < MUXG_MAX_MUX && config[n] && config[n][0]) n++;
    if (n == 0) {
        rtapi_print_msg(RTAPI_MSG_ERR, "MUX_GENERIC: ERROR: no config given (e.g. config=\"bb8,fu12\")\n");
        return -EINVAL;
    }
    comp_id = hal_init("mux_generic");
    if (comp_id < 0) return comp_id;
    for (int i = 0; i < n && r == 0; i++)
        r = muxg_make(config[i], i);
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
