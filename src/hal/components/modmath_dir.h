/* modmath_dir.h: modmath's signed distance from actual to desired on a ring or a range. */
#ifndef MODMATH_DIR_H
#define MODMATH_DIR_H

/* v folded into min..min+range-1 with C's remainder (LinuxCNC: values below min may stay below). */
static inline long long modmath_fold(long long v, long long min, long long range)
{
    return min + (v - min) % range;
}

/* Sign (1, -1 or 0) of desired - actual after folding, the other way round when wrap and more than
 * half the range; a range below 1 (max < min) neither folds nor wraps. */
static inline int modmath_direction(int actual, int desired, int min, int max, int wrap)
{
    long long range = (long long)max - min + 1, a = actual, b = desired;
    if (range < 1) {
        long long d = b - a;
        return d > 0 ? 1 : d < 0 ? -1 : 0;
    }
    long long d = modmath_fold(b, min, range) - modmath_fold(a, min, range);
    if (wrap && d > range / 2)
        d -= range;
    else if (wrap && d < -(range / 2))
        d += range;
    return d > 0 ? 1 : d < 0 ? -1 : 0;
}

#endif
