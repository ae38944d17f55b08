/* halcmd_save.c: save [type [file]]: dump the HAL setup as halcmd commands. */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "hal.h"
#include "halcmd.h"
#include "halcmd_cmds.h"
#include "halcmd_hal.h"
#include "halcmd_show.h"

/* Print loadrt lines for RT comps, oldest first. */
static void hc_save_comps(FILE *out)
{
    int n = 0;
    hal_comp_t *c;
    fprintf(out, "# components\n");
    for (c = halpr_first_comp(); c; c = halpr_next_comp(c))
        n++;
    for (int i = n - 1; i >= 0; i--) {
        int k = 0;
        for (c = halpr_first_comp(); c && k < i; c = halpr_next_comp(c))
            k++;
        if (c->type != HAL_COMP_RT)
            continue;
        if (halpr_insmod_args(c))
            fprintf(out, "loadrt %s %s\n", c->name, halpr_insmod_args(c));
        else
            fprintf(out, "#loadrt %s  (not loaded by loadrt, no args saved)\n", c->name);
    }
}

/* Print one alias command if aliased. */
static void hc_save_alias(FILE *out, const char *kind, int oldname, const char *name)
{
    if (oldname)
        fprintf(out, "alias %s %s %s\n", kind, halpr_original_name(oldname), name);
}

/* Print the pin and param alias sections (headers always, as LinuxCNC does). */
static void hc_save_aliases(FILE *out)
{
    fprintf(out, "# pin aliases\n");
    for (hal_pin_t *p = halpr_first_pin(); p; p = halpr_next_pin(p))
        hc_save_alias(out, "pin", p->oldname, p->name);
    fprintf(out, "# param aliases\n");
    for (hal_param_t *p = halpr_first_param(); p; p = halpr_next_param(p))
        hc_save_alias(out, "param", p->oldname, p->name);
}

/* Print newsig lines (all signals, or only pinless ones). */
static void hc_save_sigs(FILE *out, int only_unlinked)
{
    fprintf(out, "# signals\n");
    for (hal_sig_t *s = halpr_first_sig(); s; s = halpr_next_sig(s)) {
        if (only_unlinked && (s->readers || s->writers || s->bidirs))
            continue;
        fprintf(out, "newsig %s %s\n", s->name, hc_type_name5(s->type));
    }
}

/* Print linkps lines for every linked pin (with or without arrows). */
static void hc_save_links(FILE *out, int arrows)
{
    static const char *pin_arrows[] = {"<==", "==>", "<=>"};
    fprintf(out, "# links\n");
    for (hal_pin_t *p = halpr_first_pin(); p; p = halpr_next_pin(p)) {
        if (!p->signal)
            continue;
        const char *sig = ((hal_sig_t *)SHMPTR(p->signal))->name;
        int a = p->dir == HAL_IN ? 0 : p->dir == HAL_OUT ? 1 : 2;
        fprintf(out, "linkps %s %s %s\n", p->name, arrows ? pin_arrows[a] : "", sig);
    }
}

/* Print newsig + linksp lines per signal (net / neta). */
static void hc_save_nets_linksp(FILE *out, int arrows)
{
    fprintf(out, "# nets\n");
    for (hal_sig_t *s = halpr_first_sig(); s; s = halpr_next_sig(s)) {
        fprintf(out, "newsig %s %s\n", s->name, hc_type_name5(s->type));
        for (hal_pin_t *p = halpr_first_sig_pin(s); p; p = halpr_next_sig_pin(p))
            fprintf(out, "linksp %s %s %s\n", s->name, arrows ? hc_sig_arrow(p->dir) : "",
                    p->name);
    }
}

/* Print one "net" line with arrows: OUT => io1 <=> io2 => in1 in2. */
static void hc_save_netla_sig(FILE *out, hal_sig_t *s)
{
    int nio = 0;
    fprintf(out, "net %s", s->name);
    for (hal_pin_t *p = halpr_first_sig_pin(s); p; p = halpr_next_sig_pin(p))
        if (p->dir == HAL_OUT)
            fprintf(out, " %s =>", p->name);
    for (hal_pin_t *p = halpr_first_sig_pin(s); p; p = halpr_next_sig_pin(p))
        if (p->dir == HAL_IO)
            fprintf(out, "%s %s", nio++ ? " <=>" : "", p->name);
    if (nio && s->readers > s->bidirs)
        fprintf(out, " =>");
    for (hal_pin_t *p = halpr_first_sig_pin(s); p; p = halpr_next_sig_pin(p))
        if (p->dir == HAL_IN)
            fprintf(out, " %s", p->name);
    fprintf(out, "\n");
}

/* Print net lines (netl plain, netla with arrows); pinless signals skipped. */
static void hc_save_nets(FILE *out, int arrows)
{
    fprintf(out, "# nets\n");
    for (hal_sig_t *s = halpr_first_sig(); s; s = halpr_next_sig(s)) {
        if (!halpr_first_sig_pin(s))
            continue;
        if (arrows) {
            hc_save_netla_sig(out, s);
            continue;
        }
        fprintf(out, "net %s", s->name);
        for (hal_pin_t *p = halpr_first_sig_pin(s); p; p = halpr_next_sig_pin(p))
            fprintf(out, " %s", p->name);
        fprintf(out, "\n");
    }
}

