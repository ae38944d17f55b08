// lathe_cycles.cc: G71/G72 roughing and G70 finishing of a monotonic profile subroutine (XZ plane).
#include <cmath>
#include <string>

#include "../interp_hooks.hh"
#include "cycle_axes.hh"
#include "lathe_profile.hh"

namespace cycles {

// most roughing levels one block may cut; more means I is far too small for the stock
static const int MAX_LEVELS = 10000;

// Where a cycle starts and which axis it steps along: X for G71 and G70, Z for G72.
struct LatheJob {
    LathePoint start;      // X Z words, else the current point
    bool step_x = true;    // levels step along X (turning) or Z (facing)
    std::string who;       // "G71" in error texts
};

// value of word c, or `def` when absent
static double word_or(const Block &b, char c, double def)
{
    return b.word(c) ? b.value(c) : def;
}

// coordinate along the step axis
static double step_of(const LatheJob &j, LathePoint p)
{
    return j.step_x ? p.x : p.z;
}

// coordinate along the cut axis
static double cut_of(const LatheJob &j, LathePoint p)
{
    return j.step_x ? p.z : p.x;
}

// point from step-axis and cut-axis coordinates
static LathePoint point_of(const LatheJob &j, double step, double cut)
{
    return j.step_x ? LathePoint{step, cut} : LathePoint{cut, step};
}

// rapid or feed to a point of the XZ plane (axes a = z, b = x of the cycle moves)
static void go(CycleMoves &mv, LathePoint p, bool feed)
{
    if (feed)
        mv.feed(p.z, p.x, mv.cur(AX_Y));
    else
        mv.rapid(p.z, p.x, mv.cur(AX_Y));
}

// the profile of word Q, checked to be monotonic along both axes
static Profile load_profile(const InterpState &s, const Block &b, ProfileSource &src,
                            const std::string &who)
{
    if (!b.word('q'))
        throw InterpError("Q word missing with g" + who.substr(1));
    std::string name = std::to_string(std::lround(b.value('q')));
    Profile p = read_profile(s, src.sub_blocks(name), who);
    if (!profile_monotonic(p, true) || !profile_monotonic(p, false))
        throw InterpError(who + ": the profile in o" + name +
                          " must not turn back in X or Z (pockets are not supported)");
    return p;
}

// one contour pass along the profile moved by `shift` on the step axis, from and back to the start
static void contour_pass(CycleMoves &mv, const LatheJob &j, const Profile &p, double shift)
{
    LathePoint first = p.start();
    double s0 = step_of(j, first) + shift;
    go(mv, point_of(j, s0, cut_of(j, j.start)), false);
    go(mv, point_of(j, s0, cut_of(j, first)), true);
    for (const ProfileSeg &g : p.segs) {
        LathePoint to = point_of(j, step_of(j, g.to) + shift, cut_of(j, g.to));
        if (!g.arc) {
            go(mv, to, true);
            continue;
        }
        LathePoint c = point_of(j, step_of(j, g.center) + shift, cut_of(j, g.center));
        mv.arc(to.z, to.x, c.z, c.x, g.rotation);
    }
    LathePoint here{mv.cur(AX_X), mv.cur(AX_Z)};
    go(mv, point_of(j, step_of(j, j.start), cut_of(j, here)), false);
    go(mv, j.start, false);
}

// the step direction from the start point toward the profile; errors when the start is inside it
static double step_direction(const LatheJob &j, const Profile &p)
{
    double lo, hi;
    profile_range(p, j.step_x, lo, hi);
    double s = step_of(j, j.start);
    if (s >= hi)
        return -1;
    if (s <= lo)
        return 1;
    throw InterpError(j.who + ": the start point must be outside the profile in " +
                      (j.step_x ? "X" : "Z"));
}

// roughing levels: cut along the cut axis from the start to the profile (or its near end)
static void rough_levels(CycleMoves &mv, const LatheJob &j, const Profile &p, double dir,
                         double allowance, double depth, double retract)
{
    double lo, hi;
    profile_range(p, j.step_x, lo, hi);
    double far = (dir < 0 ? lo : hi) - dir * allowance;
    double s0 = step_of(j, j.start), c0 = cut_of(j, j.start);
    LathePoint near_end = std::fabs(step_of(j, p.end()) - s0) < std::fabs(step_of(j, p.start()) - s0)
        ? p.end() : p.start();
    if ((far - s0) * dir / depth > MAX_LEVELS)
        throw InterpError(j.who + ": I is too small for the stock to remove (more than " +
                          std::to_string(MAX_LEVELS) + " passes)");
    for (int k = 1;; k++) {
        double level = s0 + dir * depth * k;
        if ((far - level) * dir <= 1e-9)
            break;
        double hit;
        if (!profile_cross(p, j.step_x, level + dir * allowance, hit))
            hit = cut_of(j, near_end);
        go(mv, point_of(j, level, c0), false);
        go(mv, point_of(j, level, hit), true);
        go(mv, point_of(j, level - dir * retract, hit), false);
        go(mv, point_of(j, level - dir * retract, c0), false);
    }
}

// start point from the X Z words (rapid there first) or the current point
static LatheJob start_job(const InterpState &s, const Block &b, bool step_x,
                          const std::string &who)
{
    if (s.plane != CANON_PLANE_XZ)
        throw InterpError(who + " is only allowed in the XZ plane (G18)");
    LatheJob j;
    j.step_x = step_x;
    j.who = who;
    double scale = s.lathe_diameter ? 0.5 : 1.0;
    j.start.x = b.word('x') ? b.value('x') * scale : s.current[AX_X];
    j.start.z = b.word('z') ? b.value('z') : s.current[AX_Z];
    if (s.distance_incremental) {
        j.start.x = s.current[AX_X] + (b.word('x') ? b.value('x') * scale : 0);
        j.start.z = s.current[AX_Z] + word_or(b, 'z', 0);
    }
    return j;
}

// G71/G72: roughing levels, then one contour pass leaving D on the step axis
static void rough(InterpState &s, const Block &b, Canon &canon, ProfileSource &src, bool step_x)
{
    std::string who = step_x ? "G71" : "G72";
    CycleMoves mv(s, canon, plane_axes(CANON_PLANE_XZ), s.sequence_number);
    LatheJob j = start_job(s, b, step_x, who);
    double depth = word_or(b, 'i', 0), allowance = word_or(b, 'd', 0);
    if (!b.word('i') || depth <= 0)
        throw InterpError(who + ": I (depth of each pass) must be given and greater than 0");
    if (allowance < 0)
        throw InterpError(who + ": D (finishing allowance) must not be negative");
    double retract = word_or(b, 'r', depth / 2);
    if (retract <= 0)
        throw InterpError(who + ": R (retract distance) must be greater than 0");
    Profile p = load_profile(s, b, src, who);
    double dir = step_direction(j, p);
    if (b.word('x') || b.word('z'))
        go(mv, j.start, false);
    rough_levels(mv, j, p, dir, allowance, depth, retract);
    contour_pass(mv, j, p, -dir * allowance);
}

// G70: P contour passes from distance D down to distance E from the profile
static void finish(InterpState &s, const Block &b, Canon &canon, ProfileSource &src)
{
    CycleMoves mv(s, canon, plane_axes(CANON_PLANE_XZ), s.sequence_number);
    LatheJob j = start_job(s, b, true, "G70");
    double from = word_or(b, 'd', 0), to = word_or(b, 'e', 0);
    long passes = b.word('p') ? std::lround(b.value('p')) : 1;
    if (from < 0 || to < 0 || passes < 1 || passes > MAX_LEVELS)
        throw InterpError("G70: D and E must not be negative and P must be 1 to " +
                          std::to_string(MAX_LEVELS));
    Profile p = load_profile(s, b, src, "G70");
    double dir = step_direction(j, p);
    if (b.word('x') || b.word('z'))
        go(mv, j.start, false);
    for (long k = 1; k <= passes; k++)
        contour_pass(mv, j, p, -dir * (from + (to - from) * k / passes));
}

// G70 G71 G72 (G71.1/.2 and G72.1/.2 pocket variants are refused)
void execute_lathe(InterpState &s, const Block &b, Canon &canon, ProfileSource &src)
{
    int code = s.motion_mode;
    if (s.feed_mode == FEED_INVERSE_TIME)
        throw InterpError("Cannot use inverse time feed with canned cycles");
    if (s.feed_rate <= 0)
        throw InterpError("Cannot feed with zero feed rate");
    if (code == 700)
        finish(s, b, canon, src);
    else if (code == 710 || code == 720)
        rough(s, b, canon, src, code == 710);
    else
        throw InterpError("G" + std::to_string(code / 10) + "." + std::to_string(code % 10) +
                          " is not supported (use G" + std::to_string(code / 10) + ")");
}

}  // namespace cycles
