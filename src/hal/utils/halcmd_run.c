/* halcmd_run.c: executes lines and token lists: quit, "name = value", arrows, counts, tilde. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include "halcmd.h"

#define HC_RAW_LINE 1024

/* Drop tokens that are exactly "=>", "<=" or "<=>"; returns the new count. */
static int hc_remove_arrows(int argc, char *argv[])
{
    int n = 0;
    for (int i = 0; i < argc; i++) {
        if (strcmp(argv[i], "=>") == 0 || strcmp(argv[i], "<=") == 0 ||
            strcmp(argv[i], "<=>") == 0)
            continue;
        argv[n++] = argv[i];
    }
    return n;
}

/* Check the argument count of cmd; prints the error and returns -1 if wrong. */
static int hc_check_count(const hc_command_t *cmd, int nargs)
{
    if (cmd->min_args == cmd->max_args && nargs != cmd->min_args) {
        hc_error("%s requires %d arguments, %d given", cmd->name, cmd->min_args, nargs);
        return -1;
    }
    if (nargs < cmd->min_args) {
        hc_error("%s requires at least %d arguments, %d given", cmd->name, cmd->min_args, nargs);
        return -1;
    }
    if (cmd->max_args >= 0 && nargs > cmd->max_args) {
        hc_error("%s requires at most %d arguments, %d given", cmd->name, cmd->max_args, nargs);
        return -1;
    }
    return 0;
}

/* Replace a leading "~" or "~/" of every argument by $HOME (storage in bufs). */
static void hc_expand_tilde(int argc, char *argv[], char bufs[][HC_LINE_MAX])
{
    const char *home = getenv("HOME");
    for (int i = 0; i < argc && home; i++) {
        if (argv[i][0] != '~' || (argv[i][1] != '\0' && argv[i][1] != '/'))
            continue;
        snprintf(bufs[i], HC_LINE_MAX, "%s%s", home, argv[i] + 1);
        argv[i] = bufs[i];
    }
}

/* Run one tokenized command; 0 ok, -1 failed, 1 quit requested. */
int hc_run_tokens(int argc, char *argv[])
{
    static char tilde_bufs[HC_MAX_TOKENS][HC_LINE_MAX];
    char *setp_argv[3];
    const hc_command_t *cmd;
    int rc;
    if (argc == 0)
        return 0;
    if (!hc.argv_mode && (strcasecmp(argv[0], "quit") == 0 || strcasecmp(argv[0], "exit") == 0))
        return 1;
    if (argc == 3 && strcmp(argv[1], "=") == 0 && !hc_find_command(argv[0])) {
        setp_argv[0] = "setp";
        setp_argv[1] = argv[0];
        setp_argv[2] = argv[2];
        argv = setp_argv;
    }
    cmd = hc_find_command(argv[0]);
    if (!cmd) {
        hc_error("Unknown command '%s'", argv[0]);
        return -1;
    }
    if (cmd->flags & HC_ARROWS)
        argc = hc_remove_arrows(argc, argv);
    if (hc_check_count(cmd, argc - 1) < 0)
        return -1;
    if (cmd->flags & HC_TILDE)
        hc_expand_tilde(argc - 1, argv + 1, tilde_bufs);
    rc = cmd->fn(argc - 1, argv + 1);
    fflush(hc_stdout());
    return rc < 0 ? -1 : 0;
}

/* Run one logical line through comment stripping, echo, substitution, tokens. */
int hc_process_line(char *line)
{
    char expanded[HC_LINE_MAX + 16];
    char *tokens[HC_MAX_TOKENS];
    int ntokens;
    if (hc_strip_comment(line) < 0)
        return -1;
    if (hc.echo)
        fprintf(stderr, "(%d)<echo>: %s\n", hc.line, line);
    if (hc_substitute(line, expanded, sizeof expanded) < 0)
        return -1;
    if (hc_tokenize(expanded, tokens, &ntokens) < 0)
        return -1;
    return hc_run_tokens(ntokens, tokens);
}

/* Print the prompt when reading a terminal. */
static void hc_prompt(int interactive, int pending)
{
    if (!interactive)
        return;
    if (hc.script_mode)
        printf("%%%%\n");
    else
        printf(pending ? "halcmd+: " : "halcmd: ");
    fflush(stdout);
}

/* Append a physical line to the pending logical line; -1 when too long. */
static int hc_join(char *pending, size_t *len, const char *text)
{
    size_t n = strlen(text);
    if (*len + n >= 2 * HC_LINE_MAX) {
        hc_error("Line too long.");
        *len = 0;
        return -1;
    }
    memcpy(pending + *len, text, n + 1);
    *len += n;
    return 0;
}

/* Run every line of f; stops at the first failure unless -k. 0 ok, -1 failed. */
int hc_run_stream(FILE *f, int continuation, int interactive)
{
    char pending[2 * HC_LINE_MAX];
    char raw[HC_RAW_LINE];
    size_t plen = 0;
    int failed = 0, rc;
    pending[0] = '\0';
    for (;;) {
        hc_prompt(interactive, plen > 0);
        if (!fgets(raw, sizeof raw, f))
            break;
        hc.line++;
        raw[strcspn(raw, "\n")] = '\0';
        size_t n = strlen(raw);
        int more = continuation && n > 0 && raw[n - 1] == '\\';
        if (more)
            raw[n - 1] = '\0';
        rc = hc_join(pending, &plen, raw);
        if (rc == 0 && more)
            continue;
        if (rc == 0)
            rc = hc_process_line(pending);
        plen = 0;
        pending[0] = '\0';
        if (rc == 1)
            break;
        if (rc < 0) {
            failed = 1;
            if (!hc.keep_going)
                break;
        }
    }
    return failed ? -1 : 0;
}
