/* halcmd_complete.c: completion candidates (commands, HAL names) for readline and -C. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "hal.h"
#include "halcmd.h"
#include "halcmd_hal.h"
#include "halcmd_complete.h"

/* Add name to the list when it starts with prefix. */
static void hc_cand_add(hc_cands_t *c, const char *name, const char *prefix)
{
    if (strncmp(name, prefix, strlen(prefix)) != 0)
        return;
    if (c->count == c->cap) {
        int cap = c->cap ? 2 * c->cap : 64;
        char **v = realloc(c->names, cap * sizeof *v);
        if (!v)
            return;
        c->names = v;
        c->cap = cap;
    }
    c->names[c->count] = strdup(name);
    if (c->names[c->count])
        c->count++;
}

/* Words completing the argument of show/list/save/status/lock. */
static const char *hc_keyword_list(const char *cmd)
{
    if (!strcmp(cmd, "show"))
        return "comp pin sig param funct thread alias all";
    if (!strcmp(cmd, "list"))
        return "comp pin sig param funct thread";
    if (!strcmp(cmd, "save"))
        return "comp alias sig sigu link linka net neta netl netla param thread "
               "unconnectedinpins all allu";
    if (!strcmp(cmd, "status"))
        return "lock mem all";
    if (!strcmp(cmd, "lock") || !strcmp(cmd, "unlock"))
        return "all tune none";
    if (!strcmp(cmd, "newsig"))
        return NULL;
    return NULL;
}

/* Add the blank-separated words of list matching prefix. */
static void hc_cand_words(hc_cands_t *c, const char *list, const char *prefix)
{
    char buf[512], *save = NULL;
    snprintf(buf, sizeof buf, "%s", list);
    for (char *w = strtok_r(buf, " ", &save); w; w = strtok_r(NULL, " ", &save))
        hc_cand_add(c, w, prefix);
}

/* Add every HAL object name matching prefix. */
static void hc_cand_hal(hc_cands_t *c, const char *prefix)
{
    if (!hal_data)
        return;
    halpr_mutex_get();
    for (hal_pin_t *p = halpr_first_pin(); p; p = halpr_next_pin(p))
        hc_cand_add(c, p->name, prefix);
    for (hal_param_t *p = halpr_first_param(); p; p = halpr_next_param(p))
        hc_cand_add(c, p->name, prefix);
    for (hal_sig_t *s = halpr_first_sig(); s; s = halpr_next_sig(s))
        hc_cand_add(c, s->name, prefix);
    for (hal_funct_t *f = halpr_first_funct(); f; f = halpr_next_funct(f))
        hc_cand_add(c, f->name, prefix);
    for (hal_thread_t *t = halpr_first_thread(); t; t = halpr_next_thread(t))
        hc_cand_add(c, t->name, prefix);
    for (hal_comp_t *k = halpr_first_comp(); k; k = halpr_next_comp(k))
        hc_cand_add(c, k->name, prefix);
    halpr_mutex_give();
}

/* Fill c with completions of word number `index` (0 = command) of cmd. */
void hc_complete_word(hc_cands_t *c, int index, const char *cmd, const char *prefix)
{
    const char *kw = hc_keyword_list(cmd);
    const hc_command_t *k;
    if (index == 0) {
        for (int i = 0; (k = hc_command_at(i)) != NULL; i++)
            hc_cand_add(c, k->name, prefix);
        return;
    }
    if (index == 1 && kw) {
        hc_cand_words(c, kw, prefix);
        return;
    }
    hc_cand_hal(c, prefix);
}

/* Free a candidate list. */
void hc_cands_free(hc_cands_t *c)
{
    for (int i = 0; i < c->count; i++)
        free(c->names[i]);
    free(c->names);
    memset(c, 0, sizeof *c);
}

/* -C: print completions of $COMP_LINE up to $COMP_POINT, one per line. */
int hc_complete_bash(void)
{
    const char *line = getenv("COMP_LINE"), *point = getenv("COMP_POINT");
    char buf[HC_LINE_MAX], *words[HC_MAX_TOKENS + 1], *save = NULL;
    int n = 0, len;
    hc_cands_t c = {0};
    if (!line)
        return 0;
    len = point ? atoi(point) : (int)strlen(line);
    snprintf(buf, sizeof buf, "%.*s", len, line);
    for (char *w = strtok_r(buf, " \t", &save); w && n < HC_MAX_TOKENS; w = strtok_r(NULL, " \t", &save))
        words[n++] = w;
    if (len == 0 || buf[len - 1] == ' ' || buf[len - 1] == '\t')
        words[n++] = "";
    if (n < 2)
        return 0;
    if (hal_lib_init() < 0)
        hal_data = NULL;
    hc_complete_word(&c, n - 2, n > 2 ? words[1] : "", words[n - 1]);
    for (int i = 0; i < c.count; i++)
        printf("%s\n", c.names[i]);
    hc_cands_free(&c);
    return 0;
}
