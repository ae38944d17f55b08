// lathe_cycles.cc: G71/G72 roughing (.1 without pockets, .2 pockets only) and G70 finishing of a
// profile subroutine, worked in a frame where the cut runs along +u and levels step down in v.
#include <cmath>
#include <string>

#include "../interp_hooks.hh"
#include "cycle_axes.hh"
#include "lathe_profile.hh"

namespace cycles {

namespace {

// most roughing levels one block may cut; more means I is far too small for the stock
constexpr long MAX_LEVELS = 100000;
// level and point tolerance
constexpr double EPS = 1e-9;
// a place this close to an element's end point is that end point
constexpr double SAME_POINT = 1e-7;

// Maps the ZX plane to the cycle frame: (c, s) = (z, x) or (x, z) when swapped (G72), then
// u = cdir * c and v = vsign * s.
struct Frame {
    bool swap = false;
    double cdir = 1, vsign = 1;

    // (z, x) to (u, v)
    Pt to(Pt zx) const
    {
        Pt cs = swap ? Pt{zx.v, zx.u} : zx;
        return {cdir * cs.u, vsign * cs.v};
    }
    // (u, v) to (z, x)
    Pt back(Pt uv) const
    {
        Pt cs{uv.u / cdir, uv.v / vsign};
        return swap ? Pt{cs.v, cs.u} : cs;
    }
    // true when the map reverses the sense of rotation
    bool flips() const { return swap != ((cdir < 0) != (vsign < 0)); }
    // an element of the (z, x) plane in the cycle frame
    Elem to(const Elem &e) const
    {
        return Elem{e.arc, to(e.a), to(e.b), to(e.c), e.ccw != flips(), e.id, e.r, e.r_end};
    }
};

// The words and state of one cycle block.
struct Job {
    int code;                 // motion code x10: 700, 710..712, 720..722
    std::string who;          // "G71.1" in messages
    Pt start;                 // start point (z, x)
    bool moved;               // X or Z given: rapid there first
    double d, e, inc, retract;
    long passes;
};

// Emits the moves of a cycle given in the cycle frame.
class Emitter {
public:
    Emitter(CycleMoves &mv, const Frame &f) : mv_(mv), f_(f) {}
    // rapid to p
    void rapid(Pt p)
    {
        Pt zx = f_.back(p);
        mv_.rapid(zx.u, zx.v, mv_.cur(AX_Y));
        at_ = p;
    }
    // feed to p
    void feed(Pt p)
    {
        Pt zx = f_.back(p);
        mv_.feed(zx.u, zx.v, mv_.cur(AX_Y));
        at_ = p;
    }
    // move along element e (a line or an arc)
    void along(const Elem &e)
    {
        if (!e.arc) return feed(e.b);
        Pt b = f_.back(e.b), c = f_.back(e.c);
        mv_.arc(b.u, b.v, c.u, c.v, (e.ccw != f_.flips()) ? 1 : -1);
        at_ = e.b;
    }
    // the current point in the cycle frame
    Pt at() const { return at_; }

private:
    CycleMoves &mv_;
    const Frame &f_;
    Pt at_;
};

// A place on the pieces of a path: piece index and parameter.
struct Place {
    size_t k = 0;
    double t = 0;
};

// true when piece e runs downwards in v
bool descends(const Elem &e)
{
    return e.b.v < e.a.v - EPS;
}

// true when piece e runs upwards in v
bool rises(const Elem &e)
{
    return e.b.v > e.a.v + EPS;
}

// value of word c, or `def` when absent
double word_or(const Block &b, char c, double def)
{
    return b.word(c) ? b.value(c) : def;
}

// the first place at or after `from` where the path crosses level v going up (down when !up)
bool find_crossing(const std::vector<Elem> &p, Place from, double v, bool up, Place &at)
{
    for (size_t k = from.k; k < p.size(); k++) {
        double t;
        if (!(up ? rises(p[k]) : descends(p[k])) || !level_param(p[k], v, t)) continue;
        if (k == from.k && t < from.t - EPS) continue;
        at = {k, t};
        return true;
    }
    return false;
}

// lowest v of the pocket that starts at piece k (until the path is back at level `top`)
double pocket_bottom(const std::vector<Elem> &p, size_t k, double top)
{
    double low = top;
    for (; k < p.size(); k++) {
        low = std::fmin(low, std::fmin(p[k].a.v, p[k].b.v));
        if (rises(p[k]) && p[k].b.v >= top - EPS) break;
    }
    return low;
}

// follow the path from `from` to `to` (to after from); the pieces of one arc make one move
void follow(Emitter &em, const std::vector<Elem> &p, Place from, Place to)
{
    for (size_t k = from.k; k <= to.k && k < p.size(); k++) {
        double t0 = k == from.k ? from.t : 0, t1 = k == to.k ? to.t : 1;
        Elem part = elem_part(p[k], t0, t1);
        while (part.arc && t1 >= 1 && k < to.k && p[k + 1].id == p[k].id && p[k + 1].arc) {
            k++;
            t1 = k == to.k ? to.t : 1;
            part.b = elem_point(p[k], t1);
        }
        if (elem_length(part) > 1e-10 || dist(part.a, part.b) > 1e-10) em.along(part);
    }
}

// One roughing level of a pocket: from wall point w along level v to where the path rises back
// through it, retract diagonally by at most R, return and feed back to the wall.
bool pocket_level(Emitter &em, const std::vector<Elem> &p, Place w, double v, double r)
{
    Place h;
    if (!find_crossing(p, w, v, true, h)) return false;
    Pt wall = elem_point(p[w.k], w.t), hit = elem_point(p[h.k], h.t);
    em.feed({hit.u, v});
    double rr = std::fmin(r, (hit.u - wall.u) / 2);
    em.rapid({hit.u - rr, v + rr});
    em.rapid({wall.u + rr, v + rr});
    em.feed({wall.u, v});
    return true;
}

// Rough the pocket whose top is the start of descending piece k, then follow the path out of
// it; returns the place where the path is back at the top level (or its end).
Place rough_pocket(Emitter &em, const std::vector<Elem> &p, size_t k, const Job &j)
{
    double top = p[k].a.v, bottom = pocket_bottom(p, k, top);
    Place w{k, 0};
    for (double v = top; v > bottom + EPS; v -= j.inc) {
        Place next;
        if (v < top && !find_crossing(p, w, v, false, next)) break;
        if (v < top) {
            follow(em, p, w, next);
            w = next;
        }
        if (!pocket_level(em, p, w, v, j.retract)) break;
    }
    Place out;
    if (!find_crossing(p, w, top, true, out)) out = {p.size() - 1, 1};
    follow(em, p, w, Place{out.k, 1});
    return Place{out.k + 1, 0};
}

// Walk the path from its start: follow it, and at each pocket top rough the pocket (G71/G72
// and .2).
void walk(Emitter &em, const std::vector<Elem> &p, const Job &j)
{
    Place at;
    while (at.k < p.size()) {
        if (descends(p[at.k]) && at.t < EPS) {
            at = rough_pocket(em, p, at.k, j);
            continue;
        }
        follow(em, p, at, Place{at.k, 1});
        at = {at.k + 1, 0};
    }
}

// true when place `at` is the start of its path element (not inside it)
bool element_start(const std::vector<Elem> &p, Place at)
{
    bool first = at.k == 0 || p[at.k - 1].id != p[at.k].id;
    return first && dist(elem_point(p[at.k], at.t), p[at.k].a) < SAME_POINT;
}

// true when a bridge landing at h lands inside an arc (LinuxCNC then feeds to no element start
// from the flat run before the pocket up to the landing; on a line it does)
bool lands_inside_arc(const std::vector<Elem> &p, Place h)
{
    bool last = h.k + 1 == p.size() || p[h.k + 1].id != p[h.k].id;
    bool at_end = last && dist(elem_point(p[h.k], h.t), p[h.k].b) < SAME_POINT;
    return p[h.k].arc && !element_start(p, h) && !at_end;
}

// true when the pocket whose top is descending piece k is bridged into the middle of an arc
bool bridge_lands_inside(const std::vector<Elem> &p, size_t k)
{
    Place h;
    return find_crossing(p, Place{k, 0}, p[k].a.v, true, h) && lands_inside_arc(p, h);
}

// true when the flat pieces from k on lead at their level into a pocket bridged into the middle
// of an arc: the bridge then takes them in, without feeds to their starts
bool flat_into_inside_bridge(const std::vector<Elem> &p, size_t k)
{
    double level = p[k].a.v;
    for (; k < p.size(); k++) {
        if (std::fabs(p[k].a.v - level) > EPS || std::fabs(p[k].b.v - level) > EPS) break;
    }
    return k < p.size() && descends(p[k]) && std::fabs(p[k].a.v - level) <= EPS &&
           bridge_lands_inside(p, k);
}

// The final contour of G71.1/G72.1: pockets bridged by a straight cut at their top level. Each
// path element starts with a feed to its start point, except where a bridge lands inside an
// arc: that bridge joins the elements it cuts into and the flat ones leading into it.
void walk_bridged(Emitter &em, const std::vector<Elem> &p)
{
    Place at;
    bool fresh = true;
    while (at.k < p.size()) {
        const Elem &e = p[at.k];
        Place h;
        bool top = descends(e) && at.t < EPS;
        if (top && find_crossing(p, at, e.a.v, true, h)) {
            if (element_start(p, at) && !lands_inside_arc(p, h)) em.feed(e.a);
            em.feed(elem_point(p[h.k], h.t));
            fresh = element_start(p, h);
            at = h;
            continue;
        }
        if (fresh && element_start(p, at) && !(at.t < EPS && flat_into_inside_bridge(p, at.k)))
            em.feed(e.a);
        follow(em, p, at, Place{at.k, 1});
        at = {at.k + 1, 0};
        fresh = true;
    }
}

// The roughing levels outside the profile: from the start level down, each cut from the start
// along +u to the path, a diagonal retract by R and a rapid back.
void rough_levels(Emitter &em, const std::vector<Elem> &p, Pt start, const Job &j)
{
    double stop = p.front().a.v;
    long n = 0;
    for (double v = start.v; v > stop + EPS; v -= j.inc) {
        if (++n > MAX_LEVELS)
            throw InterpError(j.who + ": I is too small for the stock to remove");
        Place h;
        if (!find_crossing(p, Place{}, v, true, h)) break;
        double hit = elem_point(p[h.k], h.t).u;
        em.rapid({start.u, v});
        em.feed({hit, v});
        double rr = std::fmin(j.retract, (hit - start.u) / 2);
        em.rapid({hit - rr, v + rr});
        em.rapid({start.u + rr, v + rr});
        em.rapid({start.u, v});
    }
}

// the profile of word Q
Profile load_profile(const InterpState &s, const Block &b, ProfileSource &src, const Job &j)
{
    if (!b.word('q')) throw InterpError("Q word missing with " + j.who);
    std::string name = std::to_string(std::lround(b.value('q')));
    return read_profile(s, src.sub_blocks(name), j.start, j.who);
}

// the frame of a cycle: the cut runs from the profile start to its end along +u, the start
// point lies on the +v side of the profile start
Frame make_frame(const Profile &prof, const Job &j)
{
    Frame f;
    f.swap = j.code >= 720;
    Pt a = prof.start, z = prof.elems.back().b, s = j.start;
    double c0 = f.swap ? a.v : a.u, c1 = f.swap ? z.v : z.u;
    f.cdir = c1 >= c0 ? 1 : -1;
    double s0 = f.swap ? a.u : a.v, sv = f.swap ? s.u : s.v;
    f.vsign = sv >= s0 ? 1 : -1;
    return f;
}

// the profile in the cycle frame; monotonic along the cut; closed to the start level for roughing
std::vector<Elem> frame_path(const Profile &prof, const Frame &f, const Job &j, double v0)
{
    std::vector<Elem> path;
    for (const Elem &e : prof.elems) path.push_back(f.to(e));
    for (const Elem &e : split_monotonic(path))
        if (e.b.u < e.a.u - 1e-7)
            throw InterpError(j.who + ": the profile must be monotonic in " +
                              (f.swap ? "X" : "Z"));
    Pt end = path.back().b;
    if (j.code != 700 && end.v < v0 - EPS) path.push_back(Elem{false, end, {end.u, v0}, {}, false});
    return path;
}

// G71/G72 and their .1/.2 forms
void rough(Emitter &em, const std::vector<Elem> &path, Pt start, const Job &j)
{
    int sub = j.code % 10;
    std::vector<Elem> whole = offset_envelope(path, j.d);
    if (whole.empty()) throw InterpError(j.who + ": the profile is empty");
    for (size_t i = 0; i < whole.size(); i++) whole[i].id = (int)i;
    std::vector<Elem> env = split_monotonic(whole);
    Pt ps = env.front().a;
    em.rapid(start);
    if (sub == 2) {
        em.rapid(ps);
        return walk(em, env, j);
    }
    rough_levels(em, env, start, j);
    bool above = em.at().v > ps.v + EPS;
    if (above) em.rapid(ps);
    if (sub == 1) return walk_bridged(em, env);
    if (!above) em.feed(ps);
    walk(em, env, j);
}

// G70: P passes from distance D down to E (the last on E), each from the start point
void finish(Emitter &em, const std::vector<Elem> &path, Pt start, const Job &j)
{
    if (j.passes < 1 || j.passes > MAX_LEVELS)
        throw InterpError("G70: P must be 1 to " + std::to_string(MAX_LEVELS));
    em.rapid(start);
    for (long k = j.passes; k >= 1; k--) {
        double d = (k - 1) * (j.d - j.e) / j.passes + j.e;
        std::vector<Elem> env = offset_envelope(path, d);
        if (env.empty()) throw InterpError("G70: the profile is empty");
        if (k < j.passes) em.rapid(start);
        em.rapid(env.front().a);
        for (const Elem &e : env) em.along(e);
    }
}

// the words of a cycle block
Job read_job(const InterpState &s, const Block &b, int code)
{
    Job j;
    j.code = code;
    j.who = "G" + std::to_string(code / 10) + (code % 10 ? "." + std::to_string(code % 10) : "");
    double scale = s.lathe_diameter ? 0.5 : 1.0;
    Pt cur{s.current[AX_Z], s.current[AX_X]};
    j.moved = b.word('x') || b.word('z');
    j.start = cur;
    if (b.word('x')) j.start.v = (s.distance_incremental ? cur.v : 0) + b.value('x') * scale;
    if (b.word('z')) j.start.u = (s.distance_incremental ? cur.u : 0) + b.value('z');
    j.d = word_or(b, 'd', 0);
    j.e = word_or(b, 'e', 0);
    j.inc = word_or(b, 'i', 1.0);
    j.retract = word_or(b, 'r', 0.5);
    j.passes = b.word('p') ? std::lround(b.value('p')) : 1;
    if (j.d < 0 || j.e < 0) throw InterpError(j.who + ": D and E must not be negative");
    if (code != 700 && j.inc <= 0) throw InterpError(j.who + ": I (cutting increment) must be greater than 0");
    if (code != 700 && j.retract < 0) throw InterpError(j.who + ": R (retract distance) must not be negative");
    return j;
}

} // namespace

// G70 G71 G71.1 G71.2 G72 G72.1 G72.2
void execute_lathe(InterpState &s, const Block &b, Canon &canon, ProfileSource &src)
{
    int code = s.motion_mode;
    if (s.plane != CANON_PLANE_XZ)
        throw InterpError("G" + std::to_string(code / 10) + " is only allowed in the XZ plane (G18)");
    if (s.feed_mode == FEED_INVERSE_TIME)
        throw InterpError("Cannot use inverse time feed with canned cycles");
    if (s.feed_rate <= 0) throw InterpError("Cannot feed with zero feed rate");
    Job j = read_job(s, b, code);
    Profile prof = load_profile(s, b, src, j);
    Frame f = make_frame(prof, j);
    CycleMoves mv(s, canon, plane_axes(CANON_PLANE_XZ), s.sequence_number);
    Emitter em(mv, f);
    Pt start = f.to(j.start);
    std::vector<Elem> path = frame_path(prof, f, j, start.v);
    if (j.moved) em.rapid(start);
    if (code == 700) finish(em, path, start, j);
    else rough(em, path, start, j);
}

}  // namespace cycles
