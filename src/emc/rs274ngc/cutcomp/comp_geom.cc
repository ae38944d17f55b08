// comp_geom.cc: line/circle intersections and arc helpers used by the compensation engine.
#include "comp_geom.hh"

#include <cmath>

namespace cutcomp {

// Euclidean length
double length(Vec2 v)
{
    return std::hypot(v.x, v.y);
}

// distance between points
double distance(Vec2 a, Vec2 b)
{
    return length(a - b);
}

// unit vector from an angle
Vec2 polar(double theta)
{
    return {std::cos(theta), std::sin(theta)};
}

// angle of a direction
double angle_of(Vec2 v)
{
    return std::atan2(v.y, v.x);
}

// two lines: solve p1 + t d1 = p2 + u d2
static int line_line(const PathShape &a, const PathShape &b, Vec2 out[2])
{
    double den = cross(a.d, b.d);
    if (std::fabs(den) < 1e-12)
        return 0;
    double t = cross(b.p - a.p, b.d) / den;
    out[0] = a.p + t * a.d;
    return 1;
}

// line and circle: the two roots of |p + t d - c| = r
static int line_circle(const PathShape &l, const PathShape &c, Vec2 out[2])
{
    Vec2 pc = c.center - l.p;
    double t0 = dot(pc, l.d);
    Vec2 foot = l.p + t0 * l.d;
    double h2 = c.radius * c.radius - dot(foot - c.center, foot - c.center);
    if (h2 < 0) {
        if (h2 < -1e-9 * c.radius * c.radius)
            return 0;
        h2 = 0;
    }
    double h = std::sqrt(h2);
    out[0] = foot - h * l.d;
    out[1] = foot + h * l.d;
    return 2;
}

// two circles: the chord through their intersection points
static int circle_circle(const PathShape &a, const PathShape &b, Vec2 out[2])
{
    Vec2 ab = b.center - a.center;
    double d = length(ab);
    if (d < 1e-12)
        return 0;
    double x = (d * d + a.radius * a.radius - b.radius * b.radius) / (2 * d);
    double h2 = a.radius * a.radius - x * x;
    if (h2 < 0) {
        if (h2 < -1e-9 * a.radius * a.radius)
            return 0;
        h2 = 0;
    }
    Vec2 u = (1.0 / d) * ab;
    Vec2 n = {-u.y, u.x};
    Vec2 mid = a.center + x * u;
    double h = std::sqrt(h2);
    out[0] = mid + h * n;
    out[1] = mid - h * n;
    return 2;
}

// dispatch on the shape kinds
int intersections(const PathShape &a, const PathShape &b, Vec2 out[2])
{
    if (!a.is_arc && !b.is_arc)
        return line_line(a, b, out);
    if (!a.is_arc)
        return line_circle(a, b, out);
    if (!b.is_arc)
        return line_circle(b, a, out);
    return circle_circle(a, b, out);
}

// signed angle between two directions
double turn_angle(Vec2 a, Vec2 b)
{
    return std::atan2(cross(a, b), dot(a, b));
}

// tangent of an arc: the radius turned a quarter in the arc's direction
Vec2 arc_tangent(Vec2 center, Vec2 p, int rotation)
{
    Vec2 r = p - center;
    double len = length(r);
    if (len == 0)
        return {1, 0};
    Vec2 u = (1.0 / len) * r;
    return rotation > 0 ? Vec2{-u.y, u.x} : Vec2{u.y, -u.x};
}

// sweep angle from a to b in the arc's direction
double arc_sweep(Vec2 center, Vec2 a, Vec2 b, int rotation)
{
    double sweep = angle_of(b - center) - angle_of(a - center);
    if (rotation < 0)
        sweep = -sweep;
    while (sweep < 0)
        sweep += 2 * M_PI;
    while (sweep >= 2 * M_PI)
        sweep -= 2 * M_PI;
    return sweep;
}

// entry arc center: from new_end toward the old center by b / (2 cos g), g = chord to radius angle
bool entry_arc_center(Vec2 start, Vec2 center, Vec2 end, Vec2 new_end, Vec2 &out)
{
    if (distance(center, end) == 0)
        return false;
    double phi = angle_of(center - end);
    double gamma = angle_of(start - new_end) - phi;
    double c = std::cos(gamma);
    if (std::fabs(c) < 1e-12)
        return false;
    double radius = distance(start, new_end) / (2 * c);
    out = new_end + radius * polar(phi);
    return true;
}

}  // namespace cutcomp
