component sim_matrix_kb "Turn simulated key buttons into matrix_kb key codes";
modparam dummy config "config=RxC,... one entry per instance, R rows and C columns (1 to 8 each); default one 8x8 instance.";
modparam dummy names "names=name1,... instance names (default sim-matrix-kb.0, ...); as many names as config entries.";
pin out u32 keycode = 0x40 "The latest key event: 0xC0 + key number when a key goes down, 0x80 + key number when it goes up; 0x40 until the first event";
variable int nrows;
variable int ncols;
variable int colbits;
variable int down[64];
variable hal_bit_t *key_pin[64];
function _ "Report the first key whose input changed as a key event";
option rtapi_app no;
option extra_setup yes;
license "GPL";
author "OpenEMC";
description """Simulates a keypad that scans itself (such as a Mesa 7i73) for a simulated
machine: it watches one bit input per key, typically driven by on-screen buttons, and
emits the key codes that a matrix_kb decoder (or any consumer of that code format)
expects.

Each instance with R rows and C columns has an input pin P.key.rRcC per key. The key
number is (row << B) + column, where B is the number of bits needed for a column number
(0 for 1 column, 1 for 2, 2 for 3 or 4, 3 for 5 to 8), exactly as in matrix_kb, so an
instance configured like the matrix_kb decoder it feeds produces matching codes.

Each period the keys are checked in key-number order and the first one whose input
differs from its last reported state is reported on keycode; further changes follow in
the next periods, one per period, so none is lost. keycode keeps the latest event while
nothing changes.""";
;;
#define SMK_MAX_INST 16
#define SMK_CODE_DOWN 0xC0
#define SMK_CODE_UP 0x80
#define SMK_MAX_NAME (HAL_NAME_LEN - 10)

static char *config[SMK_MAX_INST];
RTAPI_MP_ARRAY_STRING(config, SMK_MAX_INST, "RxC for each instance");
static char *names[SMK_MAX_INST];
RTAPI_MP_ARRAY_STRING(names, SMK_MAX_INST, "instance names");

/* Parse "RxC" (1 to 8 each); return 0 and fill rows and cols, or -EINVAL. */
static int parse_config(const char *s, int *rows, int *cols)
{
    if (!s || s[0] < '1' || s[0] > '8' || (s[1] != 'x' && s[1] != 'X') || s[2] < '1' || s[2] > '8'
        || s[3] != '\0')
        return -EINVAL;
    *rows = s[0] - '0';
    *cols = s[2] - '0';
    return 0;
}

/* Parse this instance's config (8x8 when none was given) and create its key inputs. */
EXTRA_SETUP()
{
    int r, c, err = 0;
    if (config[0] && config[0][0]) err = parse_config(config[extra_arg], &nrows, &ncols);
    else nrows = ncols = 8;
    if (err) return err;
    while ((1 << colbits) < ncols) colbits++;
    for (r = 0; r < nrows; r++) {
        for (c = 0; c < ncols; c++) {
            int n = (r << colbits) + c;
            err = hal_pin_bit_newf(HAL_IN, &key_pin[n], comp_id, "%s.key.r%dc%d", prefix, r, c);
            if (err) return err;
        }
    }
    return 0;
}

/* Emit the event of the first key whose input differs from its reported state. */
FUNCTION(_)
{
    int r, c;
    for (r = 0; r < nrows; r++) {
        for (c = 0; c < ncols; c++) {
            int n = (r << colbits) + c, pressed = *key_pin[n] ? 1 : 0;
            if (pressed != down[n]) {
                down[n] = pressed;
                keycode = (pressed ? SMK_CODE_DOWN : SMK_CODE_UP) + n;
                return;
            }
        }
    }
}

/* Count the instances (config entries, or 1) and check entries and names. */
static int count_instances(void)
{
    int i, r, c, n = 0, k = 0;
    while (n < SMK_MAX_INST && config[n] && config[n][0]) n++;
    while (k < SMK_MAX_INST && names[k] && names[k][0]) k++;
    for (i = 0; i < n; i++) {
        if (parse_config(config[i], &r, &c)) {
            rtapi_print_msg(RTAPI_MSG_ERR, "sim_matrix_kb: ERROR: config entry %d \"%s\" is not RxC "
                            "with 1 to 8 rows and columns\n", i, config[i]);
            return -EINVAL;
        }
    }
    if (n == 0) n = 1;
    if (k && k != n) {
        rtapi_print_msg(RTAPI_MSG_ERR,
                        "sim_matrix_kb: ERROR: names= has %d entries but there are %d instances\n", k, n);
        return -EINVAL;
    }
    for (i = 0; i < k; i++) {
        if (strlen(names[i]) > SMK_MAX_NAME) {
            rtapi_print_msg(RTAPI_MSG_ERR, "sim_matrix_kb: ERROR: name \"%s\" is longer than %d characters\n",
                            names[i], SMK_MAX_NAME);
            return -EINVAL;
        }
    }
    return n;
}

/* Create one instance per config entry. */
int rtapi_app_main(void)
{
    int i, r = 0, n = count_instances();
    char buf[HAL_NAME_LEN + 1];
    if (n < 0) return n;
    comp_id = hal_init("sim_matrix_kb");
    if (comp_id < 0) return comp_id;
    for (i = 0; i < n && r == 0; i++) {
        if (names[0] && names[0][0]) rtapi_snprintf(buf, sizeof(buf), "%s", names[i]);
        else rtapi_snprintf(buf, sizeof(buf), "sim-matrix-kb.%d", i);
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
