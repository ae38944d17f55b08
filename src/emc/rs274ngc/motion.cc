// motion.cc: group-1 motion dispatch, end points, straight moves, G28/G30, G33, probing and cycles.
#include <cmath>

#include "interp.hh"
#include "polar.hh"

namespace {

const char AXES[] = "xyzabc";
constexpr double DEG = M_PI / 180.0;

// true when the block has any axis word (or polar word)
bool any_axis(const Block &b)
{
    for (int i = 0; i < 6; i++)
        if (b.word(AXES[i])) return true;
    return b.has_polar_radius || b.has_polar_angle;
}

} // namespace

// Group-0 codes handled at the motion step (G28/G30 and their .1, G5.3); true when the block's
// motion is done (G10, G52, G92 suspend the modal motion for the line).
bool Interp::nonmodal_motion(const Block &b)
{
    int g0 = b.g_modes[GG_NONMODAL];
    if (g0 == 280 || g0 == 300) move_home(b, g0);
    else if (g0 == 281 || g0 == 301) store_home(g0);
    else if (g0 == 53) nurbs_close(b);
    return g0 == 280 || g0 == 300 || g0 == 281 || g0 == 301 || g0 == 53 || g0 == 100 ||
           g0 == 520 || g0 == 920;
}

// The motion codes, by range of code ×10: handler and whether the block ends with
// execute-finish (probing).
struct MotionHandler {
    int lo, hi;
    void (Interp::*run)(const Block &, int);
    bool finish;
};

const MotionHandler MOTION_HANDLERS[] = {
    {0, 10, &Interp::move_straight, false},   {20, 30, &Interp::move_arc, false},
    {330, 331, &Interp::move_g33, false},     {382, 385, &Interp::move_probe, true},
    {52, 52, &Interp::nurbs_point, false},    {50, 51, &Interp::move_spline, false},
};

// G80 and the canned and lathe cycles; true when m is one of them.
bool Interp::cycle_or_cancel(Block &b, int m)
{
    if (m == 800) {
        out().comment("interpreter: motion mode set to none");
        s_.cycle_last = -1;
        return true;
    }
    bool cycle = m == 730 || m == 740 || (m >= 810 && m <= 890) || m == 760 || (m >= 700 && m <= 722);
    if (cycle) move_cycle(b);
    return cycle;
}

// Takes the block's explicit motion code as the mode; true when a motion runs on this line
// (an explicit code, or the modal one with axis words that no G43.1/G43.2 consumes).
bool Interp::motion_runs(const Block &b)
{
    int explicit_motion = b.motion();
    int tl = b.g_modes[GG_TOOL_LENGTH];
    if (explicit_motion != -1) s_.motion_mode = explicit_motion;
    return explicit_motion != -1 || (tl != 431 && tl != 432 && any_axis(b));
}

// Motion step (28); returns true when the block must end with execute-finish.
bool Interp::do_motion(Block &b)
{
    INTERP_FRAME();
    if (nonmodal_motion(b)) return false;
    if (!motion_runs(b)) return false;
    int m = s_.motion_mode;
    if (nurbs_open_ && m != 52) throw InterpError("Must close the G5.2 block with G5.3 first");
    if (cycle_or_cancel(b, m)) return false;
    s_.cycle_last = -1;
    s_.cycle_il_valid = false;
    if (m != 50 && m != 51) spline_continues_ = false;
    for (const MotionHandler &h : MOTION_HANDLERS) {
        if (m < h.lo || m > h.hi) continue;
        (this->*h.run)(b, m);
        return h.finish;
    }
    return false;
}

// End point of a move in program coordinates (G90/G91, G53, G7, polar words).
Pose Interp::find_end(const Block &b)
{
    INTERP_FRAME();
    Pose end = s_.current;
    bool g53 = b.g_modes[GG_NONMODAL] == 530;
    if (g53) end = program_to_machine_pose(s_.current);
    for (int i = 0; i < 6; i++) {
        if (!b.word(AXES[i])) continue;
        double v = b.value(AXES[i]);
        if (i == AX_X && s_.lathe_diameter) v /= 2.0;
        end[i] = (s_.distance_incremental && !g53) ? end[i] + v : v;
    }
    if (g53) return machine_to_program_pose(end);
    if (b.has_polar_radius || b.has_polar_angle) polar_end(b, end);
    return end;
}

