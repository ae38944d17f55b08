/* trsrn_math.h: LinuxCNC's xyzacb_trsrn / xyzbca_trsrn formulas (rotary table, nutating secondary and
 * primary spindle rotaries) and xyzab_tdr_kins (dual rotary table), as pure functions. */
#ifndef FIVEAXIS_TRSRN_MATH_H
#define FIVEAXIS_TRSRN_MATH_H

/* Geometry of a trsrn machine (the kinematics pins; angles as the pins give them). */
typedef struct {
    double dt;          /* tool-offset-z */
    double l_pivot;     /* y-pivot (acb) or x-pivot (bca) */
    double lz;          /* z-pivot */
    double dx, dy;      /* x-offset, y-offset */
    double rot_axis;    /* y-rot-axis (acb) or x-rot-axis (bca) */
    double z_rot_axis;
    double pre_rot;     /* radians */
    double nut_angle;   /* degrees */
    double primary;     /* primary-angle for TOOL, degrees */
    double secondary;   /* secondary-angle for TOOL, degrees */
} trsrn_geom_t;

/* Which trsrn machine. */
typedef enum { TRSRN_ACB, TRSRN_BCA } trsrn_variant_t;

/* TCP (type 1): world XYZ from joints 0..5; joints 0..2 from world XYZ with the rotary angles taken from
 * joints[3..5] (the previous joint values, as motion passes them). */
void trsrn_tcp_forward(trsrn_variant_t v, const trsrn_geom_t *g, const double *joints, double xyz[3]);
void trsrn_tcp_inverse(trsrn_variant_t v, const trsrn_geom_t *g, const double xyz[3], double *joints);
/* TOOL (type 2, tilted work plane): the head angles come from g->primary and g->secondary. */
void trsrn_tool_forward(trsrn_variant_t v, const trsrn_geom_t *g, const double *joints, double xyz[3]);
void trsrn_tool_inverse(trsrn_variant_t v, const trsrn_geom_t *g, const double xyz[3], double *joints);

/* Geometry of xyzab_tdr_kins (the kinematics pins). */
typedef struct {
    double dt, dx, dz;          /* tool-offset-z, x-offset, z-offset */
    double xr, yr, zr;          /* x/y/z-rot-point */
} tdr_geom_t;

/* TCP of xyzab_tdr_kins: joints 0..4 <-> X Y Z (A, B copied by the caller). */
void tdr_tcp_forward(const tdr_geom_t *g, const double *joints, double xyz[3]);
void tdr_tcp_inverse(const tdr_geom_t *g, const double xyz[3], double a_deg, double b_deg, double *joints);

#endif
