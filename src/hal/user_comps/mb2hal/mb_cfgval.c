/* mb_cfgval.c: typed, range-checked lookups of one INI section with file:line errors. */
#include "mb_cfgval.h"

#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

/* Prints "mb2hal: file:line: [SECTION] KEY: message" and counts it. */
void mb_cfg_error(mb_sec_t *s, int line, const char *key, const char *fmt, ...)
{
    va_list ap;
    if (line > 0)
        fprintf(stderr, "mb2hal: %s:%d: [%s] %s: ", s->ini->path, line, s->section, key);
    else
        fprintf(stderr, "mb2hal: %s: [%s] %s: ", s->ini->path, s->section, key);
    va_start(ap, fmt);
    vfprintf(stderr, fmt, ap);
    va_end(ap);
    fputc('\n', stderr);
    s->errors++;
}

/* Reports KEY as missing, at the section header line. */
void mb_cfg_missing(mb_sec_t *s, const char *key)
{
    mb_cfg_error(s, mb_ini_section_line(s->ini, s->section), key, "missing");
}

/* Line of KEY in the section, 0 when absent. */
int mb_key_line(mb_sec_t *s, const char *key)
{
    mb_ini_entry_t *e = mb_ini_get(s->ini, s->section, key);
    return e ? e->line : 0;
}

/* Integer in [min, max]. */
int mb_get_int(mb_sec_t *s, const char *key, long min, long max, int *out)
{
    mb_ini_entry_t *e = mb_ini_get(s->ini, s->section, key);
    if (!e)
        return 0;
    char *end;
    errno = 0;
    long v = strtol(e->value, &end, 10);
    if (e->value[0] == '\0' || *end != '\0' || errno) {
        mb_cfg_error(s, e->line, key, "'%s' is not an integer", e->value);
        return -1;
    }
    if (v < min || v > max) {
        mb_cfg_error(s, e->line, key, "%ld is out of range %ld..%ld", v, min, max);
        return -1;
    }
    *out = (int)v;
    return 1;
}

/* Finite number in [min, max]. */
int mb_get_double(mb_sec_t *s, const char *key, double min, double max, double *out)
{
    mb_ini_entry_t *e = mb_ini_get(s->ini, s->section, key);
    if (!e)
        return 0;
    char *end;
    double v = strtod(e->value, &end);
    if (e->value[0] == '\0' || *end != '\0' || !isfinite(v)) {
        mb_cfg_error(s, e->line, key, "'%s' is not a number", e->value);
        return -1;
    }
    if (v < min || v > max) {
        mb_cfg_error(s, e->line, key, "%g is out of range %g..%g", v, min, max);
        return -1;
    }
    *out = v;
    return 1;
}

/* Non-empty string that fits in size bytes. */
int mb_get_str(mb_sec_t *s, const char *key, char *out, size_t size)
{
    mb_ini_entry_t *e = mb_ini_get(s->ini, s->section, key);
    if (!e)
        return 0;
    if (e->value[0] == '\0') {
        mb_cfg_error(s, e->line, key, "empty value");
        return -1;
    }
    if (strlen(e->value) >= size) {
        mb_cfg_error(s, e->line, key, "'%s' is longer than %zu characters", e->value, size - 1);
        return -1;
    }
    strcpy(out, e->value);
    return 1;
}

/* One of the NULL-terminated names (case-insensitive). */
int mb_get_choice(mb_sec_t *s, const char *key, const char *const names[], int *out)
{
    mb_ini_entry_t *e = mb_ini_get(s->ini, s->section, key);
    if (!e)
        return 0;
    for (int i = 0; names[i]; i++) {
        if (strcasecmp(e->value, names[i]) == 0) {
            *out = i;
            return 1;
        }
    }
    char list[512] = "";
    for (int i = 0; names[i]; i++) {
        if (i)
            strncat(list, ", ", sizeof(list) - strlen(list) - 1);
        strncat(list, names[i], sizeof(list) - strlen(list) - 1);
    }
    mb_cfg_error(s, e->line, key, "unknown value '%s' (expected one of %s)", e->value, list);
    return -1;
}
