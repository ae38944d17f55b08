/* mb_cfgval.h: typed, range-checked lookups of one INI section with file:line errors. */
#ifndef MB_CFGVAL_H
#define MB_CFGVAL_H

#include <stddef.h>

#include "mb_ini.h"

/* A section being read; errors counts the problems reported so far. */
typedef struct {
    mb_ini_t *ini;
    const char *section;
    int errors;
} mb_sec_t;

/* Prints "mb2hal: file:line: [SECTION] KEY: message" (line 0: no line) and counts it. */
void mb_cfg_error(mb_sec_t *s, int line, const char *key, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));
/* Reports KEY as missing, at the section header line. */
void mb_cfg_missing(mb_sec_t *s, const char *key);
/* Lookups: 1 = found and valid (*out set), 0 = absent, -1 = invalid (reported). */
int mb_get_int(mb_sec_t *s, const char *key, long min, long max, int *out);
int mb_get_double(mb_sec_t *s, const char *key, double min, double max, double *out);
int mb_get_str(mb_sec_t *s, const char *key, char *out, size_t size);
/* names is NULL-terminated; *out gets the index of the (case-insensitive) match. */
int mb_get_choice(mb_sec_t *s, const char *key, const char *const names[], int *out);
/* Line of KEY in the section, 0 when absent. */
int mb_key_line(mb_sec_t *s, const char *key);

#endif
