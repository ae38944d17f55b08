/* cl_eval.h: one PLC scan over the loaded sections (no HAL, no allocation). */
#ifndef CL_EVAL_H
#define CL_EVAL_H

#include "cl_data.h"

/* Width and height of the block an element occupies (main cell at its top-right). */
typedef struct {
    int width, height;
} cl_block_t;

cl_block_t cl_element_block(int type);
void cl_scan(cl_mem_t *m, long period_ns);

#endif
