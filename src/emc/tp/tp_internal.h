/* tp_internal.h: the planner's state: segment, element and region rings, the executor and its settings. */
#ifndef TP_INTERNAL_H
#define TP_INTERNAL_H

#include <stdint.h>
#include "tp_ops.h"
#include "tp_geom.h"
#include "tp_caps.h"
#include "tp_profile.h"
#include "tp_blend.h"

/* How a segment meets the next one. */
typedef enum tp_jct {
    TP_JCT_OPEN = 0,            /* next segment not known yet */
    TP_JCT_STOP = 1,            /* come to rest at the vertex */
    TP_JCT_TANGENT = 2,         /* pass at speed, no blend needed */
    TP_JCT_BLEND = 3            /* replace the corner by a blend */
} tp_jct_t;

/* Spindle synchronisation of a segment. */
typedef enum tp_sync {
    TP_SYNC_NONE = 0,
    TP_SYNC_VEL = 1,            /* G95-style: speed follows spindle speed */
    TP_SYNC_POS = 2             /* G33: position follows spindle revolutions */
} tp_sync_t;

/* Region flags. */
#define TP_REG_STOP 0x01u       /* come to rest at the region start */
#define TP_REG_SYNC_POS 0x02u
#define TP_REG_SYNC_VEL 0x04u
#define TP_REG_TAP 0x08u        /* a rigid tap: driven by its own state machine */

/* What a blend would like: the cut for a speed v is min(cap, 1.5 need_cut(corner, v, acc, jerk)). */
typedef struct tp_want {
    double theta, kink;         /* the corner */
    double acc, jerk;           /* limits the cut is sized for (jerk 0: trapezoid) */
    double cap;                 /* most the tolerance allows (INFINITY: none) */
    double v_need;              /* speed wanted through the corner */
    tp_blend_shape_t shape;
} tp_want_t;

/* One queued move and its junction bookkeeping. */
typedef struct tp_seg {
    tp_segment_t in;            /* as added */
    uint64_t serial;
    uint64_t unit, unit_last;   /* head (first move) of its unit; in the head: the unit's last move */
    double own0, own1;          /* the stretch of the unit's geometry this move owns */
    double unit_dev;            /* head: how far the unit's line strays from its moves' end points */
    tp_geo_t geo;               /* the move (in a unit's head: the unit's line) */
    tp_geo_t blend;             /* blend into the next move (jct_out == BLEND, once built) */
    tp_axlim_t lim;             /* axis and path limits along this move */
    tp_jct_t jct_in, jct_out;
    tp_term_cond_t term;        /* term condition in force when it was added */
    double tol;                 /* G64 P tolerance in force when it was added */
    double want_in, want_out;   /* cut the blends at its ends would like */
    tp_want_t wf_in, wf_out;    /* how those wants depend on the speed */
    double cut_in, cut_out;     /* length taken from its start / end by blends */
    int tiled;                  /* the two blends meet: nothing straight in between */
    int k_in_set, k_out_set;    /* curvature given at the cut points (tiling) */
    tp_vec_t k_in, k_out;
    int finalized;              /* its elements are emitted */
    tp_sync_t sync;
    double sync_k;              /* units per spindle revolution */
    int spindle;
    uint64_t dout_mask, dout_vals, aout_mask;
    uint32_t aout_first, aout_count;
    int started;                /* executor has entered it (I/O emitted) */
    double s_end;               /* global position of its end, once emitted */
} tp_seg_t;

/* A piece of the path the executor walks: part of a move or half of a blend. */
typedef struct tp_elem {
    uint64_t owner;             /* serial of the segment it belongs to */
    uint64_t geo_seg;           /* serial of the segment holding the geometry */
    int is_blend;               /* geometry is geo_seg's blend, else its move */
    double u0;                  /* geometry parameter at the element start */
    double s0, len;             /* global path position and length */
} tp_elem_t;

/* A stretch of path with one set of caps; a speed limit starts at every region start. */
typedef struct tp_region {
    double s0, len;
    double v_mach;              /* machine speed cap */
    double v_feed, v_rapid;     /* smallest requested feed / traverse speed, INFINITY if none */
    double a, j;                /* usable tangential acceleration and jerk (0 = trapezoid) */
    double a_rest;              /* usable at rest; below speed w: a_rest - (a_rest - a) w^2 / v_mach^2 */
    double sync_k;              /* velocity sync: units per revolution */
    double v_start;             /* speed cap at the start point (0 = stop, INFINITY = none) */
    uint32_t flags;
    uint64_t seg;               /* serial of the segment at its start */
} tp_region_t;

/* A speed target of the lookahead: at most v at position s, braking with lim before it. */
typedef struct tp_target {
    double s;
    double v;
    tp_lim1_t lim;
    int stop;                   /* a full stop the executor must land on */
} tp_target_t;

#define TP_WINDOW_MAX 64
/* Ring entries one add may need: blend halves, a body per move of a unit (64), fallback pieces. */
#define TP_EMIT_SPACE 72
/* Pieces (each with its own caps) a blend is emitted in; even. */
#define TP_BLEND_PIECES 4
#define TP_CROSS_MAX 16

