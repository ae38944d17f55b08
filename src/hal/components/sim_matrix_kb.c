/* sim_matrix_kb.c: 64 simulated key buttons scanned into matrix-keypad codes, one change per period. */
#include "rtapi.h"
#include "rtapi_app.h"
#include "rtapi_string.h"
#include "rtapi_errno.h"
#include "hal.h"
#include "comp_args.h"

MODULE_LICENSE("GPL");
MODULE_AUTHOR("OpenEMC");
MODULE_DESCRIPTION("Simulated 8x8 keypad: button.cCC.rRR to matrix_kb scan codes");

static int count;
RTAPI_MP_INT(count, "number of instances (default 1)");
static char *names = "";
RTAPI_MP_STRING(names, "instance names (instead of count)");

#define SMK_SIDE 8
#define SMK_KEYS (SMK_SIDE * SMK_SIDE)
#define SMK_CODE_DOWN 0xC0
#define SMK_CODE_UP 0x80
#define SMK_CODE_HELD 0x40

/* One simulated keypad; key number n = 8 * row + column. */
typedef struct {
    hal_bit_t *button[SMK_KEYS];
    hal_u32_t *out;
    int down[SMK_KEYS];   /* last reported state of each key */
} smk_t;

/* Report the first key (row by row) whose button changed; otherwise 0 or 0x40. */
static void smk_scan(void *arg, long period)
{
    smk_t *k = arg;
    int held = 0;
    (void)period;
    for (int n = 0; n < SMK_KEYS; n++) {
        int b = *k->button[n] != 0;
        if (b != k->down[n]) {
            rtapi_print("row: %d column: %d code: %d\n", n / SMK_SIDE, n % SMK_SIDE, n);
            k->down[n] = b;
            *k->out = (hal_u32_t)n | (b ? SMK_CODE_DOWN : SMK_CODE_UP);
            return;
        }
        held |= b;
    }
    *k->out = held ? SMK_CODE_HELD : 0;
}

/* Create the pins and funct of one instance. */
static int smk_make(int comp_id, int i, const char *prefix)
{
    smk_t *k = hal_malloc(sizeof(*k));
    int r = 0;
    (void)i;
    if (!k) return -ENOMEM;
    memset(k, 0, sizeof(*k));
    for (int n = 0; n < SMK_KEYS && r == 0; n++)
        r = hal_pin_bit_newf(HAL_IN, &k->button[n], comp_id, "%s.button.c%02d.r%02d", prefix, n % SMK_SIDE,
                             n / SMK_SIDE);
    if (r == 0) r = hal_pin_u32_newf(HAL_OUT, &k->out, comp_id, "%s.out", prefix);
    if (r == 0) r = hal_export_funct(prefix, smk_scan, k, 0, 0, comp_id);
    return r;
}

/* Create the instances (count= or names=, one by default). */
int rtapi_app_main(void)
{
    return comp_setup_named("sim_matrix_kb", "sim-matrix-kb", count, names, 1, smk_make);
}

/* Remove the component. */
void rtapi_app_exit(void)
{
    comp_teardown();
}
