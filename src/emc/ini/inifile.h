/* inifile.h: C API of the INI library: LinuxCNC's path-based iniFind* lookups and a handle API. */
#ifndef OPENEMC_INIFILE_H
#define OPENEMC_INIFILE_H

#include <limits.h>
#include <stdbool.h>
#include <stddef.h>

#include "rtapi_stdint.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Longest line older callers size their buffers for (values themselves have no limit). */
#define INI_MAX_LINELEN PATH_MAX

/* Copy file with a leading "~/" replaced by $HOME/ into path (size bytes).
   0 on success, -EINVAL on bad arguments, -ENOENT when HOME is unset, -ENOSPC when too long. */
int TildeExpansion(const char *file, char *path, size_t size);

/* Path-based lookups of the first `tag` in `section` (NULL or "" = any section) of the INI file
   `inipath`. They return 0 on success, -EINVAL for a NULL argument or a file that cannot be
   loaded, -ENOENT when the tag is missing or its value does not convert (the reason is printed
   on stderr), and iniFindString -ENOSPC when buf cannot hold the value and its NUL. */
int iniFindString(const char *inipath, const char *tag, const char *section, char *buf, size_t bufsize);
int iniFindBool(const char *inipath, const char *tag, const char *section, bool *result);
int iniFindSInt(const char *inipath, const char *tag, const char *section, rtapi_s64 *result);
int iniFindUInt(const char *inipath, const char *tag, const char *section, rtapi_u64 *result);
int iniFindDouble(const char *inipath, const char *tag, const char *section, double *result);
/* iniFindSInt truncated to int, for older callers. */
int iniFindInt(const char *inipath, const char *tag, const char *section, int *result);

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

#ifdef __cplusplus
}
#endif

#endif
