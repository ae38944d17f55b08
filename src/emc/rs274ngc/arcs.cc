// arcs.cc: G2/G3 arcs and helices: center and radius formats with LinuxCNC's tolerances (LinuxCNC's arc rules).
#include <cmath>
#include <cstdio>

#include "interp.hh"

namespace {

// In-plane axis indexes, offset letters and names for one plane.
struct PlaneAxes {
    int first, second, normal;     // axis indexes
    char off1, off2;               // center offset letters
    char name1, name2;             // axis letters for messages
    const char *missing;           // radius-format error
};

// the axes of the active plane (XZ is Z first)
PlaneAxes plane_axes(CanonPlane p)
{
    if (p == CANON_PLANE_XZ)
        return {AX_Z, AX_X, AX_Y, 'k', 'i', 'Z', 'X', "X and z words missing for arc in xz plane"};
    if (p == CANON_PLANE_YZ)
        return {AX_Y, AX_Z, AX_X, 'j', 'k', 'Y', 'Z', "Y and z words missing for arc in yz plane"};
    return {AX_X, AX_Y, AX_Z, 'i', 'j', 'X', 'Y', "X and y words missing for arc in xy plane"};
}

// "(X1.0000,Y2.0000)" for a message
std::string point_text(const PlaneAxes &pa, double a, double b)
{
    char buf[800];
    snprintf(buf, sizeof buf, "(%c%.4f,%c%.4f)", pa.name1, a, pa.name2, b);
    return buf;
}

} // namespace

// Center of a radius-format arc (R > 0: at most 180 degrees, R < 0: more).
void Interp::arc_center_r(const Block &b, double s1, double s2, double e1, double e2, int mode,
                          double &c1, double &c2)
{
    INTERP_FRAME();
    double r = b.value('r');
    double tol = s_.units == CANON_UNITS_INCHES ? 0.00005 : 0.00127;
    if (s1 == e1 && s2 == e2) throw InterpError("Current point same as end point of arc");
    double m1 = (s1 + e1) / 2.0, m2 = (s2 + e2) / 2.0;
    double half = std::hypot(m1 - e1, m2 - e2);
    double ar = std::fabs(r);
    if (half - ar > tol) throw InterpError("Arc radius too small to reach end point");
    if (half / ar > 1.0 - 1e-12) half = ar;
    bool right = (mode == 20 && r > 0) || (mode == 30 && r < 0);
    // LinuxCNC's arithmetic to the last bit: the quarter turn added in long double, the center
    // distance as R cos(asin(half / R)) (a semicircle's center is then off the chord by about
    // 1e-17, which decides the sign of a center coordinate printed as zero)
    long double quarter = right ? -M_PI_2l : M_PI_2l;
    double dir = (double)(std::atan2(e2 - s2, e1 - s1) + quarter);
    double dist = ar * std::cos(std::asin(half / ar));
    c1 = m1 + dist * std::cos(dir);
    c2 = m2 + dist * std::sin(dir);
}

// Center of a center-format arc, checked against the radius tolerances.
void Interp::arc_center_ijk(const Block &b, double s1, double s2, double e1, double e2,
                            double &c1, double &c2)
{
    INTERP_FRAME();
    PlaneAxes pa = plane_axes(s_.plane);
    if (s_.ijk_absolute) {
        if (!b.word(pa.off1))
            throw InterpError(std::string(1, (char)toupper(pa.off1)) +
                              " word missing in absolute center arc");
        if (!b.word(pa.off2))
            throw InterpError(std::string(1, (char)toupper(pa.off2)) +
                              " word missing in absolute center arc");
        c1 = b.value(pa.off1);
        c2 = b.value(pa.off2);
    } else {
        c1 = s1 + (b.word(pa.off1) ? b.value(pa.off1) : 0.0);
        c2 = s2 + (b.word(pa.off2) ? b.value(pa.off2) : 0.0);
    }
    double rtol = s_.units == CANON_UNITS_INCHES ? 0.00005 : 0.00127;
    double ctol = s_.units == CANON_UNITS_INCHES ? 2 * 0.001 * M_SQRT2 : 2 * 0.01 * M_SQRT2;
    double r1 = std::hypot(s1 - c1, s2 - c2), r2 = std::hypot(e1 - c1, e2 - c2);
    char buf[2048];
    std::string pts = "start=" + point_text(pa, s1, s2) + " center=" + point_text(pa, c1, c2) +
                      " end=" + point_text(pa, e1, e2);
    if (r1 < rtol || r2 < rtol) {
        snprintf(buf, sizeof buf, "Zero-radius arc: %s r1=%.4f r2=%.4f", pts.c_str(), r1, r2);
        throw InterpError(buf);
    }
    double abs_err = std::fabs(r1 - r2);
    double rel_err = abs_err / std::max(r1, r2);
    if (abs_err > 100 * ctol || (rel_err > 0.001 && abs_err > ctol)) {
        snprintf(buf, sizeof buf,
                 "Radius to end of arc differs from radius to start: %s r1=%.4f r2=%.4f "
                 "abs_err=%.4g rel_err=%.4f%%", pts.c_str(), r1, r2, abs_err, rel_err * 100);
        throw InterpError(buf);
    }
}