/* A region the next cycle may enter: where, its speed cap and the limits while in it. */
typedef struct tp_stretch {
    double s;
    double v;
    tp_lim1_t lim;              /* anticipating the stretches soon after it */
    double jerk_own;            /* its own jerk cap (for settling what is already under way) */
} tp_stretch_t;

/* The lookahead computed at the start of a cycle. */
typedef struct tp_window {
    int n;
    tp_target_t t[TP_WINDOW_MAX];
    int nr;                     /* stretches: [0] the current region, then those this cycle may enter */
    tp_stretch_t r[TP_CROSS_MAX];
} tp_window_t;

/* Rigid tap phases (motion.md sec. 11). */
typedef enum tp_tap_state {
    TP_TAP_NONE = -1,
    TP_TAP_TAPPING = 0,
    TP_TAP_REVERSING = 1,
    TP_TAP_RETRACTION = 2,
    TP_TAP_FINAL_REVERSAL = 3,
    TP_TAP_FINAL_PLACEMENT = 4
} tp_tap_state_t;

/* What the executor is doing along the path. */
typedef struct tp_exec {
    double s, v, a;             /* global position, speed, acceleration along the path */
    uint64_t elem, reg;         /* current element / region */
    double window_end;          /* the lookahead never shrinks below this position */
    int dir;                    /* +1 forward, -1 reverse run */
    uint64_t cleared_stop;      /* region + 1 whose start stop has been served */
    int waiting;                /* at a stop, waiting for spindle at-speed or index */
    int index_state;            /* 0 idle, 1 armed, 2 waiting for the index */
    int sync_active;            /* position sync running: revs reference taken */
    double sync_revs0;          /* spindle revs at the sync start */
    double sync_s0;             /* path position at the sync start */
    double sync_dir;            /* spindle direction at the sync start */
    int spindle;                /* spindle of the synced or waiting segment */
    tp_tap_state_t tap;
    double tap_x, tap_v, tap_a; /* position along the tap line, its speed and acceleration */
    double tap_revs_prev;
    uint64_t tap_seg;
    int unlock_joint;           /* locking indexer joint unlocked for the current move, -1 none */
    int relock_pending;         /* an indexer was told to lock; wait until it reports locked */
} tp_exec_t;

/* Pending synced outputs (M62-M68 before the next move). */
typedef struct tp_io_pending {
    uint64_t dout_mask, dout_vals, aout_mask;
    double aout_vals[TP_MAX_AIO];
} tp_io_pending_t;

struct tp_planner {
    int queue_size;
    /* rings; counters grow for ever, index = counter % cap */
    tp_seg_t *segs;
    uint32_t seg_cap;
    uint64_t seg_head, seg_tail, seg_done;
    uint64_t seg_room;          /* moves before it no longer count against the queue size */
    tp_elem_t *elems;
    uint32_t elem_cap;
    uint64_t elem_head, elem_tail;
    tp_region_t *regs;
    uint32_t reg_cap;
    uint64_t reg_head, reg_tail;
    int reg_open;               /* the last region may still grow */
    int stop_next;              /* the next emitted region starts with a stop */
    struct { int idx; double val; } *aouts;
    uint32_t aout_cap;
    uint64_t aout_head, aout_tail;
    /* configuration */
    tp_limits_t lim;
    tp_term_cond_t term_cond;
    double tolerance;
    tp_planner_type_t type;
    int type_pending;           /* -1 none, else the deferred planner type */
    tp_sync_t sync_mode;        /* for the next segments */
    double sync_k;
    int sync_spindle;
    tp_io_pending_t io;
    int reverse_req;
    /* queue end */
    tp_vec_t goal;
    double s_emit;              /* global position where the next element starts */
    struct {                    /* state before the provisional part (emitted before its end is known) */
        int valid;
        uint64_t elem_head, reg_head;
        tp_region_t last_reg;
        int reg_open, stop_next;
        double s_emit;
        uint64_t body_elem;     /* the open unit's body, one element for all its moves */
        int lazy;               /* not emitted yet: the executor is far from the path end */
        uint64_t lazy_b, lazy_c;/* the units it is made of (lazy_b UINT64_MAX: none) */
    } prov;
    /* execution */
    tp_exec_t ex;
    tp_vec_t pos;
    int paused, aborting;
    int have_moved;
    uint64_t emergencies;       /* cycles that found no safe continuation (diagnostics) */
    uint64_t path_version;      /* bumped when emitted path before the end changes */
    struct {                    /* the last lookahead targets the executor was safe with */
        int valid;
        uint64_t version;
        double fs, rs, spindle;
        int n;
        tp_target_t t[TP_WINDOW_MAX];
    } prev;
};

/* Ring slot of a counter. */
#define TP_SLOT(cnt, cap) ((uint32_t)((cnt) % (cap)))

static inline tp_seg_t *tp_seg_at(tp_planner_t *tp, uint64_t serial)
{
    return &tp->segs[TP_SLOT(serial, tp->seg_cap)];
}

