/* motion_bad_tp.c: test module exporting a tp_ops table of another version. */
#include "bad_tables.h"
#include "tp_ops.h"

const tp_ops_t tp_ops = { .version = BAD_VERSION, .size = sizeof(tp_ops_t), .name = "motion_bad_tp" };
EXPORT_SYMBOL(tp_ops);
BAD_TABLE_MODULE("motion_bad_tp")
