// lathe_geom_unit.cc: checks the plane geometry of the lathe cycles; prints one line per check
// and exits 1 when any check fails.
#include <cmath>
#include <cstdio>
#include <string>

#include "emc/rs274ngc/cycles/lathe_geom.hh"

using namespace cycles;

static int failures = 0;

// report a check: name, the values seen, pass/fail
static void check(const std::string &name, bool ok, const std::string &seen)
{
    std::printf("%s %s: %s\n", ok ? "ok" : "FAIL", name.c_str(), seen.c_str());
    if (!ok) failures++;
}

static bool near(double a, double b)
{
    return std::fabs(a - b) < 1e-9;
}

static std::string pt(Pt p)
{
    char buf[64];
    std::snprintf(buf, sizeof buf, "(%.4f %.4f)", p.u, p.v);
    return buf;
}

static Elem line(Pt a, Pt b)
{
    return Elem{false, a, b, {}, false};
}

static Elem arc(Pt a, Pt b, Pt c, bool ccw)
{
    return Elem{true, a, b, c, ccw};
}

// two crossing lines meet once, at the parameters of the crossing
static void line_line()
{
    auto hits = elem_intersections(line({0, 0}, {2, 2}), line({0, 2}, {2, 0}));
    bool ok = hits.size() == 1 && near(hits[0].first, 0.5) && near(hits[0].second, 0.5);
    check("line crosses line", ok, std::to_string(hits.size()) + " hit(s)");
    auto none = elem_intersections(line({0, 0}, {1, 0}), line({0, 1}, {1, 1}));
    check("parallel lines", none.empty(), std::to_string(none.size()) + " hit(s)");
}

// a line through a half circle meets it once inside the sweep; a near miss counts with `miss`
static void line_arc()
{
    Elem half = arc({1, 0}, {-1, 0}, {0, 0}, true);  // upper half circle, counterclockwise
    auto hits = elem_intersections(line({-2, 0.5}, {2, 0.5}), half);
    bool ok = hits.size() == 2;
    check("line crosses upper half circle twice", ok, std::to_string(hits.size()) + " hit(s)");
    auto below = elem_intersections(line({-2, -0.5}, {2, -0.5}), half);
    check("line below the sweep", below.empty(), std::to_string(below.size()) + " hit(s)");
    auto graze = elem_intersections(line({-2, 1.001}, {2, 1.001}), half, 0.002);
    ok = graze.size() == 1 && near(graze[0].first, 0.5) && near(graze[0].second, 0.5);
    check("near miss within the join tolerance touches", ok, std::to_string(graze.size()) + " hit(s)");
}

// a quarter arc rising then falling in v is split at its top; each piece reaches a level once
static void monotonic_and_levels()
{
    Elem a = arc({1, 0}, {-1, 0}, {0, 0}, true);
    auto pieces = split_monotonic({a});
    bool ok = pieces.size() == 2 && near(pieces[0].b.v, 1) && near(pieces[0].b.u, 0);
    check("half circle split at its top", ok, std::to_string(pieces.size()) + " pieces, first ends " + pt(pieces[0].b));
    double t = -1;
    ok = level_param(pieces[0], std::sqrt(0.5), t) && near(t, 0.5);
    check("rising piece reaches level sqrt(1/2) half way", ok, std::to_string(t));
    ok = !level_param(pieces[1], 1.5, t);
    check("no crossing above the arc", ok, "");
}

// a step profile offset by 0.1: a corner arc outside the convex corner, a trimmed concave corner
static void envelope()
{
    // in the cycle frame the material is on the left of the travel (+v side of a +u run)
    std::vector<Elem> step{line({0, 0}, {1, 0}), line({1, 0}, {1, 1}), line({1, 1}, {2, 1})};
    auto env = offset_envelope(step, 0.1);
    std::string seen;
    for (const Elem &e : env) seen += (e.arc ? "arc" : "line") + pt(e.a) + pt(e.b) + " ";
    bool ok = env.size() == 4 && !env[0].arc && near(env[0].b.u, 0.9) && near(env[0].b.v, 0.1) &&
              env[2].arc && near(env[2].c.u, 1) && near(env[2].c.v, 1) && near(env[3].b.v, 1.1);
    check("step envelope at 0.1", ok, seen);
    auto same = offset_envelope(step, 0);
    check("zero offset keeps the path", same.size() == 3, std::to_string(same.size()) + " elements");
}

int main()
{
    line_line();
    line_arc();
    monotonic_and_levels();
    envelope();
    return failures ? 1 : 0;
}
