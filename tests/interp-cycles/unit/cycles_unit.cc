// cycles_unit.cc: drives the canned cycles and G76 from a script on stdin and prints the canon calls.
#include <string>

#include "emc/rs274ngc/interp_hooks.hh"
#include "record_canon.hh"
#include "script_block.hh"
#include "script_run.hh"

// apply one modal G code of the script to the state; true when it is a cycle motion code
static bool apply_g(InterpState &s, int g)
{
    switch (g) {
    case 170: s.plane = CANON_PLANE_XY; return false;
    case 180: s.plane = CANON_PLANE_XZ; return false;
    case 190: s.plane = CANON_PLANE_YZ; return false;
    case 171: s.plane = CANON_PLANE_UV; return false;
    case 70: s.lathe_diameter = true; return false;
    case 80: s.lathe_diameter = false; return false;
    case 610: s.control_mode = CANON_EXACT_PATH; return false;
    case 640: s.control_mode = CANON_CONTINUOUS; return false;
    case 900: s.distance_incremental = false; return false;
    case 910: s.distance_incremental = true; return false;
    case 980: s.retract = RETRACT_OLD_Z; return false;
    case 990: s.retract = RETRACT_R_PLANE; return false;
    default: break;
    }
    if (g == 730 || g == 740 || g == 760 || (g >= 810 && g <= 890)) {
        s.motion_mode = g;
        return true;
    }
    return false;
}

// "g0 x y z": jump the current point there without output, ending any cycle sequence
static void position(InterpState &s, const Block &b)
{
    take_axis_words(b, s.current);
    s.motion_mode = 0;
    s.cycle_last = -1;
    s.cycle_il_valid = false;
}

// spindle direction from M3/M4/M5
static void apply_m(InterpState &s, int m)
{
    if (m == 3) s.spindle_dir[0] = CANON_CLOCKWISE;
    if (m == 4) s.spindle_dir[0] = CANON_COUNTERCLOCKWISE;
    if (m == 5) s.spindle_dir[0] = CANON_STOPPED;
}

// run one script line: modal words, then the cycle when the line has one or axis words
static void run_line(InterpState &s, RecordCanon &canon, const std::string &text)
{
    ScriptLine sl = parse_script_line(text);
    bool cycle = false;
    for (int g : sl.g) {
        if (g == 0) {
            position(s, sl.block);
            return;
        }
        cycle |= apply_g(s, g);
    }
    for (int m : sl.m)
        apply_m(s, m);
    if (sl.block.word('f'))
        s.feed_rate = sl.block.value('f');
    bool axes = false;
    for (char c : {'x', 'y', 'z', 'u', 'v', 'w'})
        axes |= sl.block.word(c);
    if (!cycle && !(axes && s.motion_mode >= 730))
        return;
    sl.block.g_modes[GG_MOTION] = s.motion_mode;
    if (s.motion_mode == 760)
        cycles::execute_g76(s, sl.block, canon);
    else
        cycles::execute(s, sl.block, canon);
}

// read script lines; '#' lines are echoed, errors printed
int main()
{
    InterpState s;
    s.peck_clearance_g73 = 0.05;
    s.peck_clearance_g83 = 0.1;
    s.feed_rate = 10;
    RecordCanon canon;
    return run_script(
        std::cin, [&](const std::string &line) { run_line(s, canon, line); }, [] {});
}
