/* bad_tables.h: a pinless module exporting one ops table of the wrong version (test fixture). */
#ifndef BAD_TABLES_H
#define BAD_TABLES_H

#include "rtapi.h"
#include "rtapi_app.h"
#include "hal.h"

#define BAD_VERSION 99u

/* Entry points of a pinless component called name. */
#define BAD_TABLE_MODULE(name) \
    MODULE_LICENSE("GPL"); \
    static int comp_id; \
    int rtapi_app_main(void) \
    { \
        comp_id = hal_init(name); \
        if (comp_id < 0) \
            return comp_id; \
        hal_ready(comp_id); \
        return 0; \
    } \
    void rtapi_app_exit(void) \
    { \
        hal_exit(comp_id); \
    }

#endif
