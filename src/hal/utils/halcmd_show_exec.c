/* halcmd_show_exec.c: show funct/thread sections, the show dispatcher and list. */
#include <stdio.h>
#include <string.h>
#include "hal.h"
#include "halcmd.h"
#include "halcmd_cmds.h"
#include "halcmd_hal.h"
#include "halcmd_show.h"

/* Print the funct section. */
void hc_show_functs(char *pat[], int npat)
{
    if (!hc.script_mode)
        hc_out("Exported Functions:\nOwner   CodeAddr      Arg           FP   Users   Name\n");
    for (hal_funct_t *f = halpr_first_funct(); f; f = halpr_next_funct(f)) {
        if (!hc_match(pat, npat, f->name))
            continue;
        hal_comp_t *owner = halpr_owner(f->owner_ptr);
        unsigned long long code = (unsigned long long)(uintptr_t)f->funct;
        unsigned long long arg = (unsigned long long)(uintptr_t)f->arg;
        if (hc.script_mode)
            hc_out("%s %08llx %08llx YES %3d %s\n", owner->name, code, arg, f->users, f->name);
        else
            hc_out(" %05d  %08llx  %08llx  YES  %5d   %s\n", owner->comp_id, code, arg,
                   f->users, f->name);
    }
    hc_out("\n");
}

/* Print the functs of one entry list, numbered from 1. */
static void hc_show_entries(int list)
{
    int n = 1;
    for (hal_funct_entry_t *e = halpr_first_entry(list); e; e = halpr_next_entry(e), n++) {
        if (hc.script_mode)
            hc_out(" %s\n", halpr_entry_funct(e)->name);
        else
            hc_out("%17s %2d %s\n", "", n, halpr_entry_funct(e)->name);
    }
}

/* Print the header line of one thread; -1 when its time pin/tmax are gone. */
static int hc_show_thread_head(hal_thread_t *t)
{
    char name[HAL_NAME_LEN + 16];
    hal_pin_t *time;
    hal_param_t *tmax;
    long tv, mv;
    snprintf(name, sizeof name, "%s.time", t->name);
    time = halpr_find_pin_by_name(name);
    snprintf(name, sizeof name, "%s.tmax", t->name);
    tmax = halpr_find_param_by_name(name);
    if (!time || !tmax) {
        fprintf(hc_stderr(), "unexpected: cannot find time/tmax pin for %s thread\n", t->name);
        return -1;
    }
    tv = *(const hal_s32_t *)(const void *)halpr_pin_value(time);
    mv = *(const hal_s32_t *)(const void *)halpr_param_value(tmax);
    if (hc.script_mode)
        hc_out("%ld YES %s %8ld %ld\n", t->period, t->name, tv, mv);
    else
        hc_out("%11ld  YES  %20s ( %8ld, %8ld )\n", t->period, t->name, tv, mv);
    return 0;
}

/* Print the thread section. */
void hc_show_threads(char *pat[], int npat)
{
    if (!hc.script_mode)
        hc_out("Realtime Threads:\n     Period  FP     Name               (     Time, Max-Time )\n");
    for (hal_thread_t *t = halpr_first_thread(); t; t = halpr_next_thread(t)) {
        if (!hc_match(pat, npat, t->name))
            continue;
        hc_show_thread_head(t);
        hc_show_entries(t->funct_list);
        hc_show_entries(t->init_list);
    }
    hc_out("\n");
}

/* Consume a leading "-tTYPE" / "-t TYPE"; returns the type filter or -1. */
static int hc_type_filter(int *argc, char ***argv)
{
    const char *word;
    int used;
    if (*argc < 1 || strncmp((*argv)[0], "-t", 2) != 0)
        return -1;
    if ((*argv)[0][2]) {
        word = (*argv)[0] + 2;
        used = 1;
    } else {
        word = *argc > 1 ? (*argv)[1] : "";
        used = *argc > 1 ? 2 : 1;
    }
    *argc -= used;
    *argv += used;
    return hc_parse_filter_type(word);
}

