/* comptest_home.c: comptest commands that call a loaded homing module's API (LinuxCNC's names). */
#include <dlfcn.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Address of a homing API function, or NULL after saying which one is missing. */
static void *home_fn(void *module, const char *name)
{
    void *f = module ? dlsym(module, name) : NULL;
    if (!f)
        printf("missing homing function %s\n", name);
    return f;
}

/* hinit N: homing_init with N joints, pins in component 1. */
static void cmd_hinit(void *module, int argc, char **argv)
{
    int (*init)(int, double, int, int, void *) = (int (*)(int, double, int, int, void *))home_fn(module, "homing_init");
    if (init)
        printf("homing_init %d\n", init(1, 0.001, argc > 1 ? atoi(argv[1]) : 1, 0, NULL));
}

/* hcycle N: one servo period for N joints: read pins, do_homing (printed), write pins. */
static void cmd_hcycle(void *module, int argc, char **argv)
{
    void (*rd)(int) = (void (*)(int))home_fn(module, "read_homing_in_pins");
    bool (*doh)(void) = (bool (*)(void))home_fn(module, "do_homing");
    void (*wr)(int) = (void (*)(int))home_fn(module, "write_homing_out_pins");
    int n = argc > 1 ? atoi(argv[1]) : 1;
    if (!rd || !doh || !wr)
        return;
    rd(n);
    int all = doh();
    wr(n);
    printf("do_homing %d\n", all);
}

/* hquery J: the per-joint queries for joint J. */
static void cmd_hquery(void *module, int argc, char **argv)
{
    static const char *const q[] = {"get_homed", "get_home_is_idle", "get_home_is_synchronized",
                                    "get_home_needs_unlock_first", "get_homing",
                                    "get_homing_at_index_search_wait", "get_index_enable"};
    int j = argc > 1 ? atoi(argv[1]) : 0;
    printf("joint %d:", j);
    for (unsigned i = 0; i < sizeof(q) / sizeof(q[0]); i++) {
        bool (*f)(int) = (bool (*)(int))home_fn(module, q[i]);
        if (f)
            printf(" %s=%d", q[i] + 4, f(j));
    }
    int (*seq)(int) = (int (*)(int))home_fn(module, "get_home_sequence");
    bool (*all)(void) = (bool (*)(void))home_fn(module, "get_allhomed");
    bool (*active)(void) = (bool (*)(void))home_fn(module, "get_homing_is_active");
    if (seq && all && active)
        printf(" home_sequence=%d allhomed=%d homing_is_active=%d", seq(j), all(), active());
    printf("\n");
}

/* Handle a homing-API command; 1 when argv[0] was one. */
int comptest_home_dispatch(void *module, int argc, char **argv)
{
    if (!strcmp(argv[0], "hinit"))
        cmd_hinit(module, argc, argv);
    else if (!strcmp(argv[0], "hcycle"))
        cmd_hcycle(module, argc, argv);
    else if (!strcmp(argv[0], "hquery"))
        cmd_hquery(module, argc, argv);
    else
        return 0;
    return 1;
}
