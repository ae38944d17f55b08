// spline_geom.hh: cubic Bezier curves in a plane approximated by tangent-continuous arcs (G5/G5.1 length, canon consumers).
#ifndef OPENEMC_RS274NGC_SPLINE_GEOM_HH
#define OPENEMC_RS274NGC_SPLINE_GEOM_HH

#include <vector>

namespace spline {

// A point or vector in the XY plane.
struct Vec2 {
    double x = 0, y = 0;
};

// A cubic Bezier curve given by its four control points.
struct Cubic {
    Vec2 p[4];
    // point at parameter t (0..1)
    Vec2 at(double t) const;
    // unit tangent at parameter t (direction of travel; falls back to nearby chords at cusps)
    Vec2 tangent(double t) const;
};

// One piece of the approximation: an arc about `center` (rotation +1 CCW, -1 CW) or a line.
struct Segment {
    Vec2 end;
    bool line = false;
    Vec2 center;
    int rotation = 1;
};

// The cubic equivalent of the quadratic Bezier q0 q1 q2 (exact degree elevation).
Cubic quadratic_to_cubic(Vec2 q0, Vec2 q1, Vec2 q2);

// The middle control point of the quadratic a degree-elevated cubic came from.
Vec2 quadratic_middle(const Cubic &c);

// Arcs (pairs of tangent arcs, "biarcs") that stay within `tolerance` of the curve; the parameter
// range is halved until each piece fits. The first segment starts at c.p[0], the last ends at c.p[3].
std::vector<Segment> cubic_to_biarcs(const Cubic &c, double tolerance);

// Length of the segments, the first starting at `start`.
double path_length(Vec2 start, const std::vector<Segment> &segs);

// Distance from p to a segment that starts at `start`.
double segment_distance(Vec2 start, const Segment &g, Vec2 p);

}  // namespace spline

#endif
