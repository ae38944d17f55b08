/* modparam_test.c: unit test of rtapi_modparam_apply for every parameter type. */
#include <stdio.h>
#include <string.h>
#include "rtapi_modparam.h"

static int count = 5;
static long big = 7;
static char *label = "def";
static int ints[3] = { 1, 2, 3 };
static long longs[2] = { 10, 20 };
static char *names[3];

static const rtapi_param_info_t params[] = {
    { "count", 'i', 0, &count, "" }, { "big", 'l', 0, &big, "" },
    { "label", 's', 0, &label, "" }, { "ints", 'i', 3, ints, "" },
    { "longs", 'l', 2, longs, "" }, { "names", 's', 3, names, "" },
};

/* Lookup by name in params[]. */
static const rtapi_param_info_t *lookup(void *ctx, const char *name)
{
    (void)ctx;
    for (size_t i = 0; i < sizeof params / sizeof params[0]; i++)
        if (strcmp(params[i].name, name) == 0)
            return &params[i];
    return NULL;
}

/* Show a possibly NULL string. */
static const char *show(const char *s)
{
    return s ? s : "(null)";
}

/* Print every parameter's current value. */
static void dump(void)
{
    printf("  count=%d big=%ld label=%s ints=%d,%d,%d longs=%ld,%ld names=%s,%s,%s\n",
           count, big, show(label), ints[0], ints[1], ints[2], longs[0], longs[1],
           show(names[0]), show(names[1]), show(names[2]));
}

/* Apply each argument in turn and show the resulting values. */
int main(void)
{
    static const char *const args[] = {
        "count=12", "count=0x1f", "count=010", "count=-3", "count=", "count=abc",
        "count=12x", "count=4294967295", "count=4294967296", "count=-2147483649",
        "big=9223372036854775807", "big=9223372036854775808", "big=-0x10",
        "label=hello,world", "label=\"quoted, \"text", "label=",
        "ints=7", "ints=4,5,6", "ints=1,,2", "ints=", "ints=3,", "ints=1,2,3,4", "ints=1,z,3",
        "longs=0x7fffffffffffffff,-1", "longs=1,2,3",
        "names=a,b", "names=", "names=x,y,z", "names=p,q,r,s",
        "bogus=1", "novalue", "=5", "\"count\"=\"33\"", "count=\"7\"",
    };
    rtapi_modparam_strings_t strings = { 0 };
    char err[256];

    dump();
    for (size_t i = 0; i < sizeof args / sizeof args[0]; i++) {
        int rc = rtapi_modparam_apply(args[i], lookup, NULL, &strings, err, sizeof err);
        printf("%s -> %d%s%s\n", args[i], rc, rc < 0 ? ": " : "", rc < 0 ? err : "");
        if (rc == 0)
            dump();
    }
    printf("strings kept: %d\n", strings.count);
    rtapi_modparam_free(&strings);
    printf("strings after free: %d\n", strings.count);
    return 0;
}
