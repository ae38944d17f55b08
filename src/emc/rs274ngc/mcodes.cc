// mcodes.cc: M codes: I/O, spindle, coolant, overrides, user codes, program stops and the M2 reset.
#include <cmath>
#include <sys/stat.h>
#include <unistd.h>

#include "interp.hh"

// M62-M68 and M66 (step 9).
void Interp::do_io(Block &b)
{
    INTERP_FRAME();
    int m = b.m_modes[MG_IO];
    if (m == -1) return;
    if (s_.comp_side != CANON_SIDE_OFF)
        throw InterpError("Cannot use M62-M68 with cutter radius compensation on");
    if (m == 66) return do_wait_input(b);
    if (m >= 62 && m <= 65) {
        if (!b.word('p')) throw InterpError("No valid P word with M" + std::to_string(m));
        int n = clamp_int(b.value('p'));
        if (m == 62) out().set_motion_output_bit(n);
        if (m == 63) out().clear_motion_output_bit(n);
        if (m == 64) out().set_aux_output_bit(n);
        if (m == 65) out().clear_aux_output_bit(n);
        return;
    }
    if (!b.word('e')) throw InterpError("No valid E word with M" + std::to_string(m));
    if (!b.word('q')) throw InterpError("No valid Q word with M" + std::to_string(m));
    int n = clamp_int(b.value('e'));
    if (m == 67)
        out().set_motion_output_value(n, b.value('q'));
    else
        out().set_aux_output_value(n, b.value('q'));
}

// The words of an M66: digital (P) or analog (E) input, wait type L, timeout Q.
void Interp::check_wait_input(const Block &b, int &type, double &timeout) const
{
    if (b.word('p') && b.word('e'))
        throw InterpError("Invalid to select both a digital and an analog input with M66");
    if (!b.word('p') && !b.word('e'))
        throw InterpError("Must select either a digital or an analog input with M66");
    type = b.word('l') ? clamp_int(b.value('l')) : 0;
    if (type < 0 || type > 4) throw InterpError("Unknown wait type for M66");
    timeout = b.word('q') ? b.value('q') : 0.0;
    if (type != 0 && timeout == 0.0)
        throw InterpError("Zero timeout with wait type != immediate return");
    if (b.word('e') && type != 0)
        throw InterpError("Analog input can only be used with immediate return (L0)");
}

// M66: wait for / read an input into #5399.
void Interp::do_wait_input(Block &b)
{
    INTERP_FRAME();
    int type;
    double timeout;
    check_wait_input(b, type, timeout);
    bool digital = b.word('p');
    int index = clamp_int(digital ? b.value('p') : b.value('e'));
    int ret = out().wait_input(index, digital ? 1 : 0, type, timeout);
    if (ret == -1) {
        s_.params[5399] = -1;
        return;
    }
    s_.params[5399] = digital ? real_out_.get_external_digital_input(index, clamp_int(s_.params[5399]))
                              : real_out_.get_external_analog_input(index, s_.params[5399]);
}

// M3/M4/M5 on spindle s.
void Interp::spindle_direction(int m, int s)
{
    if (m == 3) out().start_spindle_clockwise(s);
    if (m == 4) out().start_spindle_counterclockwise(s);
    if (m == 5) out().stop_spindle_turning(s);
    s_.spindle_dir[s] = m == 3 ? CANON_CLOCKWISE : m == 4 ? CANON_COUNTERCLOCKWISE : CANON_STOPPED;
}

// M19 R angle P mode [Q timeout] on spindle sp.
void Interp::orient_spindle(const Block &b, int sp)
{
    double angle = (b.word('r') ? b.value('r') : 0.0) + s_.settings.orient_offset;
    int mode = b.word('p') ? clamp_int(b.value('p')) : 0;
    if (mode < 0 || mode > 2) throw InterpError("M19 P must be 0, 1 or 2");
    if (b.word('r') || b.word('p')) out().orient_spindle(sp, angle, mode);
    s_.spindle_dir[sp] = CANON_STOPPED;
    if (b.word('q')) out().wait_spindle_orient_complete(sp, b.value('q'));
}

