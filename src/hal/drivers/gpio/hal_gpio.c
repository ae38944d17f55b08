/* hal_gpio.c: HAL driver for GPIO lines through libgpiod, by line name (LinuxCNC's hal_gpio). */
#include <stdio.h>
#include <string.h>
#include "rtapi.h"
#include "rtapi_app.h"
#include "rtapi_errno.h"
#include "hal.h"
#include "gpio_args.h"
#include "gpio_lines.h"

MODULE_LICENSE("GPL");
MODULE_AUTHOR("OpenEMC");
MODULE_DESCRIPTION("GPIO lines by name through libgpiod: inputs=, outputs=, invert=, reset=, ...");

static char *inputs[GPIO_MAX_LINES];
RTAPI_MP_ARRAY_STRING(inputs, GPIO_MAX_LINES, "names of the input lines");
static char *outputs[GPIO_MAX_LINES];
RTAPI_MP_ARRAY_STRING(outputs, GPIO_MAX_LINES, "names of the output lines");
static char *invert[GPIO_MAX_LINES];
RTAPI_MP_ARRAY_STRING(invert, GPIO_MAX_LINES, "outputs driven inverted");
static char *reset[GPIO_MAX_LINES];
RTAPI_MP_ARRAY_STRING(reset, GPIO_MAX_LINES, "outputs the reset function returns to their inactive level");
static char *opendrain[GPIO_MAX_LINES];
RTAPI_MP_ARRAY_STRING(opendrain, GPIO_MAX_LINES, "open-drain outputs");
static char *opensource[GPIO_MAX_LINES];
RTAPI_MP_ARRAY_STRING(opensource, GPIO_MAX_LINES, "open-source outputs");
static char *biasdisable[GPIO_MAX_LINES];
RTAPI_MP_ARRAY_STRING(biasdisable, GPIO_MAX_LINES, "lines with bias disabled");
static char *pulldown[GPIO_MAX_LINES];
RTAPI_MP_ARRAY_STRING(pulldown, GPIO_MAX_LINES, "lines with the pull-down bias");
static char *pullup[GPIO_MAX_LINES];
RTAPI_MP_ARRAY_STRING(pullup, GPIO_MAX_LINES, "lines with the pull-up bias");

/* HAL objects (in HAL memory): one pin pair per line, the reset time. */
typedef struct {
    hal_bit_t *pin[2 * GPIO_MAX_LINES];      /* -in for inputs, -out for outputs */
    hal_bit_t *pin_not[2 * GPIO_MAX_LINES];  /* -in-not for inputs */
    hal_u32_t reset_ns;
} gpio_hal_t;

static int comp_id = -1;
static gpio_hal_t *hal;
static gpio_line_spec_t specs[2 * GPIO_MAX_LINES];
static int line_count;
static gpio_lines_t lines;
static int io_error_reported;

/* Message sink for the argument checks and the line requests. */
static void report(void *ctx, int is_error, const char *text)
{
    (void)ctx;
    rtapi_print_msg(is_error ? RTAPI_MSG_ERR : RTAPI_MSG_WARN, "%s\n", text);
}

/* Report the first failing bulk access once (from the realtime thread: queued, never blocks). */
static void io_failed(const char *what, const gpio_group_t *g)
{
    if (io_error_reported)
        return;
    io_error_reported = 1;
    rtapi_print_msg(RTAPI_MSG_ERR, "hal_gpio: %s of line %s failed\n", what, specs[g->spec[0]].name);
}

/* funct hal_gpio.read: every input group to its -in and -in-not pins. */
static void gpio_read(void *arg, long period)
{
    int values[GPIOD_LINE_BULK_MAX_LINES];
    (void)arg; (void)period;
    for (int i = 0; i < lines.group_count; i++) {
        gpio_group_t *g = &lines.groups[i];
        if (g->is_output)
            continue;
        if (gpiod_line_get_value_bulk(&g->bulk, values) != 0) {
            io_failed("reading", g);
            continue;
        }
        for (unsigned k = 0; k < g->bulk.num_lines; k++) {
            *hal->pin[g->spec[k]] = values[k] != 0;
            *hal->pin_not[g->spec[k]] = values[k] == 0;
        }
    }
}

/* Write values to an output group when they differ from what it holds, noting the time. */
static void put_group(gpio_group_t *g, const int *values)
{
    if (g->written && memcmp(values, g->values, sizeof(int) * g->bulk.num_lines) == 0)
        return;
    if (gpiod_line_set_value_bulk(&g->bulk, (int *)values) != 0) {
        io_failed("writing", g);
        return;
    }
    memcpy(g->values, values, sizeof(int) * g->bulk.num_lines);
    g->written = 1;
    g->write_time_ns = rtapi_get_time();
}

