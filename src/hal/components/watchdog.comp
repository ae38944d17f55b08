component watchdog "Check that several bit inputs keep toggling";
pin in bit input-#[32 : personality] "Inputs that must change state within their timeout";
pin in bit enable_in "A rising edge (re)arms the watchdog";
pin out bit ok_out "TRUE while armed and every input toggled in time";
param rw float timeout-#[32 : personality] "Seconds each input may stay unchanged";
variable int last[32];
variable double quiet[32];
variable int old_enable;
variable int armed;
function process "Check the inputs";
function set_timeouts "Accept changed timeouts (negative values are made positive)";
option rtapi_app no;
option singleton yes;
license "GPL";
author "OpenEMC";
description "Load with num_inputs=N (1 to 32). Pins and functs are named watchdog.*.";
;;
static int num_inputs = 0;
RTAPI_MP_INT(num_inputs, "number of inputs (1 to 32)");

/* Watch every input; any input quiet for longer than its timeout drops ok-out. */
FUNCTION(process)
{
    int i, en = enable_in;
    if (en && !old_enable) {
        armed = 1;
        for (i = 0; i < personality; i++) {
            quiet[i] = 0;
            last[i] = input(i);
        }
    }
    old_enable = en;
    if (!en) armed = 0;
    for (i = 0; i < personality && armed; i++) {
        int v = input(i);
        if (v != last[i]) quiet[i] = 0;
        else quiet[i] += fperiod;
        last[i] = v;
        if (!(quiet[i] <= timeout(i))) armed = 0;  /* a NaN timeout counts as expired */
    }
    ok_out = armed;
}

/* Make every timeout non-negative. */
FUNCTION(set_timeouts)
{
    int i;
    for (i = 0; i < personality; i++)
        if (timeout(i) < 0) timeout(i) = -timeout(i);
}

/* Create the watchdog with num_inputs inputs. */
int rtapi_app_main(void)
{
    int r;
    if (num_inputs < 1 || num_inputs > 32) {
        rtapi_print_msg(RTAPI_MSG_ERR, "WATCHDOG: ERROR: num_inputs must be 1 to 32, got %d\n", num_inputs);
        return -EINVAL;
    }
    comp_id = hal_init("watchdog");
    if (comp_id < 0) return comp_id;
    r = export("watchdog", 0, num_inputs);
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
