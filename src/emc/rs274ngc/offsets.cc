// offsets.cc: work offsets (G10 L2/L20, G54..), G52/G92 family and program<->machine conversion.
#include <cmath>

#include "interp.hh"

namespace {

constexpr double DEG = M_PI / 180.0;
const char AXES[] = "xyzabcuvw";

// true for the rotary axes, whose values are never unit-converted
bool rotary(int i) { return i >= AX_A && i <= AX_C; }

// stored value v of axis i in program units (LinuxCNC's arithmetic; rotary values as they are)
double user_len(const InterpState &s, int i, double v) { return rotary(i) ? v : s.user_to_program(v); }

// program value v of axis i in the stored machine units
double prog_len(const InterpState &s, int i, double v) { return rotary(i) ? v : s.program_to_user(v); }

} // namespace

// machine = Rot(R)(program + g92) + g5x + tlo, all in program units.
Pose Interp::program_to_machine_pose(const Pose &p) const
{
    INTERP_FRAME();
    Pose m;
    for (int i = 0; i < AX_COUNT; i++) m[i] = p[i] + s_.axis_offset[i];
    if (s_.rotation_xy != 0.0) {
        double c = std::cos(s_.rotation_xy * DEG), sn = std::sin(s_.rotation_xy * DEG);
        double x = m[0] * c - m[1] * sn, y = m[0] * sn + m[1] * c;
        m[0] = x;
        m[1] = y;
    }
    for (int i = 0; i < AX_COUNT; i++) m[i] += s_.origin_offset[i] + s_.tool_offset[i];
    return m;
}

// Inverse of program_to_machine_pose.
Pose Interp::machine_to_program_pose(const Pose &m) const
{
    INTERP_FRAME();
    Pose p;
    for (int i = 0; i < AX_COUNT; i++) p[i] = m[i] - s_.origin_offset[i] - s_.tool_offset[i];
    if (s_.rotation_xy != 0.0) {
        double c = std::cos(-s_.rotation_xy * DEG), sn = std::sin(-s_.rotation_xy * DEG);
        double x = p[0] * c - p[1] * sn, y = p[0] * sn + p[1] * c;
        p[0] = x;
        p[1] = y;
    }
    for (int i = 0; i < AX_COUNT; i++) p[i] -= s_.axis_offset[i];
    return p;
}

// Emit SET_G5X_OFFSET for the active system.
void Interp::emit_g5x()
{
    INTERP_FRAME();
    out().set_g5x_offset(s_.origin_index, to_canon_pose(s_.origin_offset));
}

// Emit SET_G92_OFFSET.
void Interp::emit_g92()
{
    INTERP_FRAME();
    out().set_g92_offset(to_canon_pose(s_.axis_offset));
}

// Make system index (1..9) active, keeping the machine position.
void Interp::set_origin_index(int index)
{
    INTERP_FRAME();
    Pose m = program_to_machine_pose(s_.current);
    s_.origin_index = index;
    s_.params[5220] = index;
    for (int i = 0; i < AX_COUNT; i++)
        s_.origin_offset[i] = user_len(s_, i, s_.params[5201 + 20 * index + i]);
    s_.rotation_xy = s_.params[5210 + 20 * index];
    s_.current = machine_to_program_pose(m);
}

// Group 0 codes except motion-like ones (step 26).
void Interp::do_nonmodal(Block &b)
{
    INTERP_FRAME();
    int g = b.g_modes[GG_NONMODAL];
    if (g == 100) g10(b);
    if (g == 520 || g == 920) g92_family(g, b);
}

// G92.1/.2/.3 (step 27).
void Interp::do_g92_family(Block &b)
{
    INTERP_FRAME();
    int g = b.g_modes[GG_G92];
    if (g != -1) g92_family(g, b);
}

// G52/G92: set the offsets of the axes given; the current point moves by the offset change
// (G92: the current point gets the given values).
void Interp::g92_set(int code, const Block &b)
{
    bool any = false;
    for (int i = 0; i < 6; i++) any = any || b.word(AXES[i]);
    if (!any) throw InterpError("All axes missing with g52 or g92");
    for (int i = 0; i < 6; i++) {
        if (!b.word(AXES[i])) continue;
        double v = axis_word(b, i);
        double old = s_.axis_offset[i];
        s_.axis_offset[i] = code == 520 ? v : s_.current[i] + old - v;
        s_.current[i] = code == 520 ? s_.current[i] + old - v : v;
    }
    s_.params[5210] = 1;
}