// M70/M71/M72/M73: save, invalidate, restore the modal state.
void Interp::modal_state_code(int m)
{
    if (m == 70 || m == 73) modal_save(m == 73);
    if (m == 71) {
        calls_.back().saved.valid = false;
        calls_.back().autorestore = false;
    }
    if (m == 72) {
        if (!calls_.back().saved.valid)
            throw InterpError("Cannot restore context - no context saved with M70");
        SavedModal saved = calls_.back().saved;
        modal_restore(saved);
    }
}

// M3/M4/M5/M19 and M70-M73 (step 11).
void Interp::do_spindle(Block &b)
{
    INTERP_FRAME();
    int m = b.m_modes[MG_SPINDLE];
    if (m == -1) return;
    int sp = b.has_dollar ? clamp_int(b.dollar) : 0;
    if (sp < -1 || sp >= s_.num_spindles) throw InterpError("Invalid spindle ($) number");
    int first = sp == -1 ? 0 : sp, last = sp == -1 ? s_.num_spindles - 1 : sp;
    if (m >= 3 && m <= 5)
        for (int s = first; s <= last; s++) spindle_direction(m, s);
    if (m == 19) orient_spindle(b, first);
    if (m >= 70 && m <= 73) modal_state_code(m);
}

// M7/M8/M9 (step 12).
void Interp::do_coolant(Block &b)
{
    INTERP_FRAME();
    int m = b.m_modes[MG_COOLANT];
    if (m == 7) { out().mist_on(); s_.mist = true; }
    if (m == 8) { out().flood_on(); s_.flood = true; }
    if (m == 9) {
        out().mist_off();
        out().flood_off();
        s_.mist = s_.flood = false;
    }
}

// M48-M53 (step 13): P0 disables, P1 (or none) enables; M48/M49 both feed and speed.
void Interp::do_overrides(Block &b)
{
    INTERP_FRAME();
    int m = b.m_modes[MG_OVERRIDE];
    if (m == -1) return;
    if (s_.comp_side != CANON_SIDE_OFF)
        throw InterpError("Cannot change overrides with cutter radius compensation on");
    bool on = m == 48 || (m != 49 && (!b.word('p') || b.value('p') != 0.0));
    bool both = m == 48 || m == 49;
    if (both || m == 50) set_switch(s_.feed_override, on, &Canon::enable_feed_override,
                                    &Canon::disable_feed_override);
    if (both || m == 51) {
        s_.speed_override = on;
        on ? out().enable_speed_override(0) : out().disable_speed_override(0);
    }
    if (m == 52) set_switch(s_.adaptive_feed, on, &Canon::enable_adaptive_feed,
                            &Canon::disable_adaptive_feed);
    if (m == 53) set_switch(s_.feed_hold, on, &Canon::enable_feed_hold, &Canon::disable_feed_hold);
}

// Set an override switch and emit its enable or disable call.
void Interp::set_switch(bool &state, bool on, void (Canon::*enable)(), void (Canon::*disable)())
{
    state = on;
    (out().*(on ? enable : disable))();
}

// M100-M199 (step 14): run by the user-M handler; without one (rs274) they are unknown.
void Interp::do_user_m(Block &b)
{
    INTERP_FRAME();
    int m = b.m_modes[MG_USER];
    if (m == -1) return;
    double p = b.word('p') ? b.value('p') : 0.0, q = b.word('q') ? b.value('q') : 0.0;
    if (!user_m_ || !user_m_(m, p, q)) throw InterpError("Unknown m code used: M" + std::to_string(m));
}

