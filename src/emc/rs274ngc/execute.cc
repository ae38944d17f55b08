// execute.cc: executes one block in the order of gcode.md §3 and checks word usage (§2).
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

// Execute a parsed block.
InterpStatus Interp::execute_block(Block &b)
{
    INTERP_FRAME();
    BlockScope scope(current_block_, &b);
    for (auto &a : b.num_assign) s_.params[a.first] = a.second;
    for (auto &a : b.named_assign) set_named(a.first, a.second);
    if (b.o_kind != O_NONE) return execute_oword(b);
    if (b.o_fanuc) return fanuc_label(b);
    check_block(b);
    if (b.m98) { fanuc_call(b); return INTERP_OK; }
    check_remap_args(b);
    return run_steps(b, 0, false);
}

// Check axis-word and modal-group combination rules of gcode.md §2 and words without users.
void Interp::check_block(Block &b)
{
    INTERP_FRAME();
    int g0 = b.g_modes[GG_NONMODAL];
    int motion = b.g_modes[GG_MOTION];
    bool axes = has_axis(b);
    bool g0_axes = g0_uses_axes(g0);
    if (g0_axes && motion != -1 && motion != 800)
        throw InterpError("Cannot use two g codes that both use axis values");
    if (motion == 800 && axes && !g0_axes)
        throw InterpError("Cannot use axis values with g80");
    int tl = b.g_modes[GG_TOOL_LENGTH];
    bool tl_axes = tl == 431 || tl == 432;
    if (axes && !g0_axes && !tl_axes && motion == -1 && s_.motion_mode == 800)
        throw InterpError("Cannot use axis values without a g code that uses them");
    if ((b.has_polar_radius || b.has_polar_angle) && b.word('x'))
        throw InterpError("Cannot specify both polar coordinate and X word");
    if ((b.has_polar_radius || b.has_polar_angle) && b.word('y'))
        throw InterpError("Cannot specify both polar coordinate and Y word");
    if (g0 == 530) {
        int m = motion != -1 ? motion : s_.motion_mode;
        if (m != 0 && m != 10) throw InterpError("Must use g0 or g1 with g53");
        if (s_.comp_side != CANON_SIDE_OFF)
            throw InterpError("Cannot use G53 with cutter radius comp");
    }
    check_words(b);
}

// Letters that need a code to use them.
void Interp::check_words(Block &b)
{
    INTERP_FRAME();
    int motion = b.g_modes[GG_MOTION] != -1 ? b.g_modes[GG_MOTION] : s_.motion_mode;
    int g0 = b.g_modes[GG_NONMODAL];
    int comp = b.g_modes[GG_COMP];
    int tl = b.g_modes[GG_TOOL_LENGTH];
    bool cycle = (motion >= 810 && motion <= 890) || motion == 730 || motion == 740;
    bool lathe = motion >= 700 && motion <= 722;
    if (b.word('d') && !(comp >= 410 || lathe || motion == 730 || motion == 830 ||
                         b.g_modes[GG_SPINDLE] == 960 || motion == 760))
        throw InterpError("D word with no G41, G41.1, G42, G42.1, G71, G71.1, G71.2 G73, G83 "
                          "or G96 to use it");
    if (b.word('h') && tl != 430 && tl != 432 && motion != 760)
        throw InterpError("H word with no G43 or G76 to use it");
    bool r_user = motion == 20 || motion == 30 || cycle || g0 == 100 || motion == 760 || lathe ||
                  b.m_modes[MG_SPINDLE] == 19 || b.g_modes[GG_PATH] == 640;
    if (b.word('r') && !r_user) throw InterpError("R word with no g code that uses it");
    if (b.word('r') && b.g_modes[GG_PATH] == 640 && b.m_modes[MG_SPINDLE] == 19)
        throw InterpError("R word is ambiguous on a line with both G64 and M19 - use separate lines");
    if (b.word('l') && !(g0 == 100 || cycle || motion == 760 || motion == 52 || comp == 411 || comp == 421 ||
                         b.m_modes[MG_IO] == 66 || lathe || b.m98))
        throw InterpError("L word with no G10, G76, cycle or M66 to use it");
    if (g0 == 40 && (motion == 20 || motion == 30) && b.g_modes[GG_MOTION] != -1)
        throw InterpError("G4 not allowed with G2 or G3 because they both use P");
}

// G96/G97 (step 4).
void Interp::do_spindle_mode(Block &b)
{
    INTERP_FRAME();
    int g = b.g_modes[GG_SPINDLE];
    if (g == -1) return;
    int sp = 0;
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
    int sp = b.has_dollar ? clamp_int(b.dollar) : 0;
    if (sp < 0 || sp >= s_.settings.spindles) throw InterpError("Invalid spindle ($) number");
    s_.speed[sp] = b.value('s');
    out().set_spindle_speed(sp, s_.speed[sp]);
}

// G4 dwell (step 15).
void Interp::do_dwell(Block &b)
{
    INTERP_FRAME();
    if (b.g_modes[GG_NONMODAL] != 40) return;
    if (!b.word('p') || b.value('p') < 0) throw InterpError("Dwell time missing with g4");
    out().dwell(b.value('p'));
}
