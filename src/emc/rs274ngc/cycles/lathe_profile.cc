// lathe_profile.cc: reading and querying the profile subroutine of the lathe cycles G70/G71/G72.
#include "lathe_profile.hh"

#include <cmath>

namespace cycles {

// angle of point p about center c in the (z, x) frame of the XZ plane
static double frame_angle(LathePoint c, LathePoint p)
{
    return std::atan2(p.x - c.x, p.z - c.z);
}

// center of an R-format arc from a to b; rotation +1 counterclockwise in (z, x)
static LathePoint center_from_radius(LathePoint a, LathePoint b, double r, int rotation,
                                     const std::string &who)
{
    double dz = b.z - a.z, dx = b.x - a.x;
    double chord = std::hypot(dz, dx);
    double half = chord / 2;
    if (chord == 0 || std::fabs(r) < half - 1e-6)
        throw InterpError(who + ": profile arc radius too small to reach its end point");
    double off = std::sqrt(std::max(r * r - half * half, 0.0));
    double side = (rotation > 0) == (r > 0) ? 1.0 : -1.0;  // center left of the chord for CCW
    LathePoint c;
    c.z = (a.z + b.z) / 2 - side * off * dx / chord;
    c.x = (a.x + b.x) / 2 + side * off * dz / chord;
    return c;
}

// end point of one profile block: absolute or incremental words, X halved in diameter mode
static LathePoint block_end(const InterpState &s, const Block &b, LathePoint cur, bool incremental)
{
    LathePoint p = cur;
    double scale = s.lathe_diameter ? 0.5 : 1.0;
    if (b.word('x'))
        p.x = incremental ? cur.x + b.value('x') * scale : b.value('x') * scale;
    if (b.word('z'))
        p.z = incremental ? cur.z + b.value('z') : b.value('z');
    return p;
}

// the arc element from cur to end of a G2/G3 block (I K offsets or R)
static ProfileSeg arc_seg(const InterpState &s, const Block &b, LathePoint cur, LathePoint end,
                          int motion, const std::string &who)
{
    ProfileSeg seg;
    seg.from = cur;
    seg.to = end;
    seg.arc = true;
    seg.rotation = motion == 30 ? 1 : -1;
    if (b.word('r')) {
        seg.center = center_from_radius(cur, end, b.value('r'), seg.rotation, who);
    } else if (b.word('i') || b.word('k')) {
        double i = b.word('i') ? b.value('i') : 0, k = b.word('k') ? b.value('k') : 0;
        seg.center = s.ijk_absolute ? LathePoint{i, k} : LathePoint{cur.x + i, cur.z + k};
    } else {
        throw InterpError(who + ": profile arc needs I K or R words");
    }
    return seg;
}

// the modal motion and distance mode of the profile blocks, turned into elements
Profile read_profile(const InterpState &s, const std::vector<Block> &blocks, const std::string &who)
{
    Profile prof;
    LathePoint cur;
    bool have_start = false, incremental = s.distance_incremental;
    int motion = -1;
    for (const Block &b : blocks) {
        if (b.g_modes[GG_DISTANCE] != -1)
            incremental = b.g_modes[GG_DISTANCE] == 910;
        if (b.motion() != -1)
            motion = b.motion();
        if (!b.word('x') && !b.word('z'))
            continue;
        if (motion != 0 && motion != 10 && motion != 20 && motion != 30)
            throw InterpError(who + ": profile moves must be G0, G1, G2 or G3");
        LathePoint end = block_end(s, b, cur, incremental);
        if (!have_start) {
            cur = end;
            have_start = true;
            continue;
        }
        ProfileSeg seg;
        if (motion == 20 || motion == 30) {
            seg = arc_seg(s, b, cur, end, motion, who);
        } else {
            seg.from = cur;
            seg.to = end;
        }
        prof.segs.push_back(seg);
        cur = end;
    }
    if (prof.segs.empty())
        throw InterpError(who + ": the profile needs a start point and at least one move");
    return prof;
}

// coordinate of p along the chosen axis
static double coord(LathePoint p, bool x_axis)
{
    return x_axis ? p.x : p.z;
}

// point of an arc at a fraction of its sweep
static LathePoint arc_point(const ProfileSeg &g, double frac)
{
    double a0 = frame_angle(g.center, g.from), a1 = frame_angle(g.center, g.to);
    double sweep = g.rotation > 0 ? a1 - a0 : a0 - a1;
    while (sweep <= 0)
        sweep += 2 * M_PI;
    double a = a0 + (g.rotation > 0 ? 1 : -1) * sweep * frac;
    double r = std::hypot(g.from.x - g.center.x, g.from.z - g.center.z);
    return {g.center.x + r * std::sin(a), g.center.z + r * std::cos(a)};
}

// sample the profile densely enough to see every turn of an arc
static std::vector<LathePoint> samples(const Profile &p)
{
    std::vector<LathePoint> pts{p.start()};
    for (const ProfileSeg &g : p.segs) {
        int n = g.arc ? 64 : 1;
        for (int i = 1; i <= n; i++)
            pts.push_back(g.arc ? arc_point(g, (double)i / n) : g.to);
    }
    return pts;
}

// the chosen coordinate only moves one way along the profile
bool profile_monotonic(const Profile &p, bool x_axis)
{
    std::vector<LathePoint> pts = samples(p);
    int dir = 0;
    for (size_t i = 1; i < pts.size(); i++) {
        double d = coord(pts[i], x_axis) - coord(pts[i - 1], x_axis);
        if (std::fabs(d) < 1e-9)
            continue;
        int sd = d > 0 ? 1 : -1;
        if (dir != 0 && sd != dir)
            return false;
        dir = sd;
    }
    return true;
}

// extent of the profile along the chosen axis
void profile_range(const Profile &p, bool x_axis, double &lo, double &hi)
{
    std::vector<LathePoint> pts = samples(p);
    lo = hi = coord(pts[0], x_axis);
    for (const LathePoint &q : pts) {
        lo = std::min(lo, coord(q, x_axis));
        hi = std::max(hi, coord(q, x_axis));
    }
}

// crossing of a line element with the level
static bool line_cross(const ProfileSeg &g, bool x_axis, double level, double &other)
{
    double a = coord(g.from, x_axis), b = coord(g.to, x_axis);
    if ((level - a) * (level - b) > 0 || a == b)
        return false;
    double t = (level - a) / (b - a);
    other = coord(g.from, !x_axis) + t * (coord(g.to, !x_axis) - coord(g.from, !x_axis));
    return true;
}

// crossing of an arc element with the level: the root inside the arc's sweep
static bool arc_cross(const ProfileSeg &g, bool x_axis, double level, double &other)
{
    double r = std::hypot(g.from.x - g.center.x, g.from.z - g.center.z);
    double d = level - coord(g.center, x_axis);
    if (std::fabs(d) > r)
        return false;
    double h = std::sqrt(r * r - d * d);
    for (double sign : {-1.0, 1.0}) {
        double o = coord(g.center, !x_axis) + sign * h;
        LathePoint q = x_axis ? LathePoint{level, o} : LathePoint{o, level};
        double a0 = frame_angle(g.center, g.from), aq = frame_angle(g.center, q);
        double a1 = frame_angle(g.center, g.to);
        double full = g.rotation > 0 ? a1 - a0 : a0 - a1, part = g.rotation > 0 ? aq - a0 : a0 - aq;
        while (full <= 0) full += 2 * M_PI;
        while (part < 0) part += 2 * M_PI;
        if (part <= full + 1e-9) {
            other = o;
            return true;
        }
    }
    return false;
}

// first element of the profile that reaches the level
bool profile_cross(const Profile &p, bool x_axis, double level, double &other)
{
    for (const ProfileSeg &g : p.segs)
        if (g.arc ? arc_cross(g, x_axis, level, other) : line_cross(g, x_axis, level, other))
            return true;
    return false;
}

}  // namespace cycles
