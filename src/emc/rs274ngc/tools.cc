// tools.cc: T, M6, M61, G10 L0/L1/L10/L11 and tool-table lookups (LinuxCNC's tool rules).
#include <cmath>

#include "interp.hh"

namespace {

const char AXES[] = "xyzabcuvw";

// set axis i of a canon pose
void pose_set(CanonPose &p, int i, double v)
{
    double *f[] = {&p.x, &p.y, &p.z, &p.a, &p.b, &p.c, &p.u, &p.v, &p.w};
    *f[i] = v;
}

} // namespace

// Tool-data index of tool number toolno (index 0 = spindle excluded), -1 if absent.
int Interp::find_tool_index(int toolno) const
{
    INTERP_FRAME();
    // a random changer's spindle (index 0) is a pocket too: its tool can be selected again
    for (size_t i = s_.settings.random_toolchanger ? 0 : 1; i < s_.tools.size(); i++)
        if (s_.tools[i].toolno == toolno) return (int)i;
    return -1;
}

// T word (step 8).
void Interp::do_select_tool(Block &b)
{
    INTERP_FRAME();
    if (!b.word('t')) return;
    int t = clamp_int(b.value('t'));
    // T0 unloads a non-random spindle; on a random changer tool 0 is a tool like any other
    int index = t == 0 && !s_.settings.random_toolchanger ? 0 : find_tool_index(t);
    if (index < 0)
        throw InterpError("Requested tool " + std::to_string(t) + " not found in the tool table");
    out().select_tool(t);
    s_.selected_tool = t;
    s_.selected_pocket = index;
}

// M6 / M61 (step 10); returns true when the block must end with execute-finish.
bool Interp::do_tool_change(Block &b)
{
    INTERP_FRAME();
    int m = b.m_modes[MG_TOOL];
    if (m == -1) return false;
    if (s_.comp_side != CANON_SIDE_OFF)
        throw InterpError("Cannot change tools with cutter radius compensation on");
    if (m == 61) {
        set_tool_number(b);
        return true;
    }
    if (s_.selected_pocket < 0) throw InterpError("Need tool prepared -Txx- for toolchange");
    tool_change_moves();
    out().change_tool();
    int index = s_.selected_pocket;
    if (index > 0 && index < (int)s_.tools.size()) s_.tools[0] = s_.tools[index];
    if (index == 0) load_empty_spindle();
    s_.current_pocket = index;
    if (s_.settings.retain_g43 && s_.tlo_code == 430) reapply_tool_length();
    return true;
}

// M61 Qn: declare tool n loaded without moving anything.
void Interp::set_tool_number(const Block &b)
{
    if (!b.word('q') || b.value('q') < 0)
        throw InterpError("Need non-negative Q-word to specify tool number with M61");
    int q = clamp_int(b.value('q'));
    int index = q == 0 ? 0 : find_tool_index(q);
    if (index < 0)
        throw InterpError("Requested tool " + std::to_string(q) + " not found in the tool table");
    out().change_tool_number(index);
    s_.current_pocket = index;
    // the spindle slot takes the tool's whole entry (G43 without H and #5400-#5413 use it);
    // M61 Q0 empties it
    if (index > 0) s_.tools[0] = s_.tools[index];
    else load_empty_spindle();
}

// T0 M6 or M61 Q0: the spindle holds no tool (number 0, no offsets).
void Interp::load_empty_spindle()
{
    CanonTool none;
    none.toolno = 0;
    s_.tools[0] = none;
}

// Spindle stop, quill-up move and G30 move that the INI settings ask for before an M6.
void Interp::tool_change_moves()
{
    if (!s_.settings.tool_change_with_spindle_on) {
        for (int sp = 0; sp < s_.num_spindles; sp++) {
            out().stop_spindle_turning(sp);
            s_.spindle_dir[sp] = CANON_STOPPED;
        }
    }
    if (s_.settings.tool_change_quill_up) {
        out().comment("AXIS,hide");
        Pose p = s_.current;
        p[AX_Z] = 0.0 - s_.tool_offset[AX_Z];
        out().straight_traverse(-1, to_canon_pose(p));
        s_.current = p;
        out().comment("AXIS,show");
    }
    if (s_.settings.tool_change_at_g30) {
        out().comment("AXIS,hide");
        Pose m = program_to_machine_pose(s_.current);
        for (int i = 0; i < AX_COUNT; i++) {
            double v = s_.params[PARAM_G30_HOME + i];
            m[i] = (i >= AX_A && i <= AX_C) ? v : s_.user_to_program(v);
        }
        s_.current = machine_to_program_pose(m);
        out().straight_traverse(-1, to_canon_pose(s_.current));
        out().comment("AXIS,show");
    }
}

