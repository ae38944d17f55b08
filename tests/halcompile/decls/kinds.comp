component kinds "Every declaration kind of the .comp language";
pin in float in_value = 1.5 "An input with a default";
pin out s32 count-out "Name with a dash";
pin io bit flag "Toggled by the funct";
pin out u32 out-#[3] "A pin array";
pin in s64 big = -5 "A 64-bit input";
pin out u64 ubig;
pin in real r = 2.5 "New-API type";
pin out si32 s_out "New-API output written with s_out_set";
param rw float gain_ = 2 "Trailing underscore: HAL name gain";
param r u32 calls "Calls since load";
param rw bit bits-##[2] = TRUE "A param array";
variable double acc = 0.5;
variable int hist[3] = 3;
variable int *ptr;
function _ "Main funct";
function reset_all "Second funct";
modparam int level = 7 "A module parameter";
option extra_setup yes;
option post_export yes;
option extra_cleanup yes;
option data kinds_data;
include <rtapi_math.h>;
license "GPL";
author "OpenEMC tests";
description """Two
lines.""";
notes "Notes text.";
see_also "ddt(9)";
;;
typedef struct { int n; } kinds_data;

EXTRA_SETUP()
{
    data.n = 40 + (int)extra_arg + level;
    ptr = 0;
    return 0;
}

POST_EXPORT()
{
    calls = 100;
    return 0;
}

EXTRA_CLEANUP()
{
    rtapi_print("cleanup\n");
}

FUNCTION(_)
{
    int i;
    acc += in_value * gain_;
    count_out = (int)acc;
    for (i = 0; i < 3; i++) out(i) = hist[i] + i + data.n;
    ubig = big < 0 ? -big : big;
    s_out_set(r * 2);
    calls++;
    flag = !flag;
    if (ptr == 0 && bits(0) && bits(1)) hist[0] = (int)floor(fperiod * 1000.0);
}

FUNCTION(reset_all)
{
    acc = 0;
    calls = 0;
}
