// spline_geom_unit.cc: checks that biarcs start and end on the curve, join smoothly and stay within tolerance.
#include <cmath>
#include <cstdio>

#include "emc/rs274ngc/spline_geom.hh"

using spline::Cubic;
using spline::Segment;
using spline::Vec2;

namespace {

// unit tangent of a segment at its start (s) or end
Vec2 seg_tangent(Vec2 s, const Segment &g, bool at_end)
{
    Vec2 p = at_end ? g.end : s;
    if (g.line) {
        double n = std::hypot(g.end.x - s.x, g.end.y - s.y);
        return {(g.end.x - s.x) / n, (g.end.y - s.y) / n};
    }
    double rx = p.x - g.center.x, ry = p.y - g.center.y, n = std::hypot(rx, ry);
    return {-ry / n * g.rotation, rx / n * g.rotation};
}

// largest distance from dense curve samples to the nearest segment
double max_deviation(const Cubic &c, const std::vector<Segment> &segs)
{
    double worst = 0;
    for (int k = 0; k <= 2000; k++) {
        Vec2 p = c.at(k / 2000.0);
        double best = 1e30;
        Vec2 s = c.p[0];
        for (const Segment &g : segs) {
            best = std::min(best, spline::segment_distance(s, g, p));
            s = g.end;
        }
        worst = std::max(worst, best);
    }
    return worst;
}

// run one curve; prints ok/FAIL and returns 0 on success
int check(const char *name, const Cubic &c, double tol)
{
    std::vector<Segment> segs = spline::cubic_to_biarcs(c, tol);
    bool ends = !segs.empty() && std::hypot(segs.back().end.x - c.p[3].x,
                                            segs.back().end.y - c.p[3].y) < 1e-12;
    bool smooth = true;
    Vec2 s = c.p[0];
    for (size_t i = 0; i + 1 < segs.size(); i++) {
        Vec2 a = seg_tangent(s, segs[i], true), b = seg_tangent(segs[i].end, segs[i + 1], false);
        if (a.x * b.x + a.y * b.y < std::cos(2.0 * M_PI / 180.0)) smooth = false;
        s = segs[i].end;
    }
    double dev = max_deviation(c, segs);
    bool ok = ends && smooth && dev <= tol * 1.5;
    printf("%s %s: ends %s, joins %s, within tolerance %s\n", ok ? "ok" : "FAIL", name,
           ends ? "yes" : "no", smooth ? "smooth" : "kinked", dev <= tol * 1.5 ? "yes" : "no");
    return ok ? 0 : 1;
}

} // namespace

// a set of typical and awkward curves
int main()
{
    int fails = 0;
    fails += check("s-curve", Cubic{{{0, 0}, {0, 1}, {1, 0}, {1, 1}}}, 0.001);
    fails += check("arch", Cubic{{{0, 0}, {0, 2}, {3, 2}, {3, 0}}}, 0.001);
    fails += check("straight", Cubic{{{0, 0}, {1, 1}, {2, 2}, {3, 3}}}, 0.001);
    fails += check("cusp-ends", Cubic{{{0, 0}, {0, 0}, {2, 1}, {2, 1}}}, 0.001);
    fails += check("loop", Cubic{{{0, 0}, {3, 2}, {-1, 2}, {2, 0}}}, 0.001);
    fails += check("tight-mm", Cubic{{{0, 0}, {50, 80}, {-30, 80}, {20, 0}}}, 0.0254);
    fails += check("quadratic", spline::quadratic_to_cubic({0, 0}, {1, 0}, {1, 1}), 0.001);
    Cubic q = spline::quadratic_to_cubic({0, 0}, {3, 3}, {6, 0});
    bool exact = std::fabs(q.at(0.5).y - 1.5) < 1e-12 && std::fabs(q.at(0.5).x - 3.0) < 1e-12;
    Vec2 mid = spline::quadratic_middle(q);
    exact = exact && std::fabs(mid.x - 3.0) < 1e-12 && std::fabs(mid.y - 3.0) < 1e-12;
    printf("%s quadratic elevation keeps the curve and its middle point\n", exact ? "ok" : "FAIL");
    Cubic line{{{0, 0}, {1, 1}, {2, 2}, {3, 3}}};
    double len = spline::path_length(line.p[0], spline::cubic_to_biarcs(line, 0.001));
    Cubic quarter{{{1, 0}, {1, 0.5523}, {0.5523, 1}, {0, 1}}};
    double arc = spline::path_length(quarter.p[0], spline::cubic_to_biarcs(quarter, 0.0001));
    bool lengths = std::fabs(len - 3 * M_SQRT2) < 1e-9 && std::fabs(arc - M_PI / 2) < 1e-3;
    printf("%s path lengths: line %.6f, quarter circle %.4f\n", lengths ? "ok" : "FAIL", len, arc);
    return fails + (exact ? 0 : 1) + (lengths ? 0 : 1);
}