/* Print setp lines for every RW param. */
static void hc_save_params(FILE *out)
{
    char val[64];
    fprintf(out, "# parameter values\n");
    for (hal_param_t *p = halpr_first_param(); p; p = halpr_next_param(p)) {
        if (p->dir == HAL_RO)
            continue;
        hc_format_value20(p->type, (const void *)halpr_param_value(p), val, sizeof val);
        fprintf(out, "setp %s %s\n", p->name, val);
    }
}

/* Print setp lines for unlinked IN and IO pins. */
static void hc_save_unconnected(FILE *out)
{
    char val[64];
    fprintf(out, "# unconnected pin values\n");
    for (hal_pin_t *p = halpr_first_pin(); p; p = halpr_next_pin(p)) {
        if (p->signal || p->dir == HAL_OUT || p->type == HAL_PORT)
            continue;
        hc_format_value20(p->type, (const void *)&p->dummysig, val, sizeof val);
        fprintf(out, "setp %s %s\n", p->name, val);
    }
}

/* Print addf/initf lines per thread, slowest first. */
static void hc_save_threads(FILE *out)
{
    fprintf(out, "# realtime thread/function links\n");
    for (hal_thread_t *t = halpr_first_thread(); t; t = halpr_next_thread(t)) {
        for (hal_funct_entry_t *e = halpr_first_entry(t->funct_list); e; e = halpr_next_entry(e))
            fprintf(out, "addf %s %s\n", halpr_entry_funct(e)->name, t->name);
        for (hal_funct_entry_t *e = halpr_first_entry(t->init_list); e; e = halpr_next_entry(e))
            fprintf(out, "initf %s %s\n", halpr_entry_funct(e)->name, t->name);
    }
}

/* Write one save type to out (mutex held); -1 on unknown type. */
static int hc_save_type(const char *w, FILE *out)
{
    int all = !strcmp(w, "all"), allu = !strcmp(w, "allu");
    if (all || allu) {
        hc_save_comps(out);
        hc_save_aliases(out);
        hc_save_sigs(out, 1);
        hc_save_nets(out, 1);
        hc_save_params(out);
        if (allu)
            hc_save_unconnected(out);
        hc_save_threads(out);
    } else if (!strcmp(w, "comp")) hc_save_comps(out);
    else if (!strcmp(w, "alias")) hc_save_aliases(out);
    else if (!strcmp(w, "sig") || !strcmp(w, "signal")) hc_save_sigs(out, 0);
    else if (!strcmp(w, "sigu")) hc_save_sigs(out, 1);
    else if (!strcmp(w, "link") || !strcmp(w, "linka")) hc_save_links(out, w[4] == 'a');
    else if (!strcmp(w, "net") || !strcmp(w, "neta")) hc_save_nets_linksp(out, w[3] == 'a');
    else if (!strcmp(w, "netl")) hc_save_nets(out, 0);
    else if (!strcmp(w, "netla") || !strcmp(w, "netal")) hc_save_nets(out, 1);
    else if (!strcmp(w, "param") || !strcmp(w, "parameter")) hc_save_params(out);
    else if (!strcmp(w, "thread")) hc_save_threads(out);
    else if (!strcmp(w, "unconnectedinpins")) hc_save_unconnected(out);
    else return -1;
    return 0;
}

/* Open the destination of save: a temporary file beside F, /dev/null (-Q) or stdout. */
static FILE *hc_save_open(int argc, char *argv[], char *tmp, size_t size)
{
    if (argc > 1) {
        snprintf(tmp, size, "%s.tmp%d", argv[1], (int)getpid());
        return fopen(tmp, "w");
    }
    return hc.quiet ? fopen("/dev/null", "w") : hc_stdout();
}

/* save [type [file]]: to stdout, or atomically replacing file. */
int hc_cmd_save(int argc, char *argv[])
{
    const char *type = argc > 0 ? argv[0] : "all";
    char tmp[4096];
    FILE *out = hc_save_open(argc, argv, tmp, sizeof tmp);
    int rc, write_failed = 0;
    if (!out) {
        hc_error("Can't open 'save' destination '%s'", argc > 1 ? argv[1] : "/dev/null");
        return -1;
    }
    halpr_mutex_get();
    rc = hc_save_type(type, out);
    halpr_mutex_give();
    if (out != hc_stdout())
        write_failed = fclose(out) != 0;
    fflush(hc_stdout());
    if (rc < 0)
        hc_error("Unknown 'save' type '%s'", type);
    if (argc > 1 && (rc < 0 || write_failed || rename(tmp, argv[1]) < 0)) {
        if (rc == 0)
            hc_error("Can't write 'save' destination '%s': %s", argv[1], strerror(errno));
        unlink(tmp);
        return -1;
    }
    return rc;
}
