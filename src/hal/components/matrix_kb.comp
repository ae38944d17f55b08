component matrix_kb "Decode keypad key codes into one pin per key, or scan a key matrix itself";
modparam dummy config "config=RxC[s],... one entry per instance: R rows and C columns (1 to 8 each); a trailing s makes the instance scan the matrix itself.";
modparam dummy names "names=name1,... instance names (default matrix_kb.0, matrix_kb.1, ...); as many names as config entries.";
pin in u32 keycode "Decoder: the key code to decode, applied every period (ignored by a scanner)";
param rw bit negative_logic = 1 "Scan mode: the selected row is driven FALSE (others TRUE) and a FALSE column input means a pressed key";
param rw u32 key_rollover = 2 "Scan mode: most keys held down at once; further presses are ignored until a key is released (values below 1 act as 1)";
variable int nrows;
variable int ncols;
variable int scan;
variable int colbits;
variable int cur_row;
variable int ndown;
variable int primed;
variable int old_neg;
variable int down[64];
variable hal_bit_t *key_pin[64];
variable hal_bit_t *row_pin[8];
variable hal_bit_t *col_pin[8];
variable hal_u32_t *keycode_out;
function _ "Decode the key code (or scan one row) and update the key pins";
option rtapi_app no;
option extra_setup yes;
license "GPL";
author "OpenEMC";
description """Turns key events of a matrix keypad into one HAL bit per key. Each instance is
either a decoder, fed with key codes by hardware that scans the keypad itself (such as a
Mesa 7i73), or a scanner (config entry ending in s) that drives the rows and reads the
columns of a keypad wired to plain I/O pins and produces the same key codes.

Key codes: a key's number is (row << B) + column, where B is the number of bits needed
for a column number (0 for 1 column, 1 for 2, 2 for 3 or 4, 3 for 5 to 8). A key-down event
is 0xC0 + number, a key-up event is 0x80 + number, and 0x40 means all keys are up.
Other codes, and numbers outside the configured matrix, are ignored.

Pins of an instance named P with R rows and C columns:
  P.key.rRcC   bit out  TRUE while the key at row R, column C is down (one per key)
  P.keycode    u32 in   (decoder) key code to decode; it is applied every period
  P.keycode-out u32 out (scanner) the latest key event, 0x40 until the first event
  P.row-NN-out bit out  (scanner) row drive outputs, NN = 00 .. R-1
  P.col-NN-in  bit in   (scanner) column inputs, NN = 00 .. C-1

Scanning: each period the scanner reads the columns of the row it drove in the previous
period (so the read function must run before it and the write function after it in the
thread), reports at most one change of that row (the first changed column) as a key
event, then selects the next row. Other changes of that row are reported on its next
visit, so no event is lost. A full scan takes R periods. When negative-logic is changed
the scanner re-drives the rows and skips reading for one period.""";
;;
#define MKB_MAX_INST 16
#define MKB_MAX_DIM 8
#define MKB_CODE_DOWN 0xC0
#define MKB_CODE_UP 0x80
#define MKB_CODE_ALL_UP 0x40
#define MKB_FLAGS 0xC0
#define MKB_MAX_NAME (HAL_NAME_LEN - 15)

static char *config[MKB_MAX_INST];
RTAPI_MP_ARRAY_STRING(config, MKB_MAX_INST, "RxC or RxCs for each instance");
static char *names[MKB_MAX_INST];
RTAPI_MP_ARRAY_STRING(names, MKB_MAX_INST, "instance names");

/* Parse "RxC" or "RxCs"; return 0 and fill rows, cols, scan, or -EINVAL. */
static int parse_config(const char *s, int *rows, int *cols, int *scan_mode)
{
    if (!s || s[0] < '1' || s[0] > '8' || (s[1] != 'x' && s[1] != 'X') || s[2] < '1' || s[2] > '8')
        return -EINVAL;
    *rows = s[0] - '0';
    *cols = s[2] - '0';
    *scan_mode = s[3] == 's' || s[3] == 'S';
    if (s[3 + *scan_mode] != '\0')
        return -EINVAL;
    return 0;
}

/* Bits needed to hold a column number 0 .. cols-1. */
static int bits_for(int cols)
{
    int b = 0;
    while ((1 << b) < cols) b++;
    return b;
}

/* Create the key.rRcC pins of one instance. */
static int make_key_pins(struct __comp_state *__comp_inst, const char *prefix)
{
    int r, c, i, err;
    for (r = 0; r < nrows; r++) {
        for (c = 0; c < ncols; c++) {
            i = (r << colbits) + c;
            err = hal_pin_bit_newf(HAL_OUT, &key_pin[i], comp_id, "%s.key.r%dc%d", prefix, r, c);
            if (err) return err;
            *key_pin[i] = 0;
        }
    }
    return 0;
}

/* Create the row outputs (row 0 selected, negative logic), column inputs and key code output. */
static int make_scan_pins(struct __comp_state *__comp_inst, const char *prefix)
{
    int i, err;
    for (i = 0; i < nrows; i++) {
        err = hal_pin_bit_newf(HAL_OUT, &row_pin[i], comp_id, "%s.row-%02d-out", prefix, i);
        if (err) return err;
        *row_pin[i] = i != 0;
    }
    for (i = 0; i < ncols; i++) {
        err = hal_pin_bit_newf(HAL_IN, &col_pin[i], comp_id, "%s.col-%02d-in", prefix, i);
        if (err) return err;
    }
    err = hal_pin_u32_newf(HAL_OUT, &keycode_out, comp_id, "%s.keycode-out", prefix);
    if (err) return err;
    *keycode_out = MKB_CODE_ALL_UP;
    return 0;
}

