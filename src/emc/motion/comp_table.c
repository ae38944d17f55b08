/* comp_table.c: screw-compensation table rows and their interpolation (bounded binary search). */
#include <errno.h>
#include "comp_table.h"

/* Append a row with a nominal above the last one. */
int comp_table_add(comp_table_t *t, double nominal, double forward, double reverse)
{
    if (t->count >= COMP_MAX_ENTRIES)
        return -ENOSPC;
    if (t->count > 0 && !(nominal > t->nominal[t->count - 1]))
        return -EINVAL;
    t->nominal[t->count] = nominal;
    t->forward[t->count] = forward;
    t->reverse[t->count] = reverse;
    t->count++;
    return 0;
}

/* Index i with nominal[i] <= pos < nominal[i+1] (count >= 2, pos inside the table). */
static int find_row(const comp_table_t *t, double pos)
{
    int lo = 0, hi = t->count - 1;

    while (hi - lo > 1) {
        int mid = (lo + hi) / 2;
        if (t->nominal[mid] <= pos)
            lo = mid;
        else
            hi = mid;
    }
    return lo;
}

/* Interpolated correction at pos for the direction's column. */
double comp_table_lookup(const comp_table_t *t, double pos, int dir)
{
    const double *col = dir < 0 ? t->reverse : t->forward;
    int i;
    double frac;

    if (t->count == 0)
        return 0.0;
    if (pos <= t->nominal[0])
        return col[0];
    if (pos >= t->nominal[t->count - 1])
        return col[t->count - 1];
    i = find_row(t, pos);
    frac = (pos - t->nominal[i]) / (t->nominal[i + 1] - t->nominal[i]);
    return col[i] + frac * (col[i + 1] - col[i]);
}
