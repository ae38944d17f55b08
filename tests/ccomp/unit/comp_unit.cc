// comp_unit.cc: drives the cutter compensation engine from a script on stdin and prints the canon calls.
#include <memory>
#include <string>

#include "emc/rs274ngc/interp_hooks.hh"
#include "../../interp-cycles/unit/record_canon.hh"
#include "../../interp-cycles/unit/script_block.hh"
#include "../../interp-cycles/unit/script_run.hh"

// The script state: interpreter state, the real (printing) canon and the engine in front of it.
struct Driver {
    InterpState s;
    RecordCanon out;
    std::unique_ptr<cutcomp::Engine> engine = cutcomp::make_engine(s, out);
};

// end pose of a move: given axis words replace the current values
static Pose end_of(const InterpState &s, const Block &b)
{
    Pose p = s.current;
    take_axis_words(b, p);
    return p;
}

// CanonPose of a Pose
static CanonPose canon_of(const Pose &p)
{
    CanonPose c;
    c.x = p[AX_X]; c.y = p[AX_Y]; c.z = p[AX_Z];
    c.a = p[AX_A]; c.b = p[AX_B]; c.c = p[AX_C];
    return c;
}

// G2/G3 with I J (XY) or I K (XZ) center offsets from the start point
static void arc(Driver &d, const Block &b, int rotation)
{
    Pose end = end_of(d.s, b);
    bool xz = d.s.plane == CANON_PLANE_XZ;
    double cx = d.s.current[AX_X] + b.value('i');
    double c2 = xz ? d.s.current[AX_Z] + b.value('k') : d.s.current[AX_Y] + b.value('j');
    if (xz)
        d.engine->canon().arc_feed(1, end[AX_Z], end[AX_X], c2, cx, rotation, end[AX_Y], 0, 0, 0,
                                   0, 0, 0);
    else
        d.engine->canon().arc_feed(1, end[AX_X], end[AX_Y], cx, c2, rotation, end[AX_Z], 0, 0, 0,
                                   0, 0, 0);
    d.s.current = end;
}

// G41/G42: side, radius from D (a diameter), orientation from L
static void comp_on(Driver &d, const Block &b, CanonSide side)
{
    d.s.comp_side = side;
    d.s.comp_radius = b.value('d') / 2;
    d.s.comp_orientation = b.word('l') ? (int)b.value('l') : 0;
    d.engine->start(d.s);
}

// one G code of the script
static void run_g(Driver &d, const Block &b, int g)
{
    Canon &c = d.engine->canon();
    switch (g) {
    case 0: c.straight_traverse(1, canon_of(end_of(d.s, b))); d.s.current = end_of(d.s, b); break;
    case 10: c.straight_feed(1, canon_of(end_of(d.s, b))); d.s.current = end_of(d.s, b); break;
    case 20: arc(d, b, -1); break;
    case 30: arc(d, b, 1); break;
    case 170: d.s.plane = CANON_PLANE_XY; break;
    case 180: d.s.plane = CANON_PLANE_XZ; break;
    case 400: d.engine->stop(d.s); d.s.comp_side = CANON_SIDE_OFF; break;
    case 410: comp_on(d, b, CANON_SIDE_LEFT); break;
    case 420: comp_on(d, b, CANON_SIDE_RIGHT); break;
    default: break;
    }
}

// one script line: "(text)" comment, "!text" message, else words
static void run_line(Driver &d, const std::string &text)
{
    Canon &c = d.engine->canon();
    if (text[0] == '(') {
        c.comment(text.substr(1, text.size() - 2));
        return;
    }
    if (text[0] == '!') {
        c.message(text.substr(1));
        return;
    }
    ScriptLine sl = parse_script_line(text);
    if (sl.block.word('f'))
        c.set_feed_rate(sl.block.value('f'));
    for (int m : sl.m) {
        if (m == 8) c.flood_on();
        if (m == 2) { d.engine->flush(); c.program_end(); }
    }
    for (int g : sl.g)
        run_g(d, sl.block, g);
}

// read script lines; '#' lines are echoed, errors printed and the engine reset
int main()
{
    Driver d;
    return run_script(
        std::cin, [&](const std::string &line) { run_line(d, line); },
        [&] {
            d.engine->reset();
            d.s.comp_side = CANON_SIDE_OFF;
        });
}
