/* tpb_run.c: feed a program to the planner library as motion would (queue kept full) and record every cycle. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include "tpb.h"

/* Largest speed (or acceleration) along unit direction u with per-axis limits lim. */
static double along(const double *u, const double *lim, double cap)
{
    double m = cap;
    for (int i = 0; i < 3; i++)
        if (fabs(u[i]) > 1e-12)
            m = fmin(m, lim[i] / fabs(u[i]));
    return m;
}

/* The segment canon would send for move k starting at from: speeds, limits along the move. */
void tpb_segment(const tpb_program_t *p, const tpb_machine_t *mc, int k, const double *from, tp_segment_t *s)
{
    const tpb_move_t *m = &p->m[k];
    memset(s, 0, sizeof(*s));
    s->kind = m->arc ? TP_SEG_CIRCLE : TP_SEG_LINE;
    s->motion_type = m->arc ? TP_MOTION_ARC : TP_MOTION_FEED;
    s->end.tran.x = m->end[0];
    s->end.tran.y = m->end[1];
    s->end.tran.z = m->end[2];
    s->vel = m->feed / 60.0;
    double d[3] = {m->end[0] - from[0], m->end[1] - from[1], m->end[2] - from[2]};
    double len = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    if (m->arc) {
        double plane[3];
        for (int i = 0; i < 3; i++)
            plane[i] = fabs(m->normal[i]) > 0.5 ? 0.0 : 1.0;
        double v = 1e9, a = 1e9;
        for (int i = 0; i < 3; i++)
            if (plane[i] > 0.0) {
                v = fmin(v, mc->vel[i]);
                a = fmin(a, mc->acc[i]);
            }
        s->ini_maxvel = fmin(v, mc->vtraj);
        s->acc = a;
        s->center.x = m->center[0];
        s->center.y = m->center[1];
        s->center.z = m->center[2];
        s->normal.x = m->normal[0];
        s->normal.y = m->normal[1];
        s->normal.z = m->normal[2];
        s->turn = m->turn;
    } else {
        double u[3] = {0, 0, 0};
        for (int i = 0; i < 3 && len > 0.0; i++)
            u[i] = d[i] / len;
        s->ini_maxvel = along(u, mc->vel, mc->vtraj);
        s->acc = along(u, mc->acc, 1e9);
        /* canon's jerk along a line: the per-axis limits projected, no path cap */
        const double jerk3[3] = {mc->jerk, mc->jerk, mc->jerk};
        s->jerk = mc->jerk > 0.0 ? along(u, jerk3, 1e18) : 0.0;
    }
    if (m->feed >= 1e8) {       /* a rapid: the machine velocity along the move */
        s->motion_type = TP_MOTION_TRAVERSE;
        s->vel = s->ini_maxvel;
    }
    if (m->arc)
        s->jerk = mc->jerk;
    s->enables = TP_ENABLE_FS | TP_ENABLE_FH;
    s->indexer_jnum = -1;
    s->id = m->line;
}

/* Planner set up for the bench machine. */
static tp_planner_t *bench_planner(const tpb_machine_t *mc, int queue)
{
    tp_planner_t *tp = tp_planner_create(queue);
    tp_limits_t l;
    memset(&l, 0, sizeof(l));
    l.cycle_time = mc->period;
    l.vlimit = mc->vtraj;
    l.amax = mc->atraj;
    l.jmax = mc->jerk;
    l.max_feed_override = 1.0;
    for (int i = 0; i < 3; i++) {
        l.axis_vel[i] = mc->vel[i];
        l.axis_acc[i] = mc->acc[i];
        l.axis_jerk[i] = mc->jerk;
    }
    tp_planner_set_limits(tp, &l);
    if (mc->jerk > 0.0)
        tp_planner_set_type(tp, TP_PLANNER_SCURVE);
    return tp;
}

