/* trsrn_math.c: LinuxCNC's trsrn (TCP and TOOL, both machine variants) and tdr formulas. */
#include <math.h>
#include "trsrn_math.h"

#define DEG (M_PI / 180.0)

/* Sines and cosines and the nutation terms shared by every formula. */
typedef struct {
    double sw, cw, ss, cs, sp, cp, sv, cv, stc, ctc;
    double r, s, t, cvss, svss;
} trsrn_trig_t;

/* Trig terms for table w, secondary s and primary p (degrees) with the geometry's nutation and pre-rotation. */
static trsrn_trig_t trsrn_trig(const trsrn_geom_t *g, double w, double sec, double pri)
{
    trsrn_trig_t k;
    k.sw = sin(w * DEG); k.cw = cos(w * DEG);
    k.ss = sin(sec * DEG); k.cs = cos(sec * DEG);
    k.sp = sin(pri * DEG); k.cp = cos(pri * DEG);
    k.sv = sin(g->nut_angle * DEG); k.cv = cos(g->nut_angle * DEG);
    k.stc = sin(g->pre_rot); k.ctc = cos(g->pre_rot);
    k.r = k.cs + k.sv * k.sv * (1 - k.cs);
    k.s = k.cs + k.cv * k.cv * (1 - k.cs);
    k.t = k.sv * k.cv * (1 - k.cs);
    k.cvss = k.cv * k.ss;
    k.svss = k.sv * k.ss;
    return k;
}

/* Table, secondary and primary joint values of the variant (acb: A B C; bca: B A C). */
static void trsrn_angles(trsrn_variant_t v, const double *joints, double *w, double *sec, double *pri)
{
    *w = v == TRSRN_ACB ? joints[3] : joints[4];
    *sec = v == TRSRN_ACB ? joints[4] : joints[3];
    *pri = joints[5];
}

/* xyzacb TCP forward. */
static void acb_tcp_forward(const trsrn_geom_t *g, const trsrn_trig_t *k, const double *P, double *o)
{
    double Dt = g->dt, Lz = g->lz, Ly = g->l_pivot, Dx = g->dx, Dy = g->dy;
    double Dray = g->rot_axis - (Dy + Ly), Draz = g->z_rot_axis - Lz;
    o[0] = -(k->cp * k->svss - k->sp * k->t) * (Dt + Lz) - k->cp * Dx + (k->cp * k->cvss + k->sp * k->r) * Ly
           + Dy * k->sp + Dx + P[0];
    o[1] = -k->cp * k->cw * Dy - k->cw * Dx * k->sp - k->cw * (Dray - P[1])
           - (k->cw * k->sp * k->svss + k->cp * k->cw * k->t - k->sw * k->s) * (Dt + Lz)
           + (k->cvss * k->cw * k->sp - k->cp * k->cw * k->r + k->sw * k->t) * Ly + (Draz - P[2]) * k->sw
           + Dray + Dy + Ly;
    o[2] = -k->cp * Dy * k->sw - Dx * k->sp * k->sw - k->cw * (Draz - P[2])
           - (k->sp * k->svss * k->sw + k->cp * k->sw * k->t + k->cw * k->s) * (Dt + Lz)
           + (k->cvss * k->sp * k->sw - k->cp * k->sw * k->r - k->cw * k->t) * Ly - (Dray - P[1]) * k->sw
           + Draz + Dt + Lz;
}

/* xyzacb TCP inverse. */
static void acb_tcp_inverse(const trsrn_geom_t *g, const trsrn_trig_t *k, const double *Q, double *j)
{
    double Dt = g->dt, Lz = g->lz, Ly = g->l_pivot, Dx = g->dx, Dy = g->dy;
    double Dray = g->rot_axis - (Dy + Ly), Draz = g->z_rot_axis - Lz;
    j[0] = (k->cp * k->svss - k->sp * k->t) * (Dt + Lz) + k->cp * Dx - (k->cp * k->cvss + k->sp * k->r) * Ly
           - Dy * k->sp - Dx + Q[0];
    j[1] = k->cp * Dy + Dx * k->sp - k->cw * (Dray + Dy + Ly - Q[1]) + (k->sp * k->svss + k->cp * k->t) * (Dt + Lz)
           - (k->cvss * k->sp - k->cp * k->r) * Ly - (Draz + Dt + Lz - Q[2]) * k->sw + Dray;
    j[2] = (Dt + Lz) * k->s + Ly * k->t - k->cw * (Draz + Dt + Lz - Q[2]) + (Dray + Dy + Ly - Q[1]) * k->sw + Draz;
}

