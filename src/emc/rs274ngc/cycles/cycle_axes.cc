// cycle_axes.cc: plane axis tables and move emission shared by all canned cycles.
#include "cycle_axes.hh"

namespace cycles {

// axis triple (position, position, depth) of each canon plane
PlaneAxes plane_axes(CanonPlane p)
{
    switch (p) {
    case CANON_PLANE_XZ: return {AX_Z, AX_X, AX_Y, "xz"};
    case CANON_PLANE_YZ: return {AX_Y, AX_Z, AX_X, "yz"};
    case CANON_PLANE_UV: return {AX_U, AX_V, AX_W, "uv"};
    case CANON_PLANE_UW: return {AX_W, AX_U, AX_V, "uw"};
    case CANON_PLANE_VW: return {AX_V, AX_W, AX_U, "vw"};
    case CANON_PLANE_XY:
    default: return {AX_X, AX_Y, AX_Z, "xy"};
    }
}

// letters of the nine axes in Pose order
char axis_letter(int i)
{
    static const char letters[] = "xyzabcuvw";
    return letters[i];
}

// remember where to emit and in which axes
CycleMoves::CycleMoves(InterpState &s, Canon &c, const PlaneAxes &ax, int line)
    : s_(s), canon_(c), ax_(ax), line_(line)
{
}

// current point with the cycle axes set
Pose CycleMoves::target(double a, double b, double c) const
{
    Pose p = s_.current;
    p[ax_.aa] = a;
    p[ax_.bb] = b;
    p[ax_.cc] = c;
    return p;
}

// rapid move in cycle axes
void CycleMoves::rapid(double a, double b, double c)
{
    s_.current = target(a, b, c);
    canon_.straight_traverse(line_, to_canon_pose(s_.current));
}

// feed move in cycle axes
void CycleMoves::feed(double a, double b, double c)
{
    s_.current = target(a, b, c);
    canon_.straight_feed(line_, to_canon_pose(s_.current));
}

// arc feed in the cycle plane, the depth axis and the other axes unchanged
void CycleMoves::arc(double a, double b, double ca, double cb, int rotation)
{
    s_.current[ax_.aa] = a;
    s_.current[ax_.bb] = b;
    const Pose &p = s_.current;
    canon_.arc_feed(line_, a, b, ca, cb, rotation, p[ax_.cc], p[AX_A], p[AX_B], p[AX_C], p[AX_U],
                    p[AX_V], p[AX_W]);
}

// Feed for the two tapping feeds of G84/G74, reproducing LinuxCNC 2.10 exactly (the conformance
// cases interp/g84/g18 and interp/g84/g19 show it). In G17 it is a plain feed. In G18 and G19 the
// reference emits STRAIGHT_FEED with the cycle's own triple (first plane axis, second plane axis,
// depth) left unrotated in one of the two side planes, so the printed X Y Z are a rotation of the
// true target: G18 (cycle triple Z X Y) prints X=depth Y, Y=Z, Z=X; G19 (cycle triple Y Z X) prints
// X=Z, Y=depth X, Z=Y. Only the printed call is rotated: s.current gets the true target, so the
// next move of the cycle (and of the program) starts from the correct point, as in the reference.
// Pinned by tests/interp-cycles/tap-axis-order.
void CycleMoves::feed_swapped(double a, double b, double c)
{
    if (ax_.cc != AX_Y && ax_.cc != AX_X) {
        feed(a, b, c);
        return;
    }
    Pose p = s_.current;
    if (ax_.cc == AX_Y) {          // XZ plane printed as YZ: X=c, Y=a, Z=b
        p[AX_X] = c; p[AX_Y] = a; p[AX_Z] = b;
    } else {                       // YZ plane printed as XZ: X=b, Y=c, Z=a
        p[AX_X] = b; p[AX_Y] = c; p[AX_Z] = a;
    }
    s_.current = target(a, b, c);
    canon_.straight_feed(line_, to_canon_pose(p));
}

}  // namespace cycles