/* Add moves from *next while the queue has room, at most max of them (motion's per-cycle share). */
static void fill(tp_planner_t *tp, const tpb_program_t *p, const tpb_machine_t *mc, int *next, double *at,
                 int max)
{
    for (int added = 0; added < max && *next < p->n && !tp_planner_queue_full(tp); added++) {
        const tpb_move_t *m = &p->m[*next];
        tp_segment_t s;
        tpb_segment(p, mc, *next, at, &s);
        tp_planner_set_term_cond(tp, m->exact ? TP_TERM_COND_EXACT : TP_TERM_COND_BLEND, m->tol);
        tp_result_t r = tp_planner_add(tp, &s);
        if (r == TP_QUEUE_FULL)
            break;
        if (r == TP_OK)
            memcpy(at, m->end, sizeof(m->end));
        (*next)++;
    }
}

static double thread_cpu(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

/* Run the program to completion; record positions (tr may be NULL) and the CPU microseconds of
 * each of the first cpu_cap cycles (adds and run_cycle; cpu_us may be NULL). */
int tpb_run(const tpb_program_t *p, const tpb_machine_t *mc, int queue, tpb_trace_t *tr,
            double *cpu_us, long cpu_cap, long *cycles_out)
{
    return tpb_run_split(p, mc, queue, tr, cpu_us, cpu_cap, cycles_out, NULL, NULL);
}

/* As tpb_run, also adding up the CPU seconds spent adding moves and running cycles. */
int tpb_run_split(const tpb_program_t *p, const tpb_machine_t *mc, int queue, tpb_trace_t *tr,
                  double *cpu_us, long cpu_cap, long *cycles_out, double *add_cpu, double *cycle_cpu)
{
    tp_planner_t *tp = bench_planner(mc, queue);
    int next = 0;
    double at[3] = {p->start[0], p->start[1], p->start[2]};
    tp_cycle_in_t in;
    tp_cycle_out_t out;
    memset(&in, 0, sizeof(in));
    in.feed_scale = in.rapid_scale = in.adaptive_feed = 1.0;
    in.num_spindles = 1;
    /* the clock itself costs time: measure it to take it out of the split */
    double clock_cost = 0.0;
    if (add_cpu) {
        double c0 = thread_cpu();
        for (int k = 0; k < 10000; k++)
            thread_cpu();
        clock_cost = (thread_cpu() - c0) / 10001.0;
    }
    double t_start = add_cpu ? thread_cpu() : 0.0;
    fill(tp, p, mc, &next, at, 1 << 30); /* held start: the queue is full before motion */
    long cycles = 0;
    for (;;) {
        double t0 = cpu_us ? thread_cpu() : 0.0;
        fill(tp, p, mc, &next, at, TPB_ADDS_PER_CYCLE);
        double t1 = add_cpu ? thread_cpu() : 0.0;
        tp_planner_run_cycle(tp, &in, &out);
        if (add_cpu)
            *cycle_cpu += thread_cpu() - t1 - clock_cost;
        if (cpu_us && cycles < cpu_cap)
            cpu_us[cycles] = (thread_cpu() - t0) * 1e6;
        cycles++;
        if (tr) {
            if (tr->n == tr->cap) {
                tr->cap = tr->cap ? 2 * tr->cap : 65536;
                tr->p = realloc(tr->p, (size_t)tr->cap * sizeof(*tr->p));
            }
            tr->p[tr->n][0] = out.pos.tran.x;
            tr->p[tr->n][1] = out.pos.tran.y;
            tr->p[tr->n][2] = out.pos.tran.z;
            tr->n++;
        }
        if (out.done && next >= p->n)
            break;
        if (cycles > 100000000L)
            break;
    }
    if (add_cpu)
        *add_cpu = thread_cpu() - t_start - *cycle_cpu - 2.0 * clock_cost * cycles;
    if (cycles_out)
        *cycles_out = cycles;
    unsigned long em = tp_planner_emergencies(tp);
    tp_planner_destroy(tp);
    return (int)em;
}