/* funct hal_gpio.write: every -out pin (xor invert) to its line. */
static void gpio_write(void *arg, long period)
{
    int values[GPIOD_LINE_BULK_MAX_LINES];
    (void)arg; (void)period;
    for (int i = 0; i < lines.group_count; i++) {
        gpio_group_t *g = &lines.groups[i];
        if (!g->is_output)
            continue;
        for (unsigned k = 0; k < g->bulk.num_lines; k++)
            values[k] = *hal->pin[g->spec[k]] ^ !!(specs[g->spec[k]].flags & GPIO_FLAG_INVERT);
        put_group(g, values);
    }
}

/* funct hal_gpio.reset: reset_ns after write, return the reset outputs to their inactive level. */
static void gpio_reset(void *arg, long period)
{
    int values[GPIOD_LINE_BULK_MAX_LINES];
    (void)arg;
    if (hal->reset_ns > (hal_u32_t)(period / 4))
        hal->reset_ns = (hal_u32_t)(period / 4);
    for (int i = 0; i < lines.group_count; i++) {
        gpio_group_t *g = &lines.groups[i];
        if (!g->is_output || !g->written)
            continue;
        for (unsigned k = 0; k < g->bulk.num_lines; k++) {
            unsigned flags = specs[g->spec[k]].flags;
            values[k] = (flags & GPIO_FLAG_RESET) ? !!(flags & GPIO_FLAG_INVERT) : g->values[k];
        }
        if (memcmp(values, g->values, sizeof(int) * g->bulk.num_lines) == 0)
            continue;
        while (rtapi_get_time() < g->write_time_ns + hal->reset_ns)
            ;
        put_group(g, values);
    }
}

/* Create the pins of every line. */
static int export_pins(void)
{
    int r = 0;
    for (int i = 0; i < line_count && r == 0; i++) {
        if (specs[i].is_output) {
            r = hal_pin_bit_newf(HAL_IN, &hal->pin[i], comp_id, "hal_gpio.%s-out", specs[i].name);
            continue;
        }
        r = hal_pin_bit_newf(HAL_OUT, &hal->pin[i], comp_id, "hal_gpio.%s-in", specs[i].name);
        if (r == 0)
            r = hal_pin_bit_newf(HAL_OUT, &hal->pin_not[i], comp_id, "hal_gpio.%s-in-not", specs[i].name);
        if (r == 0) {
            *hal->pin[i] = 0;
            *hal->pin_not[i] = 1;
        }
    }
    return r;
}

/* Create the pins, the reset parameter and the functs. */
static int export_all(void)
{
    int any_reset = 0, r;
    hal = hal_malloc(sizeof(*hal));
    if (!hal)
        return -ENOMEM;
    memset(hal, 0, sizeof(*hal));
    for (int i = 0; i < line_count; i++)
        if (specs[i].is_output && (specs[i].flags & GPIO_FLAG_RESET))
            any_reset = 1;
    r = export_pins();
    if (r == 0 && any_reset)
        r = hal_param_u32_new("hal_gpio.reset_ns", HAL_RW, &hal->reset_ns, comp_id);
    if (r == 0)
        r = hal_export_funct("hal_gpio.read", gpio_read, NULL, 0, 0, comp_id);
    if (r == 0)
        r = hal_export_funct("hal_gpio.write", gpio_write, NULL, 0, 0, comp_id);
    if (r == 0 && any_reset)
        r = hal_export_funct("hal_gpio.reset", gpio_reset, NULL, 0, 0, comp_id);
    return r;
}

/* Check the arguments, request the lines and create the HAL objects. */
int rtapi_app_main(void)
{
    gpio_args_t args = { inputs, outputs, invert, reset, opendrain, opensource, biasdisable, pulldown, pullup };
    int r;
    rtapi_print_msg(RTAPI_MSG_INFO, "Libgpiod is %s\n", gpiod_version_string());
    line_count = gpio_args_collect(&args, specs, report, NULL);
    if (line_count < 0)
        return -EINVAL;
    for (int i = 0; i < line_count; i++)
        rtapi_print_msg(RTAPI_MSG_INFO, "line %s flags %02x\n", specs[i].name, specs[i].flags);
    r = gpio_lines_open(&lines, specs, line_count, report, NULL);
    if (r != 0)
        return r == -ENOENT ? -1 : r;
    comp_id = hal_init("hal_gpio");
    if (comp_id < 0) {
        gpio_lines_close(&lines);
        return comp_id;
    }
    r = export_all();
    if (r != 0) {
        gpio_lines_close(&lines);
        hal_exit(comp_id);
        return r;
    }
    hal_ready(comp_id);
    return 0;
}

/* Release the lines and remove the component. */
void rtapi_app_exit(void)
{
    gpio_lines_close(&lines);
    hal_exit(comp_id);
}
