// spline.cc: G5 (cubic) and G5.1 (quadratic) splines (XY plane) and G5.2/G5.3 NURBS blocks
// (XY, XZ or YZ plane) as NURBS_G5_FEED.
#include <cmath>
#include <cstdio>

#include "interp.hh"
#include "spline_geom.hh"

namespace {

// arc-approximation tolerance used to measure a G5/G5.1 curve for G93, in inches (mm: x 25.4)
constexpr double SPLINE_TOLERANCE_INCH = 0.001;
// default NURBS order when the first G5.2 line has no L word
constexpr unsigned NURBS_DEFAULT_ORDER = 3;

// true when the block moves an axis that a spline cannot move
bool has_other_axis(const Block &b)
{
    return b.word('z') || b.word('a') || b.word('b') || b.word('c');
}

} // namespace

// Errors shared by G5, G5.1 and G5.2: plane, cutter comp, axes and feed.
void Interp::check_spline(const Block &b)
{
    INTERP_FRAME();
    if (s_.comp_side != CANON_SIDE_OFF)
        throw InterpError("Cannot convert spline with cutter radius compensation");
    if (s_.plane != CANON_PLANE_XY) throw InterpError("Splines must be in the XY plane");
    if (has_other_axis(b)) throw InterpError("Splines may not have motion in Z, A, B, or C");
    if (s_.feed_mode == FEED_INVERSE_TIME && !b.word('f'))
        throw InterpError("F word missing with inverse time arc move");
    if (s_.feed_mode != FEED_INVERSE_TIME && s_.feed_rate == 0.0)
        throw InterpError("Cannot make arc with zero feed rate");
}

// The control points of a G5 (I J P Q) or G5.1 (I J) block ending at `end`.
spline::Cubic Interp::spline_curve(const Block &b, int mode, const Pose &end)
{
    INTERP_FRAME();
    spline::Vec2 p0{s_.current[AX_X], s_.current[AX_Y]}, p3{end[AX_X], end[AX_Y]};
    double i = b.word('i') ? b.value('i') : 0.0, j = b.word('j') ? b.value('j') : 0.0;
    if (mode == 51) {
        if (i == 0.0 && j == 0.0) throw InterpError("Must specify non-zero I or J with G5.1");
        return spline::quadratic_to_cubic(p0, {p0.x + i, p0.y + j}, p3);
    }
    if (!b.word('p') || !b.word('q')) throw InterpError("Must specify both P and Q with G5");
    if (b.word('i') != b.word('j')) throw InterpError("Must specify both I and J with G5, or neither");
    if (!b.word('i') && !spline_continues_)
        throw InterpError("Must specify I and J with the first G5 after a non-spline move");
    spline::Cubic c;
    c.p[0] = p0;
    if (b.word('i'))
        c.p[1] = {p0.x + i, p0.y + j};
    else
        c.p[1] = {2 * p0.x - spline_cp2_[0], 2 * p0.y - spline_cp2_[1]};
    c.p[2] = {p3.x + b.value('p'), p3.y + b.value('q')};
    c.p[3] = p3;
    return c;
}

