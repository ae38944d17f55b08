/* tp_reverse.c: reverse run: back along the executed path (as far as its history reaches) and forward again. */
#include <math.h>
#include "tp_internal.h"

/* Direction motion asks for: reverse run, or a negative adaptive feed while it is enabled. */
int tp_rev_wanted(const tp_planner_t *tp, const tp_cycle_in_t *in, const tp_seg_t *s)
{
    uint32_t en = s ? s->in.enables : 0;
    if (tp->reverse_req)
        return -1;
    return (en & TP_ENABLE_AF) && in->adaptive_feed < 0.0 ? -1 : 1;
}

/* Move the element and region pointers back to the executor position. */
void tp_rev_locate(tp_planner_t *tp)
{
    while (tp->ex.elem > tp->elem_tail && tp->ex.s < tp_elem_at(tp, tp->ex.elem)->s0)
        tp->ex.elem--;
    /* on a region start going backwards the executor is in the region before it */
    while (tp->ex.reg > tp->reg_tail && tp->ex.s <= tp_reg_at(tp, tp->ex.reg)->s0)
        tp->ex.reg--;
}