/* xyzacb TOOL forward. */
static void acb_tool_forward(const trsrn_geom_t *g, const trsrn_trig_t *k, const double *P, double *o)
{
    double Lz = g->lz, Ly = g->l_pivot, Dx = g->dx, Dy = g->dy;
    double a = k->cs * k->ctc - k->cvss * k->stc, b = k->ctc * k->cvss + k->stc * k->r;
    double c = k->ctc * k->cvss + k->cs * k->stc, d = k->cvss * k->stc - k->ctc * k->r;
    o[0] = (a * k->cp - b * k->sp) * (Dx + P[0]) - a * Dx + (b * k->cp + a * k->sp) * (Dy + Ly + P[1]) - b * Dy
           - (k->ctc * k->svss - k->stc * k->t) * (Lz + P[2]) - Ly * k->stc;
    o[1] = -(c * k->cp - d * k->sp) * (Dx + P[0]) + c * Dx - (d * k->cp + c * k->sp) * (Dy + Ly + P[1]) + d * Dy
           - k->ctc * Ly + (k->stc * k->svss + k->ctc * k->t) * (Lz + P[2]);
    o[2] = (k->cp * k->svss - k->sp * k->t) * (Dx + P[0]) + (k->sp * k->svss + k->cp * k->t) * (Dy + Ly + P[1])
           - Dx * k->svss + (Lz + P[2]) * k->s - Dy * k->t - Lz;
}

/* xyzacb TOOL inverse. */
static void acb_tool_inverse(const trsrn_geom_t *g, const trsrn_trig_t *k, const double *Q, double *j)
{
    double Lz = g->lz, Ly = g->l_pivot, Dx = g->dx, Dy = g->dy;
    double e = k->cp * k->cs - k->cvss * k->sp, f = k->cp * k->cvss + k->sp * k->r;
    double h = k->cp * k->cvss + k->cs * k->sp, m = k->cvss * k->sp - k->cp * k->r;
    j[0] = k->cp * Dx - f * Ly + (k->cp * k->svss - k->sp * k->t) * Lz + (e * k->ctc - f * k->stc) * Q[0]
           - (f * k->ctc + e * k->stc) * Q[1] + (k->cp * k->svss - k->sp * k->t) * Q[2] - Dy * k->sp - Dx;
    j[1] = k->cp * Dy - m * Ly + (k->sp * k->svss + k->cp * k->t) * Lz + (h * k->ctc - m * k->stc) * Q[0]
           - (m * k->ctc + h * k->stc) * Q[1] + (k->sp * k->svss + k->cp * k->t) * Q[2] + Dx * k->sp - Dy - Ly;
    j[2] = -(k->ctc * k->svss - k->stc * k->t) * Q[0] + (k->stc * k->svss + k->ctc * k->t) * Q[1] + Lz * k->s
           + Q[2] * k->s + Ly * k->t - Lz;
}

/* xyzbca TCP forward. */
static void bca_tcp_forward(const trsrn_geom_t *g, const trsrn_trig_t *k, const double *P, double *o)
{
    double Dt = g->dt, Lz = g->lz, Lx = g->l_pivot, Dx = g->dx, Dy = g->dy;
    double Drax = g->rot_axis - Lx - Dx, Draz = g->z_rot_axis - Lz;
    o[0] = -k->cp * k->cw * Dx + k->cw * Dy * k->sp - k->cw * (Drax - P[0])
           - (k->cw * k->sp * k->svss + k->cp * k->cw * k->t + k->sw * k->s) * (Dt + Lz)
           + (k->cvss * k->cw * k->sp - k->cp * k->cw * k->r - k->sw * k->t) * Lx - (Draz - P[2]) * k->sw
           + Drax + Dx + Lx;
    o[1] = (k->cp * k->svss - k->sp * k->t) * (Dt + Lz) - k->cp * Dy - (k->cp * k->cvss + k->sp * k->r) * Lx
           - Dx * k->sp + Dy + P[1];
    o[2] = k->cp * Dx * k->sw - Dy * k->sp * k->sw - k->cw * (Draz - P[2])
           + (k->sp * k->svss * k->sw + k->cp * k->sw * k->t - k->cw * k->s) * (Dt + Lz)
           - (k->cvss * k->sp * k->sw - k->cp * k->sw * k->r + k->cw * k->t) * Lx + (Drax - P[0]) * k->sw
           + Draz + Dt + Lz;
}

