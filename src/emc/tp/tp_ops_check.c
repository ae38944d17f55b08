/* tp_ops_check.c: refuse a planner ops table built for another interface version or with holes. */
#include <errno.h>
#include <stdio.h>
#include "tp_ops.h"

/* 0 when motion can use the table; else a negative errno and the reason. */
int tp_ops_check(const tp_ops_t *ops, char *why, size_t why_size)
{
    if (!ops) {
        snprintf(why, why_size, "module exports no tp_ops table");
        return -EINVAL;
    }
    const char *name = ops->name ? ops->name : "?";
    if (ops->version != TP_OPS_VERSION || ops->size != sizeof(tp_ops_t)) {
        snprintf(why, why_size, "%s: tp_ops version %u (size %u), motion needs version %u (size %zu)",
                 name, ops->version, ops->size, TP_OPS_VERSION, sizeof(tp_ops_t));
        return -EPROTO;
    }
    if (!ops->create || !ops->destroy || !ops->set_limits || !ops->set_term_cond ||
        !ops->set_planner_type || !ops->set_pos || !ops->set_spindle_sync || !ops->set_dout ||
        !ops->set_aout || !ops->set_run_dir || !ops->add || !ops->clear || !ops->pause ||
        !ops->resume || !ops->abort || !ops->run_cycle || !ops->is_done || !ops->queue_depth ||
        !ops->queue_full || !ops->get_pos || !ops->planner_type) {
        snprintf(why, why_size, "%s: tp_ops table has an empty entry", name);
        return -EINVAL;
    }
    return 0;
}
