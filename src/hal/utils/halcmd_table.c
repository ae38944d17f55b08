/* halcmd_table.c: the command table: name, handler, argument counts and flags. */
#include <string.h>
#include "halcmd.h"
#include "halcmd_cmds.h"

#define A HC_ARROWS
#define T HC_TILDE

/* Every command halcmd knows, in help order. */
static const hc_command_t hc_commands[] = {
    {"loadrt", hc_cmd_loadrt, 1, -1, 0},
    {"loadusr", hc_cmd_loadusr, 0, -1, T},
    {"waitusr", hc_cmd_waitusr, 1, 1, 0},
    {"unloadrt", hc_cmd_unloadrt, 1, 1, 0},
    {"unloadusr", hc_cmd_unloadusr, 1, 1, 0},
    {"unload", hc_cmd_unload, 1, 1, 0},
    {"net", hc_cmd_net, 1, -1, A},
    {"linkps", hc_cmd_linkps, 2, 2, A},
    {"linksp", hc_cmd_linksp, 2, 2, A},
    {"linkpp", hc_cmd_linkpp, 2, 2, A},
    {"unlinkp", hc_cmd_unlinkp, 1, 1, 0},
    {"newsig", hc_cmd_newsig, 2, 2, 0},
    {"delsig", hc_cmd_delsig, 1, 1, 0},
    {"setp", hc_cmd_setp, 2, 2, 0},
    {"sets", hc_cmd_sets, 2, 2, 0},
    {"getp", hc_cmd_getp, 1, 1, 0},
    {"gets", hc_cmd_gets, 1, 1, 0},
    {"ptype", hc_cmd_ptype, 1, 1, 0},
    {"stype", hc_cmd_stype, 1, 1, 0},
    {"addf", hc_cmd_addf, 2, 3, 0},
    {"initf", hc_cmd_initf, 2, 3, 0},
    {"delf", hc_cmd_delf, 1, 2, 0},
    {"start", hc_cmd_start, 0, 0, 0},
    {"stop", hc_cmd_stop, 0, 0, 0},
    {"show", hc_cmd_show, 0, -1, 0},
    {"list", hc_cmd_list, 1, -1, 0},
    {"save", hc_cmd_save, 0, 2, T},
    {"status", hc_cmd_status, 0, 1, 0},
    {"lock", hc_cmd_lock, 0, 1, 0},
    {"unlock", hc_cmd_unlock, 0, 1, 0},
    {"alias", hc_cmd_alias, 3, 3, 0},
    {"unalias", hc_cmd_unalias, 2, 2, 0},
    {"source", hc_cmd_source, 1, 1, T},
    {"echo", hc_cmd_echo, 0, 0, 0},
    {"unecho", hc_cmd_unecho, 0, 0, 0},
    {"print", hc_cmd_print, 0, 1, 0},
    {"debug", hc_cmd_debug, 1, 1, 0},
    {"setexact_for_test_suite_only", hc_cmd_setexact, 0, 0, 0},
    {"help", hc_cmd_help, 0, 1, 0},
};

#define HC_NCOMMANDS (sizeof hc_commands / sizeof hc_commands[0])

/* Find a command by exact (case-sensitive) name. */
const hc_command_t *hc_find_command(const char *name)
{
    for (size_t i = 0; i < HC_NCOMMANDS; i++)
        if (strcmp(hc_commands[i].name, name) == 0)
            return &hc_commands[i];
    return NULL;
}

/* The i-th command, or NULL past the end (for help and completion). */
const hc_command_t *hc_command_at(int i)
{
    return (i >= 0 && (size_t)i < HC_NCOMMANDS) ? &hc_commands[i] : NULL;
}
