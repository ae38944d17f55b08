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

/* Head rotation Q = Rz(spindle) * Rn(nutation) and the tool vector v = Q * (P + L z). */
static void trsrn_head(const trsrn_geom_t *g, double spindle_deg, double nutation_deg,
                       double head[3])
{
    double lean = g->nut_angle;
    double axis[3] = {0.0, 0.0, 0.0};
    rot3_t lean_up = rot3_principal(g->nutation_axis == ROT_X ? ROT_Y : ROT_X,
                                    g->nutation_axis == ROT_X ? -lean : lean);
    axis[g->nutation_axis == ROT_X ? 0 : 1] = 1.0;
    rot3_apply(&lean_up, axis, axis);
    rot3_t rn = rot3_about(axis, nutation_deg);
    rot3_t rz = rot3_principal(ROT_Z, spindle_deg);
    rot3_t q = rot3_mul(&rz, &rn);
    double v[3] = {g->pivot[0], g->pivot[1], g->pivot[2] + g->tool_offset};
    rot3_apply(&q, v, head);
}

/* joints = Rt(table) * (world - L z - T) + T - P + Q * (P + L z). */
int trsrn_inverse(const trsrn_geom_t *g, const double world[3], double table_deg,
                  double spindle_deg, double nutation_deg, double joints[3])
{
    double q[3], head[3];
    rot3_t rt = rot3_principal(g->table_axis, table_deg);
    for (int i = 0; i < 3; i++)
        q[i] = world[i] - g->rot_axis[i];
    q[2] -= g->tool_offset;
    rot3_apply(&rt, q, q);
    trsrn_head(g, spindle_deg, nutation_deg, head);
    for (int i = 0; i < 3; i++)
        joints[i] = q[i] + g->rot_axis[i] - g->pivot[i] + head[i];
    return rot3_all_finite(joints, 3) ? 0 : -1;
}

/* world = Rt^T * (joints + P - Q * (P + L z) - T) + T + L z. */
int trsrn_forward(const trsrn_geom_t *g, const double joints[3], double table_deg,
                  double spindle_deg, double nutation_deg, double world[3])
{
    double q[3], head[3];
    rot3_t rt = rot3_principal(g->table_axis, table_deg);
    trsrn_head(g, spindle_deg, nutation_deg, head);
    for (int i = 0; i < 3; i++)
        q[i] = joints[i] + g->pivot[i] - head[i] - g->rot_axis[i];
    rot3_apply_inv(&rt, q, q);
    for (int i = 0; i < 3; i++)
        world[i] = q[i] + g->rot_axis[i];
    world[2] += g->tool_offset;
    return rot3_all_finite(world, 3) ? 0 : -1;
}
