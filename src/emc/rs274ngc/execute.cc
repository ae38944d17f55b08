// execute.cc: executes one block in LinuxCNC's order of execution and checks word usage.
#include <cmath>

#include "interp.hh"

namespace {

// true when the block has any axis word (or polar word)
bool has_axis(const Block &b)
{
    return b.word('x') || b.word('y') || b.word('z') || b.word('a') || b.word('b') ||
           b.word('c') || b.has_polar_radius || b.has_polar_angle;
}

// group-0 codes that consume axis words
bool g0_uses_axes(int g)
{
    return g == 100 || g == 280 || g == 300 || g == 520 || g == 920;
}

} // namespace

// LinuxCNC's order of execution (comment through stop), with the remapped code each step may hand over.
const ExecStep EXEC_STEPS[] = {
    {&Interp::step_comment, SLOT_NONE, 0},       {&Interp::do_spindle_mode, SLOT_NONE, 0},
    {&Interp::do_feed_mode, SLOT_NONE, 0},       {&Interp::do_feed_rate, SLOT_F, 0},
    {&Interp::do_speed, SLOT_S, 0},              {&Interp::do_select_tool, SLOT_T, 0},
    {&Interp::do_io, SLOT_M, MG_IO},             {&Interp::step_tool_change, SLOT_M, MG_TOOL},
    {&Interp::do_spindle, SLOT_M, MG_SPINDLE},   {&Interp::do_coolant, SLOT_M, MG_COOLANT},
    {&Interp::do_overrides, SLOT_M, MG_OVERRIDE}, {&Interp::do_user_m, SLOT_M, MG_USER},
    {&Interp::do_dwell, SLOT_NONE, 0},           {&Interp::do_plane, SLOT_NONE, 0},
    {&Interp::do_units, SLOT_NONE, 0},           {&Interp::do_lathe_mode, SLOT_NONE, 0},
    {&Interp::do_comp, SLOT_NONE, 0},            {&Interp::do_tool_length, SLOT_NONE, 0},
    {&Interp::do_coord_system, SLOT_NONE, 0},    {&Interp::do_path_control, SLOT_NONE, 0},
    {&Interp::do_distance, SLOT_NONE, 0},        {&Interp::do_retract, SLOT_NONE, 0},
    {&Interp::do_nonmodal, SLOT_NONE, 0},        {&Interp::do_g92_family, SLOT_NONE, 0},
    {&Interp::step_motion, SLOT_G, GG_MOTION},   {&Interp::step_stop, SLOT_M, MG_STOP},
};
constexpr size_t EXEC_STEP_COUNT = sizeof EXEC_STEPS / sizeof EXEC_STEPS[0];

// The execution steps (remap_args.cc checks the remapped codes of a block against them).
const ExecStep *Interp::exec_steps(size_t &count)
{
    count = EXEC_STEP_COUNT;
    return EXEC_STEPS;
}

// Execute a parsed block.
InterpStatus Interp::execute_block(Block &b)
{
    INTERP_FRAME();
    BlockScope scope(current_block_, &b);
    for (auto &a : b.num_assign) s_.params[a.first] = a.second;
    for (auto &a : b.named_assign) set_named(a.first, a.second);
    if (b.o_kind != O_NONE) return execute_oword(b);
    if (b.o_fanuc) return fanuc_label(b);
    check_remap_args(b);
    check_block(b);
    if (b.m98) { fanuc_call(b); return INTERP_OK; }
    return execute_steps(b, 0);
}

// Run the block's steps from `first` on; a remapped code suspends the block at its step
// (the rest runs when its procedure returns).
InterpStatus Interp::execute_steps(Block &b, size_t first)
{
    INTERP_FRAME();
    BlockScope scope(current_block_, &b);
    for (size_t i = first; i < EXEC_STEP_COUNT; i++) {
        const ExecStep &st = EXEC_STEPS[i];
        const RemapDef *def = have_remaps_ && st.slot != SLOT_NONE ? remap_due(b, st) : nullptr;
        if (def) return start_remap(b, *def, i);
        (this->*st.run)(b);
        if (b.status != INTERP_OK) return (InterpStatus)b.status;
    }
    return b.execute_finish ? INTERP_EXECUTE_FINISH : INTERP_OK;
}

// Step 3: the comment or active comment, and a ;py, statement.
void Interp::step_comment(Block &b)
{
    if (b.has_comment) do_comment(b);
    if (!b.py_code.empty()) python_comment(b.py_code);
}

