/* rtapi_vsnprintf.h: the definition of rtapi_vsnprintf() for code that brings its own (as LinuxCNC's header
 * of this name does): C printf conversions, with every floating-point conversion (%f %e %g %a) printed as a
 * hexadecimal float ("0x1.91eb851eb851fp+1"), which needs no floating-point formatting code.
 * Include it in exactly one translation unit; it defines the function rtapi.h declares. */
#ifndef RTAPI_VSNPRINTF_H
#define RTAPI_VSNPRINTF_H

#include <stdarg.h>
#include <stdint.h>
#include <string.h>

#include "rtapi.h"

/* Output under construction: writes past `size` are counted but dropped. */
struct rtapi_vsn_out {
    char *buf;
    unsigned long size, len;
};

/* One conversion specification. */
struct rtapi_vsn_spec {
    int left, zero, plus, space, alt;   /* flags - 0 + space # */
    int width, precision;               /* -1 when absent */
    int length;                          /* 0 none, 'H' hh, 'h', 'l', 'L' ll or L, 'z' */
    char conv;
};

static void rtapi_vsn_put(struct rtapi_vsn_out *o, char c)
{
    if (o->len + 1 < o->size) o->buf[o->len] = c;
    o->len++;
}

static void rtapi_vsn_pad(struct rtapi_vsn_out *o, char c, int n)
{
    while (n-- > 0) rtapi_vsn_put(o, c);
}

/* Emit prefix (sign, 0x) and body within the field width of s. */
static void rtapi_vsn_field(struct rtapi_vsn_out *o, const struct rtapi_vsn_spec *s, const char *prefix,
                            const char *body, int body_len)
{
    int plen = (int)strlen(prefix), fill = s->width - plen - body_len;
    if (!s->left && !s->zero) rtapi_vsn_pad(o, ' ', fill);
    while (*prefix) rtapi_vsn_put(o, *prefix++);
    if (!s->left && s->zero) rtapi_vsn_pad(o, '0', fill);
    while (body_len-- > 0) rtapi_vsn_put(o, *body++);
    if (s->left) rtapi_vsn_pad(o, ' ', fill);
}

/* Integer conversions d i u o x X p. */
static void rtapi_vsn_integer(struct rtapi_vsn_out *o, const struct rtapi_vsn_spec *s, unsigned long long v,
                              int negative)
{
    char digits[72], prefix[4] = "";
    const char *set = s->conv == 'X' ? "0123456789ABCDEF" : "0123456789abcdef";
    unsigned base = s->conv == 'o' ? 8 : (s->conv == 'x' || s->conv == 'X' || s->conv == 'p') ? 16 : 10;
    int n = 0, prec = s->precision < 0 ? 1 : s->precision;
    char *end = digits + sizeof(digits);
    while (v) { *--end = set[v % base]; v /= base; n++; }
    while (n < prec && n < 64) { *--end = '0'; n++; }
    if (negative) strcpy(prefix, "-");
    else if (s->plus && base == 10) strcpy(prefix, "+");
    else if (s->space && base == 10) strcpy(prefix, " ");
    if ((s->alt && base == 16 && n) || s->conv == 'p') strcat(prefix, s->conv == 'X' ? "0X" : "0x");
    if (s->alt && base == 8 && (n == 0 || *end != '0')) { *--end = '0'; n++; }
    struct rtapi_vsn_spec t = *s;
    if (s->precision >= 0) t.zero = 0;
    rtapi_vsn_field(o, &t, prefix, end, n);
}

/* A double as a hexadecimal float ("%a"); upper case for %A %E %F %G. */
static void rtapi_vsn_hexfloat(struct rtapi_vsn_out *o, const struct rtapi_vsn_spec *s, double d)
{
    int upper = s->conv == 'A' || s->conv == 'E' || s->conv == 'F' || s->conv == 'G';
    const char *set = upper ? "0123456789ABCDEF" : "0123456789abcdef";
    uint64_t bits;
    memcpy(&bits, &d, sizeof bits);
    char prefix[4] = "", body[48];
    int n = 0, exp2 = (int)((bits >> 52) & 0x7ff);
    uint64_t mant = bits & 0xfffffffffffffULL;
    if (bits >> 63) strcpy(prefix, "-");
    else if (s->plus) strcpy(prefix, "+");
    else if (s->space) strcpy(prefix, " ");
    if (exp2 == 0x7ff) {
        memcpy(body, mant ? (upper ? "NAN" : "nan") : (upper ? "INF" : "inf"), 3);
        struct rtapi_vsn_spec t = *s;
        t.zero = 0;
        rtapi_vsn_field(o, &t, prefix, body, 3);
        return;
    }
    strcat(prefix, upper ? "0X" : "0x");
    body[n++] = exp2 ? '1' : '0';
    int e = exp2 ? exp2 - 1023 : (mant ? -1022 : 0);
    int last = 12;
    while (last >= 0 && ((mant >> (4 * (12 - last))) & 0xf) == 0) last--;
    if (last >= 0 || s->alt) body[n++] = '.';
    for (int i = 0; i <= last; i++) body[n++] = set[(mant >> (4 * (12 - i))) & 0xf];
    body[n++] = upper ? 'P' : 'p';
    body[n++] = e < 0 ? '-' : '+';
    char exp_digits[8];
    int k = 0, ae = e < 0 ? -e : e;
    do { exp_digits[k++] = (char)('0' + ae % 10); ae /= 10; } while (ae);
    while (k) body[n++] = exp_digits[--k];
    rtapi_vsn_field(o, s, prefix, body, n);
}

