// comp_arc.cc: compensated arcs after the entry: offset radius, corners into an arc, concave trims.
#include <cmath>

#include "comp_engine.hh"

namespace cutcomp {

// squared value
static double sq(double v)
{
    return v * v;
}

// A later arc: same center, radius grown (tool outside) or shrunk (tool inside) by the tool
// radius. theta is the held path's direction at the corner, alpha the arc's start tangent and
// beta the corner angle on the tool side; delta ends as the direction from the programmed start
// to the compensated start.
void CompEngine::next_arc(int line, const Pose &end, Vec2 center, int rotation)
{
    Vec2 e = plane_point(ax_, end), op = prog_, c = cur_;
    bool inside = tool_inside(rotation);
    if (inside && std::hypot(center.x - op.x, center.y - op.y) <= radius_)
        throw InterpError("Tool radius not less than arc radius with comp");
    double arc_radius = std::hypot(center.x - e.x, center.y - e.y);
    double theta = std::atan2(c.y - op.y, c.x - op.x);
    theta = left_ ? theta - M_PI_2l : theta + M_PI_2l;
    double delta = std::atan2(center.y - op.y, center.x - op.x);
    double alpha = rotation > 0 ? delta - M_PI_2l : delta + M_PI_2l;
    double beta = left_ ? theta - alpha : alpha - theta;
    beta = beta > 1.5 * M_PIl ? beta - 2 * M_PIl : beta < -M_PI_2l ? beta + 2 * M_PIl : beta;
    double gamma;
    if (inside) {
        gamma = std::atan2(center.y - e.y, center.x - e.x);
        if (arc_radius <= radius_)
            throw InterpError("Tool radius not less than arc radius with comp");
    } else {
        gamma = std::atan2(e.y - center.y, e.x - center.x);
        delta = delta + M_PIl;
    }
    Vec2 ne = {e.x + radius_ * std::cos(gamma), e.y + radius_ * std::sin(gamma)};
    const double small = TOLERANCE_CONCAVE_CORNER;
    // a near reversal into an arc the tool runs outside of (the middle of an "m") is concave
    // nothing held (a synchronised move flushed it): no corner to trim
    bool concave = queue_.front_move() &&
                   (beta < -small || beta > M_PIl + small ||
                    (std::fabs(beta - M_PIl) < small && !inside));
    if (concave) {
        double r2 = inside ? arc_radius - radius_ : arc_radius + radius_;
        bool after_arc = queue_.front_move()->kind == HeldMove::ARC;
        move_end_and_flush(after_arc ? arc_arc_corner(center, r2, rotation)
                                     : line_arc_corner(theta, center, arc_radius, r2, rotation));
    } else if (beta > small) {
        Vec2 mid = {op.x + radius_ * std::cos(delta), op.y + radius_ * std::sin(delta)};
        move_end_and_flush(c);
        corner_arc(line, mid, end);
        dequeue();
        set_endpoint(mid);
    } else {
        dequeue();
        set_endpoint(c);
    }
    HeldMove m;
    m.kind = HeldMove::ARC;
    m.line = line;
    m.end = with_plane_point(ax_, end, ne);
    m.center = center;
    m.rotation = rotation;
    m.original_sweep = find_turn(op, center, rotation, e);
    queue_.push_move(m);
    prog_ = e;
    cur_ = ne;
    cur_perp_ = end[ax_.perp];
}

// where the held line (through the compensated point, direction theta) meets the new arc's
// offset circle (programmed end radius arc_radius, offset radius r2): the center's distance to
// the programmed line, measured along the line's normal on the side the arc turns to, taken as
// arc_radius times the cosine of the angle at the corner (as LinuxCNC does: the end radius)
Vec2 CompEngine::line_arc_corner(double theta, Vec2 center, double arc_radius, double r2,
                                 int rotation)
{
    Vec2 op = prog_;
    double normal = rotation > 0 ? theta + M_PI_2l : theta - M_PI_2l;
    double phi = std::atan2(center.y - op.y, center.x - op.x);
    double d = arc_radius * std::cos(normal - phi);
    bool inside = tool_inside(rotation);
    double l = (inside ? d - radius_ : d + radius_) / r2;
    if (l > 1.0 || l < -1.0)
        throw InterpError("Straight to arc motion makes a corner the compensated tool can't fit "
                          "in without gouging");
    bool plus = inside ? rotation > 0 : rotation < 0;
    double angle = plus ? std::acos(l) + normal + M_PIl : -std::acos(l) + normal + M_PIl;
    return {center.x + r2 * std::cos(angle), center.y + r2 * std::sin(angle)};
}

// where the held arc's offset circle meets the new arc's (radius r2), by the law of cosines on
// the triangle of the two centers and the meeting point
Vec2 CompEngine::arc_arc_corner(Vec2 center, double r2, int rotation)
{
    HeldMove &prev = *queue_.front_move();
    Vec2 pe = plane_point(ax_, prev.end);
    double oldrad = std::hypot(prev.center.y - pe.y, prev.center.x - pe.x);
    double arc_cc = std::hypot(prev.center.y - center.y, prev.center.x - center.x);
    if (oldrad == 0 || arc_cc == 0)
        throw InterpError("Arc to arc motion is invalid because the arcs have the same center");
    double a = (sq(oldrad) + sq(arc_cc) - sq(r2)) / (2 * oldrad * arc_cc);
    if (a > 1.0 || a < -1.0)
        throw InterpError("Arc to arc motion makes a corner the compensated tool can't fit in "
                          "without gouging");
    double pullback = std::acos(a);
    double cc_dir = std::atan2(center.y - prev.center.y, center.x - prev.center.x);
    bool plus = tool_inside(prev.rotation) ? rotation > 0 : rotation < 0;
    double dir = plus ? cc_dir + pullback : cc_dir - pullback;
    return {prev.center.x + oldrad * std::cos(dir), prev.center.y + oldrad * std::sin(dir)};
}

}  // namespace cutcomp
