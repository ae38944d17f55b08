/* matrix_kb.c: decode keypad key codes into one pin per key, or scan a key matrix and produce them. */
#include "rtapi.h"
#include "rtapi_app.h"
#include "rtapi_string.h"
#include "rtapi_errno.h"
#include "hal.h"
#include "comp_args.h"

MODULE_LICENSE("GPL");
MODULE_AUTHOR("OpenEMC");
MODULE_DESCRIPTION("Matrix keypad: config=RxC[s],... names=...");

#define MKB_MAX_INST 16
#define MKB_MAX_DIM 8
#define MKB_MAX_KEYS 64
#define MKB_CODE_DOWN 0xC0
#define MKB_CODE_UP 0x80
#define MKB_CODE_ALL_UP 0x40
#define MKB_FLAGS 0xC0
#define MKB_DEFAULT_ROLLOVER 2
#define MKB_MAX_NAME (HAL_NAME_LEN - 15)   /* room for ".negative-logic" */

static char *config[MKB_MAX_INST];
RTAPI_MP_ARRAY_STRING(config, MKB_MAX_INST, "RxC (decoder) or RxCs (scanner) for each instance");
static char *names[MKB_MAX_INST];
RTAPI_MP_ARRAY_STRING(names, MKB_MAX_INST, "instance names (default matrix_kb.N)");

/* One keypad. */
typedef struct {
    int rows, cols, scan, colbits;
    hal_bit_t *key[MKB_MAX_KEYS];     /* key.rRcC, index (row << colbits) + column */
    hal_bit_t *row[MKB_MAX_DIM];      /* scanner: row-NN-out */
    hal_bit_t *col[MKB_MAX_DIM];      /* scanner: col-NN-in */
    hal_u32_t *keycode;               /* IN for a decoder, OUT for a scanner */
    hal_bit_t negative_logic;         /* param */
    hal_u32_t key_rollover;           /* param (scanner) */
    int down[MKB_MAX_KEYS], ndown, cur_row, primed, old_neg;
} mkb_t;

static int comp_id;

/* Parse "RxC" or "RxCs"; 0 with the sizes filled in, or -EINVAL. */
static int mkb_parse(const char *s, int *rows, int *cols, int *scan)
{
    if (!s || s[0] < '1' || s[0] > '8' || (s[1] != 'x' && s[1] != 'X') || s[2] < '1' || s[2] > '8')
        return -EINVAL;
    *rows = s[0] - '0';
    *cols = s[2] - '0';
    *scan = s[3] == 's' || s[3] == 'S';
    return s[3 + *scan] == '\0' ? 0 : -EINVAL;
}

/* Set key number n down or up if it lies inside the matrix; 1 when it changed. */
static int mkb_set(mkb_t *k, unsigned n, int is_down)
{
    unsigned r = n >> k->colbits, c = n & ((1u << k->colbits) - 1);
    if (r >= (unsigned)k->rows || c >= (unsigned)k->cols || k->down[n] == is_down)
        return 0;
    k->down[n] = is_down;
    *k->key[n] = is_down;
    k->ndown += is_down ? 1 : -1;
    return 1;
}

/* Decoder: apply the key code on the keycode input. */
static void mkb_decode(mkb_t *k)
{
    unsigned code = *k->keycode, flags = code & MKB_FLAGS;
    if (code > 0xFF) return;
    if (flags == MKB_CODE_DOWN) mkb_set(k, code & 0x3F, 1);
    else if (flags == MKB_CODE_UP) mkb_set(k, code & 0x3F, 0);
    else if (flags == MKB_CODE_ALL_UP)
        for (unsigned n = 0; n < MKB_MAX_KEYS; n++) mkb_set(k, n, 0);
}

/* Scanner: report the first changed column of the current row, within the rollover limit. */
static void mkb_read_row(mkb_t *k, int neg)
{
    unsigned limit = k->key_rollover < 1 ? 1 : k->key_rollover;
    for (int c = 0; c < k->cols; c++) {
        unsigned n = (k->cur_row << k->colbits) + c;
        int pressed = *k->col[c] != neg;
        if (pressed && !k->down[n] && (unsigned)k->ndown >= limit) continue;
        if (mkb_set(k, n, pressed)) {
            *k->keycode = (pressed ? MKB_CODE_DOWN : MKB_CODE_UP) + n;
            return;
        }
    }
}

