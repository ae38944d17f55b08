// comp_corner.cc: joining compensated moves at corners: convex corner arcs, concave trimming, gouge checks.
#include <cmath>

#include "comp_engine.hh"

namespace cutcomp {

// turns smaller than this (radians) count as tangent: no corner arc, no trimming, as the reference
static const double TANGENT_TOLERANCE = 0.05;
// near reversals (radians from a half turn) are decided by the curvature of the two moves
static const double REVERSAL_TOLERANCE = 0.05;

// convex corners get an arc about the programmed corner, concave ones are trimmed to the intersection
Vec2 CompEngine::corner(const Joint &j)
{
    double turn = turn_angle(end_dir_, j.dir);
    if (M_PI - std::fabs(turn) < REVERSAL_TOLERANCE && end_kappa_ + j.kappa != 0)
        turn = end_kappa_ + j.kappa > 0 ? -M_PI : M_PI;
    double concave = left_ ? turn : -turn;
    if (concave > TANGENT_TOLERANCE) {
        Vec2 x = concave_point(j);
        trim_held(x);
        flush_all();
        return x;
    }
    flush_all();
    if (concave < -TANGENT_TOLERANCE) {
        HeldMove arc;
        arc.kind = HeldMove::ARC;
        arc.line = s_.sequence_number;
        arc.end = with_plane_point(ax_, tool_end_, j.start);
        arc.center = j.corner_point;
        arc.rotation = left_ ? -1 : 1;
        emit_move(out_, ax_, arc, shift_);
        tool_end_ = arc.end;
        path_end_ = j.start;
    }
    return j.start;
}

// of the intersections, prefer one on both moves, then one on the held move, then the nearest
Vec2 CompEngine::concave_point(const Joint &j)
{
    Vec2 cand[2];
    int n = intersections(end_shape_, j.shape, cand);
    if (n == 0)
        gouge_error();
    HeldMove *m = queue_.last_plane_move();
    int best = -1, best_score = -1;
    for (int i = 0; i < n; i++) {
        int score = (m && on_held(*m, cand[i]) ? 2 : 0) + (on_new(j, cand[i]) ? 1 : 0);
        bool nearer = best >= 0 && distance(cand[i], path_end_) < distance(cand[best], path_end_);
        if (score > best_score || (score == best_score && nearer)) {
            best = i;
            best_score = score;
        }
    }
    return cand[best];
}

// position along the new move: lines by projection, arcs by swept angle
bool CompEngine::on_new(const Joint &j, Vec2 x) const
{
    if (j.rotation == 0) {
        double t = dot(x - j.start, j.dir);
        return t > -1e-9 && t < distance(j.start, j.end);
    }
    double total = arc_sweep(j.shape.center, j.start, j.end, j.rotation);
    if (total == 0)
        total = 2 * M_PI;
    double upto = arc_sweep(j.shape.center, j.start, x, j.rotation);
    return upto < total || upto > 2 * M_PI - 1e-9;
}

// position along a held move: past its start and not beyond its end
bool CompEngine::on_held(const HeldMove &m, Vec2 x) const
{
    Vec2 end = plane_point(ax_, m.end);
    if (m.kind != HeldMove::ARC) {
        double t = dot(x - m.start, m.dir);
        return t > 0 && t <= dot(end - m.start, m.dir) + 1e-9;
    }
    double total = arc_sweep(m.center, m.arc_from, end, m.rotation);
    if (total == 0)
        total = 2 * M_PI;
    double begin = arc_sweep(m.center, m.arc_from, m.start, m.rotation);
    double upto = arc_sweep(m.center, m.arc_from, x, m.rotation);
    return upto > begin && upto <= total + 1e-9;
}

// the gouging error naming the kind of the held move
void CompEngine::gouge_error()
{
    HeldMove *m = queue_.last_plane_move();
    HeldMove::Kind kind = m ? m->kind : HeldMove::FEED;
    if (kind == HeldMove::ARC)
        throw InterpError("Arc move in concave corner cannot be reached by the tool without "
                          "gouging");
    if (kind == HeldMove::TRAVERSE)
        throw InterpError("Straight traverse in concave corner cannot be reached by the tool "
                          "without gouging");
    throw InterpError("Straight feed in concave corner cannot be reached by the tool without "
                      "gouging");
}

// move the end of the held move back to x; error when that reverses or empties it
void CompEngine::trim_held(Vec2 x)
{
    HeldMove *m = queue_.last_plane_move();
    if (!m)
        return;
    Vec2 old_end = plane_point(ax_, m->end);
    if (m->kind == HeldMove::ARC) {
        double total = arc_sweep(m->center, m->arc_from, old_end, m->rotation);
        if (total == 0)
            total = 2 * M_PI;
        double begin = arc_sweep(m->center, m->arc_from, m->start, m->rotation);
        double upto = arc_sweep(m->center, m->arc_from, x, m->rotation);
        if (std::abs(m->rotation) == 1 && (upto <= begin || upto > total + 1e-9))
            gouge_error();
    } else if (dot(x - m->start, m->dir) <= 0) {
        gouge_error();
    }
    queue_.move_end(ax_, x);
    tool_end_ = with_plane_point(ax_, tool_end_, x);
    path_end_ = x;
}

}  // namespace cutcomp