/* xyzbca TCP inverse. */
static void bca_tcp_inverse(const trsrn_geom_t *g, const trsrn_trig_t *k, const double *Q, double *j)
{
    double Dt = g->dt, Lz = g->lz, Lx = g->l_pivot, Dx = g->dx, Dy = g->dy;
    double Drax = g->rot_axis - Lx - Dx, Draz = g->z_rot_axis - Lz;
    j[0] = k->cp * Dx - Dy * k->sp - k->cw * (Drax + Dx + Lx - Q[0]) + (k->sp * k->svss + k->cp * k->t) * (Dt + Lz)
           - (k->cvss * k->sp - k->cp * k->r) * Lx + (Draz + Dt + Lz - Q[2]) * k->sw + Drax;
    j[1] = -(k->cp * k->svss - k->sp * k->t) * (Dt + Lz) + k->cp * Dy + (k->cp * k->cvss + k->sp * k->r) * Lx
           + Dx * k->sp - Dy + Q[1];
    j[2] = (Dt + Lz) * k->s + Lx * k->t - k->cw * (Draz + Dt + Lz - Q[2]) - (Drax + Dx + Lx - Q[0]) * k->sw + Draz;
}

/* xyzbca TOOL forward. */
static void bca_tool_forward(const trsrn_geom_t *g, const trsrn_trig_t *k, const double *P, double *o)
{
    double Lz = g->lz, Lx = g->l_pivot, Dx = g->dx, Dy = g->dy;
    double a = k->cvss * k->stc - k->ctc * k->r, b = k->ctc * k->cvss + k->cs * k->stc;
    double c = k->ctc * k->cvss + k->stc * k->r, d = k->cs * k->ctc - k->cvss * k->stc;
    o[0] = -(a * k->cp + b * k->sp) * (Dx + Lx + P[0]) + a * Dx + (b * k->cp - a * k->sp) * (Dy + P[1]) - b * Dy
           - k->ctc * Lx + (k->stc * k->svss + k->ctc * k->t) * (Lz + P[2]);
    o[1] = -(c * k->cp + d * k->sp) * (Dx + Lx + P[0]) + c * Dx + (d * k->cp - c * k->sp) * (Dy + P[1]) - d * Dy
           + (k->ctc * k->svss - k->stc * k->t) * (Lz + P[2]) + Lx * k->stc;
    o[2] = (k->sp * k->svss + k->cp * k->t) * (Dx + Lx + P[0]) - (k->cp * k->svss - k->sp * k->t) * (Dy + P[1])
           + Dy * k->svss + (Lz + P[2]) * k->s - Dx * k->t - Lz;
}

/* xyzbca TOOL inverse. */
static void bca_tool_inverse(const trsrn_geom_t *g, const trsrn_trig_t *k, const double *Q, double *j)
{
    double Lz = g->lz, Lx = g->l_pivot, Dx = g->dx, Dy = g->dy;
    double m = k->cvss * k->sp - k->cp * k->r, h = k->cp * k->cvss + k->cs * k->sp;
    double f = k->cp * k->cvss + k->sp * k->r, e = k->cp * k->cs - k->cvss * k->sp;
    j[0] = k->cp * Dx - m * Lx + (k->sp * k->svss + k->cp * k->t) * Lz - (m * k->ctc + h * k->stc) * Q[0]
           - (h * k->ctc - m * k->stc) * Q[1] + (k->sp * k->svss + k->cp * k->t) * Q[2] - Dy * k->sp - Dx - Lx;
    j[1] = k->cp * Dy + f * Lx - (k->cp * k->svss - k->sp * k->t) * Lz + (f * k->ctc + e * k->stc) * Q[0]
           + (e * k->ctc - f * k->stc) * Q[1] - (k->cp * k->svss - k->sp * k->t) * Q[2] + Dx * k->sp - Dy;
    j[2] = (k->stc * k->svss + k->ctc * k->t) * Q[0] + (k->ctc * k->svss - k->stc * k->t) * Q[1] + Lz * k->s
           + Q[2] * k->s + Lx * k->t - Lz;
}