/* Show every section (show all / show with no type). */
static void hc_show_all(char *pat[], int npat)
{
    hc_show_comps(pat, npat);
    hc_show_pins(-1, pat, npat);
    hc_show_pin_aliases(pat, npat);
    hc_show_sigs(-1, pat, npat);
    hc_show_params(-1, pat, npat);
    hc_show_param_aliases(pat, npat);
    hc_show_functs(pat, npat);
    hc_show_threads(pat, npat);
}

/* Run one show type with its patterns (mutex held); -1 on unknown type. */
static int hc_show_type(const char *what, int argc, char *argv[])
{
    int t = -1;
    if (!strcmp(what, "pin") || !strcmp(what, "sig") || !strcmp(what, "signal") ||
        !strcmp(what, "param") || !strcmp(what, "parameter"))
        t = hc_type_filter(&argc, &argv);
    if (!strcmp(what, "comp")) hc_show_comps(argv, argc);
    else if (!strcmp(what, "pin")) hc_show_pins(t, argv, argc);
    else if (!strcmp(what, "sig") || !strcmp(what, "signal")) hc_show_sigs(t, argv, argc);
    else if (!strcmp(what, "param") || !strcmp(what, "parameter")) hc_show_params(t, argv, argc);
    else if (!strcmp(what, "funct") || !strcmp(what, "function")) hc_show_functs(argv, argc);
    else if (!strcmp(what, "thread")) hc_show_threads(argv, argc);
    else if (!strcmp(what, "alias")) {
        hc_show_pin_aliases(argv, argc);
        hc_show_param_aliases(argv, argc);
    } else if (!strcmp(what, "all")) hc_show_all(argv, argc);
    else return -1;
    return 0;
}

/* show [type [-t type] [pattern...]] */
int hc_cmd_show(int argc, char *argv[])
{
    int rc;
    halpr_mutex_get();
    if (argc == 0) {
        hc_show_all(NULL, 0);
        rc = 0;
    } else {
        rc = hc_show_type(argv[0], argc - 1, argv + 1);
    }
    halpr_mutex_give();
    fflush(hc_stdout());
    if (rc < 0)
        hc_error("Unknown 'show' type '%s'", argv[0]);
    return rc;
}

/* Print one name followed by a blank if it matches. */
static void hc_list_name(const char *name, char *pat[], int npat)
{
    if (hc_match(pat, npat, name))
        hc_out("%s ", name);
}

/* Print the names of one list type (mutex held); -1 on unknown type. */
static int hc_list_type(const char *w, char *pat[], int npat)
{
    if (!strcmp(w, "comp")) {
        for (hal_comp_t *c = halpr_first_comp(); c; c = halpr_next_comp(c))
            hc_list_name(c->name, pat, npat);
    } else if (!strcmp(w, "pin")) {
        for (hal_pin_t *p = halpr_first_pin(); p; p = halpr_next_pin(p))
            hc_list_name(p->name, pat, npat);
    } else if (!strcmp(w, "sig") || !strcmp(w, "signal")) {
        for (hal_sig_t *s = halpr_first_sig(); s; s = halpr_next_sig(s))
            hc_list_name(s->name, pat, npat);
    } else if (!strcmp(w, "param") || !strcmp(w, "parameter")) {
        for (hal_param_t *p = halpr_first_param(); p; p = halpr_next_param(p))
            hc_list_name(p->name, pat, npat);
    } else if (!strcmp(w, "funct") || !strcmp(w, "function")) {
        for (hal_funct_t *f = halpr_first_funct(); f; f = halpr_next_funct(f))
            hc_list_name(f->name, pat, npat);
    } else if (!strcmp(w, "thread")) {
        for (hal_thread_t *t = halpr_first_thread(); t; t = halpr_next_thread(t))
            hc_list_name(t->name, pat, npat);
    } else {
        return -1;
    }
    hc_out("\n");
    return 0;
}

/* list type [pattern...] */
int hc_cmd_list(int argc, char *argv[])
{
    int rc;
    halpr_mutex_get();
    rc = hc_list_type(argv[0], argv + 1, argc - 1);
    halpr_mutex_give();
    fflush(hc_stdout());
    if (rc < 0)
        hc_error("Unknown 'list' type '%s'", argv[0]);
    return rc;
}
