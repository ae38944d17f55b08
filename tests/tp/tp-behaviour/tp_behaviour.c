/* tp_behaviour.c: LinuxCNC's planner behaviour (motion.md sec. 11) through the library, one scenario per function. */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "tp_planner.h"

#define T 0.001

/* The machine of motion.md sec. 11: axis velocity 4, acceleration 100, MAX_LINEAR_VELOCITY 5. */
static tp_planner_t *machine(double jerk)
{
    tp_planner_t *tp = tp_planner_create(200);
    tp_limits_t l;
    memset(&l, 0, sizeof(l));
    l.cycle_time = T;
    l.vlimit = 5.0;
    l.amax = 100.0;
    l.jmax = jerk;
    l.max_feed_override = 1.2;
    for (int i = 0; i < TP_NUM_AXES; i++) {
        l.axis_vel[i] = 4.0;
        l.axis_acc[i] = 100.0;
        l.axis_jerk[i] = jerk;
    }
    tp_planner_set_limits(tp, &l);
    if (jerk > 0.0)
        tp_planner_set_type(tp, TP_PLANNER_SCURVE);
    return tp;
}

/* A feed move to (x, y, z) at vel units/s, id = line. */
static tp_segment_t move(double x, double y, double z, double vel, int id)
{
    tp_segment_t s;
    memset(&s, 0, sizeof(s));
    s.kind = TP_SEG_LINE;
    s.motion_type = TP_MOTION_FEED;
    s.end.tran.x = x;
    s.end.tran.y = y;
    s.end.tran.z = z;
    s.vel = vel;
    s.ini_maxvel = 5.0;
    s.acc = 100.0;
    s.enables = TP_ENABLE_FS | TP_ENABLE_FH | TP_ENABLE_AF;
    s.indexer_jnum = -1;
    s.id = id;
    return s;
}

/* Inputs at 100 % with one spindle. */
static tp_cycle_in_t inputs(void)
{
    tp_cycle_in_t in;
    memset(&in, 0, sizeof(in));
    in.feed_scale = in.rapid_scale = in.adaptive_feed = 1.0;
    in.num_spindles = 1;
    return in;
}

/* Sampled path speed between two outputs. */
static double speed(const tp_cycle_out_t *a, const tp_cycle_out_t *b)
{
    double dx = b->pos.tran.x - a->pos.tran.x, dy = b->pos.tran.y - a->pos.tran.y;
    double dz = b->pos.tran.z - a->pos.tran.z;
    return sqrt(dx * dx + dy * dy + dz * dz) / T;
}

/* Run until done (at most n cycles); report the smallest speed near x = xs and the peak speed. */
static void run_probe(tp_planner_t *tp, tp_cycle_in_t *in, double xs, double *v_at, double *v_peak,
                      int *cycles)
{
    tp_cycle_out_t prev, out;
    memset(&prev, 0, sizeof(prev));
    tp_planner_get_pos(tp, &prev.pos);
    *v_at = 1e9;
    *v_peak = 0.0;
    for (int k = 0; k < 200000; k++) {
        tp_planner_run_cycle(tp, in, &out);
        double v = speed(&prev, &out);
        *v_peak = fmax(*v_peak, v);
        if (fabs(out.pos.tran.x - xs) < 0.02 && fabs(out.pos.tran.y) < 1e-9 + fabs(out.pos.tran.y))
            *v_at = fmin(*v_at, v);
        prev = out;
        if (out.done) {
            *cycles = k + 1;
            return;
        }
    }
    *cycles = -1;
}

/* G61.1 stops between collinear moves; G61 keeps speed through them. */
static void exact_modes(void)
{
    static const char *name[] = {"G61.1", "G61"};
    for (int m = 0; m < 2; m++) {
        tp_planner_t *tp = machine(0.0);
        tp_cycle_in_t in = inputs();
        tp_planner_set_term_cond(tp, m == 0 ? TP_TERM_COND_STOP : TP_TERM_COND_EXACT, 0.0);
        tp_segment_t a = move(2, 0, 0, 2.0, 1), b = move(3, 0, 0, 2.0, 2);
        tp_planner_add(tp, &a);
        tp_planner_add(tp, &b);
        double v_at, v_peak;
        int n;
        run_probe(tp, &in, 2.0, &v_at, &v_peak, &n);
        printf("%s collinear: speed at X2 %.3f, peak %.3f\n", name[m], v_at, v_peak);
        tp_planner_destroy(tp);
    }
}

