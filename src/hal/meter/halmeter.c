/* halmeter.c: headless HAL meter; prints the current value of one pin, signal or param. */
#include <stdio.h>
#include <string.h>
#include "rtapi.h"
#include "hal.h"

/* Prints the command line summary to out; the explanation only for --help (on stdout). */
static void usage(FILE *out)
{
    fprintf(out, "Usage: halmeter [-s] {pin|sig|param} NAME\n");
    if (out == stdout)
        fprintf(out, "Prints the current value of one HAL pin, signal or parameter and exits.\n"
                     "  -s      accepted for compatibility (the output is always one line)\n"
                     "  --help  this text\n");
}

/* Prints a value cell of the given type as `halcmd getp` does; the cell is read through its
   own type, as a param cell is aligned only for that type. */
static void print_value(hal_type_t type, const void *d)
{
    switch (type) {
    case HAL_BIT: printf("%s\n", *(const hal_bit_t *)d ? "TRUE" : "FALSE"); break;
    case HAL_FLOAT: printf("%.7g\n", (double)*(const hal_float_t *)d); break;
    case HAL_S32: printf("%d\n", (int)*(const hal_s32_t *)d); break;
    case HAL_U32: printf("%u\n", (unsigned)*(const hal_u32_t *)d); break;
    case HAL_S64: printf("%lld\n", (long long)*(const hal_s64_t *)d); break;
    case HAL_U64: printf("%llu\n", (unsigned long long)*(const hal_u64_t *)d); break;
    default: printf("%d\n", (int)*(const hal_port_t *)d); break;
    }
}

/* Looks NAME up as a pin, sig or param; 0 and prints it, or -1 with an error. */
static int meter_read(const char *kind, const char *name)
{
    hal_type_t type;
    hal_data_u *data = NULL;
    bool flag;
    int retval;

    if (strcmp(kind, "pin") == 0) {
        retval = hal_get_pin_value_by_name(name, &type, &data, &flag);
    } else if (strcmp(kind, "sig") == 0 || strcmp(kind, "signal") == 0) {
        retval = hal_get_signal_value_by_name(name, &type, &data, &flag);
    } else {
        retval = hal_get_param_value_by_name(name, &type, &data);
    }
    if (retval < 0 || data == NULL) {
        fprintf(stderr, "halmeter: ERROR: %s '%s' not found\n", kind, name);
        return -1;
    }
    print_value(type, data);
    return 0;
}

/* Entry point: parse `[-s] kind NAME`, attach to HAL, print, detach. */
int main(int argc, char **argv)
{
    int first = 1, retval;

    if (argc > 1 && (strcmp(argv[1], "--help") == 0 || strcmp(argv[1], "-h") == 0)) {
        usage(stdout);
        return 0;
    }
    if (argc > 1 && strcmp(argv[1], "-s") == 0) {
        first = 2;
    }
    if (argc - first != 2) {
        usage(stderr);
        return 1;
    }
    if (strcmp(argv[first], "pin") != 0 && strcmp(argv[first], "sig") != 0
        && strcmp(argv[first], "signal") != 0 && strcmp(argv[first], "param") != 0) {
        fprintf(stderr, "halmeter: ERROR: unknown item type '%s', must be pin, sig or param\n",
                argv[first]);
        usage(stderr);
        return 1;
    }
    retval = hal_lib_init();
    if (retval < 0) {
        fprintf(stderr, "halmeter: ERROR: cannot attach to HAL: %s\n", hal_strerror(retval));
        return 1;
    }
    retval = meter_read(argv[first], argv[first + 1]);
    hal_lib_exit();
    return retval < 0 ? 1 : 0;
}
