/* mb_ini.c: line-numbered INI reader used by mb2hal (sections, KEY=VALUE, # and ; comments). */
#include "mb_ini.h"

#include <ctype.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Strips leading and trailing whitespace in place and returns the start. */
static char *trim(char *s)
{
    while (isspace((unsigned char)*s))
        s++;
    size_t n = strlen(s);
    while (n > 0 && isspace((unsigned char)s[n - 1]))
        s[--n] = '\0';
    return s;
}

/* Grows an array of elem-sized items to hold count + 1. */
static int grow(void **arr, int count, size_t elem)
{
    void *p = realloc(*arr, (size_t)(count + 1) * elem);
    if (!p)
        return -1;
    *arr = p;
    return 0;
}

/* Handles "[name]"; returns 0 or -1 on a malformed header. */
static int add_section(mb_ini_t *ini, char *text, int line)
{
    char *end = strchr(text, ']');
    if (!end || *trim(end + 1) != '\0') {
        fprintf(stderr, "mb2hal: %s:%d: malformed section header '%s'\n", ini->path, line, text);
        return -1;
    }
    *end = '\0';
    char *name = trim(text + 1);
    if (grow((void **)&ini->sections, ini->nsections, sizeof(char *)) ||
        grow((void **)&ini->section_lines, ini->nsections, sizeof(int)))
        return -1;
    ini->sections[ini->nsections] = strdup(name);
    ini->section_lines[ini->nsections++] = line;
    return ini->sections[ini->nsections - 1] ? 0 : -1;
}

/* Handles "KEY=VALUE" inside the current section; returns 0 or -1. */
static int add_entry(mb_ini_t *ini, char *text, int line)
{
    char *eq = strchr(text, '=');
    const char *sec = ini->nsections ? ini->sections[ini->nsections - 1] : NULL;
    if (!eq) {
        fprintf(stderr, "mb2hal: %s:%d: [%s] '%s': expected KEY=VALUE\n", ini->path, line,
                sec ? sec : "", text);
        return -1;
    }
    if (!sec) {
        fprintf(stderr, "mb2hal: %s:%d: '%s': key outside of any section\n", ini->path, line, text);
        return -1;
    }
    *eq = '\0';
    if (grow((void **)&ini->entries, ini->count, sizeof(mb_ini_entry_t)))
        return -1;
    mb_ini_entry_t *e = &ini->entries[ini->count++];
    e->section = strdup(sec);
    e->key = strdup(trim(text));
    e->value = strdup(trim(eq + 1));
    e->line = line;
    e->used = 0;
    return (e->section && e->key && e->value) ? 0 : -1;
}

/* Classifies one line and stores what it holds. */
static int parse_line(mb_ini_t *ini, char *buf, int line)
{
    char *text = trim(buf);
    if (*text == '\0' || *text == '#' || *text == ';')
        return 0;
    if (*text == '[')
        return add_section(ini, text, line);
    return add_entry(ini, text, line);
}

/* Reads path into ini; returns 0, or -1 after printing the problem. */
int mb_ini_load(mb_ini_t *ini, const char *path)
{
    memset(ini, 0, sizeof(*ini));
    ini->path = path;
    FILE *fp = fopen(path, "r");
    if (!fp) {
        fprintf(stderr, "mb2hal: %s: cannot open: %s\n", path, strerror(errno));
        return -1;
    }
    char buf[4096];
    int line = 0, rc = 0;
    while (rc == 0 && fgets(buf, sizeof(buf), fp)) {
        line++;
        if (!strchr(buf, '\n') && !feof(fp)) {
            fprintf(stderr, "mb2hal: %s:%d: line too long\n", path, line);
            rc = -1;
            break;
        }
        rc = parse_line(ini, buf, line);
    }
    fclose(fp);
    if (rc)
        mb_ini_free(ini);
    return rc;
}

/* First entry for key in section, or NULL; marks it used. */
mb_ini_entry_t *mb_ini_get(mb_ini_t *ini, const char *section, const char *key)
{
    for (int i = 0; i < ini->count; i++) {
        mb_ini_entry_t *e = &ini->entries[i];
        if (strcmp(e->section, section) == 0 && strcmp(e->key, key) == 0) {
            e->used = 1;
            return e;
        }
    }
    return NULL;
}

/* Line of "[section]" or 0 when absent. */
int mb_ini_section_line(const mb_ini_t *ini, const char *section)
{
    for (int i = 0; i < ini->nsections; i++)
        if (strcmp(ini->sections[i], section) == 0)
            return ini->section_lines[i];
    return 0;
}

/* Frees everything mb_ini_load allocated. */
void mb_ini_free(mb_ini_t *ini)
{
    for (int i = 0; i < ini->count; i++) {
        free(ini->entries[i].section);
        free(ini->entries[i].key);
        free(ini->entries[i].value);
    }
    for (int i = 0; i < ini->nsections; i++)
        free(ini->sections[i]);
    free(ini->entries);
    free(ini->sections);
    free(ini->section_lines);
    memset(ini, 0, sizeof(*ini));
}
