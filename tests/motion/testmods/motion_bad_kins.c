/* motion_bad_kins.c: test module exporting a kins_ops table of another version. */
#include "bad_tables.h"
#include "kins_ops.h"

const kins_ops_t kins_ops = { BAD_VERSION, sizeof(kins_ops_t), "motion_bad_kins",
                              NULL, NULL, NULL, NULL, NULL };
EXPORT_SYMBOL(kins_ops);
BAD_TABLE_MODULE("motion_bad_kins")
