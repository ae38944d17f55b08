// lathe_geom.cc: line/arc elements of the lathe cycles, their intersections and offset envelopes.
#include "lathe_geom.hh"

#include <cmath>

namespace cycles {

namespace {

constexpr double TWO_PI = 2 * M_PI;
// parameter tolerance for "at the end" / "inside the element"
constexpr double T_EPS = 1e-9;
// length below which an element counts as a point
constexpr double LEN_EPS = 1e-10;
// how far two consecutive offset elements may miss each other and still be joined
constexpr double JOIN_MISS = 0.002;
// turns smaller than this (sine of the angle) count as tangent: no corner arc
constexpr double TANGENT_SIN = 1e-3;
// shortest piece an arc is split into where it turns in v
constexpr double SPLIT_MIN = 1e-6;
// id of the arcs inserted around convex corners (they end exactly where the next element starts)
constexpr int CORNER_ID = -2;

// cross product of two direction vectors
double cross(Pt p, Pt q)
{
    return p.u * q.v - p.v * q.u;
}

// angle of p about center c
double angle_of(Pt c, Pt p)
{
    return std::atan2(p.v - c.v, p.u - c.u);
}

// fraction of the sweep at which arc e reaches point p (p on its circle); may lie outside [0, 1]
double arc_param(const Elem &e, Pt p)
{
    double s = arc_sweep(e);
    if (s <= 0) return 0;
    double d = e.ccw ? angle_of(e.c, p) - angle_of(e.c, e.a) : angle_of(e.c, e.a) - angle_of(e.c, p);
    d = std::fmod(d, TWO_PI);
    if (d < 0) d += TWO_PI;
    if (d > s + (TWO_PI - s) / 2) d -= TWO_PI;  // nearer to the start (from behind) than to the end
    return d / s;
}

// true when t lies on the element (with tolerance); clamps it into [0, 1]
bool on_element(double &t)
{
    if (t < -T_EPS || t > 1 + T_EPS) return false;
    t = std::fmin(1.0, std::fmax(0.0, t));
    return true;
}

// point at parameter t of e; a line is extended past its ends
Pt line_point(const Elem &e, double t)
{
    if (e.arc) return elem_point(e, t);
    return {e.a.u + t * (e.b.u - e.a.u), e.a.v + t * (e.b.v - e.a.v)};
}

// the left normal of a unit direction
Pt left_of(Pt t)
{
    return {-t.v, t.u};
}

// p + k q
Pt add(Pt p, Pt q, double k)
{
    return {p.u + k * q.u, p.v + k * q.v};
}

// unit vector from c towards p
Pt unit_from(Pt c, Pt p)
{
    double r = dist(c, p);
    return r > 0 ? Pt{(p.u - c.u) / r, (p.v - c.v) / r} : Pt{1, 0};
}

// the circle a following arc f is joined on: its end radius (LinuxCNC joins a programmed arc
// whose ends lie at slightly different radii to the element before it on the end's circle)
double join_radius(const Elem &f)
{
    return f.r_end > 0 ? f.r_end : dist(f.c, f.b);
}

// intersections of line e with line f
void line_line(const Elem &e, const Elem &f, std::vector<std::pair<double, double>> &out)
{
    Pt d1{e.b.u - e.a.u, e.b.v - e.a.v}, d2{f.b.u - f.a.u, f.b.v - f.a.v};
    double den = cross(d1, d2);
    if (std::fabs(den) < 1e-14) return;
    Pt w{f.a.u - e.a.u, f.a.v - e.a.v};
    double t = cross(w, d2) / den, s = cross(w, d1) / den;
    if (on_element(t) && on_element(s)) out.emplace_back(t, s);
}

// intersections of line e with arc f (swap: report as (arc param, line param))
void line_arc(const Elem &e, const Elem &f, bool swap, double miss,
              std::vector<std::pair<double, double>> &out)
{
    Pt d{e.b.u - e.a.u, e.b.v - e.a.v}, w{e.a.u - f.c.u, e.a.v - f.c.v};
    double r = swap ? arc_radius(f) : join_radius(f);
    double qa = d.u * d.u + d.v * d.v, qb = 2 * (d.u * w.u + d.v * w.v);
    double qc = w.u * w.u + w.v * w.v - r * r;
    if (qa <= 0) return;
    double disc = qb * qb - 4 * qa * qc;
    double gap = std::fabs(cross(d, w)) / std::sqrt(qa) - r;  // line-to-center distance - r
    if (disc < -1e-12 * qb * qb - 1e-18 && gap > miss) return;
    if (disc < 0 && gap <= miss) disc = 0;  // passing just outside: meet at the closest point
    double root = std::sqrt(std::fmax(0.0, disc));
    int n = root > 0 ? 2 : 1;
    double reach = miss / std::sqrt(qa);  // how far past its ends the line may be met
    // a next element (line when swapped, else the arc) may be met before its start, as when a
    // line and an arc that were tangent cross twice after offsetting: the first crossing counts
    double back = miss > 0 ? 1.0 : 0.0;
    for (int k = 0; k < n; k++) {
        double t = (-qb + (k == 0 ? -root : root)) / (2 * qa);
        if (t < -(swap ? back : reach) - T_EPS || t > 1 + reach + T_EPS) continue;
        double s = arc_param(f, Pt{e.a.u + t * d.u, e.a.v + t * d.v});
        double arc_reach = miss / std::fmax(elem_length(f), 1e-12);
        if (s < -(swap ? arc_reach : back) - T_EPS || s > 1 + arc_reach + T_EPS) continue;
        if (swap) out.emplace_back(s, t);
        else out.emplace_back(t, s);
    }
}

// intersections of arc e with arc f
void arc_arc(const Elem &e, const Elem &f, double miss, std::vector<std::pair<double, double>> &out)
{
    double r1 = arc_radius(e), r2 = join_radius(f), d = dist(e.c, f.c);
    double tol = std::fmax(1e-9, miss);
    if (d < 1e-12 || d > r1 + r2 + tol || d < std::fabs(r1 - r2) - tol) return;
    double a = (r1 * r1 - r2 * r2 + d * d) / (2 * d);
    double h = std::sqrt(std::fmax(0.0, r1 * r1 - a * a));
    if (d > r1 + r2 || d < std::fabs(r1 - r2)) h = 0;  // passing just apart: the closest point
    Pt dir{(f.c.u - e.c.u) / d, (f.c.v - e.c.v) / d};
    Pt mid = add(e.c, dir, a);
    int n = h > 1e-12 ? 2 : 1;
    double reach_e = miss / std::fmax(elem_length(e), 1e-12);
    double back_f = miss > 0 ? 1.0 : 0.0;  // a next element may be met before its start
    for (int k = 0; k < n; k++) {
        Pt p = add(mid, left_of(dir), k == 0 ? h : -h);
        double t = arc_param(e, p), s = arc_param(f, p);
        if (t >= -reach_e - T_EPS && t <= 1 + reach_e + T_EPS && s >= -back_f - T_EPS &&
            s <= 1 + T_EPS)
            out.emplace_back(t, s);
    }
}

// the offset of one element at distance d on its left; false when an arc shrinks to nothing
bool offset_elem(const Elem &e, double d, Elem &o)
{
    o = e;
    if (!e.arc) {
        Pt n = left_of(elem_tangent(e, 0));
        o.a = add(e.a, n, d);
        o.b = add(e.b, n, d);
        return true;
    }
    double r = arc_radius(e) + (e.ccw ? -d : d);
    if (r <= 1e-9) return false;
    o.r = r;
    o.r_end = std::fmax(1e-9, dist(e.c, e.b) + (e.ccw ? -d : d));
    o.a = add(e.c, unit_from(e.c, e.a), r);
    o.b = add(e.c, unit_from(e.c, e.b), r);
    return true;
}

// the arc about vertex p joining the offsets of two elements at a right (convex) turn
bool corner_arc(Pt p, Pt t_in, Pt t_out, double d, Elem &arc)
{
    double c = cross(t_in, t_out), dot = t_in.u * t_out.u + t_in.v * t_out.v;
    if (dot > 0 && c > -TANGENT_SIN) return false;
    if (dot <= 0 && c > 1e-9) return false;
    arc.arc = true;
    arc.id = CORNER_ID;
    arc.c = p;
    arc.ccw = false;
    arc.r = d;
    arc.a = add(p, left_of(t_in), d);
    arc.b = add(p, left_of(t_out), d);
    return dist(arc.a, arc.b) > LEN_EPS;
}

// the raw offset: every element's offset and corner arcs at convex vertices, in path order
std::vector<Elem> raw_offset(const std::vector<Elem> &path, double d)
{
    std::vector<Elem> raw;
    for (size_t i = 0; i < path.size(); i++) {
        Elem arc, o;
        if (i > 0 && corner_arc(path[i].a, elem_tangent(path[i - 1], 1), elem_tangent(path[i], 0), d, arc))
            raw.push_back(arc);
        if (offset_elem(path[i], d, o) && elem_length(o) > LEN_EPS) raw.push_back(o);
    }
    return raw;
}

// the first crossing of raw[i] after parameter t0 with a later element (not its plain joint);
// the next element also counts when it passes within JOIN_MISS (a programmed arc end slightly
// off its circle): the joint is then the closest point
bool first_crossing(const std::vector<Elem> &raw, size_t i, double t0, double &t, size_t &j, double &s)
{
    bool found = false;
    for (size_t k = i + 1; k < raw.size(); k++) {
        if (k == i + 1 && raw[i].id == CORNER_ID) continue;
        for (auto &ts : elem_intersections(raw[i], raw[k], k == i + 1 ? JOIN_MISS : 0)) {
            if (ts.first <= t0 + T_EPS) continue;
            bool joint = ts.first >= 1 - T_EPS && ts.second <= T_EPS;
            if (k == i + 1 && joint && dist(raw[i].b, raw[k].a) < 1e-9) continue;
            if (found && (ts.first > t + 1e-12 || (std::fabs(ts.first - t) <= 1e-12 && k <= j)))
                continue;
            found = true;
            t = ts.first;
            j = k;
            s = ts.second;
        }
    }
    return found;
}

} // namespace

double dist(Pt p, Pt q)
{
    return std::hypot(p.u - q.u, p.v - q.v);
}

double arc_radius(const Elem &e)
{
    return e.r > 0 ? e.r : dist(e.c, e.a);
}

double arc_sweep(const Elem &e)
{
    if (dist(e.a, e.b) < LEN_EPS) return 0;
    double s = e.ccw ? angle_of(e.c, e.b) - angle_of(e.c, e.a) : angle_of(e.c, e.a) - angle_of(e.c, e.b);
    while (s <= 0) s += TWO_PI;
    while (s > TWO_PI) s -= TWO_PI;
    return s;
}

Pt elem_point(const Elem &e, double t)
{
    if (t <= 0) return e.a;
    if (t >= 1) return e.b;
    if (!e.arc) return {e.a.u + t * (e.b.u - e.a.u), e.a.v + t * (e.b.v - e.a.v)};
    double th = angle_of(e.c, e.a) + (e.ccw ? 1 : -1) * t * arc_sweep(e);
    double r = arc_radius(e);
    return {e.c.u + r * std::cos(th), e.c.v + r * std::sin(th)};
}

Pt elem_tangent(const Elem &e, double t)
{
    if (!e.arc) return unit_from(e.a, e.b);
    Pt r = unit_from(e.c, elem_point(e, t));
    return e.ccw ? Pt{-r.v, r.u} : Pt{r.v, -r.u};
}

Elem elem_part(const Elem &e, double t0, double t1)
{
    Elem p = e;
    p.a = elem_point(e, t0);
    p.b = elem_point(e, t1);
    return p;
}

double elem_length(const Elem &e)
{
    return e.arc ? arc_radius(e) * arc_sweep(e) : dist(e.a, e.b);
}

std::vector<std::pair<double, double>> elem_intersections(const Elem &e, const Elem &f,
                                                          double miss)
{
    std::vector<std::pair<double, double>> out;
    if (!e.arc && !f.arc) line_line(e, f, out);
    else if (!e.arc) line_arc(e, f, false, miss, out);
    else if (!f.arc) line_arc(f, e, true, miss, out);
    else arc_arc(e, f, miss, out);
    return out;
}

std::vector<Elem> split_monotonic(const std::vector<Elem> &path)
{
    std::vector<Elem> out;
    for (const Elem &e : path) {
        if (!e.arc) {
            out.push_back(e);
            continue;
        }
        double r = arc_radius(e), prev = 0;
        // an arc that starts or ends (within SPLIT_MIN) at its top or bottom is not cut there
        double margin = SPLIT_MIN / std::fmax(elem_length(e), SPLIT_MIN);
        std::vector<double> cuts;
        for (double sign : {1.0, -1.0}) {
            double t = arc_param(e, Pt{e.c.u, e.c.v + sign * r});
            if (t > margin && t < 1 - margin) cuts.push_back(t);
        }
        if (cuts.size() == 2 && cuts[0] > cuts[1]) std::swap(cuts[0], cuts[1]);
        for (double t : cuts) {
            out.push_back(elem_part(e, prev, t));
            prev = t;
        }
        out.push_back(elem_part(e, prev, 1));
    }
    return out;
}

bool level_param(const Elem &e, double v, double &t)
{
    double va = e.a.v, vb = e.b.v;
    if (std::fabs(vb - va) < 1e-12 || (v - va) * (v - vb) > 1e-18) return false;
    if (!e.arc) {
        t = (v - va) / (vb - va);
        return on_element(t);
    }
    double r = arc_radius(e);
    double h = std::sqrt(std::fmax(0.0, r * r - (v - e.c.v) * (v - e.c.v)));
    for (double sign : {1.0, -1.0}) {
        t = arc_param(e, Pt{e.c.u + sign * h, v});
        if (on_element(t)) return true;
    }
    return false;
}

std::vector<Elem> offset_envelope(const std::vector<Elem> &path, double d)
{
    // no allowance: the programmed elements as they are, joined at their programmed end points
    if (d == 0) return path;
    std::vector<Elem> raw = raw_offset(path, d);
    std::vector<Elem> out;
    size_t i = 0;
    double t0 = 0;
    bool joined = false;
    Pt join;
    while (i < raw.size()) {
        double t, s;
        size_t j;
        bool jump = first_crossing(raw, i, t0, t, j, s);
        Elem part = elem_part(raw[i], t0, jump ? t : 1);
        if (joined) part.a = join;
        joined = jump;
        if (jump) {
            // an arc met before its start has no point of its own there: the crossing on raw[i]
            Pt pi = line_point(raw[i], t);
            Pt pj = raw[j].arc && (s < 0 || s > 1) ? pi : line_point(raw[j], s);
            join = !raw[i].arc ? pi : !raw[j].arc ? pj : Pt{(pi.u + pj.u) / 2, (pi.v + pj.v) / 2};
            part.b = join;
        }
        if (elem_length(part) > LEN_EPS) out.push_back(part);
        if (jump) {
            i = j;
            t0 = s;
            continue;
        }
        if (i + 1 < raw.size() && dist(raw[i].b, raw[i + 1].a) > 1e-9)
            out.push_back(Elem{false, raw[i].b, raw[i + 1].a, {}, false});
        i++;
        t0 = 0;
    }
    return out;
}

}  // namespace cycles
