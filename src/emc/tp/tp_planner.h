/* tp_planner.h: the planner library's entry points (the functions behind tp_ops). */
#ifndef TP_PLANNER_H
#define TP_PLANNER_H

#include "tp_ops.h"

#ifdef __cplusplus
extern "C" {
#endif

tp_planner_t *tp_planner_create(int queue_size);
void tp_planner_destroy(tp_planner_t *tp);
tp_result_t tp_planner_set_limits(tp_planner_t *tp, const tp_limits_t *limits);
tp_result_t tp_planner_set_term_cond(tp_planner_t *tp, tp_term_cond_t cond, double tolerance);
tp_result_t tp_planner_set_type(tp_planner_t *tp, tp_planner_type_t type);
tp_result_t tp_planner_set_pos(tp_planner_t *tp, const EmcPose *pos);
tp_result_t tp_planner_set_spindle_sync(tp_planner_t *tp, int spindle, double uu_per_rev,
                                        int velocity_mode);
tp_result_t tp_planner_set_dout(tp_planner_t *tp, int index, int start_value, int end_value);
tp_result_t tp_planner_set_aout(tp_planner_t *tp, int index, double start_value, double end_value);
tp_result_t tp_planner_set_run_dir(tp_planner_t *tp, int reverse);
tp_result_t tp_planner_add(tp_planner_t *tp, const tp_segment_t *seg);
tp_result_t tp_planner_clear(tp_planner_t *tp);
tp_result_t tp_planner_pause(tp_planner_t *tp);
tp_result_t tp_planner_resume(tp_planner_t *tp);
tp_result_t tp_planner_abort(tp_planner_t *tp);
tp_result_t tp_planner_run_cycle(tp_planner_t *tp, const tp_cycle_in_t *in, tp_cycle_out_t *out);
int tp_planner_is_done(const tp_planner_t *tp);
int tp_planner_queue_depth(const tp_planner_t *tp);
int tp_planner_queue_full(const tp_planner_t *tp);
int tp_planner_get_pos(const tp_planner_t *tp, EmcPose *pos);
int tp_planner_type(const tp_planner_t *tp);

/* Cycles in which the executor found no safe continuation (0 on a correct run; for tests). */
unsigned long tp_planner_emergencies(const tp_planner_t *tp);

/* The library's table (name "tp"); tpmod exports the same functions as tp_ops. */
extern const tp_ops_t tp_library_ops;

#ifdef __cplusplus
}
#endif

#endif
