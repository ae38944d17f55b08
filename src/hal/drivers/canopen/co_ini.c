/* co_ini.c: read an INI file into entries that remember their line numbers. */
#include <ctype.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "co_ini.h"

#define CO_INI_LINE_MAX 1024
#define CO_MSG_LEN 512

/* Report "path:line: text". */
static void bad_line(co_ini_t *ini, int line, const char *text, co_report_fn report, void *ctx)
{
    char msg[CO_MSG_LEN];
    snprintf(msg, sizeof(msg), "%s:%d: %s", ini->path, line, text);
    report(ctx, msg);
}

/* Trim blanks at both ends in place. */
static char *trim(char *s)
{
    char *end;
    while (isspace((unsigned char)*s))
        s++;
    end = s + strlen(s);
    while (end > s && isspace((unsigned char)end[-1]))
        *--end = '\0';
    return s;
}

/* Cut a trailing comment: ';' or '#' that follows a blank. */
static void cut_comment(char *s)
{
    for (char *p = s; *p; p++)
        if ((*p == ';' || *p == '#') && p > s && isspace((unsigned char)p[-1])) {
            *p = '\0';
            return;
        }
}

/* Append a section header; 0 or -1 (out of memory). */
static int add_section(co_ini_t *ini, const char *name, int line)
{
    co_ini_section_t *s = realloc(ini->sections, sizeof(*s) * (ini->section_count + 1));
    if (!s)
        return -1;
    ini->sections = s;
    s[ini->section_count].name = strdup(name);
    s[ini->section_count].line = line;
    if (!s[ini->section_count].name)
        return -1;
    ini->section_count++;
    return 0;
}

/* Append a KEY = VALUE entry; 0 or -1 (out of memory). */
static int add_entry(co_ini_t *ini, char *key, char *value, int line)
{
    co_ini_entry_t *e = realloc(ini->entries, sizeof(*e) * (ini->count + 1));
    if (!e)
        return -1;
    ini->entries = e;
    e += ini->count;
    e->section = ini->section_count ? ini->sections[ini->section_count - 1].name : "";
    e->key = strdup(key);
    e->value = strdup(value);
    e->line = line;
    if (!e->key || !e->value)
        return -1;
    ini->count++;
    return 0;
}

/* Take one line of text; returns 0, 1 for a syntax error (reported) or -1 (out of memory). */
static int take_line(co_ini_t *ini, char *text, int line, co_report_fn report, void *ctx)
{
    char *s = trim(text), *eq;
    if (!*s || *s == '#' || *s == ';')
        return 0;
    if (*s == '[') {
        char *close = strchr(s, ']');
        if (!close || close == s + 1 || *trim(close + 1)) {
            bad_line(ini, line, "a section header must look like [NAME]", report, ctx);
            return 1;
        }
        *close = '\0';
        return add_section(ini, s + 1, line);
    }
    eq = strchr(s, '=');
    if (!eq || eq == s) {
        bad_line(ini, line, "expected KEY = VALUE or [SECTION]", report, ctx);
        return 1;
    }
    *eq = '\0';
    cut_comment(eq + 1);
    return add_entry(ini, trim(s), trim(eq + 1), line);
}

/* Read path; returns 0 (bad lines reported and counted), or -1 when the file cannot be read. */
int co_ini_load(co_ini_t *ini, const char *path, co_report_fn report, void *ctx)
{
    char text[CO_INI_LINE_MAX], msg[CO_MSG_LEN];
    int line = 0, r = 0;
    FILE *f = fopen(path, "r");
    memset(ini, 0, sizeof(*ini));
    ini->path = path;
    if (!f) {
        snprintf(msg, sizeof(msg), "cia402: cannot read the configuration %s: %s", path, strerror(errno));
        report(ctx, msg);
        return -1;
    }
    while (r >= 0 && fgets(text, sizeof(text), f)) {
        line++;
        if (!strchr(text, '\n') && !feof(f)) {
            bad_line(ini, line, "line longer than 1023 characters", report, ctx);
            ini->errors++;
            int c;
            while ((c = fgetc(f)) != EOF && c != '\n')
                ;
            continue;
        }
        r = take_line(ini, text, line, report, ctx);
        ini->errors += r > 0;
    }
    fclose(f);
    if (r < 0)
        report(ctx, "cia402: out of memory reading the configuration");
    if (r < 0) {
        co_ini_free(ini);
        return -1;
    }
    return 0;
}

/* Free what co_ini_load allocated. */
void co_ini_free(co_ini_t *ini)
{
    for (int i = 0; i < ini->count; i++) {
        free(ini->entries[i].key);
        free(ini->entries[i].value);
    }
    for (int i = 0; i < ini->section_count; i++)
        free(ini->sections[i].name);
    free(ini->entries);
    free(ini->sections);
    ini->entries = NULL;
    ini->sections = NULL;
    ini->count = ini->section_count = 0;
}
