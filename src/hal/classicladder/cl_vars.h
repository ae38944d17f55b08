/* cl_vars.h: reading, writing and naming PLC variables (%B, %W, %I, %Q, %T0.D, ...). */
#ifndef CL_VARS_H
#define CL_VARS_H

#include "cl_data.h"

/* Description of one variable type. */
typedef struct {
    int type;
    const char *prefix;       /* "%W", "%T" ... */
    const char *suffix;       /* "" or ".D", ".V" ... */
    int size_index;           /* CL_N_* bounding the number */
    int writable;
} cl_var_desc_t;

const cl_var_desc_t *cl_var_desc(int type);
int cl_var_count(const cl_mem_t *m, int type);
int32_t cl_var_read(const cl_mem_t *m, int type, int num);
void cl_var_write(cl_mem_t *m, int type, int num, int32_t value);
int cl_var_parse(const char *text, int *type, int *num);

#endif
