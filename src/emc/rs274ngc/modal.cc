// modal.cc: modal G-code groups: plane, units, lathe mode, comp, TLO, coord system, path, distance, retract.
#include <cmath>

#include "interp.hh"

// G17..G19.1 (step 16).
void Interp::do_plane(Block &b)
{
    INTERP_FRAME();
    int g = b.g_modes[GG_PLANE];
    if (g == -1) return;
    if (s_.comp_side != CANON_SIDE_OFF)
        throw InterpError("Cannot change plane with cutter radius compensation on");
    static const struct { int g; CanonPlane p; } map[] = {
        {170, CANON_PLANE_XY}, {180, CANON_PLANE_XZ}, {190, CANON_PLANE_YZ},
        {171, CANON_PLANE_UV}, {181, CANON_PLANE_UW}, {191, CANON_PLANE_VW}};
    for (const auto &m : map)
        if (m.g == g) s_.plane = m.p;
    out().select_plane(s_.plane);
}

// G20/G21 (step 17): convert the position and offsets, not the stored parameters.
void Interp::do_units(Block &b)
{
    INTERP_FRAME();
    int g = b.g_modes[GG_UNITS];
    if (g == -1) return;
    CanonUnits to = g == 200 ? CANON_UNITS_INCHES : CANON_UNITS_MM;
    convert_units(to);
    out().use_length_units(to);
}

// Switch program units, scaling every length the state holds.
void Interp::convert_units(CanonUnits to)
{
    INTERP_FRAME();
    if (to == s_.units) return;
    double k = to == CANON_UNITS_MM ? 25.4 : 1.0 / 25.4;
    static const int linear[] = {AX_X, AX_Y, AX_Z, AX_U, AX_V, AX_W};
    for (int i : linear) {
        s_.current[i] *= k;
        s_.origin_offset[i] *= k;
        s_.axis_offset[i] *= k;
        s_.tool_offset[i] *= k;
    }
    s_.comp_radius *= k;
    s_.cycle_il *= k;
    s_.units = to;
}

// G7/G8 (step 18).
void Interp::do_lathe_mode(Block &b)
{
    INTERP_FRAME();
    int g = b.g_modes[GG_LATHE];
    if (g == -1) return;
    bool dia = g == 70;
    if (dia != s_.lathe_diameter)
        out().comment(dia ? "interpreter: Lathe diameter mode changed to diameter"
                          : "interpreter: Lathe diameter mode changed to radius");
    s_.lathe_diameter = dia;
}

// G40/G41/G42/G41.1/G42.1 (step 19).
void Interp::do_comp(Block &b)
{
    INTERP_FRAME();
    int g = b.g_modes[GG_COMP];
    if (g == -1) return;
    if (g == 400) return comp_off();
    if (s_.comp_side != CANON_SIDE_OFF)
        throw InterpError("Cannot turn cutter radius comp on when on");
    if (s_.plane != CANON_PLANE_XY && s_.plane != CANON_PLANE_XZ)
        throw InterpError("Cutter radius compensation allowed only in XY, XZ planes");
    int orient = 0;
    double radius = g == 411 || g == 421 ? dynamic_comp_radius(b, g, orient)
                                         : tool_comp_radius(b, orient);
    if (radius < 0) {  // a negative table diameter compensates on the other side
        radius = -radius;
        g = g == 410 ? 420 : 410;
    }
    bool left = g == 410 || g == 411;
    out().comment(left ? "interpreter: cutter radius compensation on left"
                       : "interpreter: cutter radius compensation on right");
    if (!comp_) throw InterpError("Cutter radius compensation not supported");
    s_.comp_side = left ? CANON_SIDE_LEFT : CANON_SIDE_RIGHT;
    s_.comp_radius = radius;
    s_.comp_orientation = orient;
    s_.comp_code = g;
    comp_->start(s_);
}

// G40: comp off (the engine leaves from the last compensated point).
void Interp::comp_off()
{
    out().comment("interpreter: cutter radius compensation off");
    if (comp_ && s_.comp_side != CANON_SIDE_OFF) comp_->stop(s_);
    s_.comp_side = CANON_SIDE_OFF;
    s_.comp_code = 400;
}

// G41.1/G42.1: radius from the D diameter (a negative one swaps the side), L orientation.
double Interp::dynamic_comp_radius(const Block &b, int &g, int &orient) const
{
    if (b.word('l') && s_.plane != CANON_PLANE_XZ)
        throw InterpError("G41.1 with L word, but plane is not G18");
    double dia = b.word('d') ? b.value('d') : 0.0;
    if (dia < 0) g = g == 411 ? 421 : 411;
    orient = b.word('l') ? clamp_int(b.value('l')) : 0;
    return std::fabs(dia) / 2.0;
}

// G41/G42: radius and orientation of tool D (D0 or none: the loaded tool).
double Interp::tool_comp_radius(const Block &b, int &orient) const
{
    int tool = b.word('d') ? clamp_int(b.value('d')) : 0;
    int index = tool == 0 ? 0 : find_tool_index(tool);
    if (index < 0)
        throw InterpError("Requested tool " + std::to_string(tool) + " not found in the tool table");
    orient = s_.tools[index].orientation;
    return s_.user_to_program(s_.tools[index].diameter) / 2.0;
}

// Tool-data index of a block's H word (none, or H0 on a non-random changer: the loaded tool;
// a random changer's H0 names tool 0, which must be in the table).
int Interp::h_word_index(const Block &b) const
{
    if (!b.word('h')) return 0;
    int h = clamp_int(b.value('h'));
    int index = h == 0 && !s_.settings.random_toolchanger ? 0 : find_tool_index(h);
    if (index < 0)
        throw InterpError("Requested tool " + std::to_string(h) + " not found in the tool table");
    return index;
}