/* TCP forward: angles from the joints. */
void trsrn_tcp_forward(trsrn_variant_t v, const trsrn_geom_t *g, const double *joints, double xyz[3])
{
    double w, sec, pri;
    trsrn_angles(v, joints, &w, &sec, &pri);
    trsrn_trig_t k = trsrn_trig(g, w, sec, pri);
    (v == TRSRN_ACB ? acb_tcp_forward : bca_tcp_forward)(g, &k, joints, xyz);
}

/* TCP inverse: angles from the joints as passed in (the previous joint values). */
void trsrn_tcp_inverse(trsrn_variant_t v, const trsrn_geom_t *g, const double xyz[3], double *joints)
{
    double w, sec, pri;
    trsrn_angles(v, joints, &w, &sec, &pri);
    trsrn_trig_t k = trsrn_trig(g, w, sec, pri);
    (v == TRSRN_ACB ? acb_tcp_inverse : bca_tcp_inverse)(g, &k, xyz, joints);
}

/* TOOL forward: the head angles from the primary/secondary-angle pins; the table angle is not used. */
void trsrn_tool_forward(trsrn_variant_t v, const trsrn_geom_t *g, const double *joints, double xyz[3])
{
    trsrn_trig_t k = trsrn_trig(g, 0, g->secondary, g->primary);
    (v == TRSRN_ACB ? acb_tool_forward : bca_tool_forward)(g, &k, joints, xyz);
}

/* TOOL inverse. */
void trsrn_tool_inverse(trsrn_variant_t v, const trsrn_geom_t *g, const double xyz[3], double *joints)
{
    trsrn_trig_t k = trsrn_trig(g, 0, g->secondary, g->primary);
    (v == TRSRN_ACB ? acb_tool_inverse : bca_tool_inverse)(g, &k, xyz, joints);
}

/* xyzab_tdr_kins TCP forward (A, B from joints 3 and 4). */
void tdr_tcp_forward(const tdr_geom_t *g, const double *j, double xyz[3])
{
    double sa = sin(j[3] * DEG), ca = cos(j[3] * DEG), sb = sin(j[4] * DEG), cb = cos(j[4] * DEG);
    double px = j[0] - g->xr, py = j[1] - g->yr, pz = j[2] - g->zr - g->dt;
    xyz[0] = cb * px + sb * pz + g->xr;
    xyz[1] = sa * sb * px + ca * py - cb * sa * pz + sa * g->dz + g->yr;
    xyz[2] = -ca * sb * px + sa * py + ca * cb * pz - ca * g->dz + g->zr + g->dz + g->dt;
}

/* xyzab_tdr_kins TCP inverse (A, B as requested). */
void tdr_tcp_inverse(const tdr_geom_t *g, const double xyz[3], double a_deg, double b_deg, double *j)
{
    double sa = sin(a_deg * DEG), ca = cos(a_deg * DEG), sb = sin(b_deg * DEG), cb = cos(b_deg * DEG);
    double qx = xyz[0] - g->xr - g->dx, qy = xyz[1] - g->yr, qz = xyz[2] - g->zr - g->dz - g->dt;
    j[0] = cb * qx + sa * sb * qy - ca * sb * qz + cb * g->dx - sb * g->dz + g->xr;
    j[1] = ca * qy + sa * qz + g->yr;
    j[2] = sb * qx - sa * cb * qy + ca * cb * qz + sb * g->dx + cb * g->dz + g->zr + g->dt;
}
