// cycle_axes.hh: plane-generic axes (aa, bb = hole position, cc = depth) and move emission for canned cycles.
#ifndef OPENEMC_RS274NGC_CYCLE_AXES_HH
#define OPENEMC_RS274NGC_CYCLE_AXES_HH

#include <string>

#include "../canon.hh"
#include "../interp_state.hh"

namespace cycles {

// The three axes a cycle works with in one plane, as Pose indexes and letters.
struct PlaneAxes {
    int aa, bb, cc;          // first position axis, second position axis, depth axis
    const char *plane_name;  // "xy", "xz", ... as used in error texts
};

// axes of canon plane p (XY: x y z, XZ: z x y, YZ: y z x, and the UVW planes alike)
PlaneAxes plane_axes(CanonPlane p);

// lower-case axis letter of Pose index i
char axis_letter(int i);

// Emits rapids and feeds that change only the three cycle axes of the current point.
class CycleMoves {
public:
    // emit through canon c for state s in plane axes ax, tagging moves with line
    CycleMoves(InterpState &s, Canon &c, const PlaneAxes &ax, int line);
    // rapid to (a, b, c) in cycle axes; updates s.current
    void rapid(double a, double b, double c);
    // feed to (a, b, c) in cycle axes; updates s.current
    void feed(double a, double b, double c);
    // G84/G74 tapping feed: in G18/G19 the printed X Y Z are rotated as the reference prints them (see .cc)
    void feed_swapped(double a, double b, double c);
    // arc in the cycle plane to (a, b) about (ca, cb); rotation > 0 counterclockwise
    void arc(double a, double b, double ca, double cb, int rotation);
    // rapid along the depth axis only
    void rapid_depth(double c) { rapid(cur(ax_.aa), cur(ax_.bb), c); }
    // feed along the depth axis only
    void feed_depth(double c) { feed(cur(ax_.aa), cur(ax_.bb), c); }
    // current value of Pose axis i
    double cur(int i) const { return s_.current[i]; }
    // the canon being written
    Canon &canon() { return canon_; }
    // the axes in use
    const PlaneAxes &axes() const { return ax_; }

private:
    // the pose with the cycle axes replaced
    Pose target(double a, double b, double c) const;

    InterpState &s_;
    Canon &canon_;
    PlaneAxes ax_;
    int line_;
};

}  // namespace cycles

#endif
