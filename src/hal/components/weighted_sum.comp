component weighted_sum "Weighted sum of groups of bit inputs";
pin in bit bit.#.in[32 : personality] "Bit inputs";
pin in bit hold "When TRUE, sum keeps its value";
pin out s32 sum "offset plus the weights of all TRUE inputs";
pin io s32 bit.#.weight[32 : personality] "Weight of each input (preset 2^M)";
pin io s32 offset "Added to the sum";
option rtapi_app no;
option post_export yes;
license "GPL";
author "OpenEMC";
description """Load with wsum_sizes=N0,N1,... (at most 8 summers of 1 to 32 bits; the list ends at
the first entry not given). Summer G has pins wsum.G.bit.M.in, wsum.G.bit.M.weight, wsum.G.offset,
wsum.G.hold, wsum.G.sum; one funct process_wsums updates every summer. While hold is TRUE sum
keeps its value; otherwise sum is offset plus the weights of the TRUE bits (32-bit wrap-around).""";
;;
#define WSUM_MAX_GROUPS 8
static int wsum_sizes[WSUM_MAX_GROUPS] = { [0 ... WSUM_MAX_GROUPS - 1] = -1 };
RTAPI_MP_ARRAY_INT(wsum_sizes, WSUM_MAX_GROUPS, "number of bits of each group");

/* Default weights are the binary place values. */
POST_EXPORT()
{
    int i;
    for (i = 0; i < personality; i++) bit_weight(i) = (hal_s32_t)(1u << i);
    return 0;
}

/* Sum one group. */
static void wsum_one(struct __comp_state *__comp_inst)
{
    int i;
    unsigned int s = (unsigned int)offset;  /* wraps like a 32-bit register, no UB */
    if (hold) return;
    for (i = 0; i < personality; i++)
        if (bit_in(i)) s += (unsigned int)bit_weight(i);
    sum = (hal_s32_t)s;
}

/* Funct process_wsums: every group. */
static void wsum_process(void *arg, long period)
{
    (void)arg;
    (void)period;
    FOR_ALL_INSTS() wsum_one(__comp_inst);
}

/* Create the configured groups and the shared funct. */
int rtapi_app_main(void)
{
    int g, n = 0, r = 0;
    char buf[HAL_NAME_LEN + 1];
    while (n < WSUM_MAX_GROUPS && wsum_sizes[n] != -1) n++;
    if (n == 0) {
        rtapi_print_msg(RTAPI_MSG_ERR, "WEIGHTED_SUM: ERROR: no summers specified\n");
        return -EINVAL;
    }
    for (g = 0; g < n; g++) {
        if (wsum_sizes[g] < 1 || wsum_sizes[g] > 32) {
            rtapi_print_msg(RTAPI_MSG_ERR,
                            "WEIGHTED_SUM: ERROR: Invalid number of bits '%i' for summer %i%s\n",
                            wsum_sizes[g], g, wsum_sizes[g] > 32 ? " (at most 32)" : "");
            return -EINVAL;
        }
    }
    comp_id = hal_init("weighted_sum");
    if (comp_id < 0) return comp_id;
    for (g = 0; g < n && r == 0; g++) {
        rtapi_snprintf(buf, sizeof(buf), "wsum.%d", g);
        r = export(buf, g, wsum_sizes[g]);
    }
    if (r == 0) r = hal_export_funct("process_wsums", wsum_process, 0, 1, 0, comp_id);
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
