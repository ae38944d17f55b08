// spline_points_unit.cc: prints the NURBS_G5_FEED control points, weights and order of spline blocks.
#include <cstdio>
#include <string>

#include "emc/rs274ngc/interp.hh"
#include "emc/rs274ngc/sai_canon.hh"

namespace {

// G5 with I J, a G5 continuing without I J, G5.1, G91, a NURBS block with weights
const char *PROGRAM =
    "G20 F10\n"
    "G0 X1 Y1\n"
    "G5 I0.5 J0 P-0.5 Q0.25 X3 Y2\n"
    "G5 P0 Q-1 X5 Y0\n"
    "G5.1 I1 J-1 X7 Y0\n"
    "G5 P-1 Q0 X9 Y1\n"
    "G91 G5.1 I1 J0 X1 Y1\n"
    "G90 G5.2 X2 Y0 L3\n"
    "X3 Y3 P0.5\n"
    "X0 Y3 P2\n"
    "G5.3\n"
    "M2\n";

// sai output plus the control points of every NURBS_G5_FEED
class PointCanon : public SaiCanon {
public:
    using SaiCanon::SaiCanon;
    // print each point, then the usual line
    void nurbs_g5_feed(int line, const std::vector<CanonNurbsPoint> &pts, unsigned order,
                       CanonPlane plane) override
    {
        printf("order %u plane %d:", order, (int)plane);
        for (const CanonNurbsPoint &p : pts) printf(" (%.4f %.4f w%.2f)", p.x, p.y, p.weight);
        printf("\n");
        SaiCanon::nurbs_g5_feed(line, pts, order, plane);
    }
};

} // namespace

// run the program, printing errors like rs274
int main()
{
    std::string line;
    PointCanon canon(stdout, &line);
    Interp in(canon);
    in.set_var_file("/nonexistent/points.var");
    in.init();
    in.open_text("points.ngc", PROGRAM);
    for (;;) {
        InterpStatus st = in.execute_next();
        if (st == INTERP_EXIT) return 0;
        if (st == INTERP_ERROR) {
            printf("error: %s\n", in.error_text().c_str());
            return 1;
        }
    }
}
