/* tpb.h: the planner bench's program model (moves as canon would send them) and its metrics. */
#ifndef TPB_H
#define TPB_H

#include "tp_planner.h"

/* Moves motion hands the planner per servo cycle at most (the rest wait in its command ring). */
#define TPB_ADDS_PER_CYCLE 8

/* One programmed move in mm (what the interpreter and canon would produce). */
typedef struct tpb_move {
    int arc;                    /* 0 line, 1 arc */
    int turn;                   /* arc: extra full turns */
    double end[3];
    double center[3];
    double normal[3];           /* arc: unit normal, counter-clockwise about it */
    double feed;                /* mm/min */
    double tol;                 /* G64 P (0 = none) */
    double naive;               /* G64 Q */
    int exact;                  /* G61 */
    int line;                   /* source line for reporting */
} tpb_move_t;

typedef struct tpb_program {
    const char *name;
    int n, cap;
    tpb_move_t *m;
    double start[3];
} tpb_program_t;

/* The bench machine: per-axis limits, the path jerk (0 = trapezoid), servo period. */
typedef struct tpb_machine {
    double vel[3], acc[3], jerk;
    double vtraj, atraj;
    double period;
} tpb_machine_t;

/* Servo samples of a run: positions per cycle. */
typedef struct tpb_trace {
    int n, cap;
    double (*p)[3];
    unsigned char *rapid;
} tpb_trace_t;

/* What the bench reports per program. */
typedef struct tpb_result {
    long cycles;
    double feed_bound, pass_bound;
    double vel_ratio, acc_ratio, jerk_ratio;
    long vel_viol, acc_viol, jerk_viol;
    double max_dev, max_miss, tol;
    long dev_viol, miss_viol;
} tpb_result_t;

/* tpb_programs.c */
int tpb_make(tpb_program_t *p, const char *name);
void tpb_free(tpb_program_t *p);
extern const char *const tpb_names[];
int tpb_make_long(tpb_program_t *p, int segments);
/* tpb_canon.c */
int tpb_load_canon(tpb_program_t *p, const char *path);
/* tpb_metrics.c */
void tpb_naive_merge(const tpb_program_t *p, tpb_program_t *out);
void tpb_measure(const tpb_program_t *p, const tpb_machine_t *mc, const tpb_trace_t *tr, tpb_result_t *r);
/* tpb_run.c */
int tpb_run(const tpb_program_t *p, const tpb_machine_t *mc, int queue, tpb_trace_t *tr,
            double *cpu_us, long cpu_cap, long *cycles_out);
int tpb_run_split(const tpb_program_t *p, const tpb_machine_t *mc, int queue, tpb_trace_t *tr,
                  double *cpu_us, long cpu_cap, long *cycles_out, double *add_cpu, double *cycle_cpu);
void tpb_segment(const tpb_program_t *p, const tpb_machine_t *mc, int k, const double *from,
                 tp_segment_t *s);

#endif
