/* gauss_jordan.h: LinuxCNC's Gauss-Jordan inverse for the strut Jacobians of pentakins and genhexkins. */
#ifndef GAUSS_JORDAN_H
#define GAUSS_JORDAN_H

#define GJ_MAX_N 6

/* Invert the n x n matrix m (row-major, n <= 6; m is destroyed) into inv. A pivot below 0.01 is
 * swapped with the first lower row whose entry is above 0.01; entries below 1e-6 left by the
 * elimination become 0. Returns 0, or -1 when a pivot is zero (singular). */
int gj_invert(int n, double m[GJ_MAX_N][GJ_MAX_N], double inv[GJ_MAX_N][GJ_MAX_N]);

#endif
