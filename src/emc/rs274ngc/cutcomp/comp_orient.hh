// comp_orient.hh: lathe tool orientation: where the controlled tip point sits relative to the nose center.
#ifndef OPENEMC_RS274NGC_COMP_ORIENT_HH
#define OPENEMC_RS274NGC_COMP_ORIENT_HH

#include "../canon.hh"
#include "comp_geom.hh"

namespace cutcomp {

// shift (in XZ plane coordinates: z, x) from the nose-center path to the emitted tip path for
// orientation 1..8 in G18; zero for other planes and orientations 0 and 9
Vec2 tip_shift(CanonPlane plane, int orientation, double radius);

}  // namespace cutcomp

#endif
