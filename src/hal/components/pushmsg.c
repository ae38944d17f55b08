/* pushmsg.c: print configured messages, with up to two pin values in them, when trigger pins change. */
#include "rtapi.h"
#include "rtapi_app.h"
#include "rtapi_string.h"
#include "rtapi_errno.h"
#include "hal.h"

MODULE_LICENSE("GPL");
MODULE_AUTHOR("OpenEMC");
MODULE_DESCRIPTION("Messages on trigger edges: msgs=\"level|pin|text with {t:pin}\",...");

#define PM_MAX_MSGS 64
#define PM_MAX_LEN 128
#define PM_MAX_SUBST 2
#define PM_COMP "pushmsg"

static char *msgs[PM_MAX_MSGS];
RTAPI_MP_ARRAY_STRING(msgs, PM_MAX_MSGS, "messages: level|pinname|text (level e w i d; {t:pin} substitutes)");

/* A {t:ref} placeholder: its pin and where it sits in the text. */
typedef struct {
    char type;          /* b s u l k f */
    void *pin;
    int start, end;     /* the placeholder is text[start..end) */
} pm_subst_t;

/* One configured message. */
typedef struct {
    int level;
    char text[PM_MAX_LEN];
    int nsubst;
    pm_subst_t subst[PM_MAX_SUBST];
    hal_bit_t *trigger, *force, *edge;
    int last_trig, last_force;
} pm_msg_t;

typedef struct {
    hal_bit_t *enable;
    int count;
    pm_msg_t msg[PM_MAX_MSGS];
} pm_t;

static int comp_id;
static pm_t *pm;

/* Print one failure of entry i and return err. */
static int pm_fail(int i, int err, const char *fmt, const char *arg)
{
    char what[96];
    rtapi_snprintf(what, sizeof(what), fmt, arg);
    rtapi_print_msg(RTAPI_MSG_ERR, PM_COMP ": Message %d %s\n", i, what);
    return err;
}

