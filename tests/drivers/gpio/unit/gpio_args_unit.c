/* gpio_args_unit.c: prints how hal_gpio's name lists become line specs, and the errors it reports. */
#include <stdio.h>
#include <string.h>
#include "gpio_args.h"

/* Print a message as the module would. */
static void report(void *ctx, int is_error, const char *text)
{
    (void)ctx;
    printf("  %s: %s\n", is_error ? "error" : "warning", text);
}

/* Split a comma list into list (as the modparam loader does); NULL text leaves it empty. */
static char **split(char *text, char **list)
{
    int n = 0;
    memset(list, 0, sizeof(char *) * GPIO_MAX_LINES);
    if (!text)
        return list;
    for (char *p = text;; p++) {
        list[n++] = text;
        p = strchr(text, ',');
        if (!p)
            break;
        *p = '\0';
        text = p + 1;
    }
    return list;
}

/* Run one case: inputs, outputs, invert, reset, opendrain, opensource, biasdisable, pulldown, pullup. */
static void run(const char *title, const char *const text[9])
{
    static char *lists[9][GPIO_MAX_LINES];
    char copies[9][200];
    gpio_line_spec_t specs[2 * GPIO_MAX_LINES];
    char **l[9];
    for (int i = 0; i < 9; i++) {
        if (text[i])
            snprintf(copies[i], sizeof(copies[i]), "%s", text[i]);
        l[i] = split(text[i] ? copies[i] : NULL, lists[i]);
    }
    gpio_args_t args = { l[0], l[1], l[2], l[3], l[4], l[5], l[6], l[7], l[8] };
    printf("%s\n", title);
    int n = gpio_args_collect(&args, specs, report, NULL);
    printf("  -> %d\n", n);
    for (int i = 0; i < n; i++)
        printf("  %s %s flags 0x%02x\n", specs[i].is_output ? "out" : "in ", specs[i].name, specs[i].flags);
}

int main(void)
{
    run("no lines", (const char *const[9]){ 0 });
    run("inputs and outputs with every option",
        (const char *const[9]){ "in-a,in-b", "out-a,out-b,out-c", "out-b", "out-a,out-b", "out-c", "out-a",
                                "in-a", "in-b", "out-c" });
    run("invert and reset of an input are ignored",
        (const char *const[9]){ "in-a", "out-a", "in-a", "in-a", NULL, NULL, NULL, "in-a", NULL });
    run("opendrain of an input is ignored", (const char *const[9]){ "in-a", NULL, NULL, NULL, "in-a" });
    run("unknown names in option lists", (const char *const[9]){ "in-a", "out-a", "out-x", NULL, NULL, NULL, NULL,
                                                                  NULL, "nosuch" });
    run("duplicates", (const char *const[9]){ "a,b,a", "b,c,c" });
    run("empty and long names", (const char *const[9]){ "a,,b", "abcdefghijklmnopqrstuvwxyz012345,"
                                                        "abcdefghijklmnopqrstuvwxyz01234" });
    run("conflicting options", (const char *const[9]){ "in-a", "out-a", NULL, NULL, "out-a", "out-a", "in-a",
                                                        "in-a", "in-a,out-a" });
    return 0;
}
