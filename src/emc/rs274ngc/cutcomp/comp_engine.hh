// comp_engine.hh: the cutter radius compensation engine: offsets programmed moves and joins them at corners.
#ifndef OPENEMC_RS274NGC_COMP_ENGINE_HH
#define OPENEMC_RS274NGC_COMP_ENGINE_HH

#include "../interp_hooks.hh"
#include "comp_filter.hh"

namespace cutcomp {

// corners turning less than this (radians) either way are tangent: no arc, no trim
constexpr double TOLERANCE_CONCAVE_CORNER = 0.05;

// Receives programmed moves and emits LinuxCNC's compensated path: the entry move ends a tool
// radius beside the programmed end, perpendicular to the entry; every later move is offset by the
// radius; a convex corner gets an arc of the tool radius about the programmed corner; a concave
// corner moves the end of the held move back to where the two offset paths meet. Each move is
// held until the next one shows which kind of corner follows it.
class CompEngine : public CompFilter, public Engine {
public:
    // compensate for interpreter state s, writing to out
    CompEngine(InterpState &s, Canon &out);

    // Engine interface (interp_hooks.hh)
    Canon &canon() override { return *this; }
    void start(InterpState &s) override;
    void stop(InterpState &s) override;
    void flush() override { flush_all(); }
    void reset() override;

    // the three moves the interpreter sends with programmed end points
    void straight_traverse(int line, const CanonPose &p) override;
    void straight_feed(int line, const CanonPose &p) override;
    void arc_feed(int line, double first_end, double second_end, double first_axis,
                  double second_axis, int rotation, double axis_end, double a, double b,
                  double c, double u, double v, double w) override;

protected:
    void flush_all() override;

private:
    // true when moves must be compensated
    bool compensating() const { return active_ && radius_ > 0; }
    // true when the tool runs inside an arc of the given direction (left of CCW, right of CW)
    bool tool_inside(int rotation) const { return left_ == (rotation > 0); }
    // a straight move, compensated or passed through
    void straight_move(HeldMove::Kind kind, int line, const CanonPose &p);
    // first compensated straight move: ends a radius beside its end, perpendicular to it
    void entry_line(HeldMove::Kind kind, int line, const Pose &end);
    // first compensated arc: ends a radius beside its end, center moved so it starts here
    void entry_arc(int line, const Pose &end, Vec2 center, int rotation);
    // a later straight move: corner with the held move, then held itself
    void next_line(HeldMove::Kind kind, int line, const Pose &end);
    // a later arc: corner with the held move, then held itself
    void next_arc(int line, const Pose &end, Vec2 center, int rotation);
    // concave corner from a held line or arc into a new line to p: the new start point
    Vec2 concave_line_start(double theta, double beta, double gamma, Vec2 p);
    // concave corner from a held line into a new arc (end radius arc_radius, offset radius r2)
    Vec2 line_arc_corner(double theta, Vec2 center, double arc_radius, double r2, int rotation);
    // concave corner from a held arc into a new arc of compensated radius r2 about center
    Vec2 arc_arc_corner(Vec2 center, double r2, int rotation);
    // the convex corner arc about the programmed corner, ending at `to`
    void corner_arc(int line, Vec2 to, const Pose &end);
    // move the end of every held move to x (checking none reverses), emit them, x starts the next
    void move_end_and_flush(Vec2 x);
    // check that moving the held arc m's end to x keeps its radius and direction
    void check_arc_end(const HeldMove &m, Vec2 x) const;
    // emit everything held; the next move's start is unknown to the reversal checks
    void dequeue();
    // the start of the next held move (for the reversal checks)
    void set_endpoint(Vec2 x);
    // hold a compensated move
    void hold(HeldMove::Kind kind, int line, const Pose &end, Vec2 to, double perp, Vec2 dir);

    InterpState &s_;
    CompAxes ax_;
    bool active_ = false;          // G41/G42 in effect
    bool left_ = true;             // G41
    int orientation_ = 0;          // lathe tool orientation
    double radius_ = 0;
    Vec2 shift_;                   // lathe tool-tip shift of the emitted path
    bool first_ = true;            // next compensated move is the entry move
    bool arc_not_allowed_ = false; // G40 done, the exit move has not come yet
    Vec2 prog_;                    // programmed plane point at the end of the held path
    Vec2 cur_;                     // compensated plane point there
    double cur_perp_ = 0;          // perpendicular axis there
    Vec2 endpoint_;                // start of the held move
    bool endpoint_valid_ = false;
};

}  // namespace cutcomp

#endif
