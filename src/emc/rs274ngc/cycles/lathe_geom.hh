// lathe_geom.hh: plane geometry of the lathe cycles: line and arc elements, their intersections
// and the offset envelope of a profile (the path kept at distance D from it).
#ifndef OPENEMC_RS274NGC_LATHE_GEOM_HH
#define OPENEMC_RS274NGC_LATHE_GEOM_HH

#include <utility>
#include <vector>

namespace cycles {

// A point of the cycle plane (u along the cut, v along the step).
struct Pt {
    double u = 0, v = 0;
};

// A line from a to b, or an arc from a to b about c (counterclockwise when ccw) with radius r;
// `id` names the element of a path a piece was cut from.
struct Elem {
    bool arc = false;
    Pt a, b, c;
    bool ccw = false;
    int id = -1;
    double r = 0;   // arc radius (0: the distance from c to a)
    double r_end = 0;  // radius at the end (0: the distance from c to b); an arc that follows
                       // another element is joined to it on this circle
};

// distance between two points
double dist(Pt p, Pt q);
// swept angle of an arc (0..2 pi]
double arc_sweep(const Elem &e);
// radius of an arc
double arc_radius(const Elem &e);
// point at parameter t in [0, 1] (arcs: fraction of the sweep)
Pt elem_point(const Elem &e, double t);
// unit direction of travel at parameter t
Pt elem_tangent(const Elem &e, double t);
// the part of e between parameters t0 and t1
Elem elem_part(const Elem &e, double t0, double t1);
// length of e
double elem_length(const Elem &e);
// parameters (t on e, s on f) where e and f meet, both in [0, 1]; `miss` lets a line or arc
// that passes a circle by at most that much count as touching it (at the closest point)
std::vector<std::pair<double, double>> elem_intersections(const Elem &e, const Elem &f,
                                                          double miss = 0);
// e split where an arc turns in v, so that every piece runs one way in v (or is level)
std::vector<Elem> split_monotonic(const std::vector<Elem> &path);
// parameter where monotonic piece e reaches level v; false when it does not
bool level_param(const Elem &e, double v, double &t);
// the path at distance d on the left of `path` (arcs around convex corners, trimmed at concave
// ones, short elements swallowed); d == 0 gives the path itself
std::vector<Elem> offset_envelope(const std::vector<Elem> &path, double d);

}  // namespace cycles

#endif
