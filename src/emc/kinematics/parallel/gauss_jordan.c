/* gauss_jordan.c: LinuxCNC's Gauss-Jordan inverse for the strut Jacobians of pentakins and genhexkins. */
#include <math.h>
#include "gauss_jordan.h"

#define GJ_PIVOT_SWAP 0.01
#define GJ_ZERO 1e-6

/* Swap rows r and s of both matrices. */
static void gj_swap(int n, double m[GJ_MAX_N][GJ_MAX_N], double inv[GJ_MAX_N][GJ_MAX_N], int r, int s)
{
    for (int c = 0; c < n; c++) {
        double t = m[r][c];
        m[r][c] = m[s][c];
        m[s][c] = t;
        t = inv[r][c];
        inv[r][c] = inv[s][c];
        inv[s][c] = t;
    }
}

/* A small pivot in column c: swap in the first lower row with a usable entry. */
static void gj_pivot(int n, double m[GJ_MAX_N][GJ_MAX_N], double inv[GJ_MAX_N][GJ_MAX_N], int c)
{
    if (fabs(m[c][c]) >= GJ_PIVOT_SWAP)
        return;
    for (int r = c + 1; r < n; r++) {
        if (fabs(m[r][c]) > GJ_PIVOT_SWAP) {
            gj_swap(n, m, inv, c, r);
            return;
        }
    }
}

/* Invert m into inv (see gauss_jordan.h). */
int gj_invert(int n, double m[GJ_MAX_N][GJ_MAX_N], double inv[GJ_MAX_N][GJ_MAX_N])
{
    for (int r = 0; r < n; r++)
        for (int c = 0; c < n; c++)
            inv[r][c] = r == c;
    for (int c = 0; c < n; c++) {
        gj_pivot(n, m, inv, c);
        double p = m[c][c];
        if (p == 0 || p != p)
            return -1;
        for (int k = 0; k < n; k++) {
            m[c][k] /= p;
            inv[c][k] /= p;
        }
        for (int r = 0; r < n; r++) {
            if (r == c)
                continue;
            double f = m[r][c];
            for (int k = 0; k < n; k++) {
                m[r][k] -= f * m[c][k];
                if (fabs(m[r][k]) < GJ_ZERO)
                    m[r][k] = 0;
                inv[r][k] -= f * inv[c][k];
            }
        }
    }
    return 0;
}