/* Corner speed at a 90 degree corner: G61 stops, G64 keeps the feed, G64 P0.001 slows down. */
static void corner_modes(void)
{
    struct { const char *name; tp_term_cond_t c; double p; } mode[] = {
        {"G61", TP_TERM_COND_EXACT, 0.0}, {"G64", TP_TERM_COND_BLEND, 0.0},
        {"G64 P0.001", TP_TERM_COND_BLEND, 0.001}};
    for (int m = 0; m < 3; m++) {
        tp_planner_t *tp = machine(0.0);
        tp_cycle_in_t in = inputs();
        tp_planner_set_term_cond(tp, mode[m].c, mode[m].p);
        tp_segment_t a = move(2, 0, 0, 2.0, 1), b = move(2, 2, 0, 2.0, 2);
        tp_planner_add(tp, &a);
        tp_planner_add(tp, &b);
        tp_cycle_out_t prev, out;
        memset(&prev, 0, sizeof(prev));
        double v_corner = 1e9, dev = 0.0;
        for (int k = 0; k < 20000; k++) {
            tp_planner_run_cycle(tp, &in, &out);
            double dx = out.pos.tran.x - 2.0, dy = out.pos.tran.y;
            if (fabs(dx) < 0.05 && fabs(dy) < 0.05)
                v_corner = fmin(v_corner, speed(&prev, &out));
            dev = fmax(dev, fmin(fabs(dy) + (out.pos.tran.x > 2.0 ? 1e9 : 0.0), fabs(dx)));
            prev = out;
            if (out.done)
                break;
        }
        printf("%s corner: lowest speed %.3f, within tolerance %s\n", mode[m].name, v_corner,
               mode[m].p > 0.0 ? (dev <= mode[m].p ? "yes" : "no") : "n/a");
        tp_planner_destroy(tp);
    }
}

/* Peak speed of a long X move with the given feed, feed scale and rapid/feed type. */
static double peak(double vel, double fs, double rs, int rapid, double af)
{
    tp_planner_t *tp = machine(0.0);
    tp_cycle_in_t in = inputs();
    in.feed_scale = fs;
    in.rapid_scale = rs;
    in.adaptive_feed = af;
    tp_segment_t a = move(20, 0, 0, vel, 1);
    if (rapid)
        a.motion_type = TP_MOTION_TRAVERSE;
    if (af != 1.0)
        a.enables |= TP_ENABLE_AF;
    else
        a.enables &= ~TP_ENABLE_AF;
    tp_planner_add(tp, &a);
    double v_at, v_peak;
    int n;
    run_probe(tp, &in, -1, &v_at, &v_peak, &n);
    tp_planner_destroy(tp);
    return v_peak;
}

/* Feed override, MAX_FEED_OVERRIDE, rapid override, adaptive feed, axis and linear limits. */
static void overrides(void)
{
    printf("F120 at 50%%: %.3f\n", peak(2.0, 0.5, 1.0, 0, 1.0));
    printf("F120 at 200%% (MAX_FEED_OVERRIDE 1.2): %.3f\n", peak(2.0, 2.0, 1.0, 0, 1.0));
    printf("G0 at rapid 25%%: %.3f\n", peak(4.0, 1.0, 0.25, 1, 1.0));
    printf("F120 at rapid 25%%: %.3f\n", peak(2.0, 1.0, 0.25, 0, 1.0));
    printf("F120 adaptive 0.25: %.3f\n", peak(2.0, 1.0, 1.0, 0, 0.25));
    printf("G0 along X: %.3f\n", peak(10.0, 1.0, 1.0, 1, 1.0));
}

/* Feed hold stops the move and resuming finishes it; the end point is exact. */
static void hold_and_pause(void)
{
    for (int kind = 0; kind < 2; kind++) {
        tp_planner_t *tp = machine(0.0);
        tp_cycle_in_t in = inputs();
        tp_segment_t a = move(10, 0, 0, 3.0, 7);
        tp_planner_add(tp, &a);
        tp_cycle_out_t out, prev;
        memset(&prev, 0, sizeof(prev));
        int stopped_at = -1, done_at = -1;
        for (int k = 0; k < 20000; k++) {
            if (k == 1000) {
                if (kind == 0)
                    in.feed_hold = 1;
                else
                    tp_planner_pause(tp);
            }
            if (k == 3000) {
                in.feed_hold = 0;
                tp_planner_resume(tp);
            }
            tp_planner_run_cycle(tp, &in, &out);
            if (k > 1000 && k < 3000 && stopped_at < 0 && speed(&prev, &out) == 0.0)
                stopped_at = k;
            prev = out;
            if (out.done) {
                done_at = k;
                break;
            }
        }
        printf("%s: at rest %d cycles after it, paused flag %d, done %s, end X %.6f\n",
               kind == 0 ? "feed hold" : "pause", stopped_at - 1000, kind == 1, done_at > 0 ? "yes" : "no",
               out.pos.tran.x);
        tp_planner_destroy(tp);
    }
}

