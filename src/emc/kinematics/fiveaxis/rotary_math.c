/* rotary_math.c: tool-center-point transforms of dual-rotary tables (trt/tdr) and trsrn machines. */
#include "rotary_math.h"
#include "rot3.h"

/* Direction factor of conventional-directions. */
static double table2_sign(const table2_geom_t *g)
{
    return g->conventional ? -1.0 : 1.0;
}

/* Primary-axis offset including the tool length (the tool tip is the controlled point). */
static void table2_offset(const table2_geom_t *g, double d[3])
{
    d[0] = g->offset[0];
    d[1] = g->offset[1];
    d[2] = g->offset[2] + g->tool_offset;
}

/* joints = Rp(primary) * (Rs(secondary) * (world - R) - d) + d + R. */
int table2_inverse(const table2_geom_t *g, const double world[3], double primary_deg,
                   double secondary_deg, double joints[3])
{
    double s = table2_sign(g), d[3], q[3];
    rot3_t rp = rot3_principal(g->primary_axis, s * primary_deg);
    rot3_t rs = rot3_principal(g->secondary_axis, s * secondary_deg);
    table2_offset(g, d);
    for (int i = 0; i < 3; i++)
        q[i] = world[i] - g->rot_point[i];
    rot3_apply(&rs, q, q);
    for (int i = 0; i < 3; i++)
        q[i] -= d[i];
    rot3_apply(&rp, q, q);
    for (int i = 0; i < 3; i++)
        joints[i] = q[i] + d[i] + g->rot_point[i];
    return rot3_all_finite(joints, 3) ? 0 : -1;
}

/* world = Rs^T * (Rp^T * (joints - R - d) + d) + R, the exact inverse of table2_inverse. */
int table2_forward(const table2_geom_t *g, const double joints[3], double primary_deg,
                   double secondary_deg, double world[3])
{
    double s = table2_sign(g), d[3], q[3];
    rot3_t rp = rot3_principal(g->primary_axis, s * primary_deg);
    rot3_t rs = rot3_principal(g->secondary_axis, s * secondary_deg);
    table2_offset(g, d);
    for (int i = 0; i < 3; i++)
        q[i] = joints[i] - g->rot_point[i] - d[i];
    rot3_apply_inv(&rp, q, q);
    for (int i = 0; i < 3; i++)
        q[i] += d[i];
    rot3_apply_inv(&rs, q, q);
    for (int i = 0; i < 3; i++)
        world[i] = q[i] + g->rot_point[i];
    return rot3_all_finite(world, 3) ? 0 : -1;
}

