/* tp_behaviour.c: LinuxCNC's planner behaviour (motion.md sec. 11) through the library, one scenario per function. */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "tp_planner.h"

#define T 0.001

/* A planner on a machine with the same limits on every axis (path speed limit vlimit). */
static tp_planner_t *machine_with(double vel, double vlimit, double acc, double jerk, double max_fo)
{
    tp_planner_t *tp = tp_planner_create(200);
    tp_limits_t l;
    memset(&l, 0, sizeof(l));
    l.cycle_time = T;
    l.vlimit = vlimit;
    l.amax = acc;
    l.jmax = jerk;
    l.max_feed_override = max_fo;
    for (int i = 0; i < TP_NUM_AXES; i++) {
        l.axis_vel[i] = vel;
        l.axis_acc[i] = acc;
        l.axis_jerk[i] = jerk;
    }
    tp_planner_set_limits(tp, &l);
    if (jerk > 0.0)
        tp_planner_set_type(tp, TP_PLANNER_SCURVE);
    return tp;
}

/* The machine of motion.md sec. 11: axis velocity 4, acceleration 100, MAX_LINEAR_VELOCITY 5. */
static tp_planner_t *machine(double jerk)
{
    return machine_with(4.0, 5.0, 100.0, jerk, 1.2);
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

/* Lowest speed near the 90 degree corner of (0,0)-(2,0)-(2,2) at F2, and whether the path kept
 * within p of it (p 0: not checked). */
static void corner_run(const char *name, double jerk, tp_term_cond_t c, double p)
{
    tp_planner_t *tp = machine(jerk);
    tp_cycle_in_t in = inputs();
    tp_planner_set_term_cond(tp, c, p);
    tp_segment_t a = move(2, 0, 0, 2.0, 1), b = move(2, 2, 0, 2.0, 2);
    tp_planner_add(tp, &a);
    tp_planner_add(tp, &b);
    tp_cycle_out_t prev, out;
    memset(&prev, 0, sizeof(prev));
    double v_corner = 1e9, dev = 0.0;
    for (int k = 0; k < 20000; k++) {
        tp_planner_run_cycle(tp, &in, &out);
        double dx = out.pos.tran.x - 2.0, dy = out.pos.tran.y;
        if (fabs(dx) < 0.6 && fabs(dy) < 0.6)
            v_corner = fmin(v_corner, speed(&prev, &out));
        dev = fmax(dev, fmin(fabs(dy) + (out.pos.tran.x > 2.0 ? 1e9 : 0.0), fabs(dx)));
        prev = out;
        if (out.done)
            break;
    }
    printf("%s corner: lowest speed %.3f, within tolerance %s\n", name, v_corner,
           p > 0.0 ? (dev <= p ? "yes" : "no") : "n/a");
    tp_planner_destroy(tp);
}

/* Corner speed at a 90 degree corner: G61 stops, G64 keeps the feed, G64 P0.001 slows down.  With
 * jerk limits a blend the tolerance keeps tiny (P0.001) is slower than stopping, so that corner
 * stops; P0.1 still blends faster than a stop would be, and without P the blend keeps the feed. */
static void corner_modes(void)
{
    corner_run("G61", 0.0, TP_TERM_COND_EXACT, 0.0);
    corner_run("G64", 0.0, TP_TERM_COND_BLEND, 0.0);
    corner_run("G64 P0.001", 0.0, TP_TERM_COND_BLEND, 0.001);
    corner_run("S-curve G64", 1000.0, TP_TERM_COND_BLEND, 0.0);
    corner_run("S-curve G64 P0.1", 1000.0, TP_TERM_COND_BLEND, 0.1);
    corner_run("S-curve G64 P0.001", 1000.0, TP_TERM_COND_BLEND, 0.001);
}

/* G64 without P at a sharp corner between long moves: the path passes within a quarter of the
 * shorter move (LinuxCNC's bound), not across half of each. */
static void sharp_corner_no_tolerance(void)
{
    tp_planner_t *tp = machine(0.0);
    tp_cycle_in_t in = inputs();
    tp_planner_set_term_cond(tp, TP_TERM_COND_BLEND, 0.0);
    tp_segment_t a = move(5, 1, 0, 4.0, 1), b = move(0, 2, 0, 4.0, 2);
    tp_planner_add(tp, &a);
    tp_planner_add(tp, &b);
    tp_cycle_out_t out;
    double x_max = 0.0;
    for (int k = 0; k < 20000; k++) {
        tp_planner_run_cycle(tp, &in, &out);
        x_max = fmax(x_max, out.pos.tran.x);
        if (out.done)
            break;
    }
    double quarter = 0.25 * sqrt(26.0);
    printf("G64 sharp corner: the path passes within a quarter of the move of the corner: %s\n",
           5.0 - x_max <= quarter + 1e-9 ? "yes" : "no");
    tp_planner_destroy(tp);
}

/* A sampled curve without G64 P (chords of about r * step along a half circle at feed f, uneven
 * with jitter, S-curve on the bench machine): the blends along the merged chords carry the
 * curvature and follow the arc through the units' end points (not their sagittas, which differ with
 * the units' lengths), so the middle third runs near the feed (an R5 circle allows
 * min(F, sqrt(A r), cbrt(J r^2)) = 158 / 171) instead of pulsing. */
static void sampled_curve_no_tolerance(double r, double step, double f, double jitter, double share)
{
    tp_planner_t *tp = machine_with(500.0, 500.0, 5000.0, 200000.0, 1.0);
    tp_cycle_in_t in = inputs();
    tp_planner_set_term_cond(tp, TP_TERM_COND_BLEND, 0.0);
    int n = (int)(M_PI / step), added = 0;
    tp_cycle_out_t prev, out;
    memset(&prev, 0, sizeof(prev));
    tp_planner_get_pos(tp, &prev.pos);
    double v_min = 1e9;
    for (int k = 0; k < 20000; k++) {
        while (added < n && !tp_planner_queue_full(tp)) {   /* as task keeps the queue filled */
            added++;
            double ang = added == n ? M_PI : (added + jitter * sin(1.7 * added)) * step;
            tp_segment_t s = move(r * sin(ang), r - r * cos(ang), 0, f, added);
            s.ini_maxvel = 500.0;
            s.acc = 5000.0;
            tp_planner_add(tp, &s);
        }
        tp_planner_run_cycle(tp, &in, &out);
        double angle = atan2(out.pos.tran.x, r - out.pos.tran.y);
        if (angle > M_PI / 3.0 && angle < 2.0 * M_PI / 3.0)
            v_min = fmin(v_min, speed(&prev, &out));
        prev = out;
        if (out.done && added == n)
            break;
    }
    printf("S-curve sampled R%g circle (chords %s) without P at F%g: middle third at least %.0f %% of the "
           "feed: %s\n", r, jitter > 0.0 ? "uneven" : "even", f, 100.0 * share, v_min >= share * f ? "yes" : "no");
    tp_planner_destroy(tp);
}

/* A short move between two corners the tolerance slows down (a raster's step to the next row, on
 * a machine of 50 mm/s and 5000 mm/s^2): between the blends the speed rises again, it is not held
 * at the corners' speed.  Reports the cycles spent on the step and the fastest sample there. */
static void short_step(void)
{
    tp_planner_t *tp = machine_with(50.0, 50.0, 5000.0, 0.0, 1.0);
    tp_cycle_in_t in = inputs();
    const double step = 0.2;
    tp_segment_t m[3] = {move(20, 0, 0, 50.0, 1), move(20, step, 0, 50.0, 2), move(0, step, 0, 50.0, 3)};
    tp_planner_set_term_cond(tp, TP_TERM_COND_BLEND, 0.01);
    for (int k = 0; k < 3; k++) {
        m[k].ini_maxvel = 50.0;
        m[k].acc = 5000.0;
        tp_planner_add(tp, &m[k]);
    }
    tp_cycle_out_t prev, out;
    tp_planner_get_pos(tp, &prev.pos);
    double v_step = 0.0;
    int cycles = 0;
    for (int k = 0; k < 20000; k++) {
        tp_planner_run_cycle(tp, &in, &out);
        double y = out.pos.tran.y;
        if (y > 0.0 && y < step) {
            v_step = fmax(v_step, speed(&prev, &out));
            cycles++;
        }
        prev = out;
        if (out.done)
            break;
    }
    printf("G64 P0.01 short step between corners: %d cycles, fastest %.1f\n", cycles, v_step);
    tp_planner_destroy(tp);
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

/* A simulated spindle: speed follows the command (reversed on request) at a limited rate. */
typedef struct spindle_sim {
    double rps, revs, cmd;
} spindle_sim_t;

static void spindle_step(spindle_sim_t *sp, int reverse, tp_cycle_in_t *in)
{
    double want = reverse ? -sp->cmd : sp->cmd, rate = 200.0 * T;
    sp->rps += fmax(-rate, fmin(rate, want - sp->rps));
    sp->revs += sp->rps * T;
    in->spindle[0].revs = sp->revs;
    in->spindle[0].speed_rps = sp->rps;
    in->spindle[0].speed_cmd_rps = sp->cmd;
    in->spindle[0].at_speed = fabs(sp->rps - want) < 0.01;
}

/* G33: waits for at-speed and the index, then the Z move follows the spindle, 2 mm per rev. */
static void spindle_position_sync(void)
{
    tp_planner_t *tp = machine(0.0);
    tp_cycle_in_t in = inputs();
    tp_cycle_out_t out;
    spindle_sim_t sp = {0.0, 0.0, 2.0};
    tp_planner_set_spindle_sync(tp, 0, 0.5, 0);
    tp_segment_t a = move(0, 0, -3, 4.0, 1);
    a.atspeed = 1;
    a.enables = TP_ENABLE_FS;
    tp_planner_add(tp, &a);
    int armed_at = -1, index_at = -1, moving_at = -1, index_drop = -1;
    double worst = 0.0, z0 = 0.0;
    for (int k = 0; k < 20000; k++) {
        spindle_step(&sp, 0, &in);
        if (k == index_drop) {
            in.spindle[0].index_enable = 0;
            sp.revs = 0.0;              /* the encoder counts from the index */
            in.spindle[0].revs = 0.0;
            index_at = k;
        }
        tp_planner_run_cycle(tp, &in, &out);
        if (out.arm_index[0] && armed_at < 0) {
            armed_at = k;
            in.spindle[0].index_enable = 1;
            index_drop = k + 137;       /* the index comes round a little later */
        }
        if (moving_at < 0 && out.pos.tran.z < 0.0) {
            moving_at = k;
            z0 = 0.0;
        }
        if (moving_at > 0 && k > moving_at + 300 && out.pos.tran.z > -2.5)
            worst = fmax(worst, fabs(-out.pos.tran.z - 0.5 * sp.revs - z0));
        if (out.done)
            break;
    }
    printf("G33: armed the index after at-speed %s, moved only after the index %s, "
           "following error after the start-up below 0.001 %s, end Z %.6f\n",
           armed_at > 0 ? "yes" : "no", moving_at >= index_at && index_at > 0 ? "yes" : "no",
           worst < 1e-3 ? "yes" : "no", out.pos.tran.z);
    tp_planner_destroy(tp);
}

/* G95-style velocity sync: the feed is spindle speed times units per revolution. */
static void spindle_velocity_sync(void)
{
    tp_planner_t *tp = machine(0.0);
    tp_cycle_in_t in = inputs();
    tp_cycle_out_t out;
    spindle_sim_t sp = {3.0, 0.0, 3.0};
    tp_planner_set_spindle_sync(tp, 0, 0.5, 1);
    tp_segment_t a = move(5, 0, 0, 4.0, 1);
    tp_planner_add(tp, &a);
    double peak = 0.0;
    for (int k = 0; k < 20000; k++) {
        spindle_step(&sp, 0, &in);
        tp_planner_run_cycle(tp, &in, &out);
        peak = fmax(peak, out.current_vel);
        if (out.done)
            break;
    }
    printf("velocity sync 3 rev/s x 0.5: peak %.3f\n", peak);
    tp_planner_destroy(tp);
}

/* G33.1: tapping, reversing, retraction, final reversal, final placement back at the start. */
static void rigid_tap(void)
{
    tp_planner_t *tp = machine(0.0);
    tp_cycle_in_t in = inputs();
    tp_cycle_out_t out;
    memset(&out, 0, sizeof(out));
    spindle_sim_t sp = {5.0, 0.0, 5.0};
    /* a move first, finished before the tap is queued (the tap starts from where it stopped) */
    tp_segment_t pre = move(1, 0, 0, 4.0, 1);
    tp_planner_add(tp, &pre);
    for (int k = 0; k < 5000 && !out.done; k++)
        tp_planner_run_cycle(tp, &in, &out);
    tp_segment_t a = move(1, 0, -2, 4.0, 2);
    a.kind = TP_SEG_RIGID_TAP;
    a.tap_uu_per_rev = 0.25;
    tp_planner_add(tp, &a);
    int last = -2, index_drop = -1;
    double deepest = 0.0;
    printf("rigid tap phases:");
    for (int k = 0; k < 40000; k++) {
        spindle_step(&sp, out.spindle_reverse[0], &in);
        if (k == index_drop) {
            in.spindle[0].index_enable = 0;
            sp.revs = 0.0;
            in.spindle[0].revs = 0.0;
        }
        tp_planner_run_cycle(tp, &in, &out);
        if (out.arm_index[0]) {
            in.spindle[0].index_enable = 1;
            index_drop = k + 50;
        }
        if (out.rigid_tap_state != last) {
            printf(" %d", out.rigid_tap_state);
            last = out.rigid_tap_state;
        }
        deepest = fmin(deepest, out.pos.tran.z);
        if (out.done)
            break;
    }
    printf("; went past the depth %s; done at X %.6f Z %.6f\n", deepest < -2.0 ? "yes" : "no",
           out.pos.tran.x, out.pos.tran.z);
    tp_planner_destroy(tp);
}

/* A locking indexer: unlock, wait for is-unlocked, move, lock, wait before finishing. */
static void locking_indexer(void)
{
    tp_planner_t *tp = machine(0.0);
    tp_cycle_in_t in = inputs();
    tp_cycle_out_t out;
    tp_segment_t a = move(0, 0, 0, 40.0, 1);
    a.ini_maxvel = 40.0;
    a.end.a = 30.0;
    a.motion_type = TP_MOTION_INDEXROTARY;
    a.indexer_jnum = 3;
    tp_planner_add(tp, &a);
    int unlock_seen = -1, moved = -1, relock = -1, done = -1, delay = 0;
    for (int k = 0; k < 20000; k++) {
        tp_planner_run_cycle(tp, &in, &out);
        if (out.unlock_joint == 3 && unlock_seen < 0)
            unlock_seen = k;
        if (out.unlock_joint == 3 && !in.indexer_unlocked && ++delay > 20)
            in.indexer_unlocked = 1;
        if (out.unlock_joint < 0 && unlock_seen >= 0 && in.indexer_unlocked) {
            if (relock < 0)
                relock = k;
            if (k > relock + 20)
                in.indexer_unlocked = 0;
        }
        if (moved < 0 && out.pos.a > 0.0)
            moved = k;
        if (out.done) {
            done = k;
            break;
        }
    }
    printf("indexer: unlock asked %s, moved after unlocked %s, lock asked at the end %s, done after locked %s, A %.3f\n",
           unlock_seen >= 0 ? "yes" : "no", moved > unlock_seen + 20 ? "yes" : "no", relock > moved ? "yes" : "no",
           done > relock + 20 ? "yes" : "no", out.pos.a);
    tp_planner_destroy(tp);
}

/* Reverse run: stop, go back along the executed path (through the corner), then forward to the end. */
static void reverse_run(void)
{
    tp_planner_t *tp = machine(0.0);
    tp_cycle_in_t in = inputs();
    tp_cycle_out_t out;
    tp_planner_set_term_cond(tp, TP_TERM_COND_BLEND, 0.01);
    tp_segment_t a = move(3, 0, 0, 3.0, 1), b = move(3, 3, 0, 3.0, 2);
    tp_planner_add(tp, &a);
    tp_planner_add(tp, &b);
    double ymax = 0.0, xmin_back = 1e9;
    int back_line = 0, flag = 0, k;
    for (k = 0; k < 20000; k++) {
        if (k == 1500)
            tp_planner_set_run_dir(tp, 1);
        if (k == 3500)
            tp_planner_set_run_dir(tp, 0);
        tp_planner_run_cycle(tp, &in, &out);
        if (k < 1500)
            ymax = out.pos.tran.y;
        if (k > 1500 && k < 3500) {
            xmin_back = fmin(xmin_back, out.pos.tran.x);
            flag |= out.reverse;
            if (out.pos.tran.x < 2.5)
                back_line = out.exec_id;
        }
        if (out.done)
            break;
    }
    printf("reverse run: reversed flag %d, went back from Y %.2f through the corner to X below 2.5 %s "
           "(line %d), forward again to the end (%.3f, %.3f) %s\n",
           flag, ymax, xmin_back < 2.5 ? "yes" : "no", back_line, out.pos.tran.x, out.pos.tran.y,
           out.done ? "done" : "not done");
    tp_planner_destroy(tp);
}

/* A lone straight move accelerates and brakes at exactly the machine's acceleration (the samples
 * of a G0 follow a*t^2/2 as in LinuxCNC). */
static void lone_move(void)
{
    tp_planner_t *tp = machine(0.0);
    tp_cycle_in_t in = inputs();
    tp_segment_t a = move(1, 0, 0, 4.0, 1);
    tp_planner_add(tp, &a);
    double x[3] = {0.0, 0.0, 0.0}, acc_hi = 0.0, acc_lo = 0.0, x3 = 0.0;
    tp_cycle_out_t out;
    for (int k = 0; k < 5000; k++) {
        tp_planner_run_cycle(tp, &in, &out);
        x[0] = x[1];
        x[1] = x[2];
        x[2] = out.pos.tran.x;
        if (k == 2)
            x3 = out.pos.tran.x;
        if (k >= 1) {
            double acc = (x[2] - 2.0 * x[1] + x[0]) / (T * T);
            acc_hi = fmax(acc_hi, acc);
            acc_lo = fmin(acc_lo, acc);
        }
        if (out.done)
            break;
    }
    printf("lone move: x after 3 cycles %.9f, sampled acceleration %.6f .. %.6f\n", x3, acc_lo, acc_hi);
    tp_planner_destroy(tp);
}

/* Moves completed together (a blend spans several short moves) free their queue places over a
 * few cycles, so the adds that refill the queue spread out; the motion does not change. */
static void queue_room(void)
{
    tp_planner_t *tp = machine(0.0);
    tp_cycle_in_t in = inputs();
    tp_cycle_out_t out;
    enum { MOVES = 3000 };
    int next = 0, most_done = 0, most_added = 0, cycles = 0, starved = 0;
    tp_planner_set_term_cond(tp, TP_TERM_COND_BLEND, 0.002);
    for (int k = 0; k < 200000 && !(next == MOVES && cycles && out.done); k++) {
        int depth0 = tp_planner_queue_depth(tp), added = 0;
        while (next < MOVES && !tp_planner_queue_full(tp)) {
            double a = 0.004 * (next + 1);     /* chords of a circle of radius 1, 4 mm apart */
            tp_segment_t m = move(sin(a), 1.0 - cos(a), 0.0, 4.0, next + 1);
            if (tp_planner_add(tp, &m) != TP_OK)
                break;
            next++;
            added++;
        }
        if (k > 0 && next < MOVES && tp_planner_queue_depth(tp) < 100)
            starved = 1;                /* the machine's queue holds 200 moves */
        tp_planner_run_cycle(tp, &in, &out);
        int done = depth0 + added - out.queue_depth;
        most_done = done > most_done ? done : most_done;
        most_added = k > 0 && added > most_added ? added : most_added;
        cycles = k + 1;
    }
    printf("queue room: %d cycles, at most %d moves completed and %d added in one cycle, "
           "queue kept over half full %s\n", cycles, most_done, most_added, starved ? "no" : "yes");
    tp_planner_destroy(tp);
}

int main(void)
{
    exact_modes();
    lone_move();
    corner_modes();
    sharp_corner_no_tolerance();
    sampled_curve_no_tolerance(5.0, 0.01, 120.0, 0.0, 0.9);
    sampled_curve_no_tolerance(5.0, 0.01, 120.0, 0.4, 0.8);
    short_step();
    overrides();
    hold_and_pause();
    abort_move();
    synced_io();
    planner_type();
    spindle_position_sync();
    spindle_velocity_sync();
    rigid_tap();
    locking_indexer();
    reverse_run();
    queue_room();
    return 0;
}
