/* rtapi_string.h: string helpers (strlcpy/strlcat, argv splitting) for realtime code. */
#ifndef RTAPI_STRING_H
#define RTAPI_STRING_H
#include <string.h>
#include "rtapi.h"

RTAPI_BEGIN_DECLS
/* Copy src into dst (size bytes, always NUL-terminated); returns strlen(src). */
size_t rtapi_strlcpy(char *dst, const char *src, size_t size);
/* Append src to dst (size bytes in all); returns the length it tried to create. */
size_t rtapi_strlcat(char *dst, const char *src, size_t size);
/* Split str on blanks into a NULL-terminated, malloc'd vector; count in *argcp. */
char **rtapi_argv_split(int gfp, const char *str, int *argcp);
/* Free a vector returned by rtapi_argv_split. */
void rtapi_argv_free(char **argv);
RTAPI_END_DECLS
#endif
