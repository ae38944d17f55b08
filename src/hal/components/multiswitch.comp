component multiswitch "Step through N positions with up and down buttons, one output bit per position";
description """
Load with \\fBcfg=\\fR the number of positions of each instance (up to 32 instances; without
cfg one instance with 4 positions).  \\fBtop-position\\fR may be set lower than the number of
bits; stepping past either end wraps around.
""";
pin in bit up "Rising edge: next position";
pin in bit down "Rising edge: previous position";
pin out bit bit-##[32 : personality] "TRUE at position NN";
param rw u32 top_position "Highest position (the number of bits - 1 at load)";
param rw s32 position "Current position";
variable int last_up;
variable int last_down;
option count_function yes;
option extra_setup yes;
option post_export yes;
function _;
license "GPL";
author "OpenEMC";
;;
#define MS_MAX_INST 32
#define MS_MAX_BITS 32
static int cfg[MS_MAX_INST];
RTAPI_MP_ARRAY_INT(cfg, MS_MAX_INST, "number of positions of each instance");

/* Instances: leading non-zero cfg entries; one of 4 positions without cfg. */
int get_count(void)
{
    int n = 0;
    if (cfg[0] == 0) {
        cfg[0] = 4;
        return 1;
    }
    while (n < MS_MAX_INST && cfg[n] != 0)
        n++;
    return n;
}

/* The number of positions of this instance (1..32). */
EXTRA_SETUP()
{
    (void)prefix;
    if (cfg[extra_arg] < 1 || cfg[extra_arg] > MS_MAX_BITS) {
        rtapi_print_msg(RTAPI_MSG_ERR, "multiswitch: cfg[%ld]=%d: the number of positions must be 1..%d\n",
                        extra_arg, cfg[extra_arg], MS_MAX_BITS);
        return -EINVAL;
    }
    personality = cfg[extra_arg];
    return 0;
}

/* top-position starts at the last bit. */
POST_EXPORT()
{
    (void)prefix;
    (void)extra_arg;
    top_position = personality - 1;
    return 0;
}

FUNCTION(_)
{
    (void)period;
    if (up && !last_up)
        position++;
    if (down && !last_down)
        position--;
    last_up = up;
    last_down = down;
    if (position < 0)
        position = top_position;
    if ((hal_u32_t)position > top_position)
        position = 0;
    for (int i = 0; i < personality && i < MS_MAX_BITS; i++)
        bit(i) = i == position;
}
