// spline_geom.cc: biarc approximation of cubic Bezier curves, as used for G5 and G5.1.
#include "spline_geom.hh"

#include <algorithm>
#include <cmath>

namespace spline {

namespace {

constexpr int MAX_DEPTH = 12;        // at most 2^12 biarcs per curve
constexpr int SAMPLES = 5;           // curve points compared with each biarc

// a + b
Vec2 add(Vec2 a, Vec2 b) { return {a.x + b.x, a.y + b.y}; }
// a - b
Vec2 sub(Vec2 a, Vec2 b) { return {a.x - b.x, a.y - b.y}; }
// k * a
Vec2 scale(Vec2 a, double k) { return {a.x * k, a.y * k}; }
// dot product
double dot(Vec2 a, Vec2 b) { return a.x * b.x + a.y * b.y; }
// length of a
double norm(Vec2 a) { return std::hypot(a.x, a.y); }

// a scaled to length 1 (unchanged when zero)
Vec2 unit(Vec2 a)
{
    double n = norm(a);
    return n > 0 ? scale(a, 1.0 / n) : a;
}

// angle swept going from direction a to direction b in the given rotation, in [0, 2pi)
double sweep(Vec2 a, Vec2 b, int rotation)
{
    double d = std::atan2(b.y, b.x) - std::atan2(a.y, a.x);
    if (rotation < 0) d = -d;
    while (d < 0) d += 2 * M_PI;
    while (d >= 2 * M_PI) d -= 2 * M_PI;
    return d;
}

// arc (or line) from s to f that leaves s along the unit tangent t
Segment arc_from_tangent(Vec2 s, Vec2 t, Vec2 f)
{
    Segment g;
    g.end = f;
    Vec2 w = sub(f, s);
    Vec2 n{-t.y, t.x};
    double nw = dot(n, w), ww = dot(w, w);
    if (std::fabs(nw) <= 1e-9 * std::sqrt(ww)) {
        g.line = true;
        return g;
    }
    double k = ww / (2 * nw);
    g.center = add(s, scale(n, k));
    g.rotation = k > 0 ? 1 : -1;
    return g;
}

// two tangent arcs from a (unit tangent ta) to e (unit tangent te) meeting halfway; false if none
bool biarc(Vec2 a, Vec2 ta, Vec2 e, Vec2 te, Segment out[2])
{
    Vec2 v = sub(a, e), s = add(ta, te);
    double qa = dot(s, s) - 4, qb = 2 * dot(v, s), qc = dot(v, v);
    if (qc == 0) return false;
    double d;
    if (std::fabs(qa) < 1e-12) {
        if (qb >= 0) return false;
        d = -qc / qb;
    } else {
        d = (-qb - std::sqrt(qb * qb - 4 * qa * qc)) / (2 * qa);
    }
    if (!(d > 0)) return false;
    Vec2 p1 = add(a, scale(ta, d)), p3 = sub(e, scale(te, d));
    Vec2 joint = scale(add(p1, p3), 0.5);
    Vec2 tj = unit(sub(p3, p1));
    if (norm(tj) == 0) tj = ta;
    out[0] = arc_from_tangent(a, ta, joint);
    out[1] = arc_from_tangent(joint, tj, e);
    return true;
}

// largest distance between curve points inside [t0, t1] and the biarc starting at a
double biarc_error(const Cubic &c, double t0, double t1, Vec2 a, const Segment g[2])
{
    double worst = 0;
    for (int k = 1; k <= SAMPLES; k++) {
        Vec2 p = c.at(t0 + (t1 - t0) * k / (SAMPLES + 1));
        double d = std::min(segment_distance(a, g[0], p), segment_distance(g[0].end, g[1], p));
        worst = std::max(worst, d);
    }
    return worst;
}

// approximate the curve between t0 and t1, appending to out
void fit(const Cubic &c, double t0, double t1, double tol, int depth, std::vector<Segment> &out)
{
    Vec2 a = c.at(t0), e = c.at(t1);
    Segment g[2];
    bool ok = biarc(a, c.tangent(t0), e, c.tangent(t1), g);
    if (depth >= MAX_DEPTH || (ok && biarc_error(c, t0, t1, a, g) <= tol)) {
        if (ok) {
            out.push_back(g[0]);
            out.push_back(g[1]);
        } else if (norm(sub(e, a)) > 0) {
            Segment line;
            line.end = e;
            line.line = true;
            out.push_back(line);
        }
        return;
    }
    double mid = (t0 + t1) / 2;
    fit(c, t0, mid, tol, depth + 1, out);
    fit(c, mid, t1, tol, depth + 1, out);
}

} // namespace

// Bernstein form of the cubic
Vec2 Cubic::at(double t) const
{
    double u = 1 - t;
    double b0 = u * u * u, b1 = 3 * u * u * t, b2 = 3 * u * t * t, b3 = t * t * t;
    return {b0 * p[0].x + b1 * p[1].x + b2 * p[2].x + b3 * p[3].x,
            b0 * p[0].y + b1 * p[1].y + b2 * p[2].y + b3 * p[3].y};
}

// derivative direction, or the direction of a short chord where the derivative vanishes
Vec2 Cubic::tangent(double t) const
{
    double u = 1 - t;
    Vec2 d = add(add(scale(sub(p[1], p[0]), u * u), scale(sub(p[2], p[1]), 2 * u * t)),
                 scale(sub(p[3], p[2]), t * t));
    if (norm(d) > 1e-12) return unit(d);
    for (double h = 1e-6; h <= 0.5; h *= 8) {
        Vec2 chord = sub(at(std::min(1.0, t + h)), at(std::max(0.0, t - h)));
        if (norm(chord) > 1e-12) return unit(chord);
    }
    return {1, 0};
}

// control points 2/3 of the way from each end toward the quadratic's middle point
Cubic quadratic_to_cubic(Vec2 q0, Vec2 q1, Vec2 q2)
{
    Cubic c;
    c.p[0] = q0;
    c.p[1] = add(q0, scale(sub(q1, q0), 2.0 / 3.0));
    c.p[2] = add(q2, scale(sub(q1, q2), 2.0 / 3.0));
    c.p[3] = q2;
    return c;
}

// q1 = p0 + 3/2 (p1 - p0) undoes quadratic_to_cubic
Vec2 quadratic_middle(const Cubic &c)
{
    return add(c.p[0], scale(sub(c.p[1], c.p[0]), 1.5));
}

// chord lengths of lines, radius times swept angle of arcs
double path_length(Vec2 start, const std::vector<Segment> &segs)
{
    double len = 0;
    for (const Segment &g : segs) {
        if (g.line) {
            len += norm(sub(g.end, start));
        } else {
            Vec2 rs = sub(start, g.center), re = sub(g.end, g.center);
            len += norm(rs) * sweep(rs, re, g.rotation);
        }
        start = g.end;
    }
    return len;
}

// see header
std::vector<Segment> cubic_to_biarcs(const Cubic &c, double tolerance)
{
    std::vector<Segment> out;
    fit(c, 0.0, 1.0, tolerance, 0, out);
    return out;
}

// distance to the line segment, or to the arc when p lies within its sweep, else to its ends
double segment_distance(Vec2 start, const Segment &g, Vec2 p)
{
    if (g.line) {
        Vec2 d = sub(g.end, start);
        double len2 = dot(d, d);
        double k = len2 > 0 ? std::clamp(dot(sub(p, start), d) / len2, 0.0, 1.0) : 0.0;
        return norm(sub(p, add(start, scale(d, k))));
    }
    Vec2 rs = sub(start, g.center), re = sub(g.end, g.center), rp = sub(p, g.center);
    if (sweep(rs, rp, g.rotation) <= sweep(rs, re, g.rotation))
        return std::fabs(norm(rp) - norm(rs));
    return std::min(norm(sub(p, start)), norm(sub(p, g.end)));
}

}  // namespace spline
