/* mux_generic.c: multiplexers with configurable size and in/out types (config="bb8,fu12"). */
#include "rtapi.h"
#include "rtapi_app.h"
#include "rtapi_string.h"
#include "rtapi_errno.h"
#include "hal.h"
#include "comp_args.h"

MODULE_LICENSE("GPL");
MODULE_AUTHOR("OpenEMC");
MODULE_DESCRIPTION("Generic multiplexer: config=TTN,... with in/out type letters b f s u and size N");

#define MUXG_MAX_MUX 100
#define MUXG_MAX_SIZE 1024

static char *config[MUXG_MAX_MUX];
RTAPI_MP_ARRAY_STRING(config, MUXG_MAX_MUX, "mux specs: in type, out type, size (e.g. bb8,fu12)");

/* State of one multiplexer. */
typedef struct {
    comp_select_t sel;
    hal_bit_t *suppress;
    hal_u32_t *debounce_us;
    comp_value_t **in;
    comp_value_t *out;
    comp_debounce_t debounce;
} muxg_t;

/* Funct of one multiplexer: debounce the selection, then copy the chosen input to out. */
static void muxg_funct(void *arg, long period)
{
    muxg_t *m = arg;
    unsigned sel = comp_select_read(&m->sel);
    if (!comp_select_settle(&m->debounce, sel, *m->suppress, *m->debounce_us, period))
        return;
    if (sel >= (unsigned)m->sel.size)
        sel = m->sel.size - 1;
    comp_value_convert(m->out, m->sel.out_type, m->in[sel], m->sel.in_type);
}

/* Create the select and control pins and params of mux n. */
static int muxg_control(int comp_id, muxg_t *m, int n)
{
    char name[HAL_NAME_LEN + 1];
    int r;
    rtapi_snprintf(name, sizeof(name), "mux-gen.%02d", n);
    r = comp_select_pins(&m->sel, comp_id, name);
    if (r == 0) r = hal_pin_bit_newf(HAL_IN, &m->suppress, comp_id, "mux-gen.%02d.suppress-no-input", n);
    if (r == 0) r = hal_pin_u32_newf(HAL_IN, &m->debounce_us, comp_id, "mux-gen.%02d.debounce-us", n);
    if (r == 0) r = hal_param_u32_newf(HAL_RO, &m->debounce.elapsed, comp_id, "mux-gen.%02d.elapsed", n);
    if (r == 0) r = hal_param_u32_newf(HAL_RO, &m->debounce.selected, comp_id, "mux-gen.%02d.selected", n);
    if (r == 0) r = hal_export_funct(name, muxg_funct, m, 1, 0, comp_id);
    return r;
}

/* Create mux n from its config text. */
static int muxg_make(int comp_id, int n)
{
    char name[HAL_NAME_LEN + 1];
    muxg_t *m = hal_malloc(sizeof(*m));
    if (!m) return -ENOMEM;
    memset(m, 0, sizeof(*m));
    int r = comp_select_init(&m->sel, "mux_generic", config[n], MUXG_MAX_SIZE);
    if (r != 0) return r;
    m->in = hal_malloc(sizeof(*m->in) * m->sel.size);
    if (!m->in) return -ENOMEM;
    r = muxg_control(comp_id, m, n);
    for (int i = 0; i < m->sel.size && r == 0; i++) {
        rtapi_snprintf(name, sizeof(name), "mux-gen.%02d.in-%s-%02d", n,
                       comp_type_word(m->sel.in_type), i);
        r = comp_typed_pin(comp_id, m->sel.in_type, HAL_IN, (void **)&m->in[i], name);
    }
    if (r == 0) {
        rtapi_snprintf(name, sizeof(name), "mux-gen.%02d.out-%s", n, comp_type_word(m->sel.out_type));
        r = comp_typed_pin(comp_id, m->sel.out_type, HAL_OUT, (void **)&m->out, name);
    }
    return r;
}

/* Create every configured multiplexer. */
int rtapi_app_main(void)
{
    int n = comp_last_arg(config, MUXG_MAX_MUX);
    if (n == 0) {
        rtapi_print_msg(RTAPI_MSG_ERR, "The mux_generic component requires at least one valid format string\n");
        return -EINVAL;
    }
    return comp_setup("mux_generic", n, muxg_make);
}

/* Remove the component. */
void rtapi_app_exit(void)
{
    comp_teardown();
}
