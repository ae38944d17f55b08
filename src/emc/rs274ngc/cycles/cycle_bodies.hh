// cycle_bodies.hh: the per-hole move sequences of G73 G74 G81..G89 once the tool is at the R plane.
#ifndef OPENEMC_RS274NGC_CYCLE_BODIES_HH
#define OPENEMC_RS274NGC_CYCLE_BODIES_HH

#include "cycle_axes.hh"

namespace cycles {

// Everything one hole needs: where, how deep, the retract level and the cycle words.
struct Hole {
    double a = 0, b = 0;       // hole position in the two plane axes
    double bottom = 0;         // depth (Z in XY)
    double r = 0;              // R plane
    double clear = 0;          // retract level: R (G99) or initial level (G98)
    double dwell = 0;          // P seconds
    double peck = 0;           // Q
    double peck_clearance = 0; // c of G73/G83
    double i = 0, j = 0, k = 0;  // G87 back-boring offsets and level
    int spindle = 0;
    CanonDirection spindle_dir = CANON_STOPPED;
};

// A cycle body: emits the moves of one hole, starting at the R plane above it.
using CycleBody = void (*)(CycleMoves &mv, const Hole &h);

// the body of motion code `code` (G ×10), nullptr when it is not a canned cycle
CycleBody cycle_body(int code);

}  // namespace cycles

#endif
