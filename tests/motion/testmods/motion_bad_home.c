/* motion_bad_home.c: test module exporting a home_ops table of another version. */
#include "bad_tables.h"
#include "home_ops.h"

const home_ops_t home_ops = { .version = BAD_VERSION, .size = sizeof(home_ops_t),
                              .name = "motion_bad_home" };
EXPORT_SYMBOL(home_ops);
BAD_TABLE_MODULE("motion_bad_home")