// G5 / G5.1: one NURBS_G5_FEED holding the Bezier control points (G5: 4 points, order 4;
// G5.1: 3 points, order 3), as LinuxCNC's interpreter emits it; the canon consumer turns it into
// motion (spline::cubic_to_biarcs does that for a cubic). In G93 the feed comes from the length.
void Interp::move_spline(const Block &b, int mode)
{
    INTERP_FRAME();
    check_spline(b);
    Pose end = find_end(b);
    spline::Cubic c = spline_curve(b, mode, end);
    printf("x3: %8.4f y3: %8.4f (emc/rs274ngc/interp_convert.cc 719)\n", end[AX_X], end[AX_Y]);
    fflush(stdout);
    if (s_.feed_mode == FEED_INVERSE_TIME) {
        double tol = SPLINE_TOLERANCE_INCH * (s_.units == CANON_UNITS_MM ? 25.4 : 1.0);
        apply_inverse_time(spline::path_length(c.p[0], spline::cubic_to_biarcs(c, tol)), b);
    }
    std::vector<CanonNurbsPoint> pts;
    for (int k = 0; k < 4; k++) {
        if (mode == 51 && k == 1) continue;
        spline::Vec2 p = c.p[k];
        if (mode == 51 && k == 2) p = spline::quadratic_middle(c);
        pts.push_back({p.x, p.y, 1.0});
    }
    out().nurbs_g5_feed(s_.sequence_number, pts, (unsigned)pts.size(), CANON_PLANE_XY);
    s_.current = end;
    spline_cp2_[0] = c.p[2].x;
    spline_cp2_[1] = c.p[2].y;
    spline_continues_ = true;
}

// G5.2/G5.3 checks: comp off, a G17/G18/G19 plane, only its two axes move, a feed.
void Interp::check_nurbs(const Block &b, int first, int second)
{
    INTERP_FRAME();
    if (s_.comp_side != CANON_SIDE_OFF)
        throw InterpError("Cannot convert spline with cutter radius compensation");
    if (s_.plane >= CANON_PLANE_UV) throw InterpError("Splines must be in the XY, XZ or YZ plane");
    static const char letters[] = "xyzabc";
    for (int i = 0; i < 6; i++)
        if (b.word(letters[i]) && i != first && i != second)
            throw InterpError("Splines may only move the two axes of the selected plane");
    if (s_.feed_mode == FEED_INVERSE_TIME && !b.word('f'))
        throw InterpError("F word missing with inverse time arc move");
    if (s_.feed_mode != FEED_INVERSE_TIME && s_.feed_rate == 0.0)
        throw InterpError("Cannot make arc with zero feed rate");
}

// G5.2 line: the first opens a block (L = order); each adds the end point of its words in the
// selected plane (G17, G18 or G19) as a control point with weight P (default 1).
void Interp::nurbs_point(const Block &b, int)
{
    INTERP_FRAME();
    int first = s_.plane == CANON_PLANE_YZ ? AX_Y : s_.plane == CANON_PLANE_XZ ? AX_Z : AX_X;
    int second = s_.plane == CANON_PLANE_XY ? AX_Y : s_.plane == CANON_PLANE_XZ ? AX_X : AX_Z;
    check_nurbs(b, first, second);
    if (!nurbs_open_) {
        int order = b.word('l') ? clamp_int(b.value('l')) : (int)NURBS_DEFAULT_ORDER;
        if (b.word('l') && (order < 2 || order != b.value('l')))
            throw InterpError("G5.2 order L must be an integer of at least 2");
        nurbs_.clear();
        nurbs_order_ = (unsigned)order;
        nurbs_open_ = true;
    }
    double weight = b.word('p') ? b.value('p') : 1.0;
    if (!(weight > 0)) throw InterpError("G5.2 weight P must be greater than zero");
    Pose end = find_end(b);
    nurbs_.push_back({end[first], end[second], weight});
    s_.current = end;
}

// G5.3: close the open G5.2 block and emit NURBS_G5_FEED.
void Interp::nurbs_close(const Block &b)
{
    INTERP_FRAME();
    if (!nurbs_open_) throw InterpError("G5.3 without an open G5.2 block");
    static const char letters[] = "xyzabc";
    for (char c : letters)
        if (c && b.word(c)) throw InterpError("Cannot use axis values with G5.3");
    nurbs_open_ = false;
    if (nurbs_.size() < nurbs_order_)
        throw InterpError("You must specify a number of control points at least equal to the "
                          "order L = " + std::to_string(nurbs_order_));
    out().nurbs_g5_feed(s_.sequence_number, nurbs_, nurbs_order_, s_.plane);
    nurbs_.clear();
}
