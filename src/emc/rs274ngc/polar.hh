// polar.hh: polar words (@ radius, ^ angle) to an XY point, shared by moves and canned cycles.
#ifndef OPENEMC_RS274NGC_POLAR_HH
#define OPENEMC_RS274NGC_POLAR_HH

#include <cmath>

#include "block.hh"
#include "interp_state.hh"

// The XY point of a block's polar words, from the current point (x, y) of the XY plane about
// the program origin: G90 replaces the radius/angle given, G91 adds them (error at the origin).
// Degrees are multiplied by the one factor pi / 180, as LinuxCNC does: the radians then agree to
// the last bit, so a coordinate that comes out as about zero keeps the sign LinuxCNC prints.
inline void polar_point(const Block &b, bool incremental, double &x, double &y)
{
    double r = std::hypot(x, y);
    double a = std::atan2(y, x);
    if (incremental) {
        if (x == 0.0 && y == 0.0)
            throw InterpError("Incremental motion with polar coordinates is indeterminate when "
                              "at the origin");
        if (b.has_polar_radius) r += b.polar_radius;
        if (b.has_polar_angle) a += b.polar_angle * (M_PI / 180.0);
    } else {
        if (b.has_polar_radius) r = b.polar_radius;
        if (b.has_polar_angle) a = b.polar_angle * (M_PI / 180.0);
    }
    x = r * std::cos(a);
    y = r * std::sin(a);
}

#endif
