/* rtapi_modparam.c: parse module arguments for int/long/string parameters and arrays. */
#include <errno.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "rtapi_modparam.h"

/* Remember a string so it can be freed with the module; NULL on no memory. */
static char *keep_string(rtapi_modparam_strings_t *strings, const char *text, size_t len)
{
    char *copy;

    if (strings->count == strings->capacity) {
        int cap = strings->capacity ? 2 * strings->capacity : 8;
        char **items = realloc(strings->items, cap * sizeof(char *));
        if (!items)
            return NULL;
        strings->items = items;
        strings->capacity = cap;
    }
    copy = strndup(text, len);
    if (copy)
        strings->items[strings->count++] = copy;
    return copy;
}

/* Parse one number of len chars into slot (int or long); -EINVAL if malformed. */
static int parse_number(const rtapi_param_info_t *info, const char *text, size_t len,
                        int index)
{
    char buf[64], *end;
    long value = 0;

    if (len == 0 || len >= sizeof buf)
        return -EINVAL; /* an empty number (step_type= or 0,,1) is not 0 */
    memcpy(buf, text, len);
    buf[len] = '\0';
    errno = 0;
    value = strtol(buf, &end, 0);
    if (*end || errno == ERANGE)
        return -EINVAL;
    if (info->type == 'l') {
        ((long *)info->address)[index] = value;
        return 0;
    }
    if (value < INT_MIN || value > (long)UINT_MAX)
        return -EINVAL;
    ((int *)info->address)[index] = (int)(unsigned)value;
    return 0;
}

/* Store one element (number or string) of len chars at index. */
static int set_element(const rtapi_param_info_t *info, const char *text, size_t len,
                       int index, rtapi_modparam_strings_t *strings)
{
    char *copy;

    if (info->type != 's')
        return parse_number(info, text, len, index);
    copy = keep_string(strings, text, len);
    if (!copy)
        return -ENOMEM;
    ((char **)info->address)[index] = copy;
    return 0;
}

/* Report a malformed element: `elem' invalid for parameter `arg' (an empty one says so). */
static int bad_value(const char *text, size_t len, const char *arg, char *err, size_t errlen)
{
    if (len == 0) {
        snprintf(err, errlen, "empty value invalid for parameter `%s'", arg);
        return -EINVAL;
    }
    snprintf(err, errlen, "`%.*s' invalid for parameter `%s'", (int)len, text, arg);
    return -EINVAL;
}

/* Split an array value on ',' and store each element. */
static int set_array(const rtapi_param_info_t *info, const char *value, const char *arg,
                     rtapi_modparam_strings_t *strings, char *err, size_t errlen)
{
    const char *p = value;

    for (int index = 0;; index++) {
        const char *comma = strchr(p, ',');
        size_t len = comma ? (size_t)(comma - p) : strlen(p);
        if (index >= info->count) {
            snprintf(err, errlen, "%s: can only take %d arguments", arg, info->count);
            return -EINVAL;
        }
        if (set_element(info, p, len, index, strings) < 0)
            return bad_value(p, len, arg, err, errlen);
        if (!comma)
            return 0;
        p = comma + 1;
    }
}

/* Copy arg without '"' characters into out (same size as arg + 1). */
static void strip_quotes(const char *arg, char *out)
{
    for (; *arg; arg++)
        if (*arg != '"')
            *out++ = *arg;
    *out = '\0';
}

/* Apply one name=value argument to its parameter. */
static int apply_clean(char *arg, rtapi_modparam_lookup_t lookup, void *ctx,
                       rtapi_modparam_strings_t *strings, char *err, size_t errlen)
{
    char *eq = strchr(arg, '=');
    const rtapi_param_info_t *info;
    const char *value;

    if (!eq || eq == arg) {
        snprintf(err, errlen, "Invalid parameter `%s'", arg);
        return -EINVAL;
    }
    *eq = '\0';
    info = lookup(ctx, arg);
    *eq = '=';
    if (!info || (info->type != 'i' && info->type != 'l' && info->type != 's')) {
        snprintf(err, errlen, "Unknown parameter `%s'", arg);
        return -EINVAL;
    }
    value = eq + 1;
    if (info->count > 0)
        return set_array(info, value, arg, strings, err, errlen);
    if (set_element(info, value, strlen(value), 0, strings) < 0)
        return bad_value(value, strlen(value), arg, err, errlen);
    return 0;
}

/* Apply one argument after deleting its quotes. */
int rtapi_modparam_apply(const char *arg, rtapi_modparam_lookup_t lookup, void *ctx,
                         rtapi_modparam_strings_t *strings, char *err, size_t errlen)
{
    char *clean = malloc(strlen(arg) + 1);
    int rc;

    if (!clean) {
        snprintf(err, errlen, "out of memory");
        return -ENOMEM;
    }
    strip_quotes(arg, clean);
    rc = apply_clean(clean, lookup, ctx, strings, err, errlen);
    free(clean);
    return rc;
}

/* Free the strings kept for a module. */
void rtapi_modparam_free(rtapi_modparam_strings_t *strings)
{
    for (int i = 0; i < strings->count; i++)
        free(strings->items[i]);
    free(strings->items);
    memset(strings, 0, sizeof *strings);
}
