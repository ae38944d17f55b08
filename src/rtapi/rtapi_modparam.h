/* rtapi_modparam.h: apply `name=value` module arguments to RTAPI_MP_* parameters. */
#ifndef RTAPI_MODPARAM_H
#define RTAPI_MODPARAM_H

#include <stddef.h>
#include "rtapi.h"

/* Strings allocated for string parameters; freed when the module goes away. */
typedef struct {
    char **items;
    int count;
    int capacity;
} rtapi_modparam_strings_t;

/* Find a parameter's metadata by name (NULL when unknown). */
typedef const rtapi_param_info_t *(*rtapi_modparam_lookup_t)(void *ctx, const char *name);

/* Apply one argument (quotes are removed first). On error returns -EINVAL and
   writes the message (no newline) to err: ``Invalid parameter `x'``,
   ``Unknown parameter `x=1'``, `` `abc' invalid for parameter `count=abc' ``,
   `<name=value>: can only take N arguments`. */
int rtapi_modparam_apply(const char *arg, rtapi_modparam_lookup_t lookup, void *ctx,
                         rtapi_modparam_strings_t *strings, char *err, size_t errlen);
/* Free every string in the set. */
void rtapi_modparam_free(rtapi_modparam_strings_t *strings);

#endif