/* Parse this instance's config entry and create its pins. */
EXTRA_SETUP()
{
    int err = parse_config(config[extra_arg], &nrows, &ncols, &scan);
    if (err) return err;
    colbits = bits_for(ncols);
    err = make_key_pins(__comp_inst, prefix);
    if (!err && scan) err = make_scan_pins(__comp_inst, prefix);
    return err;
}

/* Set key number n down or up if it lies inside the matrix; return 1 when it changed. */
static int set_key(struct __comp_state *__comp_inst, unsigned n, int is_down)
{
    unsigned r = n >> colbits, c = n & ((1u << colbits) - 1);
    if (r >= (unsigned)nrows || c >= (unsigned)ncols || down[n] == is_down)
        return 0;
    down[n] = is_down;
    *key_pin[n] = is_down;
    ndown += is_down ? 1 : -1;
    return 1;
}

/* Release every key. */
static void all_up(struct __comp_state *__comp_inst)
{
    unsigned n;
    for (n = 0; n < 64; n++)
        set_key(__comp_inst, n, 0);
}

/* Decoder: apply the key code on the keycode input. */
static void decode(struct __comp_state *__comp_inst)
{
    unsigned code = keycode, flags = code & MKB_FLAGS;
    if (code > 0xFF) return;
    if (flags == MKB_CODE_DOWN) set_key(__comp_inst, code & 0x3F, 1);
    else if (flags == MKB_CODE_UP) set_key(__comp_inst, code & 0x3F, 0);
    else if (flags == MKB_CODE_ALL_UP) all_up(__comp_inst);
}

/* Drive the row outputs so that only cur_row is selected. */
static void drive_rows(struct __comp_state *__comp_inst, int neg)
{
    int i;
    for (i = 0; i < nrows; i++)
        *row_pin[i] = (i == cur_row) != neg;
}

/* Scanner: report the first changed column of the current row, within the rollover limit. */
static void read_row(struct __comp_state *__comp_inst, int neg)
{
    unsigned limit = key_rollover < 1 ? 1 : key_rollover;
    int c;
    for (c = 0; c < ncols; c++) {
        unsigned n = (cur_row << colbits) + c;
        int pressed = *col_pin[c] != neg;
        if (pressed && !down[n] && (unsigned)ndown >= limit) continue;
        if (set_key(__comp_inst, n, pressed)) {
            *keycode_out = (pressed ? MKB_CODE_DOWN : MKB_CODE_UP) + n;
            return;
        }
    }
}

/* Scanner: read the row driven last period, then select the next row. */
static void scan_step(struct __comp_state *__comp_inst)
{
    int neg = negative_logic ? 1 : 0;
    if (primed && neg == old_neg) {
        read_row(__comp_inst, neg);
        cur_row = (cur_row + 1) % nrows;
    }
    primed = 1;
    old_neg = neg;
    drive_rows(__comp_inst, neg);
}

/* One period of one instance. */
FUNCTION(_)
{
    if (scan) scan_step(__comp_inst);
    else decode(__comp_inst);
}

/* Count config entries; report a names= list of another length. */
static int count_instances(void)
{
    int n = 0, k = 0;
    while (n < MKB_MAX_INST && config[n] && config[n][0]) n++;
    while (k < MKB_MAX_INST && names[k] && names[k][0]) k++;
    if (n == 0) {
        rtapi_print_msg(RTAPI_MSG_ERR, "matrix_kb: ERROR: no config given (config=RxC[s],...)\n");
        return -EINVAL;
    }
    if (k && k != n) {
        rtapi_print_msg(RTAPI_MSG_ERR, "matrix_kb: ERROR: names= has %d entries but config= has %d\n", k, n);
        return -EINVAL;
    }
    return n;
}

/* Check every config entry and name before anything is created. */
static int check_configs(int n)
{
    int i, r, c, s;
    for (i = 0; i < n; i++) {
        if (parse_config(config[i], &r, &c, &s)) {
            rtapi_print_msg(RTAPI_MSG_ERR, "matrix_kb: ERROR: config entry %d \"%s\" is not RxC or RxCs "
                            "with 1 to 8 rows and columns\n", i, config[i]);
            return -EINVAL;
        }
        if (names[0] && names[0][0] && strlen(names[i]) > MKB_MAX_NAME) {
            rtapi_print_msg(RTAPI_MSG_ERR, "matrix_kb: ERROR: name \"%s\" is longer than %d characters\n",
                            names[i], MKB_MAX_NAME);
            return -EINVAL;
        }
    }
    return 0;
}

/* Create one instance per config entry. */
int rtapi_app_main(void)
{
    int i, r = 0, n = count_instances();
    char buf[HAL_NAME_LEN + 1];
    if (n < 0) return n;
    if (check_configs(n)) return -EINVAL;
    comp_id = hal_init("matrix_kb");
    if (comp_id < 0) return comp_id;
    for (i = 0; i < n && r == 0; i++) {
        if (names[0] && names[0][0]) rtapi_snprintf(buf, sizeof(buf), "%s", names[i]);
        else rtapi_snprintf(buf, sizeof(buf), "matrix_kb.%d", i);
        r = export(buf, i);
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