static inline tp_elem_t *tp_elem_at(tp_planner_t *tp, uint64_t n)
{
    return &tp->elems[TP_SLOT(n, tp->elem_cap)];
}

static inline tp_region_t *tp_reg_at(tp_planner_t *tp, uint64_t n)
{
    return &tp->regs[TP_SLOT(n, tp->reg_cap)];
}

/* Geometry an element walks. */
static inline const tp_geo_t *tp_elem_geo(tp_planner_t *tp, const tp_elem_t *e)
{
    tp_seg_t *g = tp_seg_at(tp, e->geo_seg);
    return e->is_blend ? &g->blend : &g->geo;
}

/* tp_queue.c */
tp_result_t tp_queue_add(tp_planner_t *tp, const tp_segment_t *seg);
void tp_queue_reset(tp_planner_t *tp);
int tp_queue_live(const tp_planner_t *tp);
int tp_queue_full(const tp_planner_t *tp);
void tp_queue_release(tp_planner_t *tp);
/* tp_emit.c */
void tp_emit_piece(tp_planner_t *tp, tp_seg_t *owner, tp_seg_t *geo_seg, int is_blend, double u0,
                   double u1, uint32_t flags);
void tp_emit_blend(tp_planner_t *tp, tp_seg_t *a, tp_seg_t *a_owner, tp_seg_t *b, tp_seg_t *b_owner);
int tp_emit_space(const tp_planner_t *tp);
void tp_emit_caps(tp_planner_t *tp, tp_seg_t *owner, const tp_geo_t *g, double u0, double u1,
                  const tp_axlim_t *lim, uint32_t flags, tp_region_t *r);
void tp_emit_region(tp_planner_t *tp, tp_seg_t *owner, tp_seg_t *geo_seg, int is_blend, double u0,
                    double u1, const tp_region_t *tmpl);
void tp_emit_mark(tp_planner_t *tp);
void tp_emit_rollback(tp_planner_t *tp);
/* tp_unit.c */
tp_seg_t *tp_unit_head(tp_planner_t *tp, const tp_seg_t *s);
tp_seg_t *tp_unit_last(tp_planner_t *tp, const tp_seg_t *h);
int tp_unit_can_absorb(tp_planner_t *tp, tp_seg_t *h, const tp_seg_t *s);
void tp_unit_absorb(tp_planner_t *tp, tp_seg_t *h, tp_seg_t *s);
void tp_unit_emit(tp_planner_t *tp, tp_seg_t *h, double u0, double u1, uint32_t flags);
void tp_unit_split_body(tp_planner_t *tp, tp_seg_t *h, uint64_t body_elem);
/* tp_junction.c */
void tp_jct_plan(tp_planner_t *tp, tp_seg_t *b, tp_seg_t *c);
void tp_jct_commit(tp_planner_t *tp, tp_seg_t *a, tp_seg_t *b, tp_seg_t *c);
void tp_jct_provisional(tp_planner_t *tp, tp_seg_t *b, tp_seg_t *c);
void tp_jct_provisional_due(tp_planner_t *tp, int now);
int tp_jct_can_stop_before(const tp_planner_t *tp, double s_at);
/* tp_window.c */
double tp_region_cap(const tp_planner_t *tp, const tp_region_t *r, double feed_scale,
                     double rapid_scale, double spindle_rps);
void tp_window_build(tp_planner_t *tp, tp_window_t *w, double feed_scale, double rapid_scale,
                     double spindle_rps, int dir);
void tp_window_settle(tp_planner_t *tp, tp_window_t *w, double feed_scale, double rapid_scale,
                      double spindle_rps);
/* tp_exec.c */
void tp_exec_move(tp_planner_t *tp, const tp_window_t *w, double dt);
int tp_exec_safe(const tp_planner_t *tp, const tp_window_t *w);
void tp_exec_locate(tp_planner_t *tp);
tp_vec_t tp_exec_position(tp_planner_t *tp);
/* tp_cycle.c */
tp_result_t tp_cycle_run(tp_planner_t *tp, const tp_cycle_in_t *in, tp_cycle_out_t *out);
/* tp_reverse.c */
int tp_rev_wanted(const tp_planner_t *tp, const tp_cycle_in_t *in, const tp_seg_t *s);
void tp_rev_locate(tp_planner_t *tp);
/* tp_sync.c */
double tp_sync_spindle_rps(const tp_planner_t *tp, const tp_cycle_in_t *in);
int tp_sync_start_wait(tp_planner_t *tp, const tp_cycle_in_t *in, tp_seg_t *s, tp_cycle_out_t *out);
void tp_sync_adjust(tp_planner_t *tp, const tp_cycle_in_t *in, tp_window_t *w);
void tp_sync_tap_cycle(tp_planner_t *tp, const tp_cycle_in_t *in, tp_cycle_out_t *out);
tp_vec_t tp_sync_tap_position(tp_planner_t *tp);
int tp_sync_end_hold(tp_planner_t *tp, const tp_cycle_in_t *in);

#endif
