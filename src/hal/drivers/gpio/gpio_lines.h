/* gpio_lines.h: hal_gpio's lines found by name, grouped per chip and requested in bulk (libgpiod 1.x). */
#ifndef GPIO_LINES_H
#define GPIO_LINES_H

#include <gpiod.h>
#include "gpio_args.h"

#define GPIO_CONSUMER "linuxcnc"

/* Lines of one chip with the same direction and options, read or written with one call. */
typedef struct {
    struct gpiod_line_bulk bulk;
    int is_output;
    unsigned flags;                       /* the GPIO_FLAG_* electrical options shared by the group */
    int spec[GPIOD_LINE_BULK_MAX_LINES];  /* index of each line in the spec list */
    int values[GPIOD_LINE_BULK_MAX_LINES];/* outputs: levels last written */
    int written;                          /* outputs: values[] has been written once */
    long long write_time_ns;              /* outputs: when values[] was last written */
} gpio_group_t;

/* Every requested line. */
typedef struct {
    struct gpiod_chip **chips;
    int chip_count;
    gpio_group_t *groups;
    int group_count;
} gpio_lines_t;

/* Find, group and request the lines; 0 or a negative errno (every problem reported). */
int gpio_lines_open(gpio_lines_t *set, const gpio_line_spec_t *specs, int count,
                    gpio_report_fn report, void *ctx);

/* Release the lines and close the chips. */
void gpio_lines_close(gpio_lines_t *set);

#endif
