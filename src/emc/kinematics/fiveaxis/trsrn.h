/* trsrn.h: shared glue of xyzacb_trsrn and xyzbca_trsrn (table rotary, spindle rotary, nutating). */
#ifndef FIVEAXIS_TRSRN_H
#define FIVEAXIS_TRSRN_H

/* Joint slots: 0..2 XYZ, 3 table rotary, 4 spindle rotary (C), 5 nutation. */
enum { TRSRN_TABLE = 3, TRSRN_SPINDLE = 4, TRSRN_NUTATION = 5 };

/* Which machine axes the module's table and nutation axes are; each trsrn module defines it. */
typedef struct {
    int table_axis;      /* ROT_X (A table) or ROT_Y (B table) */
    int nutation_axis;   /* ROT_X or ROT_Y: the nutation axis leans from it */
} trsrn_variant_t;
extern const trsrn_variant_t trsrn_variant;

/* Make the geometry pins under prefix; 0 or negative errno. */
int trsrn_setup(int comp_id, const char *prefix);
/* TCP forward of the module's variant (tcpswitch_def.tcp_forward). */
int trsrn_tcp_forward(const double *joints, double *world);
/* TCP inverse of trsrn_tcp_forward. */
int trsrn_tcp_inverse(const double *world, double *joints);

#endif
