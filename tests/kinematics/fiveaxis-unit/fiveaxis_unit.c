/* fiveaxis_unit.c: hand-computed poses, refusals and joint mapping of the 5/6-axis kinematics. */
#include <math.h>
#include <stdio.h>
#include "emc/kinematics/fiveaxis/rotary_math.h"
#include "emc/kinematics/fiveaxis/trsrn_math.h"
#include "emc/kinematics/fiveaxis/axis_map.h"
#include "fiveaxis_unit.h"

/* Print a labelled rc and three values (rounded so -0 prints as 0). */
static void show3(const char *label, int rc, const double v[3])
{
    printf("%s: %d %.6f %.6f %.6f\n", label, rc, v[0] + 0.0, v[1] + 0.0, v[2] + 0.0);
}

/* Trunnion tables: rotations about the rot point, offsets of the tilt axis, tool length. */
static void table2_known(void)
{
    table2_geom_t ac = {ROT_X, ROT_Z, {0, 0, 0}, {0, 0, 0}, 0, 0};
    double w[3] = {10, 0, 0}, j[3];
    show3("ac C90 (10,0,0)", table2_inverse(&ac, w, 0, 90, j), j);
    double w2[3] = {0, 10, 0};
    show3("ac A90 (0,10,0)", table2_inverse(&ac, w2, 90, 0, j), j);
    ac.conventional = 1;
    show3("ac conventional A90 (0,10,0)", table2_inverse(&ac, w2, 90, 0, j), j);
    ac.conventional = 0;
    ac.offset[2] = 20;
    double w3[3] = {0, 0, 0};
    show3("ac z-offset 20 A90 (0,0,0)", table2_inverse(&ac, w3, 90, 0, j), j);
    ac.offset[2] = 0;
    ac.tool_offset = 10;
    double w4[3] = {0, 0, 10};
    show3("ac tool 10 A90 (0,0,10)", table2_inverse(&ac, w4, 90, 0, j), j);
    ac.tool_offset = 0;
    ac.rot_point[0] = 5;
    show3("ac x-rot-point 5 C180 (10,0,0)", table2_inverse(&ac, w, 0, 180, j), j);
    table2_geom_t bc = {ROT_Y, ROT_Z, {0, 0, 0}, {0, 0, 0}, 0, 0};
    show3("bc B90 (10,0,0)", table2_inverse(&bc, w, 90, 0, j), j);
    double back[3];
    show3("bc B90 forward (0,0,-10)", table2_forward(&bc, j, 90, 0, back), back);
    table2_geom_t ab = {ROT_X, ROT_Y, {0, 0, 0}, {0, 0, 0}, 0, 0};
    show3("ab B90 (10,0,0)", table2_inverse(&ab, w, 0, 90, j), j);
}

/* Tilting heads: 5axiskins arm and maxkins head/table terms. */
static void pivot_known(void)
{
    double j[3] = {1, 2, 3}, w[3];
    show3("5axis L250 B0 C0", pivot5_forward(250, j, 0, 0, 0, w), w);
    show3("5axis L250 B90 C0", pivot5_forward(250, j, 90, 0, 0, w), w);
    show3("5axis L250 B90 C90", pivot5_forward(250, j, 90, 90, 0, w), w);
    show3("5axis L250 B0 W10", pivot5_forward(250, j, 0, 0, 10, w), w);
    double world[3] = {0, 0, 0};
    show3("5axis inverse L100 B-90 C0", pivot5_inverse(100, world, -90, 0, 0, j), j);
    double mj[9] = {1, 2, 3, 0, 90, 0, 0, 0, 0}, mw[9];
    int rc = maxkins_forward(1, 0, mj, mw);
    show3("max L1 B90", rc, mw);
    double mj2[9] = {1, 2, 3, 0, 0, 90, 0, 0, 0};
    show3("max L1 C90", maxkins_forward(1, 0, mj2, mw), mw);
    show3("max L1 C90 conventional", maxkins_forward(1, 1, mj2, mw), mw);
    double mj3[9] = {0, 0, 0, 0, 0, 0, 2, 3, 4};
    show3("max L1 U2 V3 W4", maxkins_forward(1, 0, mj3, mw), mw);
}

/* LinuxCNC's trsrn TCP by hand: only a 10 mm tool and A at 90 degrees; joints (0, 0, 0) are world (0, 10, 10). */
static void trsrn_known(void)
{
    trsrn_geom_t g = {10, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0};
    double j[6] = {0, 0, 0, 90, 0, 0}, w[3];
    trsrn_tcp_forward(TRSRN_ACB, &g, j, w);
    show3("acb TCP tool 10 A90", 0, w);
    double q[3] = {0, 10, 10};
    trsrn_tcp_inverse(TRSRN_ACB, &g, q, j);
    show3("acb TCP inverse of it", 0, j);
}

/* Non-finite input is refused instead of producing NaN joints. */
static void refusals(void)
{
    table2_geom_t ac = {ROT_X, ROT_Z, {0, 0, 0}, {0, 0, 0}, 0, 0};
    double nan_w[3] = {NAN, 0, 0}, ok[3] = {1, 2, 3}, out[3];
    double mj[9] = {0, 0, 0, 0, INFINITY, 0, 0, 0, 0}, mo[9];
    printf("refused: table2 inv %d fwd %d, 5axis inv %d fwd %d, max %d %d\n",
           table2_inverse(&ac, nan_w, 0, 0, out), table2_forward(&ac, ok, INFINITY, 0, out),
           pivot5_inverse(250, ok, NAN, 0, 0, out), pivot5_forward(NAN, ok, 0, 0, 0, out),
           maxkins_forward(1, 0, mj, mo), maxkins_inverse(NAN, 0, mj, mo));
}

/* coordinates= checks and the XYZ splice of the switchable modules. */
static void mapping(void)
{
    kins_coords_t c;
    char why[120];
    kins_coords_parse("xyzac", &c, why, sizeof(why));
    printf("missing in xyzac: B=%c C=%d\n", axis_map_missing(&c, "XYZBC"),
           axis_map_missing(&c, "XYZAC"));
    kins_coords_parse("xyyzbcw", &c, why, sizeof(why));
    double joints[7] = {1, 2, 2, 3, 45, 90, 5}, axes[9], xyz[3] = {7, 8, 9};
    axis_map_joint_axes(&c, joints, axes);
    printf("axes: %g %g %g %g %g %g %g %g %g\n", axes[0], axes[1], axes[2], axes[3], axes[4],
           axes[5], axes[6], axes[7], axes[8]);
    EmcPose p = {{0, 0, 0}, -1, -1, -1, -1, -1, -1};
    axis_map_forward_pose(&c, joints, xyz, &p);
    printf("pose: %g %g %g a=%g b=%g c=%g w=%g\n", p.tran.x, p.tran.y, p.tran.z, p.a, p.b, p.c,
           p.w);
    double out[7];
    axis_map_inverse_joints(&c, &p, xyz, out);
    printf("joints: %g %g %g %g %g %g %g\n", out[0], out[1], out[2], out[3], out[4], out[5],
           out[6]);
}

int main(void)
{
    table2_known();
    pivot_known();
    trsrn_known();
    refusals();
    mapping();
    roundtrip_all();
    return 0;
}
