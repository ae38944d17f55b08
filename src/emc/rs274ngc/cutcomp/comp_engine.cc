// comp_engine.cc: offsetting lines and arcs by the tool radius, corner arcs, concave trimming, entry and exit.
#include "comp_engine.hh"

#include <cmath>

#include "comp_orient.hh"

namespace cutcomp {

// nine-axis pose of a canon pose
static Pose pose_of(const CanonPose &p)
{
    return {p.x, p.y, p.z, p.a, p.b, p.c, p.u, p.v, p.w};
}

// a held straight move of the given line: compensated start, start direction, end pose
static HeldMove held_line(HeldMove::Kind kind, int line, Vec2 start, Vec2 dir, const Pose &end)
{
    HeldMove m;
    m.kind = kind;
    m.line = line;
    m.start = start;
    m.dir = dir;
    m.end = end;
    return m;
}

// a held arc of the given line: center, direction, untrimmed and trimmed start, end pose
static HeldMove held_arc(int line, Vec2 center, int rotation, Vec2 arc_from, Vec2 start,
                         const Pose &end)
{
    HeldMove m = held_line(HeldMove::ARC, line, start, Vec2{}, end);
    m.center = center;
    m.rotation = rotation;
    m.arc_from = arc_from;
    return m;
}

// set up with compensation off
CompEngine::CompEngine(InterpState &s, Canon &out) : CompFilter(out), s_(s)
{
}

// G41/G42/G41.1/G42.1: remember side, radius, plane and lathe tip shift
void CompEngine::start(InterpState &s)
{
    flush_all();
    ax_ = comp_axes(s.plane);
    left_ = s.comp_side == CANON_SIDE_LEFT;
    radius_ = s.comp_radius;
    shift_ = tip_shift(s.plane, s.comp_orientation, radius_);
    active_ = true;
    first_ = true;
    if (!exit_pending_)
        tool_end_ = s.current;
    exit_pending_ = false;
}

// G40: emit the held path; the next move leaves from the last compensated point
void CompEngine::stop(InterpState &)
{
    flush_all();
    exit_pending_ = compensating() && !first_;
    active_ = false;
    first_ = true;
}

// forget held moves after an error or reset
void CompEngine::reset()
{
    queue_.clear();
    active_ = false;
    first_ = true;
    exit_pending_ = false;
}

// emit every held move and deferred call
void CompEngine::flush_all()
{
    queue_.flush(out_, ax_, shift_);
}

// a straight move: passed through while comp is off, else offset and held
void CompEngine::straight_move(HeldMove::Kind kind, int line, const CanonPose &p)
{
    if (compensating()) {
        line_move(kind, line, pose_of(p));
        return;
    }
    flush_all();
    exit_pending_ = false;
    if (kind == HeldMove::TRAVERSE)
        out_.straight_traverse(line, p);
    else
        out_.straight_feed(line, p);
}

// rapid: compensated like a feed, emitted as a traverse
void CompEngine::straight_traverse(int line, const CanonPose &p)
{
    straight_move(HeldMove::TRAVERSE, line, p);
}

// feed: compensated while comp is on
void CompEngine::straight_feed(int line, const CanonPose &p)
{
    straight_move(HeldMove::FEED, line, p);
}

// arc: compensated while comp is on; not allowed as the move leaving compensation
void CompEngine::arc_feed(int line, double first_end, double second_end, double first_axis,
                          double second_axis, int rotation, double axis_end, double a, double b,
                          double c, double u, double v, double w)
{
    if (exit_pending_)
        throw InterpError("The move just after exiting cutter compensation mode must be "
                          "straight, not an arc");
    if (!compensating()) {
        flush_all();
        out_.arc_feed(line, first_end, second_end, first_axis, second_axis, rotation, axis_end,
                      a, b, c, u, v, w);
        return;
    }
    Pose end = s_.current;
    end[ax_.first] = first_end;
    end[ax_.second] = second_end;
    end[ax_.perp] = axis_end;
    end[AX_A] = a; end[AX_B] = b; end[AX_C] = c;
    end[AX_U] = u; end[AX_V] = v; end[AX_W] = w;
    arc_move(line, end, {first_axis, second_axis}, rotation);
}

// unit normal toward the compensation side of a line of angle theta
Vec2 CompEngine::line_normal(double theta) const
{
    return polar(left_ ? theta + M_PI_2 : theta - M_PI_2);
}

// -1 when the tool runs inside the arc (left of a CCW arc, right of a CW arc), else +1
double CompEngine::arc_side(int rotation) const
{
    return (left_ == (rotation > 0)) ? -1.0 : 1.0;
}

// remember the end of a newly held move
void CompEngine::hold(const HeldMove &m, Vec2 end_dir, double end_kappa, const PathShape &end_shape)
{
    end_kappa_ = end_kappa;
    queue_.push_move(m);
    path_end_ = plane_point(ax_, m.end);
    tool_end_ = m.end;
    end_dir_ = end_dir;
    end_shape_ = end_shape;
    first_ = false;
}

// straight move with compensation on
void CompEngine::line_move(HeldMove::Kind kind, int line, const Pose &end)
{
    if (first_) {
        entry_line(kind, line, end);
        return;
    }
    Vec2 s2 = plane_point(ax_, s_.current), e2 = plane_point(ax_, end);
    if (distance(s2, e2) < 1e-12) {
        HeldMove m = held_line(kind, line, path_end_, Vec2{}, with_plane_point(ax_, end, path_end_));
        m.in_plane = false;
        queue_.push_move(m);
        tool_end_ = m.end;
        return;
    }
    double theta = angle_of(e2 - s2);
    Vec2 n = line_normal(theta);
    PathShape shape = line_shape(s2 + radius_ * n, polar(theta));
    Joint j;
    j.dir = shape.d;
    j.start = shape.p;
    j.end = e2 + radius_ * n;
    j.shape = shape;
    j.corner_point = s2;
    hold(held_line(kind, line, corner(j), shape.d, with_plane_point(ax_, end, j.end)), shape.d, 0,
         shape);
}

// entry line: ends at the programmed end offset perpendicular to the move
void CompEngine::entry_line(HeldMove::Kind kind, int line, const Pose &end)
{
    Vec2 s2 = plane_point(ax_, tool_end_), e2 = plane_point(ax_, end);
    if (distance(s2, e2) <= radius_) {
        if (distance(s2, e2) < 1e-12) {
            flush_all();
            kind == HeldMove::TRAVERSE ? out_.straight_traverse(line, to_canon_pose(end))
                                       : out_.straight_feed(line, to_canon_pose(end));
            tool_end_ = end;
            return;
        }
        throw InterpError("Length of cutter compensation entry move is not greater than the "
                          "tool radius");
    }
    double theta = angle_of(e2 - s2);
    Vec2 e_off = e2 + radius_ * line_normal(theta);
    PathShape shape = line_shape(e_off, polar(theta));
    HeldMove m = held_line(kind, line, s2, polar(angle_of(e_off - s2)),
                           with_plane_point(ax_, end, e_off));
    flush_all();
    hold(m, polar(theta), 0, shape);
}

// arc move with compensation on: same center, radius grown or shrunk by the tool radius
void CompEngine::arc_move(int line, const Pose &end, Vec2 center, int rotation)
{
    if (first_) {
        entry_arc(line, end, center, rotation);
        return;
    }
    Vec2 s2 = plane_point(ax_, s_.current), e2 = plane_point(ax_, end);
    double k = arc_side(rotation);
    double r0 = distance(s2, center);
    if (k < 0 && r0 <= radius_)
        throw InterpError("Tool radius not less than arc radius with comp");
    double r_end = distance(e2, center) + k * radius_;
    PathShape shape = arc_shape(center, k > 0 ? r_end : r0 + k * radius_);
    Vec2 start = center + (r0 + k * radius_) * polar(angle_of(s2 - center));
    Vec2 e_off = center + r_end * polar(angle_of(e2 - center));
    double kappa = (rotation > 0 ? 1.0 : -1.0) / r0;
    Joint j;
    j.dir = arc_tangent(center, s2, rotation);
    j.kappa = kappa;
    j.start = start;
    j.end = e_off;
    j.shape = shape;
    j.corner_point = s2;
    j.rotation = rotation;
    Vec2 trimmed_start = corner(j);
    HeldMove m = held_arc(line, center, rotation, start, trimmed_start,
                          with_plane_point(ax_, end, e_off));
    hold(m, arc_tangent(center, e2, rotation), kappa, arc_shape(center, r_end));
}

// entry arc: the end is offset radially, the center moves along the end radius
void CompEngine::entry_arc(int line, const Pose &end, Vec2 center, int rotation)
{
    Vec2 s2 = plane_point(ax_, tool_end_), e2 = plane_point(ax_, end);
    if (distance(s2, e2) <= radius_)
        throw InterpError("Radius of cutter compensation entry arc is not greater than the tool "
                          "radius");
    double k = arc_side(rotation);
    if (k < 0 && distance(e2, center) <= radius_)
        throw InterpError("Tool radius not less than arc radius with comp");
    double r_end = distance(e2, center);
    Vec2 e_off = center + (r_end + k * radius_) * polar(angle_of(e2 - center));
    Vec2 c2;
    if (!entry_arc_center(s2, center, e2, e_off, c2))
        throw InterpError("Arc move in concave corner cannot be reached by the tool without "
                          "gouging");
    HeldMove m = held_arc(line, c2, rotation, s2, s2, with_plane_point(ax_, end, e_off));
    flush_all();
    hold(m, arc_tangent(center, e2, rotation), (rotation > 0 ? 1.0 : -1.0) / r_end,
         arc_shape(c2, distance(e_off, c2)));
}

}  // namespace cutcomp

// create the compensation engine the interpreter filters every canon call through
std::unique_ptr<cutcomp::Engine> cutcomp::make_engine(InterpState &s, Canon &out)
{
    return std::unique_ptr<Engine>(new CompEngine(s, out));
}