/* Non-zero when name is made of ASCII letters, digits, '.', '_' and '-' only. */
static int pm_name_ok(const char *s, int len)
{
    for (int k = 0; k < len; k++) {
        char c = s[k];
        if (!((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '.' ||
              c == '_' || c == '-'))
            return 0;
    }
    return 1;
}

/* HAL type of a placeholder letter, or -1. */
static int pm_type(char t)
{
    switch (t | 0x20) {
    case 'b': return HAL_BIT;
    case 's': return HAL_S32;
    case 'u': return HAL_U32;
    case 'l': return HAL_S64;
    case 'k': return HAL_U64;
    case 'f': return HAL_FLOAT;
    default: return -1;
    }
}

/* Parse and create the pin of the placeholder starting at text[start] ('{'); returns 0 or an error. */
static int pm_placeholder(pm_msg_t *m, int i, const char *name, int start)
{
    char ref[PM_MAX_LEN], pin[HAL_NAME_LEN + 1];
    const char *t = m->text + start, *close = strchr(t, '}');
    if (!close)
        return pm_fail(i, -EBADMSG, "%smissing '}' in substitution", "");
    int len = (int)(close - t) - 1;
    if (len < 3)
        return pm_fail(i, -EBADMSG, "%ssubstitution too small, need type and pinname", "");
    if (t[2] != ':')
        return pm_fail(i, -EBADMSG, "%ssubstitution missing ':' after type character", "");
    if (len - 2 + 7 + (int)strlen(name) + 2 >= HAL_NAME_LEN)
        return pm_fail(i, -EBADMSG, "%ssubstitution pin name too long", "");
    if (!pm_name_ok(t + 3, len - 2))
        return pm_fail(i, -EINVAL, "%ssubstitution pin name contains bad characters", "");
    int type = pm_type(t[1]);
    if (type < 0) {
        char bad[2] = {t[1], 0};
        return pm_fail(i, -EBADMSG, "bad substitution type '%s', expected one of {b,f,s,u,k,l}", bad);
    }
    memcpy(ref, t + 3, len - 2);
    ref[len - 2] = '\0';
    rtapi_snprintf(pin, sizeof(pin), PM_COMP ".%s.%s", name, ref);
    pm_subst_t *s = &m->subst[m->nsubst++];
    s->type = t[1] | 0x20;
    s->start = start;
    s->end = (int)(close - m->text) + 1;
    return hal_pin_new(pin, (hal_type_t)type, HAL_IN, &s->pin, comp_id);
}

/* Find the first two placeholders of the text (a backslash makes the next character plain). */
static int pm_placeholders(pm_msg_t *m, int i, const char *name)
{
    for (int k = 0; m->text[k] && m->nsubst < PM_MAX_SUBST; k++) {
        if (m->text[k] == '\\' && m->text[k + 1]) {
            k++;
            continue;
        }
        if (m->text[k] != '{')
            continue;
        int r = pm_placeholder(m, i, name, k);
        if (r)
            return r;
        k = m->subst[m->nsubst - 1].end - 1;
    }
    return 0;
}

/* Create the trigger, force and edge pins of entry i named name. */
static int pm_control_pins(pm_msg_t *m, int i, const char *name)
{
    static const char *const what[] = {"trigger", "force", "edge"};
    hal_bit_t **ptr[] = {&m->trigger, &m->force, &m->edge};
    for (int k = 0; k < 3; k++) {
        int r = hal_pin_bit_newf(HAL_IN, ptr[k], comp_id, PM_COMP ".%s.%s", name, what[k]);
        if (r) {
            char why[48];
            rtapi_snprintf(why, sizeof(why), "cannot create %s pin (duplicate?)", what[k]);
            return pm_fail(i, r, "%s", why);
        }
    }
    return 0;
}

/* Check entry i ("level|name|text") and make its pins. */
static int pm_entry(pm_msg_t *m, int i, const char *e)
{
    static const char levels[] = "ewid";
    static const int level_of[] = {RTAPI_MSG_ERR, RTAPI_MSG_WARN, RTAPI_MSG_INFO, RTAPI_MSG_DBG};
    char name[HAL_NAME_LEN + 1];
    int len = (int)strlen(e);
    if (len >= PM_MAX_LEN) return pm_fail(i, -EMSGSIZE, "%stoo long, more than 127 characters", "");
    if (len < 4) return pm_fail(i, -EMSGSIZE, "%stoo short, less than 4 characters", "");
    const char *lv = strchr(levels, e[0] | 0x20);
    if (!lv || !e[0]) {
        char bad[2] = {e[0], 0};
        return pm_fail(i, -EBADMSG, "has invalid type '%s', expected one of {e,w,i,d}", bad);
    }
    if (e[1] != '|') return pm_fail(i, -EBADMSG, "%smissing first '|' separator", "");
    const char *bar = strchr(e + 2, '|');
    if (!bar) return pm_fail(i, -EBADMSG, "%smissing pin name, no second '|' separator", "");
    int nlen = (int)(bar - (e + 2));
    if (nlen + 7 + 9 >= HAL_NAME_LEN) return pm_fail(i, -EBADMSG, "%spin name too long", "");
    if (!pm_name_ok(e + 2, nlen)) return pm_fail(i, -EINVAL, "%spin name contains bad characters", "");
    memcpy(name, e + 2, nlen);
    name[nlen] = '\0';
    m->level = level_of[lv - levels];
    rtapi_snprintf(m->text, sizeof(m->text), "%s", bar + 1);
    int r = pm_control_pins(m, i, name);
    return r ? r : pm_placeholders(m, i, name);
}

/* Text of a placeholder's pin value. */
static void pm_value(const pm_subst_t *s, char *buf, int size)
{
    switch (s->type) {
    case 'b': rtapi_snprintf(buf, size, "%d", *(hal_bit_t *)s->pin ? 1 : 0); break;
    case 's': rtapi_snprintf(buf, size, "%d", *(hal_s32_t *)s->pin); break;
    case 'u': rtapi_snprintf(buf, size, "%u", *(hal_u32_t *)s->pin); break;
    case 'l': rtapi_snprintf(buf, size, "%lld", (long long)*(hal_s64_t *)s->pin); break;
    case 'k': rtapi_snprintf(buf, size, "%llu", (unsigned long long)*(hal_u64_t *)s->pin); break;
    default: rtapi_snprintf(buf, size, "%f", *(hal_float_t *)s->pin); break;
    }
}

/* Print a message with its placeholders replaced by the pin values. */
static void pm_print(const pm_msg_t *m)
{
    char out[2 * PM_MAX_LEN + 64], val[40];
    int pos = 0, at = 0;
    for (int k = 0; k < m->nsubst; k++) {
        pos += rtapi_snprintf(out + pos, sizeof(out) - pos, "%.*s", m->subst[k].start - at, m->text + at);
        pm_value(&m->subst[k], val, sizeof(val));
        pos += rtapi_snprintf(out + pos, sizeof(out) - pos, "%s", val);
        at = m->subst[k].end;
    }
    rtapi_snprintf(out + pos, sizeof(out) - pos, "%s", m->text + at);
    rtapi_print_msg(m->level, "%s\n", out);
}

/* Funct pushmsg: print on a trigger edge (while enabled) or a force edge. */
static void pm_update(void *arg, long period)
{
    pm_t *p = arg;
    (void)period;
    for (int i = 0; i < p->count; i++) {
        pm_msg_t *m = &p->msg[i];
        int trig = *m->trigger ^ *m->edge, force = *m->force;
        if ((*p->enable && trig && !m->last_trig) || (force && !m->last_force))
            pm_print(m);
        m->last_trig = trig;
        m->last_force = force;
    }
}

/* Check every entry, make the pins and the funct. */
static int pm_setup(void)
{
    int r = hal_pin_bit_new(PM_COMP ".enable", HAL_IN, &pm->enable, comp_id);
    if (r) return r;
    *pm->enable = 1;
    while (pm->count < PM_MAX_MSGS && msgs[pm->count] && msgs[pm->count][0]) {
        r = pm_entry(&pm->msg[pm->count], pm->count, msgs[pm->count]);
        if (r) return r;
        pm->count++;
    }
    if (pm->count == 0) {
        rtapi_print_msg(RTAPI_MSG_ERR, PM_COMP ": No messages to handle\n");
        return -EINVAL;
    }
    return hal_export_funct(PM_COMP, pm_update, pm, 1, 0, comp_id);
}

/* Create the component. */
int rtapi_app_main(void)
{
    comp_id = hal_init(PM_COMP);
    if (comp_id < 0) return comp_id;
    pm = hal_malloc(sizeof(*pm));
    if (pm)
        memset(pm, 0, sizeof(*pm));
    int r = pm ? pm_setup() : -ENOMEM;
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
