// comp_geom.hh: 2-D plane points and arc sweeps for cutter radius compensation.
#ifndef OPENEMC_RS274NGC_COMP_GEOM_HH
#define OPENEMC_RS274NGC_COMP_GEOM_HH

namespace cutcomp {

// A point or direction in the compensation plane (first, second plane axis).
struct Vec2 {
    double x = 0, y = 0;
};

// Signed angle (radians) an arc of `turn` turns sweeps about `center` from point a to point b:
// positive counterclockwise; each extra turn adds a full circle; 0 when turn is 0. The arithmetic
// is LinuxCNC's, so the sweeps it compares come out the same.
double find_turn(Vec2 a, Vec2 center, int turn, Vec2 b);

}  // namespace cutcomp

#endif
