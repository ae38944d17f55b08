component modmath "Shortest direction from an actual to a desired position on a ring (tool turret) or a range";
pin in s32 actual "Current position (for example of a tool changer carousel)";
pin in s32 desired "Wanted position";
pin io s32 min_num = 0 "Lowest position";
pin io s32 max_num = 15 "Highest position";
pin io bit wrap = TRUE "TRUE: max-num is followed by min-num (a ring); FALSE: a plain range";
pin out bit up "TRUE when the shorter way from actual to desired is upward";
pin out bit down "TRUE when the shorter way from actual to desired is downward";
pin out bit on_target = TRUE "TRUE when actual equals desired";
function _;
option rtapi_app no;
include "modmath_dir.h";
license "GPL";
author "OpenEMC";
description """Load with mod_dir=N for N instances mod-dir.0 ... (0, the default, loads the
component without instances); each has a funct of the same name. Positions outside
min-num..max-num are folded into the range with C's remainder, as LinuxCNC does (so a
value below min-num can stay below it: min 0, max 15, -1 stays -1). With wrap TRUE a
distance of more than half the range goes the other way round (with an even range exactly
half goes up); with wrap FALSE the direction is the sign of desired - actual. If max-num is
below min-num nothing is folded or wrapped.""";
;;
static int mod_dir = 0;
RTAPI_MP_INT(mod_dir, "number of mod-dir instances");

FUNCTION(_)
{
    int d = modmath_direction(actual, desired, min_num, max_num, wrap);
    up = d > 0;
    down = d < 0;
    on_target = d == 0;
}

/* Create mod_dir instances mod-dir.0 ... */
int rtapi_app_main(void)
{
    int i, r = 0;
    char buf[HAL_NAME_LEN + 1];
    if (mod_dir < 0) {
        rtapi_print_msg(RTAPI_MSG_ERR, "modmath: ERROR: mod_dir=%d is negative\n", mod_dir);
        return -EINVAL;
    }
    comp_id = hal_init("modmath");
    if (comp_id < 0) return comp_id;
    for (i = 0; i < mod_dir && r == 0; i++) {
        rtapi_snprintf(buf, sizeof(buf), "mod-dir.%d", i);
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
