/* supply.c: constant sources; q/_q follow the d pin and variable/_variable follow the value pin. */
#include "rtapi.h"
#include "rtapi_app.h"
#include "rtapi_string.h"
#include "rtapi_errno.h"
#include "hal.h"
#include "comp_args.h"

MODULE_LICENSE("GPL");
MODULE_AUTHOR("OpenEMC");
MODULE_DESCRIPTION("Constant sources: q = d, _q = !d, variable = value, _variable = -value");

#define SUPPLY_MAX_CHAN 8

static int num_chan = 1;
RTAPI_MP_INT(num_chan, "number of supplies (1..8)");

/* Pins of one supply channel. */
typedef struct {
    hal_bit_t *q, *q_not, *d;
    hal_float_t *variable, *variable_neg, *value;
} supply_t;

/* Funct supply.N.update: copy and invert the d and value pins. */
static void supply_update(void *arg, long period)
{
    supply_t *s = arg;
    (void)period;
    *s->q = *s->d;
    *s->q_not = !*s->d;
    *s->variable = *s->value;
    *s->variable_neg = -*s->value;
}

/* Create the pins and funct of channel n in component comp_id. */
static int supply_export(int comp_id, int n)
{
    char name[HAL_NAME_LEN + 1];
    supply_t *s = hal_malloc(sizeof(*s));
    if (!s) return -ENOMEM;
    int r = hal_pin_bit_newf(HAL_OUT, &s->q, comp_id, "supply.%d.q", n);
    if (r == 0) r = hal_pin_bit_newf(HAL_OUT, &s->q_not, comp_id, "supply.%d._q", n);
    if (r == 0) r = hal_pin_float_newf(HAL_OUT, &s->variable, comp_id, "supply.%d.variable", n);
    if (r == 0)
        r = hal_pin_float_newf(HAL_OUT, &s->variable_neg, comp_id, "supply.%d._variable", n);
    if (r == 0) r = hal_pin_bit_newf(HAL_IO, &s->d, comp_id, "supply.%d.d", n);
    if (r == 0) r = hal_pin_float_newf(HAL_IO, &s->value, comp_id, "supply.%d.value", n);
    if (r != 0) return r;
    *s->q_not = 1; /* the inverse of d, which starts FALSE */
    rtapi_snprintf(name, sizeof(name), "supply.%d.update", n);
    return hal_export_funct(name, supply_update, s, 1, 0, comp_id);
}

/* Create num_chan supplies. */
int rtapi_app_main(void)
{
    if (num_chan < 1 || num_chan > SUPPLY_MAX_CHAN) {
        rtapi_print_msg(RTAPI_MSG_ERR, "SUPPLY: ERROR: invalid num_chan: %d (must be 1..%d)\n",
                        num_chan, SUPPLY_MAX_CHAN);
        return -EINVAL;
    }
    return comp_setup("supply", num_chan, supply_export);
}

/* Remove the component. */
void rtapi_app_exit(void)
{
    comp_teardown();
}