/* Scanner: read the row driven last period, then select the next row. */
static void mkb_scan(mkb_t *k)
{
    int neg = k->negative_logic ? 1 : 0;
    if (k->primed && neg == k->old_neg) {
        mkb_read_row(k, neg);
        k->cur_row = (k->cur_row + 1) % k->rows;
    }
    k->primed = 1;
    k->old_neg = neg;
    for (int i = 0; i < k->rows; i++)
        *k->row[i] = (i == k->cur_row) != neg;
}

/* Funct of one instance. */
static void mkb_update(void *arg, long period)
{
    mkb_t *k = arg;
    (void)period;
    if (k->scan) mkb_scan(k);
    else mkb_decode(k);
}

/* The key pins, the keycode pin (direction by mode) and the params. */
static int mkb_common_pins(mkb_t *k, const char *p)
{
    int r = 0;
    for (int row = 0; row < k->rows; row++)
        for (int c = 0; c < k->cols && r == 0; c++)
            r = hal_pin_bit_newf(HAL_OUT, &k->key[(row << k->colbits) + c], comp_id, "%s.key.r%dc%d", p, row, c);
    if (r == 0) r = hal_pin_u32_newf(k->scan ? HAL_OUT : HAL_IN, &k->keycode, comp_id, "%s.keycode", p);
    if (r == 0) r = hal_param_bit_newf(HAL_RW, &k->negative_logic, comp_id, "%s.negative-logic", p);
    if (r == 0) r = hal_param_u32_newf(HAL_RW, &k->key_rollover, comp_id, "%s.key_rollover", p);
    return r;
}

/* Create instance i from its config entry. */
static int mkb_make(int i, const char *p)
{
    mkb_t *k = hal_malloc(sizeof(*k));
    int r;
    if (!k) return -ENOMEM;
    memset(k, 0, sizeof(*k));
    mkb_parse(config[i], &k->rows, &k->cols, &k->scan);
    while ((1 << k->colbits) < k->cols) k->colbits++;
    k->negative_logic = 1;
    k->key_rollover = MKB_DEFAULT_ROLLOVER;
    r = mkb_common_pins(k, p);
    for (int row = 0; row < k->rows && k->scan && r == 0; row++)
        r = hal_pin_bit_newf(HAL_OUT, &k->row[row], comp_id, "%s.row-%02d-out", p, row);
    for (int c = 0; c < k->cols && k->scan && r == 0; c++)
        r = hal_pin_bit_newf(HAL_IN, &k->col[c], comp_id, "%s.col-%02d-in", p, c);
    if (r == 0) r = hal_export_funct(p, mkb_update, k, 0, 0, comp_id);
    return r;
}

/* Number of instances after checking config= and names=; negative errno after a message. */
static int mkb_count(void)
{
    int n = comp_count_args(config, MKB_MAX_INST), k = comp_count_args(names, MKB_MAX_INST), rows, cols, scan;
    if (n == 0) {
        rtapi_print_msg(RTAPI_MSG_ERR, "matrix_kb: ERROR: no config given (config=RxC[s],...)\n");
        return -EINVAL;
    }
    if (k && k != n) {
        rtapi_print_msg(RTAPI_MSG_ERR, "matrix_kb: ERROR: names= has %d entries but config= has %d\n", k, n);
        return -EINVAL;
    }
    for (int i = 0; i < n; i++) {
        if (mkb_parse(config[i], &rows, &cols, &scan)) {
            rtapi_print_msg(RTAPI_MSG_ERR, "matrix_kb: ERROR: config entry %d \"%s\" is not RxC or RxCs "
                            "with 1 to 8 rows and columns\n", i, config[i]);
            return -EINVAL;
        }
        if (k && comp_name_check("matrix_kb", i, names[i]) < 0) return -EINVAL;
        if (k && strlen(names[i]) > MKB_MAX_NAME) {
            rtapi_print_msg(RTAPI_MSG_ERR, "matrix_kb: ERROR: name \"%s\" is longer than %d characters\n",
                            names[i], MKB_MAX_NAME);
            return -EINVAL;
        }
    }
    return n;
}

/* Create one instance per config entry. */
int rtapi_app_main(void)
{
    char buf[HAL_NAME_LEN + 1];
    int r = 0, n = mkb_count();
    if (n < 0) return n;
    comp_id = hal_init("matrix_kb");
    if (comp_id < 0) return comp_id;
    for (int i = 0; i < n && r == 0; i++) {
        if (names[0] && names[0][0]) rtapi_snprintf(buf, sizeof(buf), "%s", names[i]);
        else rtapi_snprintf(buf, sizeof(buf), "matrix_kb.%d", i);
        r = mkb_make(i, buf);
    }
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
