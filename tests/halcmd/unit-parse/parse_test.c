/* parse_test.c: unit test of halcmd's comment stripping, substitution, tokenizer and values. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "hal.h"
#include "halcmd.h"

/* Run one "line <text>" case: print the tokens in brackets or nothing on error. */
static void run_line(char *text)
{
    char out[HC_LINE_MAX + 16], *tok[HC_MAX_TOKENS];
    int n;
    if (hc_strip_comment(text) < 0 || hc_substitute(text, out, sizeof out) < 0 ||
        hc_tokenize(out, tok, &n) < 0)
        return;
    printf("%d:", n);
    for (int i = 0; i < n; i++)
        printf(" [%s]", tok[i]);
    printf("\n");
}

/* Run one "value <type> <text>" case: print getp and show formats or the error. */
static void run_value(char *text)
{
    char type_word[16], buf[64], buf20[64];
    hc_value_t v;
    int type, rc, skip = 0;
    if (sscanf(text, "%15s %n", type_word, &skip) != 1)
        return;
    type = hc_parse_type(type_word);
    rc = hc_parse_value(type, text + skip, &v);
    if (rc < 0) {
        printf("%s '%s': %s\n", type_word, text + skip, rc == -22 ? "invalid argument" : "value out of range");
        return;
    }
    hc_format_value_plain(type, &v, buf, sizeof buf);
    hc_format_value20(type, &v, buf20, sizeof buf20);
    printf("%s '%s' -> %s |%s|\n", type_word, text + skip, buf, buf20);
}

/* Read cases from stdin: "line ..." or "value TYPE TEXT"; line numbers count inputs. */
int main(void)
{
    char line[HC_LINE_MAX];
    hc.file = "unit";
    hc.ini_file = "test.ini";
    setenv("FOO", "foo-value", 1);
    while (fgets(line, sizeof line, stdin)) {
        hc.line++;
        line[strcspn(line, "\n")] = '\0';
        fflush(stdout);
        if (strncmp(line, "line ", 5) == 0)
            run_line(line + 5);
        else if (strncmp(line, "value ", 6) == 0)
            run_value(line + 6);
        fflush(stdout);
        fflush(stderr);
    }
    return 0;
}
