// comp_engine.cc: cutter comp on and off, entry moves, and the held-move queue's end point moves.
#include "comp_engine.hh"

#include <cmath>
#include <cstdio>

#include "comp_orient.hh"

namespace cutcomp {

// entry arcs whose new center direction is this close to a right angle are refused
static const double TOLERANCE_EQUAL = 0.0001;
// how far (program units) the recomputed entry arc radii may differ before it is a bug
static const double ENTRY_ARC_TOLERANCE_INCH = 0.0005;
static const double ENTRY_ARC_TOLERANCE_MM = 0.005;
// how much a trimmed arc may sweep beyond its programmed sweep (radians, by program units)
static const double ARC_TRIM_SLACK_INCH = 0.001;
static const double ARC_TRIM_SLACK_MM = 0.0254;
// a trimmed arc's radius may change this much before it is reported as a bug
static const double ARC_TRIM_RADIUS_TOLERANCE = 0.01;

// nine-axis pose of a canon pose
static Pose pose_of(const CanonPose &p)
{
    return {p.x, p.y, p.z, p.a, p.b, p.c, p.u, p.v, p.w};
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
    orientation_ = s.comp_orientation;
    shift_ = tip_shift(s.plane, s.comp_orientation, radius_);
    active_ = true;
    first_ = true;
}

// G40: emit the held path; the next move leaves from the last compensated point
void CompEngine::stop(InterpState &)
{
    if (compensating() && !first_) {
        move_end_and_flush(cur_);
        dequeue();
        arc_not_allowed_ = true;
    }
    active_ = false;
    first_ = true;
}

// forget held moves after an error or reset
void CompEngine::reset()
{
    queue_.clear();
    active_ = false;
    first_ = true;
    arc_not_allowed_ = false;
    endpoint_valid_ = false;
}

// emit every held move and deferred call
void CompEngine::flush_all()
{
    dequeue();
}

// emit the queue; nothing is held afterwards, so no start point is known
void CompEngine::dequeue()
{
    endpoint_valid_ = false;
    queue_.flush(out_, ax_, shift_);
}

// the next held move starts at x
void CompEngine::set_endpoint(Vec2 x)
{
    endpoint_ = x;
    endpoint_valid_ = true;
}

// a straight move: passed through while comp is off, else offset and held
void CompEngine::straight_move(HeldMove::Kind kind, int line, const CanonPose &p)
{
    arc_not_allowed_ = false;
    if (compensating()) {
        if (first_)
            entry_line(kind, line, pose_of(p));
        else
            next_line(kind, line, pose_of(p));
        return;
    }
    flush_all();
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
    if (arc_not_allowed_)
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
    if (first_)
        entry_arc(line, end, {first_axis, second_axis}, rotation);
    else
        next_arc(line, end, {first_axis, second_axis}, rotation);
}

// hold a straight move to plane point `to` and perpendicular value `perp`
void CompEngine::hold(HeldMove::Kind kind, int line, const Pose &end, Vec2 to, double perp, Vec2 dir)
{
    HeldMove m;
    m.kind = kind;
    m.line = line;
    m.end = with_plane_point(ax_, end, to);
    m.end[ax_.perp] = perp;
    m.dir = dir;
    queue_.push_move(m);
}

// entry line: to the programmed end moved a radius sideways, perpendicular to the move
void CompEngine::entry_line(HeldMove::Kind kind, int line, const Pose &end)
{
    Vec2 c = plane_point(ax_, s_.current), p = plane_point(ax_, end);
    if (std::hypot(p.x - c.x, p.y - c.y) <= radius_)
        throw InterpError("Length of cutter compensation entry move is not greater than the "
                          "tool radius");
    double alpha = std::atan2(p.y - c.y, p.x - c.x) + (left_ ? M_PIl / 2. : -M_PIl / 2.);
    Vec2 e = {p.x + radius_ * std::cos(alpha), p.y + radius_ * std::sin(alpha)};
    set_endpoint(c);
    hold(kind, line, end, e, end[ax_.perp], {std::cos(alpha), std::sin(alpha)});
    first_ = false;
    prog_ = p;
    cur_ = e;
    cur_perp_ = end[ax_.perp];
}

// entry arc: the end moves a radius along the end radius and the center slides along that
// radius until the arc passes through the current point
void CompEngine::entry_arc(int line, const Pose &end, Vec2 center, int rotation)
{
    Vec2 c = plane_point(ax_, s_.current), p = plane_point(ax_, end);
    if (std::hypot(p.x - c.x, p.y - c.y) <= radius_)
        throw InterpError("Radius of cutter compensation entry arc is not greater than the tool "
                          "radius");
    bool inside = tool_inside(rotation);
    if (inside && std::hypot(center.x - c.x, center.y - c.y) <= radius_)
        throw InterpError("Tool radius not less than arc radius with comp");
    double gamma = inside ? std::atan2(center.y - p.y, center.x - p.x)
                          : std::atan2(p.y - center.y, p.x - center.x);
    Vec2 e = {p.x + radius_ * std::cos(gamma), p.y + radius_ * std::sin(gamma)};
    double b_len = std::hypot(c.y - e.y, c.x - e.x) / 2.0;
    double ab_ang = std::atan2(center.y - e.y, center.x - e.x);
    double a_ang = std::atan2(c.y - e.y, c.x - e.x) - ab_ang;
    if (std::fabs(std::cos(a_ang)) < TOLERANCE_EQUAL)
        throw InterpError("Tool radius not less than arc radius with comp");
    double c_len = b_len / std::cos(a_ang);
    Vec2 nc = {e.x + c_len * std::cos(ab_ang), e.y + c_len * std::sin(ab_ang)};
    double tol = s_.units == CANON_UNITS_INCHES ? ENTRY_ARC_TOLERANCE_INCH : ENTRY_ARC_TOLERANCE_MM;
    if (std::fabs(std::hypot(nc.x - e.x, nc.y - e.y) - std::hypot(nc.x - c.x, nc.y - c.y)) > tol)
        throw InterpError("Bug in tool radius comp");
    // a lathe tool's controlled point jumps to the tip here: a zero-length move first, so the
    // arc starts where its shifted start really is
    if (orientation_ != 0 && orientation_ != 9) {
        hold(HeldMove::FEED, line, end, c, s_.current[ax_.perp], Vec2{});
        set_endpoint(c);
    }
    HeldMove m;
    m.kind = HeldMove::ARC;
    m.line = line;
    m.end = with_plane_point(ax_, end, e);
    m.center = nc;
    m.rotation = rotation;
    m.original_sweep = find_turn(c, nc, rotation, e);
    queue_.push_move(m);
    first_ = false;
    prog_ = p;
    cur_ = e;
    cur_perp_ = end[ax_.perp];
}

// a held arc may be trimmed, never swept past its start or onto another radius
void CompEngine::check_arc_end(const HeldMove &m, Vec2 x) const
{
    Vec2 end = plane_point(ax_, m.end);
    double r1 = std::hypot(end.x - m.center.x, end.y - m.center.y);
    double r2 = std::hypot(x.x - m.center.x, x.y - m.center.y);
    double l1 = m.original_sweep;
    double l2 = find_turn(endpoint_, m.center, m.rotation, x);
    double slack = s_.units == CANON_UNITS_MM ? ARC_TRIM_SLACK_MM : ARC_TRIM_SLACK_INCH;
    if (l1 != 0 && endpoint_valid_ && std::fabs(l2) > std::fabs(l1) + slack)
        throw InterpError("Arc move in concave corner cannot be reached by the tool without "
                          "gouging");
    if (std::fabs(r1 - r2) > ARC_TRIM_RADIUS_TOLERANCE) {
        char buf[200];
        snprintf(buf, sizeof buf, "BUG: cutter compensation has generated an invalid arc with "
                 "mismatched radii r1 %f r2 %f\n", r1, r2);
        throw InterpError(buf);
    }
}

// the concave-corner trim: every held move now ends at x; a straight one must not reverse
void CompEngine::move_end_and_flush(Vec2 x)
{
    if (!queue_.holding())
        return;
    queue_.for_each_move([&](HeldMove &m) {
        if (m.kind == HeldMove::ARC) {
            check_arc_end(m, x);
        } else {
            double dot = m.dir.x * (x.x - endpoint_.x) + m.dir.y * (x.y - endpoint_.y);
            if (endpoint_valid_ && dot < 0)
                throw InterpError(m.kind == HeldMove::TRAVERSE
                    ? "Straight traverse in concave corner cannot be reached by the tool without "
                      "gouging"
                    : "Straight feed in concave corner cannot be reached by the tool without "
                      "gouging");
        }
        m.end = with_plane_point(ax_, m.end, x);
    });
    dequeue();
    set_endpoint(x);
}

}  // namespace cutcomp

// create the compensation engine the interpreter filters every canon call through
std::unique_ptr<cutcomp::Engine> cutcomp::make_engine(InterpState &s, Canon &out)
{
    return std::unique_ptr<Engine>(new CompEngine(s, out));
}
