/* fiveaxis_roundtrip.c: forward(inverse(p)) == p and inverse(forward(j)) == j over pose grids. */
#include <math.h>
#include <stdio.h>
#include "emc/kinematics/fiveaxis/rotary_math.h"
#include "emc/kinematics/fiveaxis/trsrn_math.h"
#include "fiveaxis_unit.h"

#define TOLERANCE 1e-9

static const double positions[] = {-50.0, 0.0, 37.5};
static const double tilts[] = {-90.0, -45.0, 0.0, 30.0, 90.0, 120.0};
static const double turns[] = {-30.0, 0.0, 45.0, 135.0, 270.0};

#define NPOS (int)(sizeof(positions) / sizeof(positions[0]))
#define NTILT (int)(sizeof(tilts) / sizeof(tilts[0]))
#define NTURN (int)(sizeof(turns) / sizeof(turns[0]))

/* Which machine a grid point is run through. */
typedef enum { M_AC, M_BC, M_AB, M_AC_CONV, M_5AXIS, M_ACB, M_BCA, M_ACB_TOOL, M_BCA_TOOL, M_MAX,
               M_COUNT } machine_t;

static const char *const machine_names[M_COUNT] = {
    "xyzac-trt", "xyzbc-trt", "xyzab-tdr", "xyzac-trt conventional", "5axiskins",
    "xyzacb-trsrn TCP", "xyzbca-trsrn TCP", "xyzacb-trsrn TOOL", "xyzbca-trsrn TOOL", "maxkins"
};

/* The trsrn machines (LinuxCNC's formulas) in one direction; angles t, r as table/secondary/primary. */
static int run_trsrn(machine_t m, int dir, const double in[3], double t, double r, double out[3])
{
    trsrn_variant_t v = (m == M_ACB || m == M_ACB_TOOL) ? TRSRN_ACB : TRSRN_BCA;
    int tool = m == M_ACB_TOOL || m == M_BCA_TOOL;
    trsrn_geom_t g = {33, 40, 120, 10, -5, 60, -90, 0.3, 45, t + r, r};
    double j[6] = {in[0], in[1], in[2], r, t, t + r};
    if (dir) {
        (tool ? trsrn_tool_inverse : trsrn_tcp_inverse)(v, &g, in, j);
        out[0] = j[0], out[1] = j[1], out[2] = j[2];
    } else {
        (tool ? trsrn_tool_forward : trsrn_tcp_forward)(v, &g, j, out);
    }
    return isfinite(out[0]) && isfinite(out[1]) && isfinite(out[2]) ? 0 : -1;
}

/* xyzab_tdr_kins (LinuxCNC's formulas) in one direction at A t, B r. */
static int run_tdr(int dir, const double in[3], double t, double r, double out[3])
{
    tdr_geom_t g = {18, -5, 33, 2, 3, 4};
    double j[5] = {in[0], in[1], in[2], t, r};
    if (dir) {
        tdr_tcp_inverse(&g, in, t, r, j);
        out[0] = j[0], out[1] = j[1], out[2] = j[2];
    } else {
        tdr_tcp_forward(&g, j, out);
    }
    return 0;
}

/* Largest component difference of two 3-vectors. */
static double diff3(const double a[3], const double b[3])
{
    return fmax(fabs(a[0] - b[0]), fmax(fabs(a[1] - b[1]), fabs(a[2] - b[2])));
}

/* One direction of one machine: out = fwd (dir 0) or inv (dir 1) of in at angles t, r, n. */
static int run(machine_t m, int dir, const double in[3], double t, double r, double out[3])
{
    table2_geom_t ac = {ROT_X, ROT_Z, {12, -7, 30}, {1.5, 4, 60}, 25, m == M_AC_CONV};
    table2_geom_t bc = {ROT_Y, ROT_Z, {-3, 8, 20}, {6, -2, 45}, 12, 0};
    const table2_geom_t *tg = m == M_BC ? &bc : &ac;
    if (m == M_5AXIS)
        return dir ? pivot5_inverse(250, in, t, r, 7.5, out) : pivot5_forward(250, in, t, r, 7.5, out);
    if (m == M_AB)
        return run_tdr(dir, in, t, r, out);
    if (m >= M_ACB && m <= M_BCA_TOOL)
        return run_trsrn(m, dir, in, t, r, out);
    return dir ? table2_inverse(tg, in, t, r, out) : table2_forward(tg, in, t, r, out);
}

/* maxkins with U, V, W set: 9-value round trip error. */
static double max_roundtrip(const double p[3], double t, double r)
{
    double world[9] = {p[0], p[1], p[2], 5, t, r, 0.25, -0.5, 0.125}, joints[9], back[9], err = 0;
    if (maxkins_inverse(0.666, 0, world, joints) < 0 || maxkins_forward(0.666, 0, joints, back) < 0)
        return INFINITY;
    for (int i = 0; i < 9; i++)
        err = fmax(err, fabs(back[i] - world[i]));
    return err;
}

/* Both round trips at one grid point; the larger error. */
static double roundtrip_one(machine_t m, const double p[3], double t, double r)
{
    double mid[3], back[3];
    if (m == M_MAX)
        return max_roundtrip(p, t, r);
    if (run(m, 1, p, t, r, mid) < 0 || run(m, 0, mid, t, r, back) < 0)
        return INFINITY;
    double e = diff3(p, back);
    if (run(m, 0, p, t, r, mid) < 0 || run(m, 1, mid, t, r, back) < 0)
        return INFINITY;
    return fmax(e, diff3(p, back));
}

/* Grid of one machine; prints the count and whether every error is within tolerance. */
static void roundtrip_machine(machine_t m)
{
    int count = 0;
    double worst = 0.0;
    for (int x = 0; x < NPOS; x++)
        for (int y = 0; y < NPOS; y++)
            for (int z = 0; z < NPOS; z++)
                for (int t = 0; t < NTILT; t++)
                    for (int r = 0; r < NTURN; r++) {
                        double p[3] = {positions[x], positions[y], positions[z]};
                        worst = fmax(worst, roundtrip_one(m, p, tilts[t], turns[r]));
                        count++;
                    }
    if (worst <= TOLERANCE)
        printf("round trip %s: %d poses within %g\n", machine_names[m], count, TOLERANCE);
    else
        printf("round trip %s: %d poses, error %g\n", machine_names[m], count, worst);
}

/* Round trips over grids of poses for every machine; prints one line per machine. */
void roundtrip_all(void)
{
    for (int m = 0; m < M_COUNT; m++)
        roundtrip_machine((machine_t)m);
}
