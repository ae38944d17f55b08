/* enum.c: decode an integer into one bit per named state, or encode such bits into an integer. */
#include "rtapi.h"
#include "rtapi_app.h"
#include "rtapi_string.h"
#include "rtapi_errno.h"
#include "hal.h"
#include "comp_args.h"

MODULE_LICENSE("GPL");
MODULE_AUTHOR("OpenEMC");
MODULE_DESCRIPTION("Enumerations: enums=D;s0;s1;;s3,E;a;b [names=x,y]");

#define ENUM_MAX_CHAN 256
#define ENUM_LABEL_LEN 40

static char *enums[ENUM_MAX_CHAN];
RTAPI_MP_ARRAY_STRING(enums, ENUM_MAX_CHAN, "per instance: E (encode) or D (decode), then ;-separated states");
static char *names[ENUM_MAX_CHAN];
RTAPI_MP_ARRAY_STRING(names, ENUM_MAX_CHAN, "instance names (default enum-encode.NN / enum-decode.NN)");

/* Pins of one named state. */
typedef struct {
    hal_bit_t *bit;   /* <state>-out (decode) or <state>-in (encode) */
    hal_u32_t *val;   /* <state>-val, preset to the field position */
} enum_state_t;

/* One instance. */
typedef struct {
    hal_u32_t *number;    /* input (decode) or output (encode) */
    enum_state_t *s;      /* the named states in field order */
    int count;
} enum_inst_t;

static int comp_id;

/* Funct of a decoder: every state whose value equals the input is TRUE. */
static void enum_decode(void *arg, long period)
{
    enum_inst_t *c = arg;
    (void)period;
    for (int i = 0; i < c->count; i++)
        *c->s[i].bit = *c->s[i].val == *c->number;
}

/* Funct of an encoder: the value of the last TRUE state, 0 when none is. */
static void enum_encode(void *arg, long period)
{
    enum_inst_t *c = arg;
    hal_u32_t out = 0;
    (void)period;
    for (int i = 0; i < c->count; i++)
        if (*c->s[i].bit) out = *c->s[i].val;
    *c->number = out;
}

/* Field k of the states after the mode letter: *len characters at the returned pointer, or NULL
 * past the last field (a trailing empty field is ignored). */
static const char *enum_field(const char *spec, int k, int *len)
{
    const char *p = spec + 1;
    for (int i = 0; *p == ';'; i++) {
        const char *f = ++p;
        while (*p && *p != ';') p++;
        if (!*p && p == f) return NULL;
        if (i == k) {
            *len = (int)(p - f);
            return f;
        }
    }
    return NULL;
}

/* Number of named states in spec and checks of each name; negative errno on a bad one. */
static int enum_count(const char *spec)
{
    int len, n = 0;
    const char *f;
    for (int k = 0; (f = enum_field(spec, k, &len)) != NULL; k++) {
        if (len > ENUM_LABEL_LEN) {
            rtapi_print_msg(RTAPI_MSG_ERR, "ENUM: ERROR: state name '%.*s' is longer than %d\n", len, f,
                            ENUM_LABEL_LEN);
            return -EINVAL;
        }
        n += len > 0;
    }
    if (n == 0) {
        rtapi_print_msg(RTAPI_MSG_ERR, "ENUM: ERROR: '%s' names no states\n", spec);
        return -EINVAL;
    }
    return n;
}

/* Create the pins of every named state; the value of a state is its field position. */
static int enum_states(enum_inst_t *c, const char *spec, const char *prefix, int decode)
{
    int len, r = 0;
    const char *f;
    for (int k = 0; r == 0 && (f = enum_field(spec, k, &len)) != NULL; k++) {
        if (len == 0) continue;
        enum_state_t *s = &c->s[c->count++];
        r = hal_pin_bit_newf(decode ? HAL_OUT : HAL_IN, &s->bit, comp_id, "%s.%.*s-%s", prefix, len, f,
                             decode ? "out" : "in");
        if (r == 0) r = hal_pin_u32_newf(HAL_IN, &s->val, comp_id, "%s.%.*s-val", prefix, len, f);
        if (r == 0) *s->val = (hal_u32_t)k;
    }
    return r;
}

/* Create one instance from its spec. */
static int enum_make(const char *spec, const char *prefix)
{
    int decode = spec[0] == 'D' || spec[0] == 'd', n;
    if ((!decode && spec[0] != 'E' && spec[0] != 'e') || (spec[1] != ';' && spec[1] != '\0')) {
        rtapi_print_msg(RTAPI_MSG_ERR,
                        "Each enum string must startwith either E; or D; to define the mode ('%s')\n", spec);
        return -EINVAL;
    }
    n = enum_count(spec);
    if (n < 0) return n;
    enum_inst_t *c = hal_malloc(sizeof(*c));
    enum_state_t *s = hal_malloc(n * sizeof(*s));
    if (!c || !s) return -ENOMEM;
    *c = (enum_inst_t){.s = s};
    int r = hal_pin_u32_newf(decode ? HAL_IN : HAL_OUT, &c->number, comp_id, "%s.%s", prefix,
                             decode ? "input" : "output");
    if (r == 0) r = enum_states(c, spec, prefix, decode);
    if (r == 0) r = hal_export_funct(prefix, decode ? enum_decode : enum_encode, c, 0, 0, comp_id);
    return r;
}

/* Number of instances, or -1 after the message when enums= is missing or names= does not match. */
static int enum_instances(void)
{
    int n = comp_count_args(enums, ENUM_MAX_CHAN), k = comp_count_args(names, ENUM_MAX_CHAN);
    if (n == 0) {
        rtapi_print_msg(RTAPI_MSG_ERR, "The enum_decode component requires at least one enumeration list\n");
        return -1;
    }
    if (k && k != n) {
        rtapi_print_msg(RTAPI_MSG_ERR, "Inconsistent number of names and enums\n");
        return -1;
    }
    for (int i = 0; i < k; i++)
        if (comp_name_check("enum", i, names[i]) < 0) return -1;
    rtapi_print_msg(RTAPI_MSG_INFO, "making %i instances\n", n);
    return n;
}

/* Create instance i, named from names= or enum-encode.NN / enum-decode.NN, in component id. */
static int enum_instance(int id, int i)
{
    char prefix[HAL_NAME_LEN + 1];
    int decode = enums[i][0] == 'D' || enums[i][0] == 'd';
    comp_id = id;
    if (names[0] && names[0][0]) rtapi_snprintf(prefix, sizeof(prefix), "%s", names[i]);
    else rtapi_snprintf(prefix, sizeof(prefix), "enum-%s.%02d", decode ? "decode" : "encode", i);
    return enum_make(enums[i], prefix);
}

/* Create every configured instance. */
int rtapi_app_main(void)
{
    int n = enum_instances();
    if (n < 0) return -EINVAL;
    return comp_setup("enum", n, enum_instance);
}

/* Remove the component. */
void rtapi_app_exit(void)
{
    comp_teardown();
}
