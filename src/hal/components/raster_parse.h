/* raster_parse.h: raster's number and hex parsing on peeked port bytes (no libc, realtime safe). */
#ifndef RASTER_PARSE_H
#define RASTER_PARSE_H

/* Value of a hex digit, or -1. */
static inline int raster_hex(char c)
{
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
}

/* A decimal number (sign, digits, fraction, exponent) at the start of s[0..n); the characters it
 * takes, 0 when s does not start with a number. */
static inline int raster_number(const char *s, int n, double *out)
{
    int i = 0, digits = 0, neg = 0, eneg = 0, e = 0;
    double v = 0, scale = 1;
    if (i < n && (s[i] == '+' || s[i] == '-')) neg = s[i++] == '-';
    for (; i < n && s[i] >= '0' && s[i] <= '9'; i++, digits++) v = v * 10 + (s[i] - '0');
    if (i < n && s[i] == '.')
        for (i++; i < n && s[i] >= '0' && s[i] <= '9'; i++, digits++) v += (s[i] - '0') * (scale /= 10);
    if (!digits) return 0;
    if (i + 1 < n && (s[i] == 'e' || s[i] == 'E')) {
        int j = i + 1, ed = 0;
        if (j < n && (s[j] == '+' || s[j] == '-')) eneg = s[j++] == '-';
        for (; j < n && s[j] >= '0' && s[j] <= '9' && ed < 4; j++, ed++) e = e * 10 + (s[j] - '0');
        if (ed) {
            i = j;
            for (; e > 0; e--) v = eneg ? v / 10 : v * 10;
        }
    }
    *out = neg ? -v : v;
    return i;
}

/* An integer (sign and digits only) at the start of s[0..n); the characters it takes, or 0. */
static inline int raster_integer(const char *s, int n, long *out)
{
    int i = 0, neg = 0, digits = 0;
    long v = 0;
    if (i < n && (s[i] == '+' || s[i] == '-')) neg = s[i++] == '-';
    for (; i < n && s[i] >= '0' && s[i] <= '9'; i++, digits++)
        if (v < 100000000000L) v = v * 10 + (s[i] - '0');
    if (!digits) return 0;
    *out = neg ? -v : v;
    return i;
}

#endif