// Step 10: M6/M61; a tool change ends the block with execute-finish.
void Interp::step_tool_change(Block &b)
{
    if (do_tool_change(b)) b.execute_finish = true;
}

// Step 28: motion; a probe ends the block with execute-finish.
void Interp::step_motion(Block &b)
{
    if (do_motion(b)) b.execute_finish = true;
}

// Step 29: M0 M1 M2 M30 M60 M99.
void Interp::step_stop(Block &b)
{
    b.status = do_stop(b);
}

// Check axis-word and modal-group combination rules of LinuxCNC's modal groups and words without users.
void Interp::check_block(Block &b)
{
    INTERP_FRAME();
    check_axis_words(b);
    if ((b.has_polar_radius || b.has_polar_angle) && b.word('x'))
        throw InterpError("Cannot specify both polar coordinate and X word");
    if ((b.has_polar_radius || b.has_polar_angle) && b.word('y'))
        throw InterpError("Cannot specify both polar coordinate and Y word");
    if (b.g_modes[GG_NONMODAL] == 530) {
        int motion = b.motion() != -1 ? b.motion() : s_.motion_mode;
        if (motion != 0 && motion != 10) throw InterpError("Must use g0 or g1 with g53");
        if (s_.comp_side != CANON_SIDE_OFF)
            throw InterpError("Cannot use G53 with cutter radius comp");
    }
    check_words(b);
}

// Axis words need exactly one code that uses them.
void Interp::check_axis_words(const Block &b) const
{
    int motion = b.motion();
    bool axes = has_axis(b);
    bool g0_axes = g0_uses_axes(b.g_modes[GG_NONMODAL]);
    if (g0_axes && motion != -1 && motion != 800)
        throw InterpError("Cannot use two g codes that both use axis values");
    if (motion == 800 && axes && !g0_axes)
        throw InterpError("Cannot use axis values with g80");
    int tl = b.g_modes[GG_TOOL_LENGTH];
    bool tl_axes = tl == 431 || tl == 432;
    if (axes && !g0_axes && !tl_axes && motion == -1 && s_.motion_mode == 800)
        throw InterpError("Cannot use axis values without a g code that uses them");
}

// G96/G97 (step 4).
void Interp::do_spindle_mode(Block &b)
{
    INTERP_FRAME();
    int g = b.g_modes[GG_SPINDLE];
    if (g == -1) return;
    int sp = s_.spindle_of(b);
    if (g == 960) {
        double max = b.word('d') ? b.value('d') : 1e30;
        s_.css_mode[sp] = true;
        s_.css_max[sp] = max;
        out().set_spindle_mode(sp, max);
    } else {
        s_.css_mode[sp] = false;
        out().set_spindle_mode(sp, 0);
    }
}

// G93/G94/G95 (step 5).
void Interp::do_feed_mode(Block &b)
{
    INTERP_FRAME();
    int g = b.g_modes[GG_FEED];
    if (g == -1) return;
    if (g == 930) {
        out().comment("interpreter: feed mode set to inverse time");
        s_.feed_mode = FEED_INVERSE_TIME;
        out().set_feed_mode(0, 0);
        return;
    }
    bool rev = g == 950;
    out().comment(rev ? "interpreter: feed mode set to units per revolution"
                      : "interpreter: feed mode set to units per minute");
    s_.feed_mode = rev ? FEED_UNITS_PER_REV : FEED_UNITS_PER_MINUTE;
    out().set_feed_mode(0, rev ? 1 : 0);
    s_.feed_rate = 0;
    out().set_feed_rate(0);
}

// F word (step 6); in G93 F is used per move.
void Interp::do_feed_rate(Block &b)
{
    INTERP_FRAME();
    if (!b.word('f')) return;
    s_.feed_rate = b.value('f');
    if (s_.feed_mode != FEED_INVERSE_TIME) out().set_feed_rate(s_.feed_rate);
}

// S word (step 7).
void Interp::do_speed(Block &b)
{
    INTERP_FRAME();
    if (!b.word('s')) return;
    int sp = s_.spindle_of(b);
    s_.speed[sp] = b.value('s');
    out().set_spindle_speed(sp, s_.speed[sp]);
}

// G4 dwell (step 15).
void Interp::do_dwell(Block &b)
{
    INTERP_FRAME();
    if (b.g_modes[GG_NONMODAL] != 40) return;
    if (!b.word('p')) throw InterpError("Dwell time missing with g4");
    if (b.value('p') < 0) throw InterpError("Negative dwell time used with g4");
    out().dwell(b.value('p'));
}
