/* gpio_lines.c: look hal_gpio's lines up by name on every chip, group them per chip, direction and
   electrical options (at most 64 a group) and request each group at once. */
#include <errno.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "gpio_lines.h"

#define GPIO_MSG_LEN 240
#define GPIO_CHIP_NAME_LEN 32

/* Where a named line lives. */
typedef struct {
    char chip[GPIO_CHIP_NAME_LEN];
    unsigned offset;
} gpio_place_t;

/* Format and send one message. */
static void say(gpio_report_fn report, void *ctx, int is_error, const char *fmt, ...)
{
    char text[GPIO_MSG_LEN];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(text, sizeof(text), fmt, ap);
    va_end(ap);
    report(ctx, is_error, text);
}

/* Find every line by name; returns 0 or -ENOENT after naming each missing line. */
static int locate(const gpio_line_spec_t *specs, int count, gpio_place_t *places,
                  gpio_report_fn report, void *ctx)
{
    int missing[2] = { 0, 0 };
    for (int i = 0; i < count; i++) {
        struct gpiod_line *line = gpiod_line_find(specs[i].name);
        if (!line) {
            say(report, ctx, 1, "The GPIO line %s can not be found", specs[i].name);
            missing[specs[i].is_output]++;
            continue;
        }
        snprintf(places[i].chip, sizeof(places[i].chip), "%s", gpiod_chip_name(gpiod_line_get_chip(line)));
        places[i].offset = gpiod_line_offset(line);
        gpiod_line_close_chip(line);
    }
    if (missing[0])
        say(report, ctx, 1, "hal_gpio: Failed to identify all specified input pins");
    if (missing[1])
        say(report, ctx, 1, "hal_gpio: Failed to identify all specified output pins");
    return missing[0] || missing[1] ? -ENOENT : 0;
}

/* The open chip named name, opening it on first use; NULL after reporting. */
static struct gpiod_chip *chip_for(gpio_lines_t *set, const char *name, gpio_report_fn report, void *ctx)
{
    for (int i = 0; i < set->chip_count; i++)
        if (strcmp(gpiod_chip_name(set->chips[i]), name) == 0)
            return set->chips[i];
    struct gpiod_chip *chip = gpiod_chip_open_by_name(name);
    if (!chip) {
        say(report, ctx, 1, "hal_gpio: cannot open %s: %s", name, strerror(errno));
        return NULL;
    }
    set->chips[set->chip_count++] = chip;
    return chip;
}

/* The group for a line of chip with this direction and options, started when needed. */
static gpio_group_t *group_for(gpio_lines_t *set, struct gpiod_chip *chip, const gpio_line_spec_t *spec)
{
    const unsigned electrical = ~(unsigned)(GPIO_FLAG_INVERT | GPIO_FLAG_RESET);
    unsigned flags = spec->flags & electrical;
    for (int i = 0; i < set->group_count; i++) {
        gpio_group_t *g = &set->groups[i];
        if (gpiod_line_get_chip(g->bulk.lines[0]) == chip && g->is_output == spec->is_output &&
            g->flags == flags && g->bulk.num_lines < GPIOD_LINE_BULK_MAX_LINES)
            return g;
    }
    gpio_group_t *g = &set->groups[set->group_count++];
    memset(g, 0, sizeof(*g));
    gpiod_line_bulk_init(&g->bulk);
    g->is_output = spec->is_output;
    g->flags = flags;
    return g;
}

/* libgpiod request flags for GPIO_FLAG_* options. */
static int request_flags(unsigned flags)
{
    int r = 0;
    if (flags & GPIO_FLAG_OPEN_DRAIN) r |= GPIOD_LINE_REQUEST_FLAG_OPEN_DRAIN;
    if (flags & GPIO_FLAG_OPEN_SOURCE) r |= GPIOD_LINE_REQUEST_FLAG_OPEN_SOURCE;
    if (flags & GPIO_FLAG_BIAS_DISABLE) r |= GPIOD_LINE_REQUEST_FLAG_BIAS_DISABLE;
    if (flags & GPIO_FLAG_PULL_DOWN) r |= GPIOD_LINE_REQUEST_FLAG_BIAS_PULL_DOWN;
    if (flags & GPIO_FLAG_PULL_UP) r |= GPIOD_LINE_REQUEST_FLAG_BIAS_PULL_UP;
    return r;
}

