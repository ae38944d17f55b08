/* halcmd_help.c: usage text and per-command help of halcmd. */
#include <stdio.h>
#include <string.h>
#include "halcmd.h"

/* Synopsis and one-paragraph description of a command. */
typedef struct {
    const char *name;
    const char *synopsis;
    const char *text;
} hc_help_t;

static const hc_help_t hc_help[] = {
    {"loadrt", "loadrt modname [modarg(s)]",
     "Loads realtime HAL module 'modname', passing 'modargs' to the module."},
    {"loadusr", "loadusr [options] progname [progarg(s)]",
     "Starts user space program 'progname', passing 'progargs' to it.\n"
     "  -W  wait for the HAL component to become ready\n"
     "  -Wn name  wait for component 'name' to become ready\n"
     "  -w  wait for the program to exit\n"
     "  -i  ignore the program's return value (with -w)\n"
     "  -n name  component name to wait for"},
    {"waitusr", "waitusr compname", "Waits for user space HAL component 'compname' to exit."},
    {"unloadrt", "unloadrt compname|all", "Unloads a realtime component or all of them."},
    {"unloadusr", "unloadusr compname|all", "Stops a user space component or all of them."},
    {"unload", "unload compname|all", "Unloads any component (realtime or user space)."},
    {"net", "net signame pinname(s)",
     "Creates 'signame' if needed and links every pin to it; arrows are optional."},
    {"linkps", "linkps pinname [arrow] signame", "Links pin 'pinname' to signal 'signame'."},
    {"linksp", "linksp signame [arrow] pinname", "Links pin 'pinname' to signal 'signame'."},
    {"linkpp", "linkpp pinname1 pinname2",
     "Creates a signal named after the first pin and links both pins to it."},
    {"unlinkp", "unlinkp pinname", "Unlinks pin 'pinname' from its signal."},
    {"newsig", "newsig signame type",
     "Creates a new signal; type is bit, float, u32, s32, u64, s64 or port."},
    {"delsig", "delsig signame|all", "Deletes a signal (or all) and unlinks its pins."},
    {"setp", "setp paramname|pinname value", "Sets a parameter or unlinked input pin."},
    {"sets", "sets signame value", "Sets a signal without an output pin."},
    {"getp", "getp paramname|pinname", "Prints the value of a parameter or pin."},
    {"gets", "gets signame", "Prints the value of a signal."},
    {"ptype", "ptype paramname|pinname", "Prints the type of a parameter or pin."},
    {"stype", "stype signame", "Prints the type of a signal."},
    {"addf", "addf functname threadname [position]",
     "Adds function 'functname' to thread 'threadname' (position: 1 first, -1 last)."},
    {"initf", "initf functname threadname [position]",
     "Runs function 'functname' once in the init cycle of thread 'threadname'."},
    {"delf", "delf functname threadname", "Removes a function from a thread."},
    {"start", "start", "Starts all realtime threads."},
    {"stop", "stop", "Stops all realtime threads."},
    {"show", "show [type] [-t type] [pattern(s)]",
     "Prints HAL items; type is comp, pin, sig, param, funct, thread, alias or all."},
    {"list", "list type [pattern(s)]", "Prints the names of HAL items of 'type'."},
    {"save", "save [type] [filename]", "Prints (or writes) HAL commands that rebuild the setup."},
    {"status", "status [type]", "Prints lock and memory status; type is lock, mem or all."},
    {"lock", "lock [all|tune|none]", "Locks HAL to some degree."},
    {"unlock", "unlock [all|tune|none]", "Unlocks HAL to some degree."},
    {"alias", "alias pin|param name alias", "Gives a pin or parameter an alternate name."},
    {"unalias", "unalias pin|param alias", "Removes the alternate name of a pin or parameter."},
    {"source", "source filename.hal", "Executes the commands of another HAL file."},
    {"echo", "echo", "Echoes every command to stderr."},
    {"unecho", "unecho", "Stops echoing commands."},
    {"print", "print [message]", "Prints a message on stderr."},
    {"debug", "debug level", "Sets the realtime message level (0..5)."},
    {"setexact_for_test_suite_only", "setexact_for_test_suite_only",
     "Uses the requested base period verbatim; not for real hardware."},
    {"help", "help [command]", "Prints help for halcmd or one command."},
};

/* Print the general usage text on stdout. */
void hc_usage(void)
{
    printf("Usage:  halcmd [options] [cmd [args]]\n"
           "        halcmd [options] -f [filename]\n\n"
           "options:\n"
           "  -e          echo the commands from stdin to stderr\n"
           "  -f [file]   read commands from 'file' or stdin\n"
           "  -i file     INI file for [SECTION]KEY substitution (with -f)\n"
           "  -k          keep going after failed command\n"
           "  -q          quiet - print errors only (default)\n"
           "  -Q          very quiet - print nothing\n"
           "  -R          release the HAL mutex\n"
           "  -s          script friendly - no headers or prompts\n"
           "  -v          verbose - print result of every command\n"
           "  -V          very verbose - print lots of junk\n"
           "  -h [cmd]    help on halcmd or on 'cmd'\n\n"
           "commands:\n\n");
    for (size_t i = 0; i < sizeof hc_help / sizeof hc_help[0]; i++)
        printf("  %s\n", hc_help[i].synopsis);
}

/* Print the help of one command; -1 when there is no such command. */
int hc_help_command(const char *name)
{
    for (size_t i = 0; i < sizeof hc_help / sizeof hc_help[0]; i++) {
        if (strcmp(hc_help[i].name, name) == 0) {
            printf("%s\n  %s\n", hc_help[i].synopsis, hc_help[i].text);
            return 0;
        }
    }
    printf("No help for unknown command '%s'\n", name);
    return -1;
}

/* The help command: usage without argument, command help with one. */
int hc_cmd_help(int argc, char *argv[])
{
    if (argc == 0) {
        hc_usage();
        return 0;
    }
    return hc_help_command(argv[0]);
}
