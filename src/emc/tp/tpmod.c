/* tpmod.c: the realtime module that exports the planner library to motmod as tp_ops. */
#include "rtapi.h"
#include "rtapi_app.h"
#include "hal.h"
#include "tp_planner.h"

MODULE_LICENSE("GPL");
MODULE_AUTHOR("OpenEMC");
MODULE_DESCRIPTION("Trajectory planner: jerk-limited lookahead planner exported as tp_ops");

/* Accepted and ignored, like LinuxCNC's tpmod. */
static char *tp_parms = "";
RTAPI_MP_STRING(tp_parms, "planner parameters (ignored)");

static int comp_id;

/* The table motmod finds by name and checks with tp_ops_check. */
tp_ops_t tp_ops = {
    TP_OPS_VERSION, sizeof(tp_ops_t), "tpmod",
    tp_planner_create, tp_planner_destroy,
    tp_planner_set_limits, tp_planner_set_term_cond, tp_planner_set_type, tp_planner_set_pos,
    tp_planner_set_spindle_sync, tp_planner_set_dout, tp_planner_set_aout, tp_planner_set_run_dir,
    tp_planner_add, tp_planner_clear, tp_planner_pause, tp_planner_resume, tp_planner_abort,
    tp_planner_run_cycle,
    tp_planner_is_done, tp_planner_queue_depth, tp_planner_queue_full, tp_planner_get_pos,
    tp_planner_type,
};
EXPORT_SYMBOL(tp_ops);

/* Register the pinless component. */
int rtapi_app_main(void)
{
    (void)tp_parms;
    comp_id = hal_init("tpmod");
    if (comp_id < 0)
        return comp_id;
    hal_ready(comp_id);
    return 0;
}

/* Remove the component. */
void rtapi_app_exit(void)
{
    hal_exit(comp_id);
}
