/* inifile.h: C API of the INI library (handle based, plus LinuxCNC-style iniFind on a FILE*). */
#ifndef OPENEMC_INIFILE_H
#define OPENEMC_INIFILE_H

#include <stdio.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct ini_file ini_file_t;

/* Parse path; NULL when unreadable or on a syntax error (diagnostics on stderr). */
ini_file_t *ini_open(const char *path);
/* Free a handle from ini_open (NULL is fine). */
void ini_close(ini_file_t *ini);
/* num-th (1-based) value of key in section (NULL or "" = any section); NULL if absent.
   The string stays valid until ini_close. */
const char *ini_find(const ini_file_t *ini, const char *key, const char *section, int num);
/* Typed lookups: 0 on success, -ENOENT when missing, -EINVAL when not convertible
   (diagnosed on stderr; *value untouched). */
int ini_find_int(const ini_file_t *ini, const char *key, const char *section, int num,
                 long long *value);
int ini_find_uint(const ini_file_t *ini, const char *key, const char *section, int num,
                  unsigned long long *value);
int ini_find_double(const ini_file_t *ini, const char *key, const char *section, int num,
                    double *value);
int ini_find_bool(const ini_file_t *ini, const char *key, const char *section, int num,
                  int *value);

/* LinuxCNC-style lookups on an open INI FILE* (the file is parsed once and cached).
   iniFind returns the first value or NULL; the pointer stays valid until the file changes. */
const char *iniFind(FILE *fp, const char *tag, const char *section);
/* 0 on success, -1 when missing or invalid. */
int iniFindInt(FILE *fp, const char *tag, const char *section, int *result);
int iniFindDouble(FILE *fp, const char *tag, const char *section, double *result);

#ifdef __cplusplus
}
#endif

#endif