// Turns of an arc: the P word (a positive integer), default 1.
int Interp::arc_turns(const Block &b) const
{
    if (!b.word('p')) return 1;
    double p = b.value('p');
    int turns = clamp_int(p);
    if (turns < 1 || std::fabs(p - turns) > 0.0001)
        throw InterpError("P word is not a positive integer");
    return turns;
}

// G2 / G3.
void Interp::move_arc(const Block &b, int mode)
{
    INTERP_FRAME();
    if (s_.plane >= CANON_PLANE_UV)
        throw InterpError("Cannot do an arc in planes G17.1, G18.1, or G19.1");
    if (s_.feed_mode == FEED_UNITS_PER_MINUTE && s_.feed_rate == 0.0)
        throw InterpError("Cannot make arc with zero feed rate");
    PlaneAxes pa = plane_axes(s_.plane);
    bool ijk = b.word('i') || b.word('j') || b.word('k');
    if (!b.word('r') && !ijk) throw InterpError("R i j k words all missing for arc");
    Pose end = find_end(b);
    double s1 = s_.current[pa.first], s2 = s_.current[pa.second];
    double e1 = end[pa.first], e2 = end[pa.second];
    double c1, c2;
    if (b.word('r')) {
        static const char letters[] = "xyzabc";
        bool in_plane = b.word(letters[pa.first]) || b.word(letters[pa.second]) ||
                        b.has_polar_radius || b.has_polar_angle;
        if (!in_plane) throw InterpError(pa.missing);
        arc_center_r(b, s1, s2, e1, e2, mode, c1, c2);
    } else {
        arc_center_ijk(b, s1, s2, e1, e2, c1, c2);
    }
    int rotation = mode == 20 ? -arc_turns(b) : arc_turns(b);
    if (s_.feed_mode == FEED_INVERSE_TIME)
        apply_inverse_time(arc_length(s1, s2, e1, e2, c1, c2, rotation,
                                      end[pa.normal] - s_.current[pa.normal]), b);
    out().arc_feed(s_.sequence_number, e1, e2, c1, c2, rotation, end[pa.normal], end[AX_A],
                   end[AX_B], end[AX_C], end[AX_U], end[AX_V], end[AX_W]);
    s_.current = end;
}

// Length of an arc or helix for inverse-time feeds.
double Interp::arc_length(double s1, double s2, double e1, double e2, double c1, double c2,
                          int rotation, double axial) const
{
    INTERP_FRAME();
    double r = std::hypot(s1 - c1, s2 - c2);
    double a0 = std::atan2(s2 - c2, s1 - c1), a1 = std::atan2(e2 - c2, e1 - c1);
    double sweep;
    if (rotation > 0) {
        sweep = a1 - a0;
        if (sweep <= 0) sweep += 2 * M_PI;
        sweep += 2 * M_PI * (rotation - 1);
    } else {
        sweep = a0 - a1;
        if (sweep <= 0) sweep += 2 * M_PI;
        sweep += 2 * M_PI * (-rotation - 1);
    }
    return std::hypot(r * sweep, axial);
}
