// lathe_profile.cc: reading the profile subroutine of the lathe cycles G70/G71/G72 into lines
// and arcs of the ZX plane (X and U halved in diameter mode, U/W incremental, A fillets, C chamfers).
#include "lathe_profile.hh"

#include <cmath>

namespace cycles {

namespace {

// moves shorter than this are dropped (the next move starts where the previous one ended)
constexpr double MIN_MOVE = 1e-4;

// The modal state of the profile blocks while they are read.
struct Reader {
    const InterpState &s;
    std::string who;
    bool incremental, ijk_absolute;
    int motion = 10;
    Pt cur;
};

// center of an R-format arc from a to b; ccw in the (z, x) frame
Pt center_from_radius(Pt a, Pt b, double r, bool ccw, const std::string &who)
{
    double chord = dist(a, b), half = chord / 2;
    if (chord == 0 || std::fabs(r) < half - 1e-6)
        throw InterpError(who + ": profile arc radius too small to reach its end point");
    double off = std::sqrt(std::fmax(r * r - half * half, 0.0));
    double side = (ccw == (r > 0)) ? 1.0 : -1.0;  // the short arc's center is left of the chord when ccw
    return {(a.u + b.u) / 2 - side * off * (b.v - a.v) / chord,
            (a.v + b.v) / 2 + side * off * (b.u - a.u) / chord};
}

// end point of a move: X/Z absolute or incremental, U/W always incremental, X and U halved in G7
Pt move_end(const Reader &r, const Block &b)
{
    double scale = r.s.lathe_diameter ? 0.5 : 1.0;
    Pt p = r.cur;
    if (b.word('x')) p.v = r.incremental ? r.cur.v + b.value('x') * scale : b.value('x') * scale;
    if (b.word('z')) p.u = r.incremental ? r.cur.u + b.value('z') : b.value('z');
    if (b.word('u')) p.v += b.value('u') * scale;
    if (b.word('w')) p.u += b.value('w');
    return p;
}

// the element of one G0/G1/G2/G3 move from r.cur to end
Elem move_elem(const Reader &r, const Block &b, Pt end)
{
    Elem e{false, r.cur, end, {}, false};
    if (r.motion == 0 || r.motion == 10) return e;
    if (r.motion != 20 && r.motion != 30)
        throw InterpError(r.who + ": profile moves must be G0, G1, G2 or G3");
    e.arc = true;
    e.ccw = r.motion == 30;
    if (b.word('r')) {
        e.c = center_from_radius(r.cur, end, b.value('r'), e.ccw, r.who);
    } else if (b.word('i') || b.word('k')) {
        double i = b.word('i') ? b.value('i') : 0, k = b.word('k') ? b.value('k') : 0;
        e.c = r.ijk_absolute ? Pt{k, i} : Pt{r.cur.u + k, r.cur.v + i};
    } else {
        throw InterpError(r.who + ": profile arc needs I K or R words");
    }
    e.r = dist(e.c, e.a);
    return e;
}

// Round the corner between lines `in` and `out` with a fillet (arc) or chamfer of size `size`.
void round_corner(std::vector<Elem> &elems, Elem &out, double size, bool fillet, const std::string &who)
{
    Elem &in = elems.back();
    if (in.arc || out.arc)
        throw InterpError(who + ": fillets (A) and chamfers (C) need straight moves on both sides");
    Pt d1 = elem_tangent(in, 1), d2 = elem_tangent(out, 0);
    double turn = std::atan2(d1.u * d2.v - d1.v * d2.u, d1.u * d2.u + d1.v * d2.v);
    double t = size * std::tan(std::fabs(turn) / 2);
    if (t > elem_length(in) + 1e-9 || t > elem_length(out) + 1e-9)
        throw InterpError(who + ": fillet or chamfer too large for its moves");
    Pt corner = in.b;
    Pt p1{corner.u - d1.u * t, corner.v - d1.v * t}, p2{corner.u + d2.u * t, corner.v + d2.v * t};
    in.b = p1;
    out.a = p2;
    Elem join{fillet, p1, p2, {}, turn > 0, -1, fillet ? size : 0};
    if (fillet) {
        double side = turn > 0 ? 1 : -1;
        join.c = {p1.u - side * d1.v * size, p1.v + side * d1.u * size};
    }
    if (elem_length(in) < MIN_MOVE) {
        elems.pop_back();
        if (!elems.empty() && !fillet) join.a = elems.back().b;
    }
    elems.push_back(join);
}

// Add one move's element, rounding the previous corner when the previous move asked for it.
void add_move(std::vector<Elem> &elems, Elem e, double round, bool fillet, const std::string &who)
{
    if (elem_length(e) < MIN_MOVE) return;
    if (!elems.empty()) e.a = elems.back().b;
    if (round > 0 && !elems.empty()) round_corner(elems, e, round, fillet, who);
    if (elem_length(e) >= MIN_MOVE) elems.push_back(e);
}

} // namespace

Profile read_profile(const InterpState &s, const std::vector<Block> &blocks, Pt from,
                     const std::string &who)
{
    Reader r{s, who, s.distance_incremental, s.ijk_absolute, 10, from};
    Profile prof;
    bool started = false;
    double round = 0;
    bool fillet = false;
    for (const Block &b : blocks) {
        if (b.g_modes[GG_DISTANCE] != -1) r.incremental = b.g_modes[GG_DISTANCE] == 910;
        if (b.g_modes[GG_IJK] != -1) r.ijk_absolute = b.g_modes[GG_IJK] == 901;
        if (b.motion() != -1) r.motion = b.motion();
        if (!b.word('x') && !b.word('z') && !b.word('u') && !b.word('w')) continue;
        Pt end = move_end(r, b);
        if (started) add_move(prof.elems, move_elem(r, b, end), round, fillet, who);
        else prof.start = end;
        started = true;
        fillet = b.word('a');
        round = b.word('a') ? b.value('a') : b.word('c') ? b.value('c') : 0;
        r.cur = end;
    }
    if (prof.elems.empty())
        throw InterpError(who + ": the profile needs a start point and at least one move");
    prof.start = prof.elems.front().a;
    return prof;
}

}  // namespace cycles
