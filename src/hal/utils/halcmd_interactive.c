/* halcmd_interactive.c: interactive halcmd on a terminal: readline, history, completion. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <readline/readline.h>
#include <readline/history.h>
#include "halcmd.h"
#include "halcmd_complete.h"

static hc_cands_t hc_rl_cands;

/* readline generator: hand out the collected candidates one by one. */
static char *hc_rl_generator(const char *text, int state)
{
    static int next;
    (void)text;
    if (state == 0)
        next = 0;
    if (next < hc_rl_cands.count)
        return strdup(hc_rl_cands.names[next++]);
    return NULL;
}

/* readline completion hook: command for the first word, else names. */
static char **hc_rl_complete(const char *text, int start, int end)
{
    char buf[HC_LINE_MAX], cmd[HC_LINE_MAX] = "", *save = NULL;
    int index = 0;
    (void)end;
    snprintf(buf, sizeof buf, "%.*s", start, rl_line_buffer);
    for (char *w = strtok_r(buf, " \t", &save); w; w = strtok_r(NULL, " \t", &save)) {
        if (index == 0)
            snprintf(cmd, sizeof cmd, "%s", w);
        index++;
    }
    hc_cands_free(&hc_rl_cands);
    hc_complete_word(&hc_rl_cands, index, cmd, text);
    rl_attempted_completion_over = 1;
    return rl_completion_matches(text, hc_rl_generator);
}

/* Read lines with readline until EOF or quit; backslash continues a line. */
int hc_run_interactive(void)
{
    hc_text_t pending = {0};
    int failed = 0, rc = 0;
    char *line;
    rl_readline_name = "halcmd";
    rl_attempted_completion_function = hc_rl_complete;
    while ((line = readline(pending.len ? "halcmd+: " : "halcmd: ")) != NULL) {
        size_t n = strlen(line);
        hc.line++;
        if (n > 0)
            add_history(line);
        int more = n > 0 && line[n - 1] == '\\';
        rc = hc_text_append(&pending, line, n - (more ? 1 : 0));
        free(line);
        if (rc == 0 && more)
            continue;
        if (rc == 0)
            rc = hc_process_line(pending.text);
        pending.len = 0;
        if (rc == 1)
            break;
        if (rc < 0)
            failed = 1;
    }
    free(pending.text);
    hc_cands_free(&hc_rl_cands);
    return failed ? -1 : 0;
}
