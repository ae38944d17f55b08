// comp_corner.cc: joining compensated moves at corners: convex corner arcs, concave trims, tangents.
#include <cmath>

#include "comp_engine.hh"

namespace cutcomp {

// the convex corner arc: tool radius about the programmed corner, at the held path's height
void CompEngine::corner_arc(int line, Vec2 to, const Pose &end)
{
    HeldMove arc;
    arc.kind = HeldMove::ARC;
    arc.line = line;
    arc.end = with_plane_point(ax_, end, to);
    arc.end[ax_.perp] = cur_perp_;
    arc.center = prog_;
    arc.rotation = left_ ? -1 : 1;
    queue_.push_move(arc);
}

// A later straight move. theta is the direction from the programmed corner to the compensated
// point (the held move's offset normal), alpha the new move's direction; beta, the corner angle
// measured on the tool side, says convex (arc), concave (trim) or tangent (nothing).
void CompEngine::next_line(HeldMove::Kind kind, int line, const Pose &end)
{
    Vec2 p = plane_point(ax_, end), op = prog_, c = cur_;
    double pz = end[ax_.perp];
    if (p.y == op.y && p.x == op.x) {
        hold(kind, line, end, c, pz, Vec2{});
        cur_perp_ = pz;
        return;
    }
    double theta = std::atan2(c.y - op.y, c.x - op.x);
    double alpha = std::atan2(p.y - op.y, p.x - op.x);
    double beta, gamma;
    if (left_) {
        if (theta < alpha)
            theta = theta + 2 * M_PIl;
        beta = (theta - alpha) - M_PI_2l;
        gamma = M_PI_2l;
    } else {
        if (alpha < theta)
            alpha = alpha + 2 * M_PIl;
        beta = (alpha - theta) - M_PI_2l;
        gamma = -M_PI_2l;
    }
    Vec2 e = {p.x + radius_ * std::cos(alpha + gamma), p.y + radius_ * std::sin(alpha + gamma)};
    Vec2 mid = {op.x + radius_ * std::cos(alpha + gamma), op.y + radius_ * std::sin(alpha + gamma)};
    const double small = TOLERANCE_CONCAVE_CORNER;
    HeldMove *prev = queue_.front_move();
    bool prev_arc = prev && prev->kind == HeldMove::ARC;
    // a near reversal out of an arc the tool runs outside of (the top of an "h") is concave
    // nothing held (a synchronised move flushed it): no corner to trim
    bool concave = prev && (beta < -small || beta > M_PIl + small ||
                            (beta > M_PIl - small && prev_arc && !tool_inside(prev->rotation)));
    if (!concave && beta > small) {
        move_end_and_flush(c);
        if (kind == HeldMove::FEED)
            corner_arc(line, mid, end);
        else
            hold(HeldMove::TRAVERSE, line, end, mid, cur_perp_, Vec2{});
        dequeue();
        set_endpoint(mid);
    } else if (concave) {
        move_end_and_flush(concave_line_start(theta, beta, gamma, p));
    } else {
        dequeue();
        set_endpoint(c);
    }
    hold(kind, line, end, e, pz, {p.x - op.x, p.y - op.y});
    prog_ = p;
    cur_ = e;
    cur_perp_ = pz;
}

// Where a held line or arc meets the new line's offset in a concave corner. After a line: back
// along it by r / tan(half the inside angle). After an arc: where the line's offset crosses the
// arc's offset circle, found from the center's distance to the programmed line.
Vec2 CompEngine::concave_line_start(double theta, double beta, double gamma, Vec2 p)
{
    HeldMove &prev = *queue_.front_move();
    Vec2 op = prog_, c = cur_;
    if (prev.kind != HeldMove::ARC) {
        double halfcorner = (beta + M_PIl) / 2.0;
        if (halfcorner == 0.0)
            throw InterpError("Zero degree inside corner is invalid for cutter compensation");
        double retreat = radius_ / std::tan(halfcorner);
        return {c.x + retreat * std::cos(theta + gamma), c.y + retreat * std::sin(theta + gamma)};
    }
    Vec2 pe = plane_point(ax_, prev.end);
    double oldrad = std::hypot(prev.center.y - pe.y, prev.center.x - pe.x);
    double base_dir = std::atan2(p.y - op.y, p.x - op.x);
    double normal = prev.rotation > 0 ? base_dir + M_PI_2l : base_dir - M_PI_2l;
    double phi = std::atan2(prev.center.y - op.y, prev.center.x - op.x);
    bool inside = tool_inside(prev.rotation);
    double oldrad_uncomp = inside ? oldrad + radius_ : oldrad - radius_;
    double d = oldrad_uncomp * std::cos(normal - phi);
    double l = (inside ? d - radius_ : d + radius_) / oldrad;
    if (l > 1.0 || l < -1.0)
        throw InterpError("Arc to straight motion makes a corner the compensated tool can't fit "
                          "in without gouging");
    bool plus = inside ? prev.rotation < 0 : prev.rotation > 0;
    double angle = plus ? std::acos(l) + normal + M_PIl : -std::acos(l) + normal + M_PIl;
    return {prev.center.x + oldrad * std::cos(angle), prev.center.y + oldrad * std::sin(angle)};
}

}  // namespace cutcomp
