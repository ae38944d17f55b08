/* vsnprintf_test.c: rtapi_vsnprintf.h against the C library: integers and strings as printf, floating point
 * as printf's %a (hexadecimal floats), truncation and the returned length. */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <rtapi.h>
#include <rtapi_vsnprintf.h>

static int failures;

/* rtapi and libc output of one format, compared (case-insensitive when hex floats are involved) */
static void check(int fold, const char *fmt, ...)
{
    char mine[256], libc[256];
    va_list ap, ap2;
    va_start(ap, fmt);
    va_copy(ap2, ap);
    int n1 = rtapi_vsnprintf(mine, sizeof mine, fmt, ap);
    int n2 = vsnprintf(libc, sizeof libc, fmt, ap2);
    va_end(ap2);
    va_end(ap);
    int same = n1 == n2 && (fold ? strcasecmp(mine, libc) : strcmp(mine, libc)) == 0;
    if (!same) failures++;
    printf("%-10s %-32s %s\n", fmt, mine, same ? "ok" : libc);
}

/* the float conversions all print what %a prints */
static void check_float(double v)
{
    char mine[128], libc[128];
    rtapi_snprintf(mine, sizeof mine, "%f", v);
    snprintf(libc, sizeof libc, "%A", v);
    int same = strcasecmp(mine, libc) == 0;
    if (!same) failures++;
    printf("%%f of %-12g %-32s %s\n", v, mine, same ? "ok" : libc);
}

int rtapi_snprintf(char *buf, unsigned long size, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    int n = rtapi_vsnprintf(buf, size, fmt, ap);
    va_end(ap);
    return n;
}

int main(void)
{
    double values[] = {0.0, -0.0, 1.0, 3.14, -2.5, 1e300, 1e-300, 4.9e-324, 2.2250738585072014e-308,
                       INFINITY, -INFINITY, NAN};
    for (unsigned i = 0; i < sizeof values / sizeof values[0]; i++) check_float(values[i]);
    check(1, "%a", 0.1);
    check(1, "%12a|", 0.5);
    check(1, "%-12a|", -0.5);
    check(1, "%+a", 1.0);
    check(0, "%d %i", -42, 7);
    check(0, "%5d|%-5d|%05d", 42, 42, 42);
    check(0, "%+d % d", 3, 3);
    check(0, "%.3d", 5);
    check(0, "%u %lu %llu", 4000000000u, 123456789012ul, 18446744073709551615ull);
    check(0, "%ld %lld", -9000000000l, -9000000000000ll);
    check(0, "%x %X %#x %#o %o", 255, 255, 255, 8, 0);
    check(0, "%hhd %hd", 300, 70000);
    check(0, "%c%c", 'o', 'k');
    check(0, "[%s] [%8s] [%-8s] [%.2s]", "abc", "abc", "abc", "abc");
    check(0, "%*d|%-*d", 6, 1, 6, 2);
    check(0, "%zu %%", (size_t)17);
    char small[6];
    int n = rtapi_snprintf(small, sizeof small, "%s", "truncated");
    printf("truncated to '%s', length %d\n", small, n);
    if (n != 9 || strcmp(small, "trunc")) failures++;
    printf("%d failures\n", failures);
    return failures != 0;
}
