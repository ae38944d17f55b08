/* home_ops_check.c: refuse a homing ops table built for another interface version. */
#include <errno.h>
#include <stdio.h>
#include "home_ops.h"

/* Non-zero when any entry of the table is empty. */
static int has_empty_entry(const home_ops_t *o)
{
    return !o->init || !o->read_inputs || !o->do_homing || !o->write_outputs ||
        !o->home_joint || !o->cancel || !o->set_unhomed || !o->set_params ||
        !o->update_params || !o->set_num_joints || !o->homing_active || !o->joint_homing ||
        !o->joint_homed || !o->joint_at_home || !o->joint_home_state ||
        !o->joint_home_sequence || !o->joint_sync_final_move || !o->joint_volatile ||
        !o->joint_absolute_encoder || !o->joint_home_offset || !o->joint_home;
}

/* 0 when motion can use the table; else a negative errno and the reason. */
int home_ops_check(const home_ops_t *ops, char *why, size_t why_size)
{
    if (!ops) {
        snprintf(why, why_size, "module exports no home_ops table");
        return -EINVAL;
    }
    if (ops->version != HOME_OPS_VERSION || ops->size != sizeof(home_ops_t)) {
        snprintf(why, why_size, "%s: home_ops version %u (size %u), motion needs version %u (size %zu)",
                 ops->name ? ops->name : "?", ops->version, ops->size, HOME_OPS_VERSION,
                 sizeof(home_ops_t));
        return -EPROTO;
    }
    if (has_empty_entry(ops)) {
        snprintf(why, why_size, "%s: home_ops table has an empty entry", ops->name ? ops->name : "?");
        return -EINVAL;
    }
    return 0;
}