// Apply @ (radius) and ^ (angle) words in the XY plane.
void Interp::polar_end(const Block &b, Pose &end)
{
    INTERP_FRAME();
    if (s_.plane != CANON_PLANE_XY) throw InterpError("Polar coordinates only in the XY plane");
    double x = s_.current[AX_X], y = s_.current[AX_Y];
    polar_point(b, s_.distance_incremental, x, y);
    end[AX_X] = x;
    end[AX_Y] = y;
}

// In G93 emit SET_FEED_RATE(length * F) before a move.
void Interp::apply_inverse_time(double length, const Block &b)
{
    INTERP_FRAME();
    if (s_.feed_mode != FEED_INVERSE_TIME) return;
    if (!b.word('f')) throw InterpError(s_.motion_mode == 10
                                            ? "F word missing with inverse time g1 move"
                                            : "F word missing with inverse time arc move");
    out().set_feed_rate(length > 0.0 ? length * b.value('f') : 0.1 * b.value('f'));
}

// Length of a straight move for inverse time: XYZ, else UVW, else ABC.
double Interp::straight_length(const Pose &a, const Pose &e) const
{
    INTERP_FRAME();
    double l = std::sqrt(std::pow(e[0] - a[0], 2) + std::pow(e[1] - a[1], 2) +
                         std::pow(e[2] - a[2], 2));
    if (l == 0.0)
        l = std::sqrt(std::pow(e[6] - a[6], 2) + std::pow(e[7] - a[7], 2) +
                      std::pow(e[8] - a[8], 2));
    if (l == 0.0)
        l = std::sqrt(std::pow(e[3] - a[3], 2) + std::pow(e[4] - a[4], 2) +
                      std::pow(e[5] - a[5], 2));
    return l;
}

// G0 / G1.
void Interp::move_straight(const Block &b, int mode)
{
    INTERP_FRAME();
    Pose end = find_end(b);
    int line = s_.sequence_number;
    if (mode == 0) {
        out().straight_traverse(line, to_canon_pose(end));
    } else {
        if (s_.feed_mode == FEED_INVERSE_TIME)
            apply_inverse_time(straight_length(s_.current, end), b);
        else if (s_.feed_rate == 0.0)
            throw InterpError("Cannot do g1 with zero feed rate");
        out().straight_feed(line, to_canon_pose(end));
    }
    s_.current = end;
}

// G28 / G30: rapid to the intermediate point, then to the stored home position.
void Interp::move_home(const Block &b, int code)
{
    INTERP_FRAME();
    if (s_.comp_side != CANON_SIDE_OFF)
        throw InterpError("Cannot use G28 or G30 with cutter radius compensation");
    Pose mid = find_end(b);
    out().straight_traverse(s_.sequence_number, to_canon_pose(mid));
    s_.current = mid;
    int base = code == 280 ? PARAM_G28_HOME : PARAM_G30_HOME;
    Pose m = program_to_machine_pose(mid);
    bool any = any_axis(b);
    for (int i = 0; i < AX_COUNT; i++) {
        if (any && (i >= 6 || !b.word(AXES[i]))) continue;
        double v = s_.params[base + i];
        m[i] = (i >= AX_A && i <= AX_C) ? v : s_.user_to_program(v);
    }
    Pose end = machine_to_program_pose(m);
    out().straight_traverse(s_.sequence_number, to_canon_pose(end));
    s_.current = end;
}

// G28.1 / G30.1: store the current machine position (machine units).
void Interp::store_home(int code)
{
    INTERP_FRAME();
    int base = code == 281 ? PARAM_G28_HOME : PARAM_G30_HOME;
    Pose m = program_to_machine_pose(s_.current);
    for (int i = 0; i < AX_COUNT; i++)
        s_.params[base + i] = (i >= AX_A && i <= AX_C) ? m[i] : s_.program_to_user(m[i]);
}

