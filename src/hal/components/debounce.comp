component debounce "Integrating debounce for groups of bit inputs";
pin in bit #.in[50 : personality] "Raw inputs";
pin out bit #.out[50 : personality] "Debounced outputs";
param rw s32 delay = 5 "Periods an input must agree before the output changes";
variable int counter[50];
function _ "Debounce every input of the group";
option rtapi_app no;
license "GPL";
author "OpenEMC";
description """Load with cfg=n0,n1,... giving the size of each group (at most 8 groups of at most
50 inputs). Group G has pins debounce.G.N.in/out, param debounce.G.delay and funct debounce.G.""";
;;
#define DEB_MAX_GROUPS 8
#define DEB_MAX_SIZE 50
static int cfg[DEB_MAX_GROUPS] = { [0 ... DEB_MAX_GROUPS - 1] = -1 };
RTAPI_MP_ARRAY_INT(cfg, DEB_MAX_GROUPS, "group sizes");

/* Debounce every input of this group. */
FUNCTION(_)
{
    int i, d = delay;
    if (d < 0) d = 0;
    for (i = 0; i < personality; i++) {
        if (_in(i)) {
            if (counter[i] < d) counter[i]++;
            if (counter[i] >= d) _out(i) = 1;
        } else {
            if (counter[i] > 0) counter[i]--;
            if (counter[i] <= 0) _out(i) = 0;
        }
    }
}

/* Create one instance per cfg entry. */
int rtapi_app_main(void)
{
    int g, n = 0, r = 0;
    char buf[HAL_NAME_LEN + 1];
    while (n < DEB_MAX_GROUPS && cfg[n] != -1) n++;
    if (n == 0) {
        rtapi_print_msg(RTAPI_MSG_ERR, "DEBOUNCE: ERROR: no channels configured\n");
        return -EINVAL;
    }
    for (g = 0; g < n; g++) {
        if (cfg[g] < 1 || cfg[g] > DEB_MAX_SIZE) {
            rtapi_print_msg(RTAPI_MSG_ERR, "DEBOUNCE: ERROR: bad group size %d (must be 1..%d)\n",
                            cfg[g], DEB_MAX_SIZE);
            return -EINVAL;
        }
    }
    comp_id = hal_init("debounce");
    if (comp_id < 0) return comp_id;
    for (g = 0; g < n && r == 0; g++) {
        rtapi_snprintf(buf, sizeof(buf), "debounce.%d", g);
        r = export(buf, g, cfg[g]);
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