// G52, G92, G92.1, G92.2, G92.3.
void Interp::g92_family(int code, const Block &b)
{
    INTERP_FRAME();
    if (s_.comp_side != CANON_SIDE_OFF)
        throw InterpError("Cannot change axis offsets with cutter radius comp");
    if (code == 520 || code == 920) g92_set(code, b);
    Pose stored;
    for (int i = 0; i < AX_COUNT; i++) stored[i] = user_len(s_, i, s_.params[5211 + i]);
    if (code >= 921) {
        Pose next = code == 923 ? stored : Pose{};
        for (int i = 0; i < AX_COUNT; i++) s_.current[i] += s_.axis_offset[i] - next[i];
        s_.axis_offset = next;
        s_.params[5210] = code == 923 ? 1 : 0;
    }
    if (code != 922)
        for (int i = 0; i < AX_COUNT; i++)
            s_.params[5211 + i] = prog_len(s_, i, s_.axis_offset[i]);
    emit_g92();
}

// G10: dispatch on L.
void Interp::g10(const Block &b)
{
    INTERP_FRAME();
    int l = b.word('l') ? clamp_int(b.value('l')) : -1;
    if (l == 2 || l == 20) return g10_l2(b, l);
    if (l == 0 || l == 1 || l == 10 || l == 11) return g10_tool(b, l);
    throw InterpError("Line with G10 does not have L0, L1, L10, L11, L2, or L20");
}

// G10 L2/L20: set a work offset (and rotation).
void Interp::g10_l2(const Block &b, int l)
{
    INTERP_FRAME();
    int index = g10_system(b);
    Pose m = program_to_machine_pose(s_.current);
    Pose offs;
    for (int i = 0; i < AX_COUNT; i++)
        offs[i] = user_len(s_, i, s_.params[5201 + 20 * index + i]);
    if (b.word('r')) s_.params[5210 + 20 * index] = b.value('r');
    double rot = s_.params[5210 + 20 * index];
    if (l == 20) {
        Pose q;
        for (int i = 0; i < AX_COUNT; i++) q[i] = m[i] - s_.tool_offset[i];
        offs = offsets_for_point(b, q, s_.axis_offset, offs, rot);
    } else {
        for (int i = 0; i < 6; i++)
            if (b.word(AXES[i])) offs[i] = axis_word(b, i);
    }
    for (int i = 0; i < AX_COUNT; i++)
        s_.params[5201 + 20 * index + i] = prog_len(s_, i, offs[i]);
    if (index != s_.origin_index) {
        out().comment("interpreter: setting coordinate system origin");
        return;
    }
    s_.origin_offset = offs;
    s_.rotation_xy = rot;
    s_.current = machine_to_program_pose(m);
    emit_g5x();
    out().set_xy_rotation(s_.rotation_xy);
}

// The coordinate system a G10 L2/L20 P word names (P0: the active one).
int Interp::g10_system(const Block &b) const
{
    if (!b.word('p')) throw InterpError("P word missing with G10 L2");
    double pv = b.value('p');
    int p = clamp_int(pv);
    if (std::fabs(pv - p) > 0.0001 || p < 0 || p > 9)
        throw InterpError("P value out of range (0-9) with G10 L2");
    return p == 0 ? s_.origin_index : p;
}

// Value of axis word i of a block (X halved in lathe diameter mode).
double Interp::axis_word(const Block &b, int i) const
{
    double v = b.value(AXES[i]);
    return (i == AX_X && s_.lathe_diameter) ? v / 2.0 : v;
}

// G10 L10/L11/L20 arithmetic: the offset (machine frame, program units) that makes point q
// (machine frame, relative to that offset) read the block's axis values in a frame rotated by
// rot and shifted by shift; axes without a word keep the coordinate `old` gives them.
Pose Interp::offsets_for_point(const Block &b, Pose q, const Pose &shift, Pose old, double rot) const
{
    rotate_xy(q[AX_X], q[AX_Y], -rot);
    rotate_xy(old[AX_X], old[AX_Y], -rot);
    for (int i = 0; i < 6; i++)
        if (b.word(AXES[i])) old[i] = q[i] - shift[i] - axis_word(b, i);
    rotate_xy(old[AX_X], old[AX_Y], rot);
    return old;
}
