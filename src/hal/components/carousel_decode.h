/* carousel_decode.h: carousel's position codes (gray, binary, bcd, counts) and pocket arithmetic. */
#ifndef CAROUSEL_DECODE_H
#define CAROUSEL_DECODE_H

/* A Gray code as the binary number it stands for. */
static inline unsigned carousel_gray(unsigned g)
{
    unsigned b = g;
    while (g >>= 1)
        b ^= g;
    return b;
}

/* A BCD code (4 bits per decimal digit, units in the lowest bits) as its value. */
static inline long carousel_bcd(unsigned long code, int bits)
{
    long v = 0, place = 1;
    for (int k = 0; k < bits; k += 4) {
        v += (long)((code >> k) & 0xF) * place;
        place *= 10;
    }
    return v;
}

/* (p - 1) mod n + 1 with C's remainder, then held within 1..n (0 and negatives give 1). */
static inline int carousel_target(int p, int n)
{
    long long t = ((long long)p - 1) % n + 1;
    return t < 1 ? 1 : t > n ? n : (int)t;
}

/* A pocket counted one past either end wraps to the other. */
static inline int carousel_wrap(int p, int n)
{
    return p > n ? 1 : p < 1 ? n : p;
}

/* Counts decoding: the pocket (1..n) whose window of +-width/2 around a multiple of scale holds c
 * (counts past the home position), or 0 between windows; *align is TRUE within 2 counts of one.
 * A scale below 1 decodes nothing. */
static inline int carousel_counts(long long c, int scale, int width, int n, int *align)
{
    long long w = width / 2, t;
    *align = 0;
    if (scale < 1)
        return 0;
    t = c + w >= 0 ? (c + w) / scale : -((-(c + w) + scale - 1) / scale);
    *align = c % scale >= -2 && c % scale <= 2;
    if (c < t * scale - w || c > t * scale + w)
        return 0;
    return 1 + (int)(((t % n) + n) % n);
}

#endif
