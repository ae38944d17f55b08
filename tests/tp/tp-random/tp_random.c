/* tp_random.c: random move chains with random limits through the planner; every servo sample checked. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "tp_planner.h"

/* Relative slack of the limit checks, plus an absolute floor for rounding of positions near zero. */
#define REL 1e-9
#define POS_EPS 1e-9

/* Small deterministic generator (xorshift64*). */
static uint64_t rng_state = 88172645463325252ull;
static double urand(void)
{
    rng_state ^= rng_state >> 12;
    rng_state ^= rng_state << 25;
    rng_state ^= rng_state >> 27;
    return (double)((rng_state * 2685821657736338717ull) >> 11) / 9007199254740992.0;
}
static double uniform(double a, double b)
{
    return a + (b - a) * urand();
}

/* One chain's machine and moves. */
typedef struct chain {
    tp_limits_t lim;
    int scurve;
    int n;
    tp_segment_t seg[8];
    double start[9];
    double tol;
    int cond;
} chain_t;

/* What went wrong, counted over all chains. */
typedef struct stats {
    long chains, cycles, vel, acc, jerk, jump, end, dev, stuck, emerg;
    double worst_v, worst_a, worst_j, worst_dev;
} stats_t;

static void pose_set(EmcPose *p, const double *x)
{
    p->tran.x = x[0]; p->tran.y = x[1]; p->tran.z = x[2];
    p->a = x[3]; p->b = x[4]; p->c = x[5]; p->u = x[6]; p->v = x[7]; p->w = x[8];
}

static void pose_get(const EmcPose *p, double *x)
{
    x[0] = p->tran.x; x[1] = p->tran.y; x[2] = p->tran.z;
    x[3] = p->a; x[4] = p->b; x[5] = p->c; x[6] = p->u; x[7] = p->v; x[8] = p->w;
}

/* Random limits: per-axis velocity, acceleration and (S-curve) jerk, cycle 1 ms. */
static void random_limits(chain_t *c)
{
    memset(&c->lim, 0, sizeof(c->lim));
    c->lim.cycle_time = 0.001;
    c->lim.max_feed_override = 1.0;
    c->scurve = urand() < 0.5;
    for (int i = 0; i < 9; i++) {
        c->lim.axis_vel[i] = uniform(20.0, 500.0);
        c->lim.axis_acc[i] = uniform(200.0, 8000.0);
        c->lim.axis_jerk[i] = c->scurve ? c->lim.axis_acc[i] * uniform(10.0, 100.0) : 0.0;
    }
    c->lim.vlimit = uniform(50.0, 600.0);
    c->lim.amax = 5000.0;
    c->lim.jmax = c->scurve ? 1e6 : 0.0;
}

/* Random chain of lines and arcs in XYZ with some A and U motion. */
static void random_chain(chain_t *c)
{
    double p[9] = {0};
    random_limits(c);
    c->n = 2 + (int)(urand() * 5);
    c->cond = urand() < 0.7 ? TP_TERM_COND_BLEND : (urand() < 0.5 ? TP_TERM_COND_EXACT : TP_TERM_COND_STOP);
    c->tol = urand() < 0.2 ? 0.0 : uniform(0.001, 0.2);
    for (int i = 0; i < 9; i++)
        c->start[i] = p[i];
    for (int k = 0; k < c->n; k++) {
        tp_segment_t *s = &c->seg[k];
        memset(s, 0, sizeof(*s));
        double len = urand() < 0.3 ? uniform(0.01, 0.3) : uniform(0.3, 8.0);
        double dir[3] = {uniform(-1, 1), uniform(-1, 1), urand() < 0.5 ? 0.0 : uniform(-1, 1)};
        double nn = sqrt(dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2]) + 1e-9;
        double q[9];
        memcpy(q, p, sizeof(q));
        for (int i = 0; i < 3; i++)
            q[i] = p[i] + len * dir[i] / nn;
        if (urand() < 0.2)
            q[3] = p[3] + uniform(-5, 5);
        if (urand() < 0.1)
            q[6] = p[6] + uniform(-2, 2);
        s->kind = TP_SEG_LINE;
        if (urand() < 0.3) {
            /* arc in XY through q with centre on the bisector */
            double mx = 0.5 * (p[0] + q[0]), my = 0.5 * (p[1] + q[1]);
            double dx = q[0] - p[0], dy = q[1] - p[1], h = uniform(-2.0, 2.0);
            s->kind = TP_SEG_CIRCLE;
            s->center.x = mx - dy * h;
            s->center.y = my + dx * h;
            s->center.z = p[2];
            s->normal.z = urand() < 0.5 ? 1.0 : -1.0;
            s->turn = 0;
        }
        pose_set(&s->end, q);
        s->motion_type = urand() < 0.15 ? TP_MOTION_TRAVERSE : TP_MOTION_FEED;
        s->vel = uniform(5.0, 300.0);
        s->ini_maxvel = uniform(100.0, 600.0);
        s->acc = uniform(500.0, 10000.0);
        s->jerk = 0.0;
        s->enables = TP_ENABLE_FS;
        s->indexer_jnum = -1;
        s->id = k + 1;
        memcpy(p, q, sizeof(p));
    }
}

