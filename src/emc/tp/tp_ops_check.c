/* tp_ops_check.c: refuse a planner ops table built for another interface version. */
#include <errno.h>
#include <stdio.h>
#include "tp_ops.h"

/* Non-zero when any entry of the table is empty. */
static int has_empty_entry(const tp_ops_t *o)
{
    return !o->create || !o->destroy || !o->set_limits || !o->set_term_cond ||
        !o->set_planner_type || !o->set_pos || !o->set_spindle_sync || !o->set_dout ||
        !o->set_aout || !o->set_run_dir || !o->add || !o->clear || !o->pause || !o->resume ||
        !o->abort || !o->run_cycle || !o->is_done || !o->queue_depth || !o->queue_full ||
        !o->get_pos || !o->planner_type;
}

/* 0 when motion can use the table; else a negative errno and the reason. */
int tp_ops_check(const tp_ops_t *ops, char *why, size_t why_size)
{
    if (!ops) {
        snprintf(why, why_size, "module exports no tp_ops table");
        return -EINVAL;
    }
    if (ops->version != TP_OPS_VERSION || ops->size != sizeof(tp_ops_t)) {
        snprintf(why, why_size, "%s: tp_ops version %u (size %u), motion needs version %u (size %zu)",
                 ops->name ? ops->name : "?", ops->version, ops->size, TP_OPS_VERSION,
                 sizeof(tp_ops_t));
        return -EPROTO;
    }
    if (has_empty_entry(ops)) {
        snprintf(why, why_size, "%s: tp_ops table has an empty entry", ops->name ? ops->name : "?");
        return -EINVAL;
    }
    return 0;
}
