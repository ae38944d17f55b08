// cycle_bodies.cc: move sequences of the drilling, pecking, tapping and boring cycles (LinuxCNC's canned cycles).
#include "cycle_bodies.hh"

namespace cycles {

// G81 drilling: feed to the bottom, rapid out
static void body_g81(CycleMoves &mv, const Hole &h)
{
    mv.feed_depth(h.bottom);
    mv.rapid_depth(h.clear);
}

// G82 spot drilling: feed, dwell, rapid out
static void body_g82(CycleMoves &mv, const Hole &h)
{
    mv.feed_depth(h.bottom);
    mv.canon().dwell(h.dwell);
    mv.rapid_depth(h.clear);
}

// peck drilling: each peck backs off by the clearance, after a retract to R when full_retract
static void peck(CycleMoves &mv, const Hole &h, bool full_retract)
{
    for (double d = h.r - h.peck; d > h.bottom; d -= h.peck) {
        mv.feed_depth(d);
        if (full_retract)
            mv.rapid_depth(h.r);
        mv.rapid_depth(d + h.peck_clearance);
    }
    mv.feed_depth(h.bottom);
    mv.rapid_depth(h.clear);
}

// G83 peck drilling: each peck retracts to R, then rapids back to just above the cut depth
static void body_g83(CycleMoves &mv, const Hole &h)
{
    peck(mv, h, true);
}

// G73 chip-break drilling: each peck backs off by the clearance only
static void body_g73(CycleMoves &mv, const Hole &h)
{
    peck(mv, h, false);
}

// start spindle s turning in direction dir
static void spindle_start(Canon &c, int s, CanonDirection dir)
{
    if (dir == CANON_CLOCKWISE)
        c.start_spindle_clockwise(s);
    else if (dir == CANON_COUNTERCLOCKWISE)
        c.start_spindle_counterclockwise(s);
}

// tapping with overrides off: feed in, reverse, dwell, feed out, restore direction
static void tap(CycleMoves &mv, const Hole &h, CanonDirection in, CanonDirection out)
{
    Canon &c = mv.canon();
    c.disable_feed_override();
    c.disable_speed_override(h.spindle);
    mv.feed_swapped(mv.cur(mv.axes().aa), mv.cur(mv.axes().bb), h.bottom);
    c.stop_spindle_turning(h.spindle);
    spindle_start(c, h.spindle, out);
    c.dwell(h.dwell);
    mv.feed_swapped(mv.cur(mv.axes().aa), mv.cur(mv.axes().bb), h.clear);
    c.stop_spindle_turning(h.spindle);
    spindle_start(c, h.spindle, in);
    c.enable_feed_override();
    c.enable_speed_override(h.spindle);
}

// G84 right-hand tapping (spindle clockwise going in)
static void body_g84(CycleMoves &mv, const Hole &h)
{
    tap(mv, h, CANON_CLOCKWISE, CANON_COUNTERCLOCKWISE);
}

// G74 left-hand tapping (spindle counterclockwise going in)
static void body_g74(CycleMoves &mv, const Hole &h)
{
    tap(mv, h, CANON_COUNTERCLOCKWISE, CANON_CLOCKWISE);
}

// G85 boring: feed in, feed out to R, rapid to the clear level
static void body_g85(CycleMoves &mv, const Hole &h)
{
    mv.feed_depth(h.bottom);
    mv.feed_depth(h.r);
    mv.rapid_depth(h.clear);
}

// G86 boring: feed in, dwell, stop the spindle, rapid out, restart the spindle
static void body_g86(CycleMoves &mv, const Hole &h)
{
    mv.feed_depth(h.bottom);
    mv.canon().dwell(h.dwell);
    mv.canon().stop_spindle_turning(h.spindle);
    mv.rapid_depth(h.clear);
    spindle_start(mv.canon(), h.spindle, h.spindle_dir);
}

// G87 back boring: enter offset with the spindle stopped, bore upward to K, leave offset
static void body_g87(CycleMoves &mv, const Hole &h)
{
    Canon &c = mv.canon();
    double a = mv.cur(mv.axes().aa), b = mv.cur(mv.axes().bb);
    mv.rapid(a + h.i, b + h.j, mv.cur(mv.axes().cc));
    c.stop_spindle_turning(h.spindle);
    mv.rapid_depth(h.bottom);
    mv.rapid(a, b, h.bottom);
    spindle_start(c, h.spindle, h.spindle_dir);
    mv.feed_depth(h.k);
    mv.feed_depth(h.bottom);
    c.stop_spindle_turning(h.spindle);
    mv.rapid(a + h.i, b + h.j, h.bottom);
    mv.rapid_depth(h.clear);
    mv.rapid(a, b, h.clear);
    spindle_start(c, h.spindle, h.spindle_dir);
}

// G88 boring with manual retract: feed in, dwell, stop spindle, program stop, restart spindle
static void body_g88(CycleMoves &mv, const Hole &h)
{
    mv.feed_depth(h.bottom);
    mv.canon().dwell(h.dwell);
    mv.canon().stop_spindle_turning(h.spindle);
    mv.canon().program_stop();
    spindle_start(mv.canon(), h.spindle, h.spindle_dir);
}

// G89 boring: feed in, dwell, feed out to the clear level
static void body_g89(CycleMoves &mv, const Hole &h)
{
    mv.feed_depth(h.bottom);
    mv.canon().dwell(h.dwell);
    mv.feed_depth(h.clear);
}

// table of cycle codes and their bodies
CycleBody cycle_body(int code)
{
    switch (code) {
    case 730: return body_g73;
    case 740: return body_g74;
    case 810: return body_g81;
    case 820: return body_g82;
    case 830: return body_g83;
    case 840: return body_g84;
    case 850: return body_g85;
    case 860: return body_g86;
    case 870: return body_g87;
    case 880: return body_g88;
    case 890: return body_g89;
    default: return nullptr;
    }
}

}  // namespace cycles
