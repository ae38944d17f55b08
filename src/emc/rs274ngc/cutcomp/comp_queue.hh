// comp_queue.hh: moves held by cutter compensation and the canon calls queued behind them.
#ifndef OPENEMC_RS274NGC_COMP_QUEUE_HH
#define OPENEMC_RS274NGC_COMP_QUEUE_HH

#include <deque>
#include <functional>

#include "../canon.hh"
#include "../interp_state.hh"
#include "comp_geom.hh"

namespace cutcomp {

// Which plane axes compensation works in: XY as (x, y), XZ as (z, x); `perp` is the third axis.
struct CompAxes {
    int first = AX_X, second = AX_Y, perp = AX_Z;
    CanonPlane plane = CANON_PLANE_XY;
};

// the compensation axes of canon plane p
CompAxes comp_axes(CanonPlane p);
// the plane point of pose p
Vec2 plane_point(const CompAxes &ax, const Pose &p);
// pose p with its plane point replaced by v
Pose with_plane_point(const CompAxes &ax, Pose p, Vec2 v);

// One compensated move waiting to be emitted.
struct HeldMove {
    enum Kind { TRAVERSE, FEED, ARC } kind = FEED;
    int line = 0;
    Pose end{};                 // full end pose (plane point compensated, before the tool-tip shift)
    Vec2 dir;                   // straight: the programmed plane motion, for the reversal check
    Vec2 center;                // arc center
    int rotation = 0;           // arc turns, sign = direction
    double original_sweep = 0;  // arc: programmed sweep (radians), 0 for corner arcs
};

// FIFO of held moves and deferred canon calls, emitted in order.
class CompQueue {
public:
    // true while anything is queued (calls are only queued behind a move)
    bool holding() const { return !q_.empty(); }
    // defer a canon call behind the held moves
    void push_call(std::function<void(Canon &)> call);
    // hold a move
    void push_move(const HeldMove &m);
    // the oldest held move, nullptr if none
    HeldMove *front_move();
    // call f for every held move, oldest first
    void for_each_move(const std::function<void(HeldMove &)> &f);
    // emit everything in order through `out`, shifting plane points by `shift`
    void flush(Canon &out, const CompAxes &ax, Vec2 shift);
    // drop everything
    void clear() { q_.clear(); }

private:
    // one queue slot: a move or a call
    struct Entry {
        bool is_move = false;
        HeldMove move;
        std::function<void(Canon &)> call;
    };
    std::deque<Entry> q_;
};

// emit one compensated move through `out` with its plane points shifted by `shift`
void emit_move(Canon &out, const CompAxes &ax, const HeldMove &m, Vec2 shift);

}  // namespace cutcomp

#endif
