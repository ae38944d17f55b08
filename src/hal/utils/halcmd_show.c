/* halcmd_show.c: show comp/pin/sig/param/alias sections and the show dispatcher. */
#include <fnmatch.h>
#include <stdio.h>
#include <string.h>
#include "hal.h"
#include "halcmd.h"
#include "halcmd_cmds.h"
#include "halcmd_hal.h"
#include "halcmd_show.h"

/* An item matches when no pattern is given or any pattern is a prefix or glob of it. */
int hc_match(char *patterns[], int npat, const char *name)
{
    if (npat == 0)
        return 1;
    for (int i = 0; i < npat; i++) {
        if (strncmp(name, patterns[i], strlen(patterns[i])) == 0 ||
            fnmatch(patterns[i], name, 0) == 0)
            return 1;
    }
    return 0;
}

/* Direction text of a pin or param. */
const char *hc_dir_name(int dir)
{
    switch (dir) {
    case HAL_IN: return "IN";
    case HAL_OUT: return "OUT";
    case HAL_IO: return "I/O";
    case HAL_RO: return "RO";
    case HAL_RW: return "RW";
    default: return "???";
    }
}

/* Format a value for a listing: 20 wide, or unpadded with -s. */
void hc_show_value(int type, const void *cell, char *buf, size_t size)
{
    if (hc.script_mode)
        hc_format_value_script(type, cell, buf, size);
    else
        hc_format_value20(type, cell, buf, size);
}

/* Print the comp section. */
void hc_show_comps(char *pat[], int npat)
{
    static const char *types[] = {"RT", "User", "INST"};
    if (!hc.script_mode)
        hc_out("Loaded HAL Components:\nID      Type  %-*s PID   State\n", HAL_NAME_LEN, "Name");
    for (hal_comp_t *c = halpr_first_comp(); c; c = halpr_next_comp(c)) {
        if (!hc_match(pat, npat, c->name))
            continue;
        hc_out(" %5d  %-4s  %-*s", c->comp_id, types[c->type % 3], HAL_NAME_LEN, c->name);
        if (c->type == HAL_COMP_RT)
            hc_out(" %5s", "");
        else
            hc_out(" %5d", c->pid);
        hc_out(" %s\n", c->ready ? "ready" : "initializing");
    }
    hc_out("\n");
}

/* Pin-view arrow: IN <==, OUT ==>, IO <=>. */
static const char *hc_pin_arrow(int dir)
{
    return dir == HAL_IN ? "<==" : dir == HAL_OUT ? "==>" : "<=>";
}

/* Signal-view arrow: IN ==>, OUT <==, IO <=>. */
const char *hc_sig_arrow(int dir)
{
    return dir == HAL_IN ? "==>" : dir == HAL_OUT ? "<==" : "<=>";
}

/* Print the owner, type, dir, value and name columns of a pin or param line. */
static void hc_show_item(int owner_ptr, int type, int dir, const hal_data_u *cell,
                         const char *name)
{
    char val[64];
    hal_comp_t *owner = halpr_owner(owner_ptr);
    hc_show_value(type, (const void *)cell, val, sizeof val);
    if (hc.script_mode)
        hc_out("%s %s %s %s %s", owner->name, hc_type_name5(type), hc_dir_name(dir), val, name);
    else
        hc_out(" %5d  %s %-3s  %s  %s", owner->comp_id, hc_type_name5(type), hc_dir_name(dir),
               val, name);
}

/* Print one pin line, with the signal it is linked to. */
static void hc_show_pin(hal_pin_t *p)
{
    hc_show_item(p->owner_ptr, p->type, p->dir, halpr_pin_value(p), p->name);
    if (p->signal)
        hc_out(" %s %s", hc_pin_arrow(p->dir), ((hal_sig_t *)SHMPTR(p->signal))->name);
    hc_out("\n");
}

/* Print the pin section (type filter < 0 = all types). */
void hc_show_pins(int type, char *pat[], int npat)
{
    if (!hc.script_mode)
        hc_out("Component Pins:\nOwner   Type  Dir                 Value  Name\n");
    for (hal_pin_t *p = halpr_first_pin(); p; p = halpr_next_pin(p))
        if ((type < 0 || (int)p->type == type) && hc_match(pat, npat, p->name))
            hc_show_pin(p);
    hc_out("\n");
}

/* Print the param section. */
void hc_show_params(int type, char *pat[], int npat)
{
    if (!hc.script_mode)
        hc_out("Parameters:\nOwner   Type  Dir                 Value  Name\n");
    for (hal_param_t *p = halpr_first_param(); p; p = halpr_next_param(p)) {
        if ((type >= 0 && (int)p->type != type) || !hc_match(pat, npat, p->name))
            continue;
        hc_show_item(p->owner_ptr, p->type, p->dir, halpr_param_value(p), p->name);
        hc_out("\n");
    }
    hc_out("\n");
}

/* Print one signal with its pins. */
static void hc_show_sig(hal_sig_t *s)
{
    char val[64];
    hc_show_value(s->type, (const void *)halpr_sig_value(s), val, sizeof val);
    hc_out("%s  %s  %s", hc_type_name5(s->type), val, s->name);
    if (!hc.script_mode)
        hc_out("\n");
    for (hal_pin_t *p = halpr_first_sig_pin(s); p; p = halpr_next_sig_pin(p)) {
        if (hc.script_mode)
            hc_out(" %s %s", hc_sig_arrow(p->dir), p->name);
        else
            hc_out("%32s %s %s\n", "", hc_sig_arrow(p->dir), p->name);
    }
    if (hc.script_mode)
        hc_out("\n");
}

/* Print the signal section. */
void hc_show_sigs(int type, char *pat[], int npat)
{
    if (!hc.script_mode)
        hc_out("Signals:\nType                  Value  Name     (linked to)\n");
    for (hal_sig_t *s = halpr_first_sig(); s; s = halpr_next_sig(s))
        if ((type < 0 || (int)s->type == type) && hc_match(pat, npat, s->name))
            hc_show_sig(s);
    hc_out("\n");
}

/* Print one alias line if it matches (alias or original name). */
static void hc_show_alias_line(const char *alias, int oldname, char *pat[], int npat)
{
    const char *orig = halpr_original_name(oldname);
    if (!hc_match(pat, npat, alias) && !hc_match(pat, npat, orig))
        return;
    if (hc.script_mode)
        hc_out(" %s  %s\n", alias, orig);
    else
        hc_out(" %-*s  %s\n", HAL_NAME_LEN, alias, orig);
}

/* Print the pin aliases section. */
void hc_show_pin_aliases(char *pat[], int npat)
{
    if (!hc.script_mode)
        hc_out("Pin Aliases:\n %-*s  %s\n", HAL_NAME_LEN, "Alias", "Original Name");
    for (hal_pin_t *p = halpr_first_pin(); p; p = halpr_next_pin(p))
        if (p->oldname)
            hc_show_alias_line(p->name, p->oldname, pat, npat);
    hc_out("\n");
}

/* Print the param aliases section. */
void hc_show_param_aliases(char *pat[], int npat)
{
    if (!hc.script_mode)
        hc_out("Parameter Aliases:\n %-*s  %s\n", HAL_NAME_LEN, "Alias", "Original Name");
    for (hal_param_t *p = halpr_first_param(); p; p = halpr_next_param(p))
        if (p->oldname)
            hc_show_alias_line(p->name, p->oldname, pat, npat);
    hc_out("\n");
}
