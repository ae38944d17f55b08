// lathe_profile.hh: the contour of a G70/G71/G72 cycle read from its profile subroutine (XZ plane).
#ifndef OPENEMC_RS274NGC_LATHE_PROFILE_HH
#define OPENEMC_RS274NGC_LATHE_PROFILE_HH

#include <string>
#include <vector>

#include "../interp_state.hh"

namespace cycles {

// A point of the XZ plane.
struct LathePoint {
    double x = 0, z = 0;
};

// One profile element: a line, or an arc with center and direction (+1 G3, -1 G2 in the XZ plane).
struct ProfileSeg {
    LathePoint from, to;
    bool arc = false;
    LathePoint center;
    int rotation = 0;
};

// The profile: its elements in program order (at least one).
struct Profile {
    std::vector<ProfileSeg> segs;
    // first point of the contour
    LathePoint start() const { return segs.front().from; }
    // last point of the contour
    LathePoint end() const { return segs.back().to; }
};

// read the G0/G1/G2/G3 moves of the profile blocks; `who` ("G71") prefixes the error texts
Profile read_profile(const InterpState &s, const std::vector<Block> &blocks, const std::string &who);

// true when coordinate `x_axis ? x : z` never turns back along the profile
bool profile_monotonic(const Profile &p, bool x_axis);

// the smallest and largest X (x_axis) or Z of the profile
void profile_range(const Profile &p, bool x_axis, double &lo, double &hi);

// where the profile crosses step-axis level `level` (X for x_axis, else Z): the other coordinate
// of the first crossing in profile order; false when no element reaches that level
bool profile_cross(const Profile &p, bool x_axis, double level, double &other);

}  // namespace cycles

#endif
