/* sim_axis_hardware.c: simulated home and limit switches of eight axis channels, for sim configs. */
#include <stddef.h>
#include "rtapi.h"
#include "rtapi_app.h"
#include "rtapi_string.h"
#include "rtapi_errno.h"
#include "hal.h"
#include "comp_args.h"

MODULE_LICENSE("GPL");
MODULE_AUTHOR("OpenEMC");
MODULE_DESCRIPTION("Simulated home and limit switches from axis positions (channels X X2 Y Y2 Z A U V)");

static int count;
RTAPI_MP_INT(count, "number of instances");
static char *names = "";
RTAPI_MP_STRING(names, "names of the instances");

#define SAH_NCHAN 8
/* Channel letters, in the order of the pins; the A channel never writes its *-homesw-out pins. */
static const char *const sah_letters[SAH_NCHAN] = { "X", "X2", "Y", "Y2", "Z", "A", "U", "V" };
#define SAH_A_CHANNEL 5

/* Pins of one channel. */
typedef struct {
    hal_float_t *pos, *home_pos, *home_hyst, *max_upper, *max_lower, *min_upper, *min_lower;
    hal_bit_t *homing, *home_out, *max_out, *min_out, *both_out, *max_home_out, *min_home_out,
        *both_home_out;
} sah_chan_t;

/* One instance: eight channels and the shared pins. */
typedef struct {
    sah_chan_t ch[SAH_NCHAN];
    hal_float_t *limit_offset;
    hal_bit_t *home_all, *limit_all, *limit_home_all;
} sah_t;

#define SAH_PIN(sfx, t, d, f, v) { sfx, t, d, offsetof(sah_chan_t, f), v }
static const comp_pin_def_t sah_chan_pins[] = {
    SAH_PIN("bothsw-homesw-out", HAL_BIT, HAL_OUT, both_home_out, 0),
    SAH_PIN("bothsw-out", HAL_BIT, HAL_OUT, both_out, 0),
    SAH_PIN("current-pos", HAL_FLOAT, HAL_IN, pos, 0),
    SAH_PIN("homesw-hyst", HAL_FLOAT, HAL_IN, home_hyst, 0.025),
    SAH_PIN("homesw-out", HAL_BIT, HAL_OUT, home_out, 0),
    SAH_PIN("homesw-pos", HAL_FLOAT, HAL_IN, home_pos, 1),
    SAH_PIN("homing", HAL_BIT, HAL_IN, homing, 0),
    SAH_PIN("maxsw-homesw-out", HAL_BIT, HAL_OUT, max_home_out, 0),
    SAH_PIN("maxsw-lower", HAL_FLOAT, HAL_IN, max_lower, 0),
    SAH_PIN("maxsw-out", HAL_BIT, HAL_OUT, max_out, 0),
    SAH_PIN("maxsw-upper", HAL_FLOAT, HAL_IN, max_upper, 0),
    SAH_PIN("minsw-homesw-out", HAL_BIT, HAL_OUT, min_home_out, 0),
    SAH_PIN("minsw-lower", HAL_FLOAT, HAL_IN, min_lower, 0),
    SAH_PIN("minsw-out", HAL_BIT, HAL_OUT, min_out, 0),
    SAH_PIN("minsw-upper", HAL_FLOAT, HAL_IN, min_upper, 0),
};
#define SAH_NPINS ((int)(sizeof(sah_chan_pins) / sizeof(sah_chan_pins[0])))

static const comp_pin_def_t sah_shared_pins[] = {
    { "homesw-all", HAL_BIT, HAL_OUT, offsetof(sah_t, home_all), 0 },
    { "limit-offset", HAL_FLOAT, HAL_IN, offsetof(sah_t, limit_offset), 0.01 },
    { "limitsw-all", HAL_BIT, HAL_OUT, offsetof(sah_t, limit_all), 0 },
    { "limitsw-homesw-all", HAL_BIT, HAL_OUT, offsetof(sah_t, limit_home_all), 0 },
};

/* Home switch of a channel: within half the hysteresis of the home position (closed interval). */
static int sah_home(const sah_chan_t *c)
{
    double d = *c->pos - *c->home_pos, h = *c->home_hyst / 2;
    return !(d < -h || d > h);
}

/* Home and limit switches of one channel (homing is the OR of every channel's homing input). */
static void sah_channel(sah_chan_t *c, double offset, int homing, int write_home_combos)
{
    double p = *c->pos;
    *c->home_out = sah_home(c);
    *c->max_out = (*c->max_lower + offset) < p && p < *c->max_upper;
    *c->min_out = *c->min_lower < p && p < (*c->min_upper - offset);
    *c->both_out = (*c->max_out || *c->min_out) && !homing;
    if (!write_home_combos)
        return;
    *c->max_home_out = *c->max_out || *c->home_out;
    *c->min_home_out = *c->min_out || *c->home_out;
    *c->both_home_out = *c->both_out || *c->home_out;
}

/* Funct <prefix>.update: every channel, then the combined outputs. */
static void sah_update(void *arg, long period)
{
    sah_t *s = arg;
    int homing = 0, home_any = 0, limit_any = 0;
    (void)period;
    for (int i = 0; i < SAH_NCHAN; i++)
        homing |= *s->ch[i].homing;
    for (int i = 0; i < SAH_NCHAN; i++) {
        sah_channel(&s->ch[i], *s->limit_offset, homing, i != SAH_A_CHANNEL);
        home_any |= *s->ch[i].home_out;
        limit_any |= *s->ch[i].both_out;
    }
    *s->home_all = home_any && homing;
    *s->limit_all = limit_any;
    *s->limit_home_all = *s->home_all || *s->limit_all;
}

/* Create the pins and funct of one instance. */
static int sah_make(int comp_id, int i, const char *prefix)
{
    char name[HAL_NAME_LEN + 1];
    sah_t *s = hal_malloc(sizeof(*s));
    int r;
    (void)i;
    if (!s) return -ENOMEM;
    memset(s, 0, sizeof(*s));
    for (int c = 0; c < SAH_NCHAN; c++) {
        rtapi_snprintf(name, sizeof(name), "%s.%s", prefix, sah_letters[c]);
        r = comp_pin_table(comp_id, &s->ch[c], sah_chan_pins, SAH_NPINS, name);
        if (r) return r;
    }
    rtapi_snprintf(name, sizeof(name), "%s.", prefix);
    r = comp_pin_table(comp_id, s, sah_shared_pins, 4, name);
    if (r) return r;
    rtapi_snprintf(name, sizeof(name), "%s.update", prefix);
    return hal_export_funct(name, sah_update, s, 1, 0, comp_id);
}

/* Create the instances (count= or names=, one by default). */
int rtapi_app_main(void)
{
    return comp_setup_named("sim_axis_hardware", "sim-axis-hardware", count, names, 1, sah_make);
}

/* Remove the component. */
void rtapi_app_exit(void)
{
    comp_teardown();
}
