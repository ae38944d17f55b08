/* halcmd_table.c: the command table: name, handler, argument counts, flags and help. */
#include <string.h>
#include "halcmd.h"
#include "halcmd_cmds.h"

/* Every command halcmd knows, in help order. */
static const hc_command_t hc_commands[] = {
    {"loadrt", hc_cmd_loadrt, 1, -1, 0,
     "loadrt modname [modarg(s)]",
     "Loads realtime HAL module 'modname', passing 'modargs' to the module."},
    {"loadusr", hc_cmd_loadusr, 0, -1, HC_TILDE,
     "loadusr [options] progname [progarg(s)]",
     "Starts user space program 'progname', passing 'progargs' to it.\n"
     "  -W  wait for the HAL component to become ready\n"
     "  -Wn name  wait for component 'name' to become ready\n"
     "  -w  wait for the program to exit\n"
     "  -i  ignore the program's return value (with -w)\n"
     "  -n name  component name to wait for"},
    {"waitusr", hc_cmd_waitusr, 1, 1, 0,
     "waitusr compname", "Waits for user space HAL component 'compname' to exit."},
    {"unloadrt", hc_cmd_unloadrt, 1, 1, 0,
     "unloadrt compname|all", "Unloads a realtime component or all of them."},
    {"unloadusr", hc_cmd_unloadusr, 1, 1, 0,
     "unloadusr compname|all", "Stops a user space component or all of them."},
    {"unload", hc_cmd_unload, 1, 1, 0,
     "unload compname|all", "Unloads any component (realtime or user space)."},
    {"net", hc_cmd_net, 1, -1, HC_ARROWS,
     "net signame pinname(s)",
     "Creates 'signame' if needed and links every pin to it; arrows are optional."},
    {"linkps", hc_cmd_linkps, 2, 2, HC_ARROWS,
     "linkps pinname [arrow] signame", "Links pin 'pinname' to signal 'signame'."},
    {"linksp", hc_cmd_linksp, 2, 2, HC_ARROWS,
     "linksp signame [arrow] pinname", "Links pin 'pinname' to signal 'signame'."},
    {"linkpp", hc_cmd_linkpp, 2, 2, HC_ARROWS,
     "linkpp pinname1 pinname2",
     "Creates a signal named after the first pin and links both pins to it."},
    {"unlinkp", hc_cmd_unlinkp, 1, 1, 0,
     "unlinkp pinname", "Unlinks pin 'pinname' from its signal."},
    {"newsig", hc_cmd_newsig, 2, 2, 0,
     "newsig signame type",
     "Creates a new signal; type is bit, float, u32, s32, u64, s64 or port."},
    {"delsig", hc_cmd_delsig, 1, 1, 0,
     "delsig signame|all", "Deletes a signal (or all) and unlinks its pins."},
    {"setp", hc_cmd_setp, 2, 2, 0,
     "setp paramname|pinname value", "Sets a parameter or unlinked input pin."},
    {"sets", hc_cmd_sets, 2, 2, 0,
     "sets signame value", "Sets a signal without an output pin."},
    {"getp", hc_cmd_getp, 1, 1, 0,
     "getp paramname|pinname", "Prints the value of a parameter or pin."},
    {"gets", hc_cmd_gets, 1, 1, 0,
     "gets signame", "Prints the value of a signal."},
    {"ptype", hc_cmd_ptype, 1, 1, 0,
     "ptype paramname|pinname", "Prints the type of a parameter or pin."},
    {"stype", hc_cmd_stype, 1, 1, 0,
     "stype signame", "Prints the type of a signal."},
    {"addf", hc_cmd_addf, 2, 3, 0,
     "addf functname threadname [position]",
     "Adds function 'functname' to thread 'threadname' (position: 1 first, -1 last)."},
    {"initf", hc_cmd_initf, 2, 3, 0,
     "initf functname threadname [position]",
     "Runs function 'functname' once in the init cycle of thread 'threadname'."},
    {"delf", hc_cmd_delf, 1, 2, 0,
     "delf functname threadname", "Removes a function from a thread."},
    {"start", hc_cmd_start, 0, 0, 0,
     "start", "Starts all realtime threads."},
    {"stop", hc_cmd_stop, 0, 0, 0,
     "stop", "Stops all realtime threads."},
    {"show", hc_cmd_show, 0, -1, 0,
     "show [type] [-t type] [pattern(s)]",
     "Prints HAL items; type is comp, pin, sig, param, funct, thread, alias or all."},
    {"list", hc_cmd_list, 1, -1, 0,
     "list type [pattern(s)]", "Prints the names of HAL items of 'type'."},
    {"save", hc_cmd_save, 0, 2, HC_TILDE,
     "save [type] [filename]", "Prints (or writes) HAL commands that rebuild the setup."},
    {"status", hc_cmd_status, 0, 1, 0,
     "status [type]", "Prints lock and memory status; type is lock, mem or all."},
    {"lock", hc_cmd_lock, 0, 1, 0,
     "lock [all|tune|none]", "Locks HAL to some degree."},
    {"unlock", hc_cmd_unlock, 0, 1, 0,
     "unlock [all|tune|none]", "Unlocks HAL to some degree."},
    {"alias", hc_cmd_alias, 3, 3, 0,
     "alias pin|param name alias", "Gives a pin or parameter an alternate name."},
    {"unalias", hc_cmd_unalias, 2, 2, 0,
     "unalias pin|param alias", "Removes the alternate name of a pin or parameter."},
    {"source", hc_cmd_source, 1, 1, HC_TILDE,
     "source filename.hal", "Executes the commands of another HAL file."},
    {"echo", hc_cmd_echo, 0, 0, 0,
     "echo", "Echoes every command to stderr."},
    {"unecho", hc_cmd_unecho, 0, 0, 0,
     "unecho", "Stops echoing commands."},
    {"print", hc_cmd_print, 0, 1, 0,
     "print [message]", "Prints a message on stderr."},
    {"debug", hc_cmd_debug, 1, 1, 0,
     "debug level", "Sets the realtime message level (0..5)."},
    {"setexact_for_test_suite_only", hc_cmd_setexact, 0, 0, 0,
     "setexact_for_test_suite_only",
     "Uses the requested base period verbatim; not for real hardware."},
    {"help", hc_cmd_help, 0, 1, 0,
     "help [command]", "Prints help for halcmd or one command."},
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
