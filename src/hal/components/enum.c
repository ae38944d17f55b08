/* enum.c: decode an integer into one bit per named value, or encode such bits into an integer. */
#include "rtapi.h"
#include "rtapi_app.h"
#include "rtapi_string.h"
#include "rtapi_errno.h"
#include "hal.h"
#include "comp_args.h"

MODULE_LICENSE("GPL");
MODULE_AUTHOR("OpenEMC");
MODULE_DESCRIPTION("Enumerations: enums=D;v0;v1;;v3,E;a;b names=x,y");

#define ENUM_MAX_CHAN 16
#define ENUM_MAX_VALUES 64
#define ENUM_LABEL_LEN 40

static char *enums[ENUM_MAX_CHAN];
RTAPI_MP_ARRAY_STRING(enums, ENUM_MAX_CHAN, "per channel: D or E, then ;-separated labels");
static char *names[ENUM_MAX_CHAN];
RTAPI_MP_ARRAY_STRING(names, ENUM_MAX_CHAN, "channel names (default enum.N)");

/* Pins of one named value. */
typedef struct {
    hal_bit_t *bit;
    hal_u32_t *val;
} enum_value_t;

/* One enumeration channel. */
typedef struct {
    hal_u32_t *number;
    enum_value_t v[ENUM_MAX_VALUES];
    int count;
} enum_chan_t;

static int comp_id;

/* Funct <prefix>.decode: set each value's bit when the input equals its number. */
static void enum_decode(void *arg, long period)
{
    enum_chan_t *c = arg;
    (void)period;
    for (int i = 0; i < c->count; i++)
        if (c->v[i].bit) *c->v[i].bit = *c->v[i].val == *c->number;
}

/* Funct <prefix>.encode: output the number of the first value whose bit is set, else 0. */
static void enum_encode(void *arg, long period)
{
    enum_chan_t *c = arg;
    (void)period;
    for (int i = 0; i < c->count; i++) {
        if (c->v[i].bit && *c->v[i].bit) {
            *c->number = *c->v[i].val;
            return;
        }
    }
    *c->number = 0;
}

/* Create the bit and number pins of value i named by label[0..len). */
static int enum_value(enum_chan_t *c, int i, const char *prefix, const char *label, int len,
                      int decode)
{
    int r = hal_pin_bit_newf(decode ? HAL_OUT : HAL_IN, &c->v[i].bit, comp_id, "%s.%.*s-%s",
                             prefix, len, label, decode ? "out" : "in");
    if (r == 0)
        r = hal_pin_u32_newf(HAL_IN, &c->v[i].val, comp_id, "%s.%.*s-val", prefix, len, label);
    if (r == 0) *c->v[i].val = i;
    return r;
}

/* Create the value pins listed after the mode letter; returns 0 or a negative errno. */
static int enum_values(enum_chan_t *c, const char *spec, const char *prefix, int decode)
{
    const char *p = spec + 1;
    int r = 0, named = 0;
    while (*p == ';' && r == 0) {
        const char *label = ++p;
        while (*p && *p != ';') p++;
        if (c->count >= ENUM_MAX_VALUES) {
            rtapi_print_msg(RTAPI_MSG_ERR, "ENUM: ERROR: '%s' has more than %d values\n", spec,
                            ENUM_MAX_VALUES);
            return -EINVAL;
        }
        if (p - label > ENUM_LABEL_LEN) {
            rtapi_print_msg(RTAPI_MSG_ERR, "ENUM: ERROR: label '%.*s' is too long\n",
                            (int)(p - label), label);
            return -EINVAL;
        }
        if (p > label) {
            r = enum_value(c, c->count, prefix, label, (int)(p - label), decode);
            named++;
        }
        c->count++;
    }
    if (r == 0 && !named) {
        rtapi_print_msg(RTAPI_MSG_ERR, "ENUM: ERROR: '%s' names no values\n", spec);
        return -EINVAL;
    }
    return r;
}

/* Create channel n from its spec. */
static int enum_make(const char *spec, const char *prefix)
{
    char fname[HAL_NAME_LEN + 1];
    int decode = spec[0] == 'D' || spec[0] == 'd';
    enum_chan_t *c;
    int r;
    if ((!decode && spec[0] != 'E' && spec[0] != 'e') || spec[1] != ';') {
        rtapi_print_msg(RTAPI_MSG_ERR, "ENUM: ERROR: bad spec '%s' (must start with D; or E;)\n",
                        spec);
        return -EINVAL;
    }
    c = hal_malloc(sizeof(*c));
    if (!c) return -ENOMEM;
    memset(c, 0, sizeof(*c));
    r = hal_pin_u32_newf(decode ? HAL_IN : HAL_OUT, &c->number, comp_id, "%s.%s", prefix,
                         decode ? "input" : "output");
    if (r == 0) r = enum_values(c, spec, prefix, decode);
    if (r != 0) return r;
    rtapi_snprintf(fname, sizeof(fname), "%s.%s", prefix, decode ? "decode" : "encode");
    return hal_export_funct(fname, decode ? enum_decode : enum_encode, c, 0, 0, comp_id);
}

/* Number of channels, or -1 when names= does not match enums=. */
static int enum_channels(void)
{
    int n = comp_count_args(enums, ENUM_MAX_CHAN), k = comp_count_args(names, ENUM_MAX_CHAN);
    if (n == 0) {
        rtapi_print_msg(RTAPI_MSG_ERR, "ENUM: ERROR: no enums= given (e.g. enums=D;a;b;c)\n");
        return -1;
    }
    if (k && k != n) {
        rtapi_print_msg(RTAPI_MSG_ERR, "ENUM: ERROR: %d names for %d enums\n", k, n);
        return -1;
    }
    return n;
}

/* Create channel i, named from names= or enum.<i>, in component id. */
static int enum_instance(int id, int i)
{
    char prefix[HAL_NAME_LEN + 1];
    comp_id = id;
    if (names[0] && names[0][0]) rtapi_snprintf(prefix, sizeof(prefix), "%s", names[i]);
    else rtapi_snprintf(prefix, sizeof(prefix), "enum.%d", i);
    return enum_make(enums[i], prefix);
}

/* Create every configured channel. */
int rtapi_app_main(void)
{
    int n = enum_channels();
    if (n < 0) return -EINVAL;
    return comp_setup("enum", n, enum_instance);
}

/* Remove the component. */
void rtapi_app_exit(void)
{
    comp_teardown();
}