/* Request one group; outputs start at their inactive level (FALSE, or TRUE when inverted). */
static int request_group(gpio_group_t *g, const gpio_line_spec_t *specs, gpio_report_fn report, void *ctx)
{
    int r;
    for (unsigned i = 0; i < g->bulk.num_lines; i++)
        g->values[i] = (specs[g->spec[i]].flags & GPIO_FLAG_INVERT) ? 1 : 0;
    if (g->is_output)
        r = gpiod_line_request_bulk_output_flags(&g->bulk, GPIO_CONSUMER, request_flags(g->flags), g->values);
    else
        r = gpiod_line_request_bulk_input_flags(&g->bulk, GPIO_CONSUMER, request_flags(g->flags));
    if (r == 0)
        return 0;
    r = errno;
    say(report, ctx, 1, "hal_gpio: Failed to register %s pin collection", g->is_output ? "output" : "input");
    say(report, ctx, 1, "hal_gpio: lines %s..%s on %s: %s", specs[g->spec[0]].name,
        specs[g->spec[g->bulk.num_lines - 1]].name, gpiod_chip_name(gpiod_line_get_chip(g->bulk.lines[0])),
        strerror(r));
    return -r;
}

/* Put every line into its group; 0 or a negative errno (reported). */
static int build_groups(gpio_lines_t *set, const gpio_line_spec_t *specs, const gpio_place_t *places,
                        int count, gpio_report_fn report, void *ctx)
{
    for (int i = 0; i < count; i++) {
        struct gpiod_chip *chip = chip_for(set, places[i].chip, report, ctx);
        struct gpiod_line *line = chip ? gpiod_chip_get_line(chip, places[i].offset) : NULL;
        if (!line) {
            if (chip)
                say(report, ctx, 1, "hal_gpio: line %s: %s", specs[i].name, strerror(errno));
            return -ENODEV;
        }
        gpio_group_t *g = group_for(set, chip, &specs[i]);
        g->spec[g->bulk.num_lines] = i;
        gpiod_line_bulk_add(&g->bulk, line);
    }
    return 0;
}

/* Find, group and request the lines; 0 or a negative errno (every problem reported). */
int gpio_lines_open(gpio_lines_t *set, const gpio_line_spec_t *specs, int count,
                    gpio_report_fn report, void *ctx)
{
    gpio_place_t *places = calloc(count ? count : 1, sizeof(*places));
    int r = -ENOMEM;
    memset(set, 0, sizeof(*set));
    set->chips = calloc(count ? count : 1, sizeof(*set->chips));
    set->groups = calloc(count ? count : 1, sizeof(*set->groups));
    if (places && set->chips && set->groups)
        r = locate(specs, count, places, report, ctx);
    if (r == 0)
        r = build_groups(set, specs, places, count, report, ctx);
    for (int i = 0; r == 0 && i < set->group_count; i++)
        r = request_group(&set->groups[i], specs, report, ctx);
    free(places);
    if (r != 0)
        gpio_lines_close(set);
    return r;
}

/* Release the lines and close the chips. */
void gpio_lines_close(gpio_lines_t *set)
{
    for (int i = 0; i < set->group_count; i++)
        if (set->groups[i].bulk.num_lines && gpiod_line_is_requested(set->groups[i].bulk.lines[0]))
            gpiod_line_release_bulk(&set->groups[i].bulk);
    for (int i = 0; i < set->chip_count; i++)
        gpiod_chip_close(set->chips[i]);
    free(set->chips);
    free(set->groups);
    memset(set, 0, sizeof(*set));
}
