// active_codes.cc: the interpreter's modal state in the layout of LinuxCNC's activeGCodes/MCodes/Settings (nml.md §5).
#include "interp.hh"

namespace {

// G17..G19.1 x10 by CanonPlane
int plane_code(CanonPlane p)
{
    static const int codes[] = {-1, 170, 190, 180, 171, 191, 181};
    return p >= CANON_PLANE_XY && p <= CANON_PLANE_UW ? codes[p] : -1;
}

// G54..G59.3 x10 by origin index 1..9
int coord_code(int index)
{
    static const int codes[] = {-1, 540, 550, 560, 570, 580, 590, 591, 592, 593};
    return index >= 1 && index <= 9 ? codes[index] : -1;
}

// G61 / G61.1 / G64 x10
int path_code(CanonMotionMode m)
{
    return m == CANON_EXACT_STOP ? 611 : m == CANON_EXACT_PATH ? 610 : 640;
}

} // namespace

// activeGCodes: sequence, motion, group 0 of the block, plane, comp, units, distance, feed mode,
// coordinate system, TLO, retract, path control, -1, spindle mode, IJK mode, lathe mode, G92 applied.
void Interp::active_g_codes(int g[17]) const
{
    int g0 = current_block_ ? current_block_->g_modes[GG_NONMODAL] : -1;
    g[0] = s_.sequence_number;
    g[1] = s_.motion_mode;
    g[2] = g0;
    g[3] = plane_code(s_.plane);
    g[4] = s_.comp_code == 411 ? 410 : s_.comp_code == 421 ? 420 : s_.comp_code;
    g[5] = s_.units == CANON_UNITS_INCHES ? 200 : 210;
    g[6] = s_.distance_incremental ? 910 : 900;
    g[7] = s_.feed_mode == FEED_INVERSE_TIME ? 930 : s_.feed_mode == FEED_UNITS_PER_REV ? 950 : 940;
    g[8] = coord_code(s_.origin_index);
    g[9] = s_.tlo_code;
    g[10] = s_.retract == RETRACT_OLD_Z ? 980 : 990;
    g[11] = path_code(s_.control_mode);
    g[12] = -1;
    g[13] = s_.css_mode[0] ? 960 : 970;
    g[14] = s_.ijk_absolute ? 901 : 911;
    g[15] = s_.lathe_diameter ? 70 : 80;
    g[16] = s_.params[5210] == 1.0 && g0 == -1 ? 923 : -1;
}

// activeMCodes: sequence, stop code, spindle, tool change, mist, flood, overrides, adaptive, feed hold, -1.
void Interp::active_m_codes(int m[10]) const
{
    CanonDirection dir = s_.spindle_dir[0];
    m[0] = s_.sequence_number;
    m[1] = current_block_ ? current_block_->m_modes[MG_STOP] : -1;
    m[2] = dir == CANON_CLOCKWISE ? 3 : dir == CANON_COUNTERCLOCKWISE ? 4 : 5;
    m[3] = current_block_ ? current_block_->m_modes[MG_TOOL] : -1;
    m[4] = s_.mist ? 7 : s_.flood ? -1 : 9;
    m[5] = s_.flood ? 8 : -1;
    m[6] = s_.feed_override && s_.speed_override ? 48 : 49;
    m[7] = s_.adaptive_feed ? 52 : -1;
    m[8] = s_.feed_hold ? 53 : -1;
    m[9] = -1;
}

// activeSettings: sequence, F, S, G64 P, G64 Q.
void Interp::active_settings(double v[5]) const
{
    v[0] = s_.sequence_number;
    v[1] = s_.feed_rate;
    v[2] = s_.speed[0];
    v[3] = s_.tolerance;
    v[4] = s_.naivecam_tolerance;
}