// G33 (spindle-synchronized move) / G33.1 (rigid tap).
void Interp::move_g33(const Block &b, int code)
{
    bool rigid = code == 331;
    INTERP_FRAME();
    if (s_.comp_side != CANON_SIDE_OFF && rigid)
        throw InterpError("Cannot use G33.1 with cutter radius compensation");
    if (b.word('f')) throw InterpError("F word used with a g33/g33.1");
    if (!b.word('k')) throw InterpError("K word missing with g33/g33.1");
    int sp = s_.spindle_of(b);
    if (!rigid && s_.spindle_dir[sp] == CANON_STOPPED) throw InterpError("Spindle not turning in G33");
    Pose end = find_end(b);
    out().start_speed_feed_synch(sp, b.value('k'), false);
    if (rigid) {
        double scale = b.word('i') ? std::max(1.0, b.value('i')) : 1.0;
        out().rigid_tap(s_.sequence_number, end[AX_X], end[AX_Y], end[AX_Z], scale);
    } else {
        out().straight_feed(s_.sequence_number, to_canon_pose(end));
        s_.current = end;
    }
    out().stop_speed_feed_synch();
}

// G38.2-G38.5 straight probe.
void Interp::move_probe(const Block &b, int)
{
    INTERP_FRAME();
    if (!any_axis(b)) throw InterpError("All axes missing with motion code");
    if (s_.comp_side != CANON_SIDE_OFF)
        throw InterpError("Cannot probe with cutter radius compensation on");
    if (s_.feed_mode == FEED_UNITS_PER_REV) throw InterpError("Cannot probe with feed per rev mode");
    if (s_.feed_rate == 0.0) throw InterpError("Cannot probe with zero feed rate");
    Pose end = find_end(b);
    int type = s_.motion_mode - 382;
    bool same = true;
    for (int i = 0; i < AX_COUNT; i++) same = same && end[i] == s_.current[i];
    if (same && (type == 0 || type == 2)) throw InterpError("Start point too close to probe point");
    out().turn_probe_on();
    out().straight_probe(s_.sequence_number, to_canon_pose(end), type);
    out().turn_probe_off();
    probe_result();
}

// After a probe: the trip point into #5061-#5069 and #5070; re-read the current point.
void Interp::probe_result()
{
    INTERP_FRAME();
    CanonPose p = real_out_.get_external_probe_position();
    Pose trip{p.x, p.y, p.z, p.a, p.b, p.c, p.u, p.v, p.w};
    for (int i = 0; i < AX_COUNT; i++) s_.params[5061 + i] = trip[i];
    s_.params[5070] = real_out_.get_external_probe_tripped_value();
    CanonPose c = real_out_.get_external_position();
    s_.current = Pose{c.x, c.y, c.z, c.a, c.b, c.c, c.u, c.v, c.w};
}

// Canned and lathe cycles: hand the block to the cycles module.
void Interp::move_cycle(Block &b)
{
    INTERP_FRAME();
    int m = s_.motion_mode;
    if (s_.comp_side != CANON_SIDE_OFF && m != 700)
        throw InterpError("Cannot use canned cycles with cutter radius compensation");
    if (m == 760) {
        if (!cycles::execute_g76) throw InterpError("G76 threading cycle not supported");
        cycles::execute_g76(s_, b, out());
        return;
    }
    if (m >= 700 && m <= 722) {
        if (!cycles::execute_lathe) throw InterpError("Lathe cycles not supported");
        cycles::execute_lathe(s_, b, out(), *this);
        return;
    }
    if (s_.feed_mode == FEED_INVERSE_TIME)
        throw InterpError("Cannot use inverse time feed with canned cycles");
    if (!cycles::execute) throw InterpError("Canned cycles not supported");
    cycles::execute(s_, b, out());
}