/* %s and %c. */
static void rtapi_vsn_text(struct rtapi_vsn_out *o, const struct rtapi_vsn_spec *s, const char *text, int len)
{
    struct rtapi_vsn_spec t = *s;
    t.zero = 0;
    rtapi_vsn_field(o, &t, "", text, len);
}

/* Parse flags, width, precision and length at *fmt (after '%'); returns the conversion character. */
static char rtapi_vsn_parse(const char **fmt, struct rtapi_vsn_spec *s, va_list *ap)
{
    const char *f = *fmt;
    memset(s, 0, sizeof *s);
    s->width = s->precision = -1;
    for (;; f++) {
        if (*f == '-') s->left = 1;
        else if (*f == '0') s->zero = 1;
        else if (*f == '+') s->plus = 1;
        else if (*f == ' ') s->space = 1;
        else if (*f == '#') s->alt = 1;
        else break;
    }
    if (*f == '*') { s->width = va_arg(*ap, int); f++; if (s->width < 0) { s->left = 1; s->width = -s->width; } }
    else for (s->width = 0; *f >= '0' && *f <= '9'; f++) s->width = s->width * 10 + (*f - '0');
    if (*f == '.') {
        f++;
        if (*f == '*') { s->precision = va_arg(*ap, int); f++; }
        else for (s->precision = 0; *f >= '0' && *f <= '9'; f++) s->precision = s->precision * 10 + (*f - '0');
    }
    if (f[0] == 'h' && f[1] == 'h') { s->length = 'H'; f += 2; }
    else if (f[0] == 'l' && f[1] == 'l') { s->length = 'L'; f += 2; }
    else if (*f == 'h' || *f == 'l' || *f == 'L' || *f == 'z' || *f == 'j' || *f == 't') s->length = *f++;
    s->conv = *f ? *f++ : 0;
    *fmt = f;
    return s->conv;
}

/* A signed integer argument of the spec's length. */
static long long rtapi_vsn_signed(const struct rtapi_vsn_spec *s, va_list *ap)
{
    switch (s->length) {
    case 'L': case 'j': return va_arg(*ap, long long);
    case 'l': case 'z': case 't': return va_arg(*ap, long);
    case 'h': return (short)va_arg(*ap, int);
    case 'H': return (signed char)va_arg(*ap, int);
    default: return va_arg(*ap, int);
    }
}

/* An unsigned integer argument of the spec's length. */
static unsigned long long rtapi_vsn_unsigned(const struct rtapi_vsn_spec *s, va_list *ap)
{
    switch (s->length) {
    case 'L': case 'j': return va_arg(*ap, unsigned long long);
    case 'l': case 'z': case 't': return va_arg(*ap, unsigned long);
    case 'h': return (unsigned short)va_arg(*ap, unsigned);
    case 'H': return (unsigned char)va_arg(*ap, unsigned);
    default: return va_arg(*ap, unsigned);
    }
}

/* One conversion. */
static void rtapi_vsn_convert(struct rtapi_vsn_out *o, struct rtapi_vsn_spec *s, va_list *ap)
{
    char c;
    const char *str;
    long long sv;
    switch (s->conv) {
    case 'd': case 'i':
        sv = rtapi_vsn_signed(s, ap);
        rtapi_vsn_integer(o, s, sv < 0 ? 0ULL - (unsigned long long)sv : (unsigned long long)sv, sv < 0);
        break;
    case 'u': case 'o': case 'x': case 'X': rtapi_vsn_integer(o, s, rtapi_vsn_unsigned(s, ap), 0); break;
    case 'p': rtapi_vsn_integer(o, s, (uintptr_t)va_arg(*ap, void *), 0); break;
    case 'f': case 'F': case 'e': case 'E': case 'g': case 'G': case 'a': case 'A':
        rtapi_vsn_hexfloat(o, s, s->length == 'L' ? (double)va_arg(*ap, long double) : va_arg(*ap, double));
        break;
    case 'c': c = (char)va_arg(*ap, int); rtapi_vsn_text(o, s, &c, 1); break;
    case 's':
        str = va_arg(*ap, const char *);
        if (!str) str = "(null)";
        rtapi_vsn_text(o, s, str, s->precision >= 0 ? (int)strnlen(str, (size_t)s->precision) : (int)strlen(str));
        break;
    case '%': rtapi_vsn_put(o, '%'); break;
    default: rtapi_vsn_put(o, '%'); if (s->conv) rtapi_vsn_put(o, s->conv); break;
    }
}

/* printf into buf (at most size bytes, always terminated when size > 0); returns the full length. */
int rtapi_vsnprintf(char *buf, unsigned long size, const char *fmt, va_list ap)
{
    struct rtapi_vsn_out o = {buf, size, 0};
    struct rtapi_vsn_spec s;
    va_list args;
    va_copy(args, ap);
    while (*fmt) {
        if (*fmt != '%') { rtapi_vsn_put(&o, *fmt++); continue; }
        fmt++;
        if (!rtapi_vsn_parse(&fmt, &s, &args)) break;
        rtapi_vsn_convert(&o, &s, &args);
    }
    va_end(args);
    if (size) buf[o.len < size ? o.len : size - 1] = 0;
    return (int)o.len;
}

#endif
