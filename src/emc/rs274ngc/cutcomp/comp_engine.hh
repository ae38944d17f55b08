// comp_engine.hh: the cutter radius compensation engine: offsets programmed moves and joins them at corners.
#ifndef OPENEMC_RS274NGC_COMP_ENGINE_HH
#define OPENEMC_RS274NGC_COMP_ENGINE_HH

#include "../interp_hooks.hh"
#include "comp_filter.hh"

namespace cutcomp {

// Receives programmed moves, holds each until the next is known, and emits the compensated path.
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
    // a straight move, compensated or passed through
    void straight_move(HeldMove::Kind kind, int line, const CanonPose &p);
    // a straight move while compensating
    void line_move(HeldMove::Kind kind, int line, const Pose &end);
    // an arc while compensating
    void arc_move(int line, const Pose &end, Vec2 center, int rotation);
    // first compensated straight move (entry)
    void entry_line(HeldMove::Kind kind, int line, const Pose &end);
    // first compensated arc (entry)
    void entry_arc(int line, const Pose &end, Vec2 center, int rotation);
    // The start of a new compensated move as seen by the corner logic.
    struct Joint {
        Vec2 dir;             // programmed start direction
        double kappa = 0;     // programmed start curvature (+ counterclockwise)
        Vec2 start, end;      // untrimmed offset start and offset end
        PathShape shape;      // offset path
        Vec2 corner_point;    // programmed corner
        int rotation = 0;     // arc direction, 0 for lines
    };
    // join the held path to a new move; returns where the new move really starts
    Vec2 corner(const Joint &j);
    // the concave-corner point: where the held offset path meets the new one
    Vec2 concave_point(const Joint &j);
    // true when x lies on the new move's offset path between its start and end
    bool on_new(const Joint &j, Vec2 x) const;
    // true when x lies on the held move between its start and its end
    bool on_held(const HeldMove &m, Vec2 x) const;
    // trim the held move to the concave-corner point x, checking it is still reachable
    void trim_held(Vec2 x);
    // throw the concave-corner gouging error for the held move
    [[noreturn]] void gouge_error();
    // hold a move and remember its end (direction, curvature, offset shape) as the new path end
    void hold(const HeldMove &m, Vec2 end_dir, double end_kappa, const PathShape &end_shape);
    // +1 or -1: the offset side of an arc (-1 = toward the center)
    double arc_side(int rotation) const;
    // offset normal of a straight move of angle theta
    Vec2 line_normal(double theta) const;

    InterpState &s_;
    CompAxes ax_;
    bool active_ = false;       // G41/G42 in effect
    bool left_ = true;          // G41
    double radius_ = 0;
    Vec2 shift_;                // lathe tool-tip shift of the emitted path
    bool first_ = true;         // next compensated move is the entry move
    bool exit_pending_ = false; // G40 done, the exit move has not come yet
    Vec2 path_end_;             // compensated end of the held path
    Pose tool_end_{};           // full pose at the end of the held path
    Vec2 end_dir_;              // programmed direction at the end of the held path
    double end_kappa_ = 0;      // programmed curvature there (+ counterclockwise)
    PathShape end_shape_;       // offset shape of the last plane move
};

}  // namespace cutcomp

#endif