// M0 M1 M2 M30 M60 M99 (step 29).
InterpStatus Interp::do_stop(Block &b)
{
    INTERP_FRAME();
    int m = b.m_modes[MG_STOP];
    if (m == -1) return INTERP_OK;
    if (m == 0) out().program_stop();
    if (m == 1) out().optional_program_stop();
    if (m == 60) { out().pallet_shuttle(); out().program_stop(); }
    if (m == 0 || m == 1 || m == 60) return INTERP_OK;
    if (m == 99 && fanuc_return()) return INTERP_OK;
    if (m == 99 && restart_main()) return INTERP_OK;
    m2_reset(m);
    return INTERP_EXIT;
}

// M99 in the main program under task: continue at its first line (after an opening '%'), the
// modal state kept; false when looping is off or the program is MDI.
bool Interp::restart_main()
{
    INTERP_FRAME();
    CallFrame &f = calls_.front();
    if (!loop_main_m99_ || calls_.size() != 1 || !f.file) return false;
    f.pos = f.file->percent ? f.file->percent_line + 1 : 0;
    f.flow.clear();
    return true;
}

// Program end resets (LinuxCNC's M2/M30 resets).
void Interp::m2_reset(int code)
{
    INTERP_FRAME();
    if (comp_) comp_->flush();
    if (!s_.settings.disable_auto_g54) {
        set_origin_index(1);
        emit_g5x();
        out().set_xy_rotation(s_.rotation_xy);
    }
    if (s_.plane != CANON_PLANE_XY) out().select_plane(CANON_PLANE_XY);
    s_.plane = CANON_PLANE_XY;
    s_.distance_incremental = false;
    s_.feed_mode = FEED_UNITS_PER_MINUTE;
    out().set_feed_mode(0, 0);
    s_.feed_rate = 0;
    out().set_feed_rate(0);
    if (!s_.feed_override) out().enable_feed_override();
    s_.feed_override = true;
    if (comp_ && s_.comp_side != CANON_SIDE_OFF) comp_->reset();
    s_.comp_side = CANON_SIDE_OFF;
    s_.comp_code = 400;
    m2_stop_spindles();
    s_.motion_mode = 10;
    if (s_.mist) out().mist_off();
    if (s_.flood) out().flood_off();
    s_.mist = s_.flood = false;
    if (s_.settings.disable_g92_persistence) {
        for (int i = 5210; i <= 5219; i++) s_.params[i] = 0;
        s_.axis_offset = Pose{};
        emit_g92();
    }
    if (code == 30) out().pallet_shuttle();
    out().program_end();
    check_closing_percent();
}

// M2/M30 part: stop every spindle, leave CSS mode and re-enable the speed override.
void Interp::m2_stop_spindles()
{
    for (int sp = 0; sp < s_.num_spindles; sp++) {
        out().stop_spindle_turning(sp);
        s_.spindle_dir[sp] = CANON_STOPPED;
        out().set_spindle_mode(sp, 0);
        s_.css_mode[sp] = false;
    }
    s_.speed_override = true;
}

// A program opened with % must close with %: comment when the rest of the file has none.
void Interp::check_closing_percent()
{
    CallFrame &f = calls_[0];
    if (f.file && f.file->percent) {
        bool closing = false;
        for (size_t i = f.pos; i < f.file->lines.size(); i++)
            closing = closing || f.file->lines[i].find('%') != std::string::npos;
        if (!closing) out().comment("interpreter: percent sign missing from end of file");
    }
}

// The program a user M-code runs: the first executable regular file "M<m>" in PROGRAM_PREFIX and
// then the USER_M_PATH directories (for the driver's user-M handler; rs274 installs none).
std::string Interp::find_user_m(int m) const
{
    INTERP_FRAME();
    std::vector<std::string> dirs;
    if (!s_.settings.program_prefix.empty()) dirs.push_back(s_.settings.program_prefix);
    dirs.insert(dirs.end(), s_.settings.user_m_path.begin(), s_.settings.user_m_path.end());
    for (const std::string &d : dirs) {
        std::string path = (d.empty() ? std::string(".") : d) + "/M" + std::to_string(m);
        struct stat st;
        if (stat(path.c_str(), &st) == 0 && S_ISREG(st.st_mode) && access(path.c_str(), X_OK) == 0)
            return path;
    }
    return "";
}
