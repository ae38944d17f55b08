// cycle_g76.cc: G76 multi-pass threading cycle in the XZ plane (LinuxCNC's G76).
#include <cmath>
#include <string>

#include "../interp_hooks.hh"
#include "cycle_axes.hh"

namespace cycles {

// most degressive passes one G76 block may take before the spring passes
static const int MAX_PASSES = 10000;

// The thread geometry of one G76 block.
struct Thread {
    double x0 = 0, z0 = 0;      // drive line start (current point)
    double z_end = 0;           // end of the drive line
    double pitch = 0;           // P, distance per revolution
    double peak = 0;            // I, drive line to thread peaks (negative = external)
    double first_depth = 0;     // J
    double full_depth = 0;      // K
    double degression = 1;      // R
    double tan_angle = 0;       // tan(Q)
    int spring_passes = 0;      // H
    double taper_length = 0;    // E
    int taper_ends = 0;         // L: 1 entry, 2 exit, 3 both
    int spindle = 0;
};

// required word c of a G76 block
static double required(const Block &b, char c)
{
    if (!b.word(c))
        throw InterpError(std::string(1, (char)(c - 32)) + " word missing with g76");
    return b.value(c);
}

// read and check the words of a G76 block
static void read_thread_options(const Block &b, Thread &t);

static Thread read_thread(const InterpState &s, const Block &b)
{
    Thread t;
    double scale = s.lathe_diameter ? 0.5 : 1.0;
    t.x0 = s.current[AX_X];
    t.z0 = s.current[AX_Z];
    t.pitch = required(b, 'p');
    t.z_end = required(b, 'z');
    if (s.distance_incremental)
        t.z_end += t.z0;
    t.peak = required(b, 'i') * scale;
    t.first_depth = required(b, 'j') * scale;
    t.full_depth = required(b, 'k') * scale;
    if (t.peak == 0)
        throw InterpError("In G76, I must not be 0");
    if (t.first_depth <= 0)
        throw InterpError("In G76, J must be greater than 0");
    if (t.full_depth <= t.first_depth)
        throw InterpError("In G76, K must be greater than J");
    if (t.pitch <= 0)
        throw InterpError("In G76, P must be greater than 0");
    read_thread_options(b, t);
    t.spindle = s.spindle_of(b);
    return t;
}

// the optional words of G76: R degression, Q angle, H spring passes, E L taper
static void read_thread_options(const Block &b, Thread &t)
{
    t.degression = b.word('r') ? std::max(b.value('r'), 1.0) : 1.0;
    t.tan_angle = b.word('q') ? std::tan(b.value('q') * (M_PI / 180.0)) : 0.0;
    t.spring_passes = b.word('h') ? (int)std::lround(b.value('h')) : 0;
    if (t.spring_passes < 0 || t.spring_passes > MAX_PASSES)
        throw InterpError("In G76, H must be 0 to " + std::to_string(MAX_PASSES));
    t.taper_length = b.word('e') ? b.value('e') : 0.0;
    t.taper_ends = b.word('l') ? (int)std::lround(b.value('l')) : 0;
    if (t.taper_length < 0 || t.taper_ends < 0 || t.taper_ends > 3)
        throw InterpError("In G76, E must not be negative and L must be 0 to 3");
}

// one threading pass at `depth` beyond the peak
static void thread_pass(CycleMoves &mv, const Thread &t, double depth)
{
    Canon &c = mv.canon();
    double side = t.peak < 0 ? -1.0 : 1.0;              // toward the thread
    double dir = t.z_end < t.z0 ? -1.0 : 1.0;           // along the drive line
    double cut = std::fabs(t.peak) + depth;
    double full = std::fabs(t.peak) + t.full_depth;
    double x_cut = t.x0 + side * cut;
    double x_safe = x_cut - side * full;
    double zoff = depth * t.tan_angle;
    double z_start = t.z0 + dir * zoff;
    double z_stop = t.z_end + dir * (zoff - t.full_depth * t.tan_angle);
    bool entry = t.taper_length > 0 && (t.taper_ends & 1);
    bool exit = t.taper_length > 0 && (t.taper_ends & 2);
    double taper_pitch = entry || exit
        ? t.pitch * std::hypot(t.taper_length, t.full_depth) / t.taper_length : t.pitch;
    // drive line axes are (a = z, b = x, c = y) in the XZ plane
    double y = mv.cur(AX_Y);
    mv.rapid(z_start, x_safe, y);
    mv.rapid(z_start, entry ? x_cut - side * t.full_depth : x_cut, y);
    c.disable_feed_override();
    if (entry) {
        c.start_speed_feed_synch(t.spindle, taper_pitch, false);
        mv.feed(z_start + dir * t.taper_length, x_cut, y);
    }
    c.start_speed_feed_synch(t.spindle, t.pitch, false);
    mv.feed(exit ? z_stop - dir * t.taper_length : z_stop, x_cut, y);
    if (exit) {
        c.start_speed_feed_synch(t.spindle, taper_pitch, false);
        mv.feed(z_stop, x_cut - side * t.full_depth, y);
    }
    c.stop_speed_feed_synch();
    mv.rapid(mv.cur(AX_Z), x_safe, y);
    c.enable_feed_override();
}

// G76 threading: degressive passes to full depth, spring passes, return to the drive line end
void execute_g76(InterpState &s, const Block &b, Canon &canon)
{
    if (s.plane != CANON_PLANE_XZ)
        throw InterpError("G76 is only allowed in the XZ plane (G18)");
    Thread t = read_thread(s, b);
    if (std::pow(t.full_depth / t.first_depth, t.degression) > MAX_PASSES)
        throw InterpError("In G76, J is too small for K with this R (more than " +
                          std::to_string(MAX_PASSES) + " passes)");
    CycleMoves mv(s, canon, plane_axes(CANON_PLANE_XZ), s.sequence_number);
    for (int n = 1;; n++) {
        double depth = t.first_depth * std::pow((double)n, 1.0 / t.degression);
        if (depth >= t.full_depth)
            break;
        thread_pass(mv, t, depth);
    }
    for (int i = 0; i <= t.spring_passes; i++)
        thread_pass(mv, t, t.full_depth);
    mv.rapid(t.z_end, t.x0, mv.cur(AX_Y));
}

}  // namespace cycles