// G43/G43.1/G43.2/G49 (step 20).
void Interp::do_tool_length(Block &b)
{
    INTERP_FRAME();
    int g = b.g_modes[GG_TOOL_LENGTH];
    if (g == -1) return;
    if (s_.comp_side != CANON_SIDE_OFF)
        throw InterpError("Cannot change tool offset with cutter radius compensation on");
    Pose tlo{};
    if (g == 430) tlo = tool_pose(s_.tools[h_word_index(b)]);
    if (g == 431 || g == 432) tlo = tlo_words(b, g);
    s_.tlo_code = g;
    apply_tlo(tlo);
}

// G43.1 (axis words replace) and G43.2 (H tool or axis words add to) the active offset.
Pose Interp::tlo_words(const Block &b, int g) const
{
    static const char axes[] = "xyzabc";
    bool any = false;
    for (int i = 0; i < 6; i++) any = any || b.word(axes[i]);
    if (g == 432 && any && b.word('h')) throw InterpError("G43.2: Can not have both H and axis words");
    if (g == 432 && !any && !b.word('h')) throw InterpError("G43.2: No axes specified and H word missing");
    Pose tlo = s_.tool_offset;
    Pose add = g == 432 && !any ? tool_pose(s_.tools[h_word_index(b)]) : Pose{};
    for (int i = 0; i < 6; i++) {
        if (!b.word(axes[i])) continue;
        (g == 431 ? tlo[i] : add[i]) = b.value(axes[i]);
    }
    for (int i = 0; i < AX_COUNT; i++) tlo[i] += add[i];
    return tlo;
}

// Make tlo the active tool length offset: adjust the position, emit, update #5081-#5089.
void Interp::apply_tlo(const Pose &tlo)
{
    INTERP_FRAME();
    Pose m = program_to_machine_pose(s_.current);
    s_.tool_offset = tlo;
    s_.current = machine_to_program_pose(m);
    out().use_tool_length_offset(to_canon_pose(tlo));
    for (int i = 0; i < AX_COUNT; i++)
        s_.params[5081 + i] = (i >= AX_A && i <= AX_C) ? tlo[i] : s_.program_to_user(tlo[i]);
}

// G54..G59.3 (step 21).
void Interp::do_coord_system(Block &b)
{
    INTERP_FRAME();
    int g = b.g_modes[GG_COORD];
    if (g == -1) return;
    if (s_.comp_side != CANON_SIDE_OFF)
        throw InterpError("Cannot change coordinate systems with cutter radius compensation on");
    int index = g < 590 ? (g - 530) / 10 : 6 + (g - 590);
    if (index == s_.origin_index) {
        out().comment("interpreter: continuing to use same coordinate system");
        return;
    }
    set_origin_index(index);
    emit_g5x();
    emit_g92();
    out().set_xy_rotation(s_.rotation_xy);
}

// G61/G61.1/G64 (step 22).
void Interp::do_path_control(Block &b)
{
    INTERP_FRAME();
    int g = b.g_modes[GG_PATH];
    if (g == -1) return;
    if (s_.comp_side != CANON_SIDE_OFF)
        throw InterpError("Cannot change control mode with cutter radius compensation on");
    if (g != 640) {
        s_.control_mode = g == 610 ? CANON_EXACT_PATH : CANON_EXACT_STOP;
        out().set_motion_control_mode(s_.control_mode, 0);
        return;
    }
    if (b.word('r')) {
        double r = b.value('r');
        if (r <= 0)
            out().set_planner_mode(0, -1);
        else
            out().set_planner_mode(1, std::min(1.0, std::max(0.1, r)));
    }
    double p = b.word('p') ? b.value('p') : 0.0;
    double q = b.word('q') ? b.value('q') : b.word('p') ? p : 0.0;
    s_.control_mode = CANON_CONTINUOUS;
    s_.tolerance = p;
    s_.naivecam_tolerance = q;
    out().set_motion_control_mode(CANON_CONTINUOUS, p);
    out().set_naivecam_tolerance(q);
}

// G90/G91 and G90.1/G91.1 (steps 23, 24).
void Interp::do_distance(Block &b)
{
    INTERP_FRAME();
    int g = b.g_modes[GG_DISTANCE];
    if (g != -1) {
        bool inc = g == 910;
        if (inc != s_.distance_incremental)
            out().comment(inc ? "interpreter: distance mode changed to incremental"
                              : "interpreter: distance mode changed to absolute");
        s_.distance_incremental = inc;
    }
    g = b.g_modes[GG_IJK];
    if (g != -1) {
        bool abs = g == 901;
        if (abs != s_.ijk_absolute)
            out().comment(abs ? "interpreter: IJK distance mode changed to absolute"
                              : "interpreter: IJK distance mode changed to incremental");
        s_.ijk_absolute = abs;
    }
}

// G98/G99 (step 25).
void Interp::do_retract(Block &b)
{
    INTERP_FRAME();
    int g = b.g_modes[GG_RETRACT];
    if (g == -1) return;
    if (s_.comp_side != CANON_SIDE_OFF)
        throw InterpError("Cannot change retract mode with cutter radius compensation on");
    s_.retract = g == 980 ? RETRACT_OLD_Z : RETRACT_R_PLANE;
    out().comment(g == 980 ? "interpreter: retract mode set to old_z"
                           : "interpreter: retract mode set to r_plane");
}
