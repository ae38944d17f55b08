// comp_geom.hh: 2-D geometry for cutter radius compensation (offset paths, corner turns, intersections).
#ifndef OPENEMC_RS274NGC_COMP_GEOM_HH
#define OPENEMC_RS274NGC_COMP_GEOM_HH

namespace cutcomp {

// A point or direction in the compensation plane (first, second plane axis).
struct Vec2 {
    double x = 0, y = 0;
};

inline Vec2 operator+(Vec2 a, Vec2 b) { return {a.x + b.x, a.y + b.y}; }
inline Vec2 operator-(Vec2 a, Vec2 b) { return {a.x - b.x, a.y - b.y}; }
inline Vec2 operator*(double k, Vec2 a) { return {k * a.x, k * a.y}; }
// dot product
inline double dot(Vec2 a, Vec2 b) { return a.x * b.x + a.y * b.y; }
// z of the cross product (positive when b turns left of a)
inline double cross(Vec2 a, Vec2 b) { return a.x * b.y - a.y * b.x; }

// length of v
double length(Vec2 v);
// distance between two points
double distance(Vec2 a, Vec2 b);
// unit vector at angle theta (radians)
Vec2 polar(double theta);
// direction angle of v
double angle_of(Vec2 v);

// One offset path element: a straight line through p with unit direction d, or a circle.
struct PathShape {
    bool is_arc = false;
    Vec2 p, d;          // line: point and unit direction
    Vec2 center;        // arc: center
    double radius = 0;  // arc: radius
};

// the shape of a line through p with unit direction d
inline PathShape line_shape(Vec2 p, Vec2 d)
{
    PathShape shape;
    shape.p = p;
    shape.d = d;
    return shape;
}

// the shape of an arc (circle) of the given center and radius
inline PathShape arc_shape(Vec2 center, double radius)
{
    PathShape shape;
    shape.is_arc = true;
    shape.center = center;
    shape.radius = radius;
    return shape;
}

// the points where two path shapes meet (0, 1 or 2 of them, written to out)
int intersections(const PathShape &a, const PathShape &b, Vec2 out[2]);

// signed turn angle from direction a to direction b in (-pi, pi], positive to the left
double turn_angle(Vec2 a, Vec2 b);

// tangent direction of an arc about `center` at point `p`; rotation > 0 is counterclockwise
Vec2 arc_tangent(Vec2 center, Vec2 p, int rotation);

// angle swept going from point a to point b about `center` in the arc's direction, in [0, 2pi)
double arc_sweep(Vec2 center, Vec2 a, Vec2 b, int rotation);

// center, on the line from `center` through `end`, of an arc through `start` and `new_end`
bool entry_arc_center(Vec2 start, Vec2 center, Vec2 end, Vec2 new_end, Vec2 &out);

}  // namespace cutcomp

#endif
