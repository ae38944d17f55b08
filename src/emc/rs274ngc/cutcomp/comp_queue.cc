// comp_queue.cc: holding compensated moves and replaying them with deferred canon calls.
#include "comp_queue.hh"

namespace cutcomp {

// XY works in (x, y) about z; XZ in (z, x) about y, matching ARC_FEED's axis order
CompAxes comp_axes(CanonPlane p)
{
    CompAxes ax;
    if (p == CANON_PLANE_XZ) {
        ax.first = AX_Z;
        ax.second = AX_X;
        ax.perp = AX_Y;
    }
    ax.plane = p;
    return ax;
}

// project a pose onto the plane
Vec2 plane_point(const CompAxes &ax, const Pose &p)
{
    return {p[ax.first], p[ax.second]};
}

// replace the plane coordinates of a pose
Pose with_plane_point(const CompAxes &ax, Pose p, Vec2 v)
{
    p[ax.first] = v.x;
    p[ax.second] = v.y;
    return p;
}

// append a deferred call
void CompQueue::push_call(std::function<void(Canon &)> call)
{
    Entry e;
    e.call = std::move(call);
    q_.push_back(std::move(e));
}

// append a held move
void CompQueue::push_move(const HeldMove &m)
{
    Entry e;
    e.is_move = true;
    e.move = m;
    q_.push_back(std::move(e));
}

// the first queued entry is always a move: calls are only queued behind one
HeldMove *CompQueue::front_move()
{
    for (auto &e : q_)
        if (e.is_move)
            return &e.move;
    return nullptr;
}

// visit the held moves in order
void CompQueue::for_each_move(const std::function<void(HeldMove &)> &f)
{
    for (auto &e : q_)
        if (e.is_move)
            f(e.move);
}

// replay the queue
void CompQueue::flush(Canon &out, const CompAxes &ax, Vec2 shift)
{
    while (!q_.empty()) {
        Entry e = std::move(q_.front());
        q_.pop_front();
        if (e.is_move)
            emit_move(out, ax, e.move, shift);
        else
            e.call(out);
    }
}

// write one move, applying the lathe tool-tip shift to end point and center
void emit_move(Canon &out, const CompAxes &ax, const HeldMove &m, Vec2 shift)
{
    Pose end = m.end;
    Vec2 c = m.center;
    if (shift.x != 0) {
        end[ax.first] += shift.x;
        c.x += shift.x;
    }
    if (shift.y != 0) {
        end[ax.second] += shift.y;
        c.y += shift.y;
    }
    if (m.kind == HeldMove::TRAVERSE) {
        out.straight_traverse(m.line, to_canon_pose(end));
    } else if (m.kind == HeldMove::FEED) {
        out.straight_feed(m.line, to_canon_pose(end));
    } else {
        out.arc_feed(m.line, end[ax.first], end[ax.second], c.x, c.y, m.rotation, end[ax.perp],
                     end[AX_A], end[AX_B], end[AX_C], end[AX_U], end[AX_V], end[AX_W]);
    }
}

}  // namespace cutcomp
