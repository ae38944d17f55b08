/* gpio_args.h: hal_gpio's module arguments (lists of line names) checked and merged into line specs. */
#ifndef GPIO_ARGS_H
#define GPIO_ARGS_H

#define GPIO_MAX_LINES 128        /* capacity of each name-list modparam */
#define GPIO_LINE_NAME_MAX 31     /* the kernel's limit; hal_gpio.<name>-in-not then fits HAL_NAME_LEN */

/* Per-line options. */
enum {
    GPIO_FLAG_INVERT = 1 << 0,       /* output level = pin XOR 1 */
    GPIO_FLAG_RESET = 1 << 1,        /* the reset funct returns the output to its inactive level */
    GPIO_FLAG_OPEN_DRAIN = 1 << 2,
    GPIO_FLAG_OPEN_SOURCE = 1 << 3,
    GPIO_FLAG_BIAS_DISABLE = 1 << 4,
    GPIO_FLAG_PULL_DOWN = 1 << 5,
    GPIO_FLAG_PULL_UP = 1 << 6
};

/* One line to request. */
typedef struct {
    const char *name;
    int is_output;
    unsigned flags;
} gpio_line_spec_t;

/* The module arguments: each list holds up to GPIO_MAX_LINES names (NULL-terminated early). */
typedef struct {
    char **inputs, **outputs, **invert, **reset;
    char **opendrain, **opensource, **biasdisable, **pulldown, **pullup;
} gpio_args_t;

/* Message sink: is_error 0 = warning. */
typedef void (*gpio_report_fn)(void *ctx, int is_error, const char *text);

/* Check the arguments and fill specs (inputs first, then outputs, in argument order).
   Returns the line count or -1 after reporting every error found. */
int gpio_args_collect(const gpio_args_t *args, gpio_line_spec_t specs[2 * GPIO_MAX_LINES],
                      gpio_report_fn report, void *ctx);

#endif
