/* halcmd_help.c: usage text and per-command help of halcmd. */
#include <stdio.h>
#include "halcmd.h"

/* Print the general usage text on stdout. */
void hc_usage(void)
{
    const hc_command_t *k;
    hc_print("Usage:  halcmd [options] [cmd [args]]\n"
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
    for (int i = 0; (k = hc_command_at(i)) != NULL; i++)
        hc_print("  %s\n", k->synopsis);
}

/* Print the help of one command; -1 when there is no such command. */
int hc_help_command(const char *name)
{
    const hc_command_t *k = hc_find_command(name);
    if (k) {
        hc_print("%s\n  %s\n", k->synopsis, k->text);
        return 0;
    }
    hc_print("No help for unknown command '%s'\n", name);
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
