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

// copy the nine values into the canon pose
CanonPose to_canon(const Pose &p)
{
    CanonPose c;
    c.x = p[AX_X]; c.y = p[AX_Y]; c.z = p[AX_Z];
    c.a = p[AX_A]; c.b = p[AX_B]; c.c = p[AX_C];
    c.u = p[AX_U]; c.v = p[AX_V]; c.w = p[AX_W];
    return c;
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
    canon_.straight_traverse(line_, to_canon(s_.current));
}

// feed move in cycle axes
void CycleMoves::feed(double a, double b, double c)
{
    s_.current = target(a, b, c);
    canon_.straight_feed(line_, to_canon(s_.current));
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

// feed whose printed coordinates use the XZ/YZ order of the other plane (reference G84/G74 behaviour)
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
    canon_.straight_feed(line_, to_canon(p));
}

}  // namespace cycles
