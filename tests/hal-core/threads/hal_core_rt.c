/* hal_core_rt.c: realtime test module for the HAL library: thread rules, addf/delf/initf, init cycle, parking. */
#include "rtapi.h"
#include "rtapi_app.h"
#include "hal.h"
#include "hal_priv.h"

MODULE_LICENSE("GPL");

/* Pins and state shared by the test functs (in HAL memory). */
struct rt_state {
    hal_s32_t *count;       /* calls of .count */
    hal_s32_t *mismatch;    /* cycles where count != threadbeat + 1 */
    hal_s32_t *period;      /* period argument seen by .count */
    hal_s32_t *init_calls;  /* calls of .init */
    hal_s32_t *init_saw;    /* .count calls made before .init ran */
    hal_s32_t *d_count;     /* calls of .d (on the parked thread) */
    hal_s64_t *beat;        /* fast.threadbeat value cell (RT address) */
};

static int comp_id;
static struct rt_state *st;

/* Counts cycles and checks the init-cycle / threadbeat relation. */
static void count_funct(void *arg, long period)
{
    struct rt_state *s = arg;
    *s->count += 1;
    *s->period = period;
    if (*s->count != *s->beat + 1)
        *s->mismatch += 1;
}

/* Runs once in the init cycle. */
static void init_funct(void *arg, long period)
{
    struct rt_state *s = arg;
    (void)period;
    *s->init_calls += 1;
    *s->init_saw = *s->count;
}

/* Counts calls on the thread whose pseudo comp was removed. */
static void d_funct(void *arg, long period)
{
    struct rt_state *s = arg;
    (void)period;
    *s->d_count += 1;
}

/* Does nothing (ordering tests). */
static void nop_funct(void *arg, long period)
{
    (void)arg;
    (void)period;
}

/* Print a result line (stderr, so it stays in order with HAL's messages). */
static void say(const char *what, int rc)
{
    rtapi_print_msg(RTAPI_MSG_ERR, "T: %s -> %d\n", what, rc);
}

/* Thread creation rules: zero period, duplicates, base period, rounding, ordering. */
static void test_threads(void)
{
    hal_thread_t *t;

    say("create t-zero period 0", hal_create_thread("t-zero", 0, 1));
    say("create fast 100000", hal_create_thread("fast", 100000, 1));
    say("create fast again", hal_create_thread("fast", 100000, 1));
    say("create slower 50000 (< base)", hal_create_thread("slower", 50000, 1));
    say("create mid 140000 (rounds to 100000)", hal_create_thread("mid", 140000, 1));
    say("create odd 250000 (rounds to 300000)", hal_create_thread("odd", 250000, 1));
    say("create short 200000 (< existing)", hal_create_thread("short", 200000, 1));
    halpr_mutex_get();
    for (t = halpr_first_thread(); t; t = halpr_next_thread(t))
        rtapi_print_msg(RTAPI_MSG_ERR, "T: thread %s period %ld\n", t->name, t->period);
    halpr_mutex_give();
}

/* Functs with their timing items. */
static int test_functs(void)
{
    int rc = hal_export_funct("hal-core-rt.count", count_funct, st, 1, 0, comp_id);
    if (rc == 0)
        rc = hal_export_funct("hal-core-rt.init", init_funct, st, 1, 0, comp_id);
    if (rc == 0)
        rc = hal_export_funct("hal-core-rt.d", d_funct, st, 1, 0, comp_id);
    if (rc == 0)
        rc = hal_export_functf(nop_funct, NULL, 1, 0, comp_id, "hal-core-rt.%c", 'a');
    if (rc == 0)
        rc = hal_export_funct("hal-core-rt.b", nop_funct, NULL, 1, 0, comp_id);
    if (rc == 0)
        rc = hal_export_funct("hal-core-rt.c", nop_funct, NULL, 1, 1, comp_id);
    say("export functs", rc);
    say("export duplicate", hal_export_funct("hal-core-rt.b", nop_funct, NULL, 1, 0, comp_id));
    say("export name too long for .tmax-increased",
        hal_export_funct("hal-core-rt.this-name-is-long-enough-to-overflow", nop_funct, NULL, 1, 0, comp_id));
    return rc;
}

