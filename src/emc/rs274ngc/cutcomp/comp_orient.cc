// comp_orient.cc: imaginary-tip offsets of the nine lathe tool orientations.
#include "comp_orient.hh"

namespace cutcomp {

// orientation n -> (z, x) direction of the imaginary tip from the nose center
Vec2 tip_shift(CanonPlane plane, int orientation, double radius)
{
    static const Vec2 tip[10] = {
        {0, 0},            // 0: no orientation
        {1, -1}, {-1, -1}, {-1, 1}, {1, 1},   // 1..4: corners
        {1, 0}, {0, -1}, {-1, 0}, {0, 1},     // 5..8: sides
        {0, 0},            // 9: nose center
    };
    if (plane != CANON_PLANE_XZ || orientation < 0 || orientation > 9)
        return {0, 0};
    return {radius * tip[orientation].x, radius * tip[orientation].y};
}

}  // namespace cutcomp
