/* halcmd_run.c: executes lines and token lists: quit, "name = value", arrows, counts, tilde. */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>
#include "halcmd.h"

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

/* Append n bytes to a growing text; -1 (reported) when memory runs out. */
int hc_text_append(hc_text_t *t, const char *s, size_t n)
{
    if (t->len + n + 1 > t->cap) {
        size_t cap = t->cap ? t->cap : 256;
        while (cap < t->len + n + 1)
            cap *= 2;
        char *text = realloc(t->text, cap);
        if (!text) {
            hc_error("out of memory for a %zu byte line", t->len + n);
            return -1;
        }
        t->text = text;
        t->cap = cap;
    }
    if (n > 0)
        memcpy(t->text + t->len, s, n);
    t->len += n;
    t->text[t->len] = '\0';
    return 0;
}

/* Forget a text's content, keeping its storage. */
static void hc_text_clear(hc_text_t *t)
{
    t->len = 0;
    if (t->text)
        t->text[0] = '\0';
}

/* Read one physical line (without its newline) into line. 1 = a line, 0 = end of file,
   -1 = a NUL byte (reported), -2 = read error or a line longer than HC_PHYS_LINE_MAX (reported;
   the rest of the file is not read, even with -k: an endless line would never end). */
static int hc_read_line(FILE *f, hc_text_t *line)
{
    char chunk[256];
    size_t n = 0, total = 0;
    int c, nul = 0;
    hc_text_clear(line);
    while ((c = getc(f)) != EOF && c != '\n' && total <= HC_PHYS_LINE_MAX) {
        nul |= c == '\0';
        chunk[n++] = (char)c;
        total++;
        if (n == sizeof chunk) {
            if (hc_text_append(line, chunk, n) < 0)
                return -2;
            n = 0;
        }
    }
    if (ferror(f)) {
        hc.line++;
        hc_error("cannot read the file: %s", strerror(errno));
        return -2;
    }
    if (c == EOF && total == 0)
        return 0;
    hc.line++;
    if (total > HC_PHYS_LINE_MAX) {
        hc_error("line is longer than %d bytes; not reading the rest of the file", HC_PHYS_LINE_MAX);
        return -2;
    }
    if (n > 0 && hc_text_append(line, chunk, n) < 0)
        return -2;
    if (nul) {
        hc_error("line contains a NUL byte; HAL files are text");
        return -1;
    }
    return 1;
}

/* Run every line of f; stops at the first failure unless -k. 0 ok, -1 failed. */
int hc_run_stream(FILE *f, int continuation, int interactive)
{
    hc_text_t pending = {0}, raw = {0};
    int failed = 0, rc;
    for (;;) {
        hc_prompt(interactive, pending.len > 0);
        rc = hc_read_line(f, &raw);
        if (rc == 0)
            break;
        int more = rc > 0 && continuation && raw.len > 0 && raw.text[raw.len - 1] == '\\';
        if (rc > 0)
            rc = hc_text_append(&pending, raw.text, raw.len - (more ? 1 : 0));
        if (rc == 0 && more)
            continue;
        if (rc == 0)
            rc = hc_process_line(pending.text);
        hc_text_clear(&pending);
        if (rc == 1)
            break;
        if (rc < 0) {
            failed = 1;
            if (!hc.keep_going || rc == -2)
                break;
        }
    }
    free(pending.text);
    free(raw.text);
    return failed ? -1 : 0;
}

/* Open a HAL file for reading; NULL with errno set (EISDIR for a directory). */
FILE *hc_open_hal_file(const char *name)
{
    struct stat st;
    FILE *f = fopen(name, "r");
    if (f && fstat(fileno(f), &st) == 0 && S_ISDIR(st.st_mode)) {
        fclose(f);
        errno = EISDIR;
        return NULL;
    }
    return f;
}
