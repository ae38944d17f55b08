/* gpio_args.c: merge hal_gpio's name lists into one spec per line, rejecting what cannot work. */
#include <stddef.h>
#include <stdio.h>
#include <string.h>
#include "gpio_args.h"

#define GPIO_MSG_LEN 200

/* An option list: its module argument name, the flag it sets, and whether only outputs use it. */
typedef struct {
    const char *arg;
    size_t offset;
    unsigned flag;
    int outputs_only;
} gpio_option_t;

static const gpio_option_t options[] = {
    { "invert", offsetof(gpio_args_t, invert), GPIO_FLAG_INVERT, 1 },
    { "reset", offsetof(gpio_args_t, reset), GPIO_FLAG_RESET, 1 },
    { "opendrain", offsetof(gpio_args_t, opendrain), GPIO_FLAG_OPEN_DRAIN, 1 },
    { "opensource", offsetof(gpio_args_t, opensource), GPIO_FLAG_OPEN_SOURCE, 1 },
    { "biasdisable", offsetof(gpio_args_t, biasdisable), GPIO_FLAG_BIAS_DISABLE, 0 },
    { "pulldown", offsetof(gpio_args_t, pulldown), GPIO_FLAG_PULL_DOWN, 0 },
    { "pullup", offsetof(gpio_args_t, pullup), GPIO_FLAG_PULL_UP, 0 },
};

/* Format and send one message. */
static void say(gpio_report_fn report, void *ctx, int is_error, const char *fmt, const char *a,
                const char *b)
{
    char text[GPIO_MSG_LEN];
    snprintf(text, sizeof(text), fmt, a, b);
    report(ctx, is_error, text);
}

/* Index of name among specs[0..n), or -1. */
static int find_spec(const gpio_line_spec_t *specs, int n, const char *name)
{
    for (int i = 0; i < n; i++)
        if (strcmp(specs[i].name, name) == 0)
            return i;
    return -1;
}

/* Add the lines of one direction list; returns the number of errors. */
static int add_lines(char **list, int is_output, gpio_line_spec_t *specs, int *n,
                     gpio_report_fn report, void *ctx)
{
    const char *arg = is_output ? "outputs" : "inputs";
    int errors = 0;
    for (int i = 0; list && i < GPIO_MAX_LINES && list[i]; i++) {
        const char *name = list[i];
        int at = find_spec(specs, *n, name);
        if (!*name) {
            say(report, ctx, 1, "hal_gpio: %s: empty line name", arg, NULL);
            errors++;
        } else if (strlen(name) > GPIO_LINE_NAME_MAX) {
            say(report, ctx, 1, "hal_gpio: %s: line name '%s' is longer than 31 characters", arg, name);
            errors++;
        } else if (at >= 0) {
            say(report, ctx, 1, specs[at].is_output == is_output ? "hal_gpio: %s: line %s is listed twice"
                : "hal_gpio: %s: line %s is also listed in the other direction", arg, name);
            errors++;
        } else {
            specs[*n].name = name;
            specs[*n].is_output = is_output;
            specs[*n].flags = 0;
            (*n)++;
        }
    }
    return errors;
}

/* Apply one option list to the specs; returns the number of errors. */
static int apply_option(const gpio_args_t *args, const gpio_option_t *o, gpio_line_spec_t *specs, int n,
                        gpio_report_fn report, void *ctx)
{
    char **list = *(char ***)((const char *)args + o->offset);
    int errors = 0;
    for (int i = 0; list && i < GPIO_MAX_LINES && list[i]; i++) {
        int at = find_spec(specs, n, list[i]);
        if (at < 0) {
            say(report, ctx, 1, "hal_gpio: %s: %s is not listed in inputs or outputs", o->arg, list[i]);
            errors++;
        } else if (o->outputs_only && !specs[at].is_output) {
            say(report, ctx, 0, "hal_gpio: %s: %s is an input; the option only applies to outputs (ignored)",
                o->arg, list[i]);
        } else {
            specs[at].flags |= o->flag;
        }
    }
    return errors;
}

/* Report lines whose electrical options contradict each other; returns the number of errors. */
static int check_conflicts(const gpio_line_spec_t *specs, int n, gpio_report_fn report, void *ctx)
{
    const unsigned bias = GPIO_FLAG_BIAS_DISABLE | GPIO_FLAG_PULL_DOWN | GPIO_FLAG_PULL_UP;
    int errors = 0;
    for (int i = 0; i < n; i++) {
        unsigned f = specs[i].flags;
        if ((f & GPIO_FLAG_OPEN_DRAIN) && (f & GPIO_FLAG_OPEN_SOURCE)) {
            say(report, ctx, 1, "hal_gpio: line %s is both opendrain and opensource%s", specs[i].name, "");
            errors++;
        }
        if ((f & bias) & ((f & bias) - 1)) {
            say(report, ctx, 1, "hal_gpio: line %s has more than one of biasdisable, pulldown and pullup%s",
                specs[i].name, "");
            errors++;
        }
    }
    return errors;
}

/* Check the arguments and fill specs (inputs first, then outputs, in argument order). */
int gpio_args_collect(const gpio_args_t *args, gpio_line_spec_t specs[2 * GPIO_MAX_LINES],
                      gpio_report_fn report, void *ctx)
{
    int n = 0, errors = 0;
    errors += add_lines(args->inputs, 0, specs, &n, report, ctx);
    errors += add_lines(args->outputs, 1, specs, &n, report, ctx);
    for (size_t i = 0; i < sizeof(options) / sizeof(options[0]); i++)
        errors += apply_option(args, &options[i], specs, n, report, ctx);
    errors += check_conflicts(specs, n, report, ctx);
    return errors ? -1 : n;
}