/* addf/delf/initf positions and errors. */
static void test_addf(void)
{
    hal_funct_entry_t *e;
    hal_thread_t *fast;

    say("addf a fast", hal_add_funct_to_thread("hal-core-rt.a", "fast", -1));
    say("addf b fast 1", hal_add_funct_to_thread("hal-core-rt.b", "fast", 1));
    say("addf c fast -1", hal_add_funct_to_thread("hal-core-rt.c", "fast", -1));
    say("addf count fast 2", hal_add_funct_to_thread("hal-core-rt.count", "fast", 2));
    say("addf c odd -2 (too low)", hal_add_funct_to_thread("hal-core-rt.c", "odd", -2));
    say("addf c odd 3 (too high)", hal_add_funct_to_thread("hal-core-rt.c", "odd", 3));
    say("addf c odd (reentrant twice)", hal_add_funct_to_thread("hal-core-rt.c", "odd", 1));
    say("addf a odd (not reentrant)", hal_add_funct_to_thread("hal-core-rt.a", "odd", 1));
    say("addf bad position 0", hal_add_funct_to_thread("hal-core-rt.d", "odd", 0));
    say("addf missing funct", hal_add_funct_to_thread("nope", "odd", 1));
    say("addf missing thread", hal_add_funct_to_thread("hal-core-rt.d", "nope", 1));
    say("delf d (not in use)", hal_del_funct_from_thread("hal-core-rt.d", "mid"));
    say("addf d mid", hal_add_funct_to_thread("hal-core-rt.d", "mid", 1));
    say("initf init fast", hal_init_funct_to_thread("hal-core-rt.init", "fast", 1));
    say("delf missing thread name", hal_del_funct_from_thread("hal-core-rt.c", NULL));
    say("delf b from odd (not there)", hal_del_funct_from_thread("hal-core-rt.b", "odd"));
    say("delf c from odd", hal_del_funct_from_thread("hal-core-rt.c", "odd"));
    say("delf c from odd again", hal_del_funct_from_thread("hal-core-rt.c", "odd"));
    halpr_mutex_get();
    fast = halpr_find_thread_by_name("fast");
    for (e = halpr_first_entry(fast->funct_list); e; e = halpr_next_entry(e))
        rtapi_print_msg(RTAPI_MSG_ERR, "T: fast runs %s (users %d)\n", halpr_entry_funct(e)->name,
                        halpr_entry_funct(e)->users);
    for (e = halpr_first_entry(fast->init_list); e; e = halpr_next_entry(e))
        rtapi_print_msg(RTAPI_MSG_ERR, "T: fast init %s\n", halpr_entry_funct(e)->name);
    halpr_mutex_give();
}

/* Remove the pseudo comp __mid: thread mid must keep running d. */
static void test_park(void)
{
    hal_comp_info_t info;
    int rc = hal_comp_by_name("__mid", &info);
    say("find __mid", rc);
    if (rc == 0)
        say("hal_exit __mid", hal_exit(info.comp_id));
    say("mid.time gone", hal_get_p("mid.time", &(hal_type_t){0}, &(int){0}, &(hal_data_u){0}));
}

/* Pins of the state block. */
static int make_pins(void)
{
    int rc = hal_pin_s32_new("hal-core-rt.count", HAL_OUT, &st->count, comp_id);
    if (rc == 0)
        rc = hal_pin_s32_new("hal-core-rt.mismatch", HAL_OUT, &st->mismatch, comp_id);
    if (rc == 0)
        rc = hal_pin_s32_new("hal-core-rt.period", HAL_OUT, &st->period, comp_id);
    if (rc == 0)
        rc = hal_pin_s32_new("hal-core-rt.init-calls", HAL_OUT, &st->init_calls, comp_id);
    if (rc == 0)
        rc = hal_pin_s32_new("hal-core-rt.init-saw", HAL_OUT, &st->init_saw, comp_id);
    if (rc == 0)
        rc = hal_pin_s32_new("hal-core-rt.d-count", HAL_OUT, &st->d_count, comp_id);
    return rc;
}

/* Run every check; the functs keep running for test.sh to inspect. */
int rtapi_app_main(void)
{
    hal_pin_t *beat;
    int rc;

    comp_id = hal_init("hal_core_rt");
    if (comp_id < 0)
        return comp_id;
    st = hal_malloc(sizeof(*st));
    rc = st ? make_pins() : -ENOMEM;
    if (rc == 0)
        rc = test_functs();
    if (rc < 0) {
        hal_exit(comp_id);
        return rc;
    }
    test_threads();
    halpr_mutex_get();
    beat = halpr_find_pin_by_name("fast.threadbeat");
    st->beat = &halpr_pin_value(beat)->ls;
    halpr_mutex_give();
    test_addf();
    test_park();
    hal_ready(comp_id);
    return 0;
}

/* Remove the component (its functs leave the threads). */
void rtapi_app_exit(void)
{
    hal_exit(comp_id);
}
