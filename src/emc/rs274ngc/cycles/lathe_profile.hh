// lathe_profile.hh: the contour of a G70/G71/G72 cycle read from its profile subroutine.
#ifndef OPENEMC_RS274NGC_LATHE_PROFILE_HH
#define OPENEMC_RS274NGC_LATHE_PROFILE_HH

#include <string>
#include <vector>

#include "../interp_state.hh"
#include "lathe_geom.hh"

namespace cycles {

// The profile in the ZX plane (u = Z, v = X radius; ccw = G3): the end of its first move, then
// the elements of the following moves with their fillets (A) and chamfers (C).
struct Profile {
    Pt start;
    std::vector<Elem> elems;
};

// read the G0/G1/G2/G3 moves of the profile blocks starting from the cycle's start point
// `from`; `who` ("G71") prefixes the error texts
Profile read_profile(const InterpState &s, const std::vector<Block> &blocks, Pt from,
                     const std::string &who);

}  // namespace cycles

#endif