// RETAIN_G43: after M6 with G43 active, apply the new tool's length offset.
void Interp::reapply_tool_length()
{
    Pose tlo{};
    if (s_.selected_tool != 0) tlo = tool_pose(s_.tools[0]);
    apply_tlo(tlo);
    if (s_.selected_tool != 0) out().use_tool_length_offset(to_canon_pose(tlo));
}

// G10 L0: reload the tool data (only with no tool in the spindle).
void Interp::g10_reload_tools()
{
    INTERP_FRAME();
    if (!s_.tools.empty() && s_.tools[0].toolno > 0)
        throw InterpError("G10 L0 not allowed with loaded tool " +
                          std::to_string(s_.tools[0].toolno) + "\n");
    out().reload_tooldata();
}

// Tool entry `t`'s offsets in program units (machine frame).
Pose Interp::tool_pose(const CanonTool &t) const
{
    const CanonPose &o = t.offset;
    auto len = [this](double v) { return s_.user_to_program(v); };
    return Pose{len(o.x), len(o.y), len(o.z), o.a, o.b, o.c, len(o.u), len(o.v), len(o.w)};
}

// The new offsets of G10 L1 (given values), L10 (current point reads the values) or L11
// (current point reads the values in G59.3 without G52/G92), program units.
Pose Interp::g10_tool_offsets(const Block &b, int l, const CanonTool &t) const
{
    Pose old = tool_pose(t);
    if (l == 1) {
        for (int i = 0; i < 6; i++)
            if (b.word(AXES[i])) old[i] = b.value(AXES[i]);
        return old;
    }
    Pose m = program_to_machine_pose(s_.current);
    const int base = l == 10 ? 5201 + 20 * s_.origin_index : 5381;
    Pose q;
    for (int i = 0; i < AX_COUNT; i++) {
        double v = s_.params[base + i];
        q[i] = m[i] - ((i >= AX_A && i <= AX_C) ? v : s_.user_to_program(v));
    }
    Pose shift = l == 10 ? s_.axis_offset : Pose{};
    return offsets_for_point(b, q, shift, old, s_.params[base + 9]);
}

// The tool-data index a G10 L1/L10/L11 P word names; L1 must set something.
int Interp::g10_tool_index(const Block &b, int l) const
{
    int p = b.word('p') ? clamp_int(b.value('p')) : 0;
    int index = p > 0 ? find_tool_index(p) : -1;
    if (index < 0) throw InterpError("P value out of range with G10 L" + std::to_string(l));
    bool any = b.word('r') || b.word('i') || b.word('j') || b.word('q');
    for (int i = 0; i < 6; i++) any = any || b.word(AXES[i]);
    if (!any && l == 1) throw InterpError("G10 L1 without offsets has no effect");
    return index;
}

// G10 L0, L1, L10, L11: tool table edits.
void Interp::g10_tool(const Block &b, int l)
{
    INTERP_FRAME();
    if (l == 0) return g10_reload_tools();
    if (s_.comp_side != CANON_SIDE_OFF)
        throw InterpError("Cannot change tool table with cutter radius compensation on");
    int index = g10_tool_index(b, l);
    CanonTool t = s_.tools[index];
    Pose offs = g10_tool_offsets(b, l, t);
    for (int i = 0; i < AX_COUNT; i++)
        pose_set(t.offset, i, (i >= AX_A && i <= AX_C) ? offs[i] : s_.program_to_user(offs[i]));
    if (b.word('r')) t.diameter = s_.program_to_user(2.0 * b.value('r'));
    if (b.word('i')) t.frontangle = b.value('i');
    if (b.word('j')) t.backangle = b.value('j');
    if (b.word('q')) t.orientation = clamp_int(b.value('q'));
    store_tool_entry(index, t);
}

// Store an edited tool entry and emit it (again for index 0 when it is the loaded tool).
void Interp::store_tool_entry(int index, const CanonTool &t)
{
    s_.tools[index] = t;
    out().set_tool_table_entry(index, t);
    if (index == s_.current_pocket && !s_.settings.random_toolchanger) {
        s_.tools[0] = t;
        out().set_tool_table_entry(0, t);
    }
}