/* Abort decelerates, drops the queue and leaves the position where it stopped. */
static void abort_move(void)
{
    tp_planner_t *tp = machine(0.0);
    tp_cycle_in_t in = inputs();
    tp_segment_t a = move(10, 0, 0, 3.0, 1), b = move(10, 10, 0, 3.0, 2);
    tp_planner_add(tp, &a);
    tp_planner_add(tp, &b);
    tp_cycle_out_t out;
    int k;
    for (k = 0; k < 1500; k++)
        tp_planner_run_cycle(tp, &in, &out);
    tp_planner_abort(tp);
    for (k = 0; k < 5000; k++) {
        tp_planner_run_cycle(tp, &in, &out);
        if (out.done)
            break;
    }
    EmcPose p;
    tp_planner_get_pos(tp, &p);
    printf("abort: done after %d cycles, queue %d, stopped on the first move %s\n", k + 1,
           out.queue_depth, p.tran.y == 0.0 && p.tran.x > 3.0 && p.tran.x < 10.0 ? "yes" : "no");
    tp_segment_t c = move(0, 0, 0, 3.0, 3);
    printf("abort: a new move queues %s\n", tp_planner_add(tp, &c) == TP_OK ? "yes" : "no");
    tp_planner_destroy(tp);
}

/* Synced outputs land in the cycle their move starts; immediate ones are motion's business. */
static void synced_io(void)
{
    tp_planner_t *tp = machine(0.0);
    tp_cycle_in_t in = inputs();
    tp_segment_t a = move(1, 0, 0, 2.0, 1), b = move(2, 0, 0, 2.0, 2);
    tp_planner_set_term_cond(tp, TP_TERM_COND_STOP, 0.0);
    tp_planner_add(tp, &a);
    tp_planner_set_dout(tp, 3, 1, 1);
    tp_planner_set_aout(tp, 1, 2.5, 2.5);
    tp_planner_add(tp, &b);
    tp_cycle_out_t out;
    for (int k = 0; k < 5000; k++) {
        tp_planner_run_cycle(tp, &in, &out);
        if (out.dout_change_mask || out.aout_change_mask) {
            printf("synced I/O: dout mask 0x%llx values 0x%llx aout mask 0x%llx value %.2f at X %.4f line %d\n",
                   (unsigned long long)out.dout_change_mask, (unsigned long long)out.dout_values,
                   (unsigned long long)out.aout_change_mask, out.aout_values[1], out.pos.tran.x,
                   out.exec_id);
        }
        if (out.done)
            break;
    }
    tp_planner_destroy(tp);
}

/* Planner type: refused without jerk, deferred while moving. */
static void planner_type(void)
{
    tp_planner_t *tp = machine(0.0);
    printf("S-curve without jerk: %d\n", tp_planner_set_type(tp, TP_PLANNER_SCURVE));
    tp_planner_destroy(tp);
    tp = machine(5000.0);
    tp_planner_set_type(tp, TP_PLANNER_TRAPEZOID);
    tp_segment_t a = move(5, 0, 0, 2.0, 1);
    tp_planner_add(tp, &a);
    tp_cycle_in_t in = inputs();
    tp_cycle_out_t out;
    tp_planner_run_cycle(tp, &in, &out);
    printf("switch while moving: %d, type now %d\n", tp_planner_set_type(tp, TP_PLANNER_SCURVE),
           tp_planner_type(tp));
    for (int k = 0; k < 10000 && !out.done; k++)
        tp_planner_run_cycle(tp, &in, &out);
    tp_planner_run_cycle(tp, &in, &out);
    printf("after the queue drained: type %d\n", tp_planner_type(tp));
    tp_planner_destroy(tp);
}

int main(void)
{
    exact_modes();
    corner_modes();
    overrides();
    hold_and_pause();
    abort_move();
    synced_io();
    planner_type();
    return 0;
}
