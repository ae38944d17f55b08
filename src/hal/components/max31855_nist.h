/* max31855_nist.h: K-type thermocouple linearisation (NIST ITS-90 polynomials) for max31855. */
#ifndef MAX31855_NIST_H
#define MAX31855_NIST_H

#include <math.h>

#define NIST_ORDER 11
/* mV of the cold junction at Ti >= 0 and Ti < 0 (degrees C -> mV). */
static const double nist_k_pos[NIST_ORDER] = {-0.0176004134, 0.0389212035, 1.85587705e-05, -9.94575942e-08,
    3.18409465e-10, -5.60728439e-13, 5.60750581e-16, -3.20207199e-19, 9.71511487e-23, -1.21047216e-26, 0};
static const double nist_k_neg[NIST_ORDER] = {0, 0.0394501276, 2.36223732e-05, -3.28589067e-07,
    -4.99048269e-09, -6.75090608e-11, -5.74103265e-13, -3.10888726e-15, -1.0451609e-17, -1.9889267e-20,
    -1.63226981e-23};
/* Inverse (mV -> degrees C) below 0 mV, below 20.644 mV and below 54.886 mV. */
static const double nist_inv_neg[NIST_ORDER] = {0, 25.1734619, -1.16628778, -1.08336377, -0.897735417,
    -0.373423755, -0.0866326466, -0.0104505979, -0.000519205758, 0, 0};
static const double nist_inv_low[NIST_ORDER] = {0, 25.0835495, 0.0786010623, -0.250313103, 0.0831526965,
    -0.0122803403, 0.000980403624, -4.41302982e-05, 1.05773404e-06, -1.05275504e-08, 0};
static const double nist_inv_high[NIST_ORDER] = {-131.805801, 48.3022194, -1.64603102, 0.0546473116,
    -0.000965071493, 8.80219341e-06, -3.1108101e-08, 0, 0, 0, 0};

/* Sum of c[k] x^k. */
static double nist_poly(const double *c, double x)
{
    double r = 0, p = 1;
    for (int k = 0; k < NIST_ORDER; k++) {
        r += c[k] * p;
        p *= x;
    }
    return r;
}

/* Thermocouple temperature corrected for the cold junction: tr the chip's reading, ti its own
 * temperature (degrees C); beyond the table the chip's reading is used. */
static double max31855_celsius(double tr, double ti)
{
    double vi = ti >= 0 ? nist_poly(nist_k_pos, ti) + 0.118597597 * exp(-0.000118343203 * (ti - 126.968597) *
                                                                         (ti - 126.968597))
                        : nist_poly(nist_k_neg, ti);
    double v = (tr - ti) * 0.041276 + vi;
    if (v < 0)
        return nist_poly(nist_inv_neg, v);
    if (v < 20.644)
        return nist_poly(nist_inv_low, v);
    if (v < 54.886)
        return nist_poly(nist_inv_high, v);
    return tr;
}

#endif
