// modal_save.cc: M70/M73 save and M72 restore of the modal state (changed settings only, units first).
#include "interp.hh"

// Save the modal state in the current call frame; autorestore for M73.
void Interp::modal_save(bool autorestore)
{
    INTERP_FRAME();
    SavedModal &m = calls_.back().saved;
    m.valid = true;
    m.units = s_.units;
    m.plane = s_.plane;
    m.comp_code = s_.comp_code;
    m.distance_incremental = s_.distance_incremental;
    m.ijk_absolute = s_.ijk_absolute;
    m.feed_mode = s_.feed_mode;
    m.origin_index = s_.origin_index;
    m.tlo_code = s_.tlo_code;
    m.retract = s_.retract;
    m.css_mode = s_.css_mode[0];
    m.lathe_diameter = s_.lathe_diameter;
    m.control_mode = s_.control_mode;
    m.tolerance = s_.tolerance;
    m.naivecam_tolerance = s_.naivecam_tolerance;
    m.feed_rate = s_.feed_rate;
    m.speed = s_.speed[0];
    m.spindle_dir = s_.spindle_dir[0];
    m.mist = s_.mist;
    m.flood = s_.flood;
    m.feed_override = s_.feed_override;
    m.speed_override = s_.speed_override;
    m.adaptive_feed = s_.adaptive_feed;
    m.feed_hold = s_.feed_hold;
    calls_.back().autorestore = autorestore;
}

// Fill b with the G/M/F/S words that bring the current modes back to the saved state m.
void Interp::modal_restore_block(const SavedModal &m, Block &b) const
{
    if (m.feed_mode != s_.feed_mode)
        b.g_modes[GG_FEED] = m.feed_mode == FEED_INVERSE_TIME ? 930
                             : m.feed_mode == FEED_UNITS_PER_REV ? 950 : 940;
    b.has['f' - 'a'] = true;
    b.val['f' - 'a'] = m.feed_rate;
    b.has['s' - 'a'] = true;
    b.val['s' - 'a'] = m.speed;
    if (m.spindle_dir != s_.spindle_dir[0])
        b.m_modes[MG_SPINDLE] = m.spindle_dir == CANON_CLOCKWISE ? 3
                                : m.spindle_dir == CANON_COUNTERCLOCKWISE ? 4 : 5;
    static const int planes[] = {0, 170, 190, 180, 171, 191, 181};
    if (m.plane != s_.plane) b.g_modes[GG_PLANE] = planes[m.plane];
    b.g_modes[GG_PATH] = m.control_mode == CANON_CONTINUOUS ? 640
                         : m.control_mode == CANON_EXACT_PATH ? 610 : 611;
    if (m.control_mode == CANON_CONTINUOUS) {
        b.has['p' - 'a'] = b.has['q' - 'a'] = true;
        b.val['p' - 'a'] = m.tolerance;
        b.val['q' - 'a'] = m.naivecam_tolerance;
    }
    restore_modal_codes(m, b);
}

// The G codes of two-state groups that differ from the saved state.
void Interp::restore_modal_codes(const SavedModal &m, Block &b) const
{
    if (m.distance_incremental != s_.distance_incremental)
        b.g_modes[GG_DISTANCE] = m.distance_incremental ? 910 : 900;
    if (m.ijk_absolute != s_.ijk_absolute) b.g_modes[GG_IJK] = m.ijk_absolute ? 901 : 911;
    if (m.retract != s_.retract) b.g_modes[GG_RETRACT] = m.retract == RETRACT_OLD_Z ? 980 : 990;
    if (m.lathe_diameter != s_.lathe_diameter) b.g_modes[GG_LATHE] = m.lathe_diameter ? 70 : 80;
    if (m.css_mode != s_.css_mode[0]) b.g_modes[GG_SPINDLE] = m.css_mode ? 960 : 970;
}

// Re-issue the settings that differ from a saved state (units first, then in execution order).
void Interp::modal_restore(const SavedModal &m)
{
    INTERP_FRAME();
    Block u;
    if (m.units != s_.units) u.g_modes[GG_UNITS] = m.units == CANON_UNITS_MM ? 210 : 200;
    do_units(u);
    Block b;
    modal_restore_block(m, b);
    do_spindle_mode(b);
    do_feed_mode(b);
    do_feed_rate(b);
    do_speed(b);
    do_spindle(b);
    restore_coolant(m, true);
    do_plane(b);
    do_lathe_mode(b);
    do_path_control(b);
    do_distance(b);
    do_retract(b);
    restore_coolant(m, false);
}

// Coolant part of M72 (only what changed): M9 and mist first, flood last.
void Interp::restore_coolant(const SavedModal &m, bool first)
{
    INTERP_FRAME();
    if (!first) {
        if (m.flood && !s_.flood) { out().flood_on(); s_.flood = true; }
        return;
    }
    if ((s_.mist && !m.mist) || (s_.flood && !m.flood)) {
        out().mist_off();
        out().flood_off();
        s_.mist = s_.flood = false;
    }
    if (m.mist && !s_.mist) { out().mist_on(); s_.mist = true; }
}
