/* kins_ops_check.c: refuse a kinematics ops table built for another interface version. */
#include <errno.h>
#include <stdio.h>
#include "kins_ops.h"

/* 0 when motion can use the table; else a negative errno and the reason. */
int kins_ops_check(const kins_ops_t *ops, char *why, size_t why_size)
{
    if (!ops) {
        snprintf(why, why_size, "module exports no kins_ops table");
        return -EINVAL;
    }
    if (ops->version != KINS_OPS_VERSION || ops->size != sizeof(kins_ops_t)) {
        snprintf(why, why_size, "%s: kins_ops version %u (size %u), motion needs version %u (size %zu)",
                 ops->name ? ops->name : "?", ops->version, ops->size,
                 KINS_OPS_VERSION, sizeof(kins_ops_t));
        return -EPROTO;
    }
    if (!ops->type || !ops->forward || !ops->inverse || !ops->switchable || !ops->switch_type) {
        snprintf(why, why_size, "%s: kins_ops table has an empty entry",
                 ops->name ? ops->name : "?");
        return -EINVAL;
    }
    return 0;
}
