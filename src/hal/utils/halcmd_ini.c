/* halcmd_ini.c: minimal INI reader for [SECTION]KEY substitution (-i). */
#include <ctype.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "halcmd.h"

/* Trim leading and trailing blanks in place; returns the start. */
static char *hc_trim(char *s)
{
    char *end;
    while (isspace((unsigned char)*s))
        s++;
    end = s + strlen(s);
    while (end > s && isspace((unsigned char)end[-1]))
        *--end = '\0';
    return s;
}

/* Does this "[NAME]" line open the wanted section (NULL/empty = any)? */
static int hc_section_match(char *line, const char *section, int *in_section)
{
    char *close = strchr(line, ']');
    if (line[0] != '[' || !close)
        return 0;
    *close = '\0';
    *in_section = (!section || !*section || strcmp(line + 1, section) == 0);
    return 1;
}

/* Return a malloc'd copy of the first KEY value in SECTION, or NULL. */
char *hc_ini_lookup(const char *file, const char *section, const char *key)
{
    char buf[HC_LINE_MAX], *line, *eq, *result = NULL;
    int in_section = 0;
    FILE *f = file ? fopen(file, "r") : NULL;
    if (!f)
        return NULL;
    while (!result && fgets(buf, sizeof buf, f)) {
        line = hc_trim(buf);
        if (*line == '#' || *line == ';' || *line == '\0')
            continue;
        if (hc_section_match(line, section, &in_section) || !in_section)
            continue;
        eq = strchr(line, '=');
        if (!eq)
            continue;
        *eq = '\0';
        if (strcmp(hc_trim(line), key) == 0)
            result = strdup(hc_trim(eq + 1));
    }
    fclose(f);
    return result;
}
