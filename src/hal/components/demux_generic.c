/* demux_generic.c: demultiplexers with configurable size and in/out types (config="bf8,us4"). */
#include "rtapi.h"
#include "rtapi_app.h"
#include "rtapi_string.h"
#include "rtapi_errno.h"
#include "hal.h"
#include "comp_args.h"

MODULE_LICENSE("GPL");
MODULE_AUTHOR("OpenEMC");
MODULE_DESCRIPTION("Generic demultiplexer: config=TTN,... (type letters b f s u, size N)");

#define DEMUX_MAX 100
#define DEMUX_MAX_SIZE 1024

static char *config[DEMUX_MAX];
RTAPI_MP_ARRAY_STRING(config, DEMUX_MAX, "demux specs: in type, out type, size (e.g. bf8,us4)");

/* State of one demultiplexer. */
typedef struct {
    comp_select_t sel;
    hal_bit_t *suppress;
    hal_u32_t *debounce_us;
    comp_value_t *in;
    comp_value_t **out;
    comp_debounce_t debounce;
} demux_t;

/* Funct of one demultiplexer: debounce the selection; the selected output follows the input, the others are 0. */
static void demux_funct(void *arg, long period)
{
    demux_t *m = arg;
    unsigned sel = comp_select_read(&m->sel);
    static const comp_value_t zero;
    if (!comp_select_settle(&m->debounce, sel, *m->suppress, *m->debounce_us, period))
        return;
    for (int i = 0; i < m->sel.size; i++) {
        if ((unsigned)i == sel)
            comp_value_convert(m->out[i], m->sel.out_type, m->in, m->sel.in_type);
        else
            comp_value_convert(m->out[i], m->sel.out_type, &zero, m->sel.out_type);
    }
}

/* Create the select pins, the input pin and the funct of demux n. */
static int demux_control(int comp_id, demux_t *m, int n)
{
    char name[HAL_NAME_LEN + 1];
    int r;
    rtapi_snprintf(name, sizeof(name), "demux-gen.%02d", n);
    r = comp_select_pins(&m->sel, comp_id, name);
    if (r == 0) r = hal_pin_bit_newf(HAL_IN, &m->suppress, comp_id, "demux-gen.%02d.suppress-no-input", n);
    if (r == 0) r = hal_pin_u32_newf(HAL_IN, &m->debounce_us, comp_id, "demux-gen.%02d.debounce-us", n);
    if (r == 0) r = hal_param_u32_newf(HAL_RO, &m->debounce.elapsed, comp_id, "demux-gen.%02d.elapsed", n);
    if (r == 0) r = hal_param_u32_newf(HAL_RO, &m->debounce.selected, comp_id, "demux-gen.%02d.selected", n);
    if (r == 0) {
        rtapi_snprintf(name, sizeof(name), "demux-gen.%02d.in-%s", n, comp_type_word(m->sel.in_type));
        r = comp_typed_pin(comp_id, m->sel.in_type, HAL_IN, (void **)&m->in, name);
    }
    if (r == 0) {
        rtapi_snprintf(name, sizeof(name), "demux-gen.%02d", n);
        r = hal_export_funct(name, demux_funct, m, 1, 0, comp_id);
    }
    return r;
}

/* Create demux n from its config text. */
static int demux_make(int comp_id, int n)
{
    char name[HAL_NAME_LEN + 1];
    demux_t *m = hal_malloc(sizeof(*m));
    int r;
    if (!m) return -ENOMEM;
    memset(m, 0, sizeof(*m));
    r = comp_select_init(&m->sel, "demux_generic", config[n], DEMUX_MAX_SIZE);
    if (r != 0) return r;
    m->out = hal_malloc(sizeof(*m->out) * m->sel.size);
    if (!m->out) return -ENOMEM;
    r = demux_control(comp_id, m, n);
    for (int i = 0; i < m->sel.size && r == 0; i++) {
        rtapi_snprintf(name, sizeof(name), "demux-gen.%02d.out-%s-%02d", n,
                       comp_type_word(m->sel.out_type), i);
        r = comp_typed_pin(comp_id, m->sel.out_type, HAL_OUT, (void **)&m->out[i], name);
    }
    return r;
}

/* Create every configured demultiplexer. */
int rtapi_app_main(void)
{
    int n = comp_last_arg(config, DEMUX_MAX);
    if (n == 0) {
        rtapi_print_msg(RTAPI_MSG_ERR, "The demux_generic component requires at least one valid format string\n");
        return -EINVAL;
    }
    return comp_setup("demux_generic", n, demux_make);
}

/* Remove the component. */
void rtapi_app_exit(void)
{
    comp_teardown();
}
