/* joint_axis_mapper.c: print "<L> Axis fault detected" when a joint's fault input rises, naming the
 * axis letter that coord= gives the joint. */
#include "rtapi.h"
#include "rtapi_app.h"
#include "rtapi_string.h"
#include "rtapi_errno.h"
#include "hal.h"

MODULE_LICENSE("GPL");
MODULE_AUTHOR("OpenEMC");
MODULE_DESCRIPTION("Axis-letter messages for joint faults (coord=XYZ...)");

#define JAM_NAME "joint_axis_mapper"
#define JAM_MAX_JOINTS 16
#define JAM_MAX_COORD 64

static char *coord = "XYZABCUVWXYZABCUVW";
RTAPI_MP_STRING(coord, "axis letter of each joint");

/* One joint that has an axis letter. */
typedef struct {
    char letter;
    hal_bit_t *fault, *latched;
} jam_joint_t;

typedef struct {
    hal_bit_t *dummy;
    int njoints;
    jam_joint_t joint[JAM_MAX_JOINTS];
} jam_t;

static int comp_id;

/* coord without blanks, tabs, line ends and the characters ; { } , " ' (at most max-1 letters). */
static void jam_clean(const char *in, char *out, int max)
{
    int n = 0;
    for (; *in && n < max - 1; in++)
        if (!strchr(" \t\r\n;{},\"'", *in))
            out[n++] = *in;
    out[n] = '\0';
}

/* Index of an axis letter in XYZABCUVW (any case), or -1. */
static int jam_axis(char c)
{
    const char *axes = "XYZABCUVW";
    const char *p = strchr(axes, c & ~0x20);
    return p && (c | 0x20) >= 'a' && (c | 0x20) <= 'z' ? (int)(p - axes) : -1;
}

/* Create the pins of joint j for letter c, its k-th use (1 = first). */
static int jam_joint_pins(jam_joint_t *j, char c, int k)
{
    char base[16];
    if (k == 1)
        rtapi_snprintf(base, sizeof(base), "jam.%c", c);
    else
        rtapi_snprintf(base, sizeof(base), "jam.%c%d", c, k);
    j->letter = c;
    int r = hal_pin_bit_newf(HAL_IN, &j->fault, comp_id, "%s-fault", base);
    return r ? r : hal_pin_bit_newf(HAL_OUT, &j->latched, comp_id, "%s-fault-latched", base);
}

/* Make the pins of every joint named in coord. */
static int jam_setup(jam_t *m)
{
    char letters[JAM_MAX_COORD];
    int uses[9] = {0};
    jam_clean(coord ? coord : "", letters, sizeof(letters));
    int n = (int)strlen(letters);
    if (n > JAM_MAX_JOINTS) {
        rtapi_print_msg(RTAPI_MSG_WARN, JAM_NAME ": coord has %d joints, using the first %d\n", n,
                        JAM_MAX_JOINTS);
        n = JAM_MAX_JOINTS;
    }
    for (int i = 0; i < n; i++) {
        int a = jam_axis(letters[i]);
        if (a < 0) {
            rtapi_print_msg(RTAPI_MSG_ERR, "Joint Axis Mapper - %c axis not found in coord string\n", letters[i]);
            continue;
        }
        int r = jam_joint_pins(&m->joint[m->njoints++], letters[i], ++uses[a]);
        if (r)
            return r;
    }
    return hal_pin_bit_new(JAM_NAME ".dummy", HAL_OUT, &m->dummy, comp_id);
}

/* Funct joint_axis_mapper: report each rising fault with the joint's axis letter. */
static void jam_update(void *arg, long period)
{
    jam_t *m = arg;
    (void)period;
    for (int i = 0; i < m->njoints; i++) {
        jam_joint_t *j = &m->joint[i];
        if (*j->fault && !*j->latched)
            rtapi_print_msg(RTAPI_MSG_ERR, "%c Axis fault detected\n", j->letter);
        *j->latched = *j->fault;
    }
}

/* Create the component. */
int rtapi_app_main(void)
{
    comp_id = hal_init(JAM_NAME);
    if (comp_id < 0) return comp_id;
    jam_t *m = hal_malloc(sizeof(*m));
    int r = m ? 0 : -ENOMEM;
    if (r == 0) {
        memset(m, 0, sizeof(*m));
        r = jam_setup(m);
    }
    if (r == 0)
        r = hal_export_funct(JAM_NAME, jam_update, m, 0, 0, comp_id);
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
