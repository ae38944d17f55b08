// comp_geom.cc: the arc sweep used to check that trimmed compensated arcs keep their direction.
#include "comp_geom.hh"

#include <cmath>

namespace cutcomp {

// sweep from the radius angle at a to the one at b, whole extra turns added (long double 2 pi)
double find_turn(Vec2 a, Vec2 center, int turn, Vec2 b)
{
    if (turn == 0)
        return 0.0;
    double alpha = std::atan2(a.y - center.y, a.x - center.x);
    double beta = std::atan2(b.y - center.y, b.x - center.x);
    if (turn > 0) {
        if (beta <= alpha)
            beta = beta + 2 * M_PIl;
        return (beta - alpha) + (turn - 1) * (2 * M_PIl);
    }
    if (alpha <= beta)
        alpha = alpha + 2 * M_PIl;
    return (beta - alpha) + (turn + 1) * (2 * M_PIl);
}

}  // namespace cutcomp