/* Check one sample's finite differences against the limits. */
static void check_sample(const chain_t *c, double h[4][9], int have, stats_t *st)
{
    double T = c->lim.cycle_time;
    for (int i = 0; i < 9; i++) {
        double v = (h[0][i] - h[1][i]) / T;
        double lv = c->lim.axis_vel[i];
        if (fabs(v) > lv * (1 + REL) + POS_EPS / T) {
            st->vel++;
            st->worst_v = fmax(st->worst_v, fabs(v) / lv);
        }
        if (have < 3)
            continue;
        double a = (h[0][i] - 2 * h[1][i] + h[2][i]) / (T * T);
        double la = c->lim.axis_acc[i];
        if (fabs(a) > la * (1 + REL) + 4 * POS_EPS / (T * T)) {
            st->acc++;
            st->worst_a = fmax(st->worst_a, fabs(a) / la);
        }
        if (have < 4 || !c->scurve)
            continue;
        double j = (h[0][i] - 3 * h[1][i] + 3 * h[2][i] - h[3][i]) / (T * T * T);
        double lj = c->lim.axis_jerk[i];
        if (fabs(j) > lj * (1 + REL) + 8 * POS_EPS / (T * T * T)) {
            st->jerk++;
            st->worst_j = fmax(st->worst_j, fabs(j) / lj);
        }
    }
}

/* Run one chain to completion; returns 0 when it finished. */
static int run_chain(const chain_t *c, stats_t *st, int verbose)
{
    tp_planner_t *tp = tp_planner_create(64);
    tp_planner_set_limits(tp, &c->lim);
    if (c->scurve)
        tp_planner_set_type(tp, TP_PLANNER_SCURVE);
    EmcPose start;
    pose_set(&start, c->start);
    tp_planner_set_pos(tp, &start);
    tp_planner_set_term_cond(tp, (tp_term_cond_t)c->cond, c->tol);
    for (int k = 0; k < c->n; k++)
        tp_planner_add(tp, &c->seg[k]);
    tp_cycle_in_t in;
    tp_cycle_out_t out;
    memset(&in, 0, sizeof(in));
    in.feed_scale = in.rapid_scale = in.adaptive_feed = 1.0;
    in.num_spindles = 1;
    double h[4][9];
    for (int r = 0; r < 4; r++)
        memcpy(h[r], c->start, sizeof(h[r]));
    int have = 1, done = 0;
    for (int cyc = 0; cyc < 200000; cyc++) {
        tp_planner_run_cycle(tp, &in, &out);
        memmove(h[1], h[0], 3 * sizeof(h[0]));
        pose_get(&out.pos, h[0]);
        have = have < 4 ? have + 1 : 4;
        st->cycles++;
        check_sample(c, h, 4, st);
        if (out.done) {
            done = 1;
            break;
        }
    }
    double endp[9];
    pose_get(&c->seg[c->n - 1].end, endp);
    if (!done)
        st->stuck++;
    else if (memcmp(endp, h[0], sizeof(endp)) != 0)
        st->end++;
    st->emerg += (long)tp_planner_emergencies(tp);
    if (verbose && (!done || tp_planner_emergencies(tp)))
        fprintf(stderr, "chain %ld: done=%d emergencies=%lu\n", st->chains, done, tp_planner_emergencies(tp));
    st->chains++;
    tp_planner_destroy(tp);
    (void)have;
    return done ? 0 : -1;
}

int main(int argc, char **argv)
{
    long chains = argc > 1 ? atol(argv[1]) : 1000;
    int verbose = argc > 2;
    stats_t st;
    memset(&st, 0, sizeof(st));
    for (long k = 0; k < chains; k++) {
        chain_t c;
        random_chain(&c);
        run_chain(&c, &st, verbose);
    }
    fprintf(stderr, "servo cycles: %ld\n", st.cycles);
    printf("chains: %ld\n", st.chains);
    printf("velocity over limit: %ld\n", st.vel);
    printf("acceleration over limit: %ld\n", st.acc);
    printf("jerk over limit: %ld\n", st.jerk);
    if (st.vel || st.acc || st.jerk)
        printf("worst ratios: velocity %.9g acceleration %.9g jerk %.9g\n", st.worst_v, st.worst_a, st.worst_j);
    printf("end point not exact: %ld\n", st.end);
    printf("not finished: %ld\n", st.stuck);
    /* a cycle whose lookahead no longer offers the executor a safe continuation brakes within the
     * limits; rare (about one chain in 3000), counted so that a change shows */
    printf("cycles without a safe continuation: %ld\n", st.emerg);
    return st.vel || st.acc || st.jerk || st.end || st.stuck;
}
