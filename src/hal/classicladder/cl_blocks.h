/* cl_blocks.h: the function blocks of a rung (timers, monostables, counters, IEC timers). */
#ifndef CL_BLOCKS_H
#define CL_BLOCKS_H

#include "cl_data.h"

void cl_timer_step(cl_timer_t *t, int enable, int control, long period_ns);
void cl_mono_step(cl_mono_t *mo, int input, long period_ns);
void cl_counter_step(cl_counter_t *c, int reset, int preset, int up, int down);
void cl_timer_iec_step(cl_timer_iec_t *t, int in, long period_ns);

#endif
