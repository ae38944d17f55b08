/* kins_entry.c: exports, load, unload and switching shared by every kinematics frame. */
#include "rtapi.h"
#include "rtapi_app.h"
#include "hal.h"
#include "kins_entry.h"

MODULE_LICENSE("GPL");
MODULE_AUTHOR("OpenEMC");

static kins_entry_t entry;   /* the loaded frame's settings */
static int comp_id;

/* The ops table; its name is filled in at load. */
kins_ops_t kins_ops = { KINS_OPS_VERSION, sizeof(kins_ops_t), "kins",
    kinematicsType, kinematicsForward, kinematicsInverse, kinematicsSwitchable, kinematicsSwitch };
EXPORT_SYMBOL(kins_ops);
EXPORT_SYMBOL(kinematicsType);
EXPORT_SYMBOL(kinematicsForward);
EXPORT_SYMBOL(kinematicsInverse);
EXPORT_SYMBOL(kinematicsSwitchable);
EXPORT_SYMBOL(kinematicsSwitch);

/* Keep *e, register the component, run build(comp_id), mark it ready; on failure remove it. */
int kins_entry_start(const kins_entry_t *e)
{
    entry = *e;
    kins_ops.name = entry.name;
    comp_id = hal_init(entry.name);
    if (comp_id < 0)
        return comp_id;
    int r = entry.build(comp_id);
    if (r < 0) {
        hal_exit(comp_id);
        return r;
    }
    hal_ready(comp_id);
    return 0;
}

/* 0 when new_type is 0..highest, else report kinematicsSwitch:BAD VALUE and return -1. */
int kins_switch_valid(int new_type, int highest)
{
    if (new_type >= 0 && new_type <= highest)
        return 0;
    rtapi_print_msg(RTAPI_MSG_ERR, "kinematicsSwitch:BAD VALUE <%d>\n", new_type);
    return -1;
}

/* Non-zero when the loaded frame has more than one kinematics. */
int kinematicsSwitchable(void)
{
    return entry.highest_type > 0;
}

/* Select kinematics 0..highest_type; a no-op returning 0 for non-switchable modules. */
int kinematicsSwitch(int new_type)
{
    if (entry.highest_type == 0)
        return 0;
    if (entry.announce_switch)
        rtapi_print("kinematicsSwitch(): type=%d\n", new_type);
    if (kins_switch_valid(new_type, entry.highest_type) < 0)
        return -1;
    if (entry.switched)
        entry.switched(new_type);
    return 0;
}

/* Remove the component. */
void rtapi_app_exit(void)
{
    hal_exit(comp_id);
}
