/* trsrn.h: shared glue of xyzacb_trsrn and xyzbca_trsrn (table rotary, spindle rotary, nutating). */
#ifndef FIVEAXIS_TRSRN_H
#define FIVEAXIS_TRSRN_H

/* Joint slots: 0..2 XYZ, 3 table rotary, 4 spindle rotary (C), 5 nutation. */
enum { TRSRN_TABLE = 3, TRSRN_SPINDLE = 4, TRSRN_NUTATION = 5 };

/* Make the geometry pins under prefix; 0 or negative errno. */
int trsrn_setup(int comp_id, const char *prefix);
/* TCP forward for a table about table_axis and a nutation axis leaning from nutation_axis. */
int trsrn_tcp_forward(int table_axis, int nutation_axis, const double *joints, double *world);
/* TCP inverse of trsrn_tcp_forward. */
int trsrn_tcp_inverse(int table_axis, int nutation_axis, const double *world, double *joints);

#endif
