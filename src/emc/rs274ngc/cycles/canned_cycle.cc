// canned_cycle.cc: one G73/G74/G81..G89 block: word checks, sticky words, positioning, repeats (LinuxCNC's canned cycles).
#include <cmath>
#include <string>

#include "../interp_hooks.hh"
#include "cycle_bodies.hh"
#include "../polar.hh"

namespace cycles {

// "g82" style name of motion code ×10
static std::string code_name(int code)
{
    return "g" + std::to_string(code / 10);
}

// value of word c, G7-halved when c is the X word in diameter mode
static double axis_word(const InterpState &s, const Block &b, char c)
{
    double v = b.value(c);
    return (c == 'x' && s.lathe_diameter) ? v / 2 : v;
}

// word c of this block, else the sticky value of the previous block of the same cycle, else error
static double sticky(const Block &b, char c, bool same, double saved, const std::string &err)
{
    if (b.word(c))
        return b.value(c);
    if (!same)
        throw InterpError(err);
    return saved;
}

// rotary axis words are not allowed in canned cycles
static void check_rotary(const Block &b)
{
    for (char c : {'a', 'b', 'c'})
        if (b.word(c))
            throw InterpError(std::string(c == 'a' ? "Cannot put an " : "Cannot put a ") + c +
                              " in canned cycle");
}

// number of repeats from the L word (default 1)
static int repeats(const Block &b)
{
    if (!b.word('l'))
        return 1;
    int l = (int)std::lround(b.value('l'));
    if (l < 0)
        throw InterpError("Cannot do negative repeats of cycle");
    if (l == 0)
        throw InterpError("Cannot do zero repeats of cycle");
    return l;
}

// spindle direction checks of the tapping and boring cycles
static void check_spindle(int code, CanonDirection dir)
{
    if (code == 840 && dir != CANON_CLOCKWISE)
        throw InterpError("Spindle not turning clockwise in G84");
    if (code == 740 && dir == CANON_CLOCKWISE)
        throw InterpError("Spindle turning clockwise in G74");
    if (code == 740 && dir != CANON_COUNTERCLOCKWISE)
        throw InterpError("Spindle not turning in G74");
    if ((code == 860 || code == 870 || code == 880) && dir == CANON_STOPPED)
        throw InterpError("Spindle not turning in G" + std::to_string(code / 10));
}

// P (dwell) and Q (peck) words, sticky within one cycle code
static void dwell_and_peck(InterpState &s, const Block &b, int code, bool same, Hole &h)
{
    std::string name = code_name(code);
    if (code == 820 || code == 860 || code == 880 || code == 890)
        h.dwell = sticky(b, 'p', same, s.cycle_p, "Dwell time p word missing with " + name);
    else if (b.word('p'))
        h.dwell = b.value('p');
    if (h.dwell < 0)
        throw InterpError("Negative dwell time used with " + name);
    s.cycle_p = h.dwell;
    if (code == 730 || code == 830) {
        h.peck = sticky(b, 'q', same, s.cycle_q, "Q word missing with " + name);
        if (h.peck <= 0)
            throw InterpError("Negative or zero q value used");
        s.cycle_q = h.peck;
        double c = code == 730 ? s.peck_clearance_g73 : s.peck_clearance_g83;
        h.peck_clearance = b.word('d') ? b.value('d') : c;
    }
}

// G87 offsets and back-bore level
static void back_bore_words(const Block &b, int code, Hole &h)
{
    if (code != 870)
        return;
    for (char c : {'i', 'j', 'k'})
        if (!b.word(c))
            throw InterpError(std::string(1, (char)(c - 32)) + " word missing with g87");
    h.i = b.value('i');
    h.j = b.value('j');
    h.k = b.value('k');
}

// R and depth levels in absolute depth-axis coordinates (G91: R from the initial level, depth from R)
static void levels(InterpState &s, const Block &b, const PlaneAxes &ax, bool same, Hole &h)
{
    char dl = axis_letter(ax.cc);
    double r = sticky(b, 'r', same, s.cycle_r, "R clearance plane unspecified in cycle");
    std::string zerr = std::string(1, (char)(dl - 32)) + " value unspecified in " +
                       ax.plane_name + " plane canned cycle";
    double z = b.word(dl) ? axis_word(s, b, dl) : sticky(b, dl, same, s.cycle_z, zerr);
    s.cycle_r = r;
    s.cycle_z = z;
    if (!s.cycle_il_valid) {
        s.cycle_il = s.current[ax.cc];
        s.cycle_il_valid = true;
    }
    h.r = s.distance_incremental ? s.cycle_il + r : r;
    h.bottom = s.distance_incremental ? h.r + z : z;
    if (h.r < h.bottom)
        throw InterpError(std::string("R less than ") + dl + " in cycle in " + ax.plane_name +
                          " plane");
}

// most pecks one G73/G83 hole may take; more means Q is far too small for the depth
static const double MAX_PECKS = 100000;

// refuse a peck count that would flood the motion queue
static void check_pecks(int code, const Hole &h)
{
    if ((code == 730 || code == 830) && (h.r - h.bottom) / h.peck > MAX_PECKS)
        throw InterpError("G" + std::to_string(code / 10) +
                          ": Q is too small for the hole depth (more than " +
                          std::to_string((long)MAX_PECKS) + " pecks)");
}

// where hole n (0-based) is: G90 at the words (or current point), G91 stepping by them;
// polar words are applied again for every repeat (G91: around the origin)
static void hole_position(const InterpState &s, const Block &b, const PlaneAxes &ax, Hole &h)
{
    if (b.has_polar_radius || b.has_polar_angle) {
        if (s.plane != CANON_PLANE_XY) throw InterpError("Polar coordinates only in the XY plane");
        h.a = s.current[AX_X];
        h.b = s.current[AX_Y];
        polar_point(b, s.distance_incremental, h.a, h.b);
        return;
    }
    char la = axis_letter(ax.aa), lb = axis_letter(ax.bb);
    if (s.distance_incremental) {
        h.a = s.current[ax.aa] + (b.word(la) ? axis_word(s, b, la) : 0);
        h.b = s.current[ax.bb] + (b.word(lb) ? axis_word(s, b, lb) : 0);
    } else {
        h.a = b.word(la) ? axis_word(s, b, la) : s.current[ax.aa];
        h.b = b.word(lb) ? axis_word(s, b, lb) : s.current[ax.bb];
    }
}

// move from the current point to the R plane above hole h
static void position(CycleMoves &mv, const Hole &h, bool first)
{
    if (first && mv.cur(mv.axes().cc) > h.r) {
        mv.rapid(h.a, h.b, mv.cur(mv.axes().cc));
        mv.rapid_depth(h.r);
        return;
    }
    mv.rapid(h.a, h.b, h.clear);
    if (h.clear > h.r)
        mv.rapid_depth(h.r);
}

// run all repeats of the cycle inside the exact-path bracket
static void run_holes(InterpState &s, const Block &b, Canon &c, CycleMoves &mv, Hole &h, int code)
{
    bool bracket = s.control_mode != CANON_EXACT_PATH;
    if (bracket)
        c.set_motion_control_mode(CANON_EXACT_PATH, 0);
    CycleBody body = cycle_body(code);
    int n = repeats(b);
    for (int i = 0; i < n; i++) {
        hole_position(s, b, mv.axes(), h);
        position(mv, h, i == 0);
        body(mv, h);
    }
    if (bracket) {
        c.set_motion_control_mode(s.control_mode, s.tolerance);
        c.set_naivecam_tolerance(s.naivecam_tolerance);
    }
}

// execute one canned-cycle block (entry point called by the interpreter)
void execute(InterpState &s, const Block &b, Canon &canon)
{
    int code = s.motion_mode;
    if (!cycle_body(code))
        throw InterpError("Unknown canned cycle code G" + std::to_string(code / 10));
    if (s.feed_rate <= 0)
        throw InterpError("Cannot feed with zero feed rate");
    PlaneAxes ax = plane_axes(s.plane);
    check_rotary(b);
    repeats(b);
    bool same = s.cycle_last == code;
    if (!same)
        s.cycle_il_valid = false;
    Hole h;
    h.spindle = s.spindle_of(b);
    h.spindle_dir = s.spindle_dir[h.spindle];
    check_spindle(code, h.spindle_dir);
    dwell_and_peck(s, b, code, same, h);
    back_bore_words(b, code, h);
    levels(s, b, ax, same, h);
    check_pecks(code, h);
    CycleMoves mv(s, canon, ax, s.sequence_number);
    if (s.cycle_il < h.r) {
        mv.rapid_depth(h.r);
        s.cycle_il = h.r;
    }
    h.clear = s.retract == RETRACT_R_PLANE ? h.r : s.cycle_il;
    s.cycle_last = code;
    run_holes(s, b, canon, mv, h, code);
}

}  // namespace cycles
