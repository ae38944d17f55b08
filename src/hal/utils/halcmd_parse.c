/* halcmd_parse.c: comment stripping, $ENV/[INI] substitution and tokenizing of HAL lines. */
#include <ctype.h>
#include <stdlib.h>
#include <string.h>
#include "halcmd.h"

/* Cut the line at the first '#' outside quotes; -1 on an unterminated quote. */
int hc_strip_comment(char *line)
{
    char quote = 0;
    for (char *p = line; *p; p++) {
        if (quote) {
            if (*p == quote)
                quote = 0;
        } else if (*p == '"' || *p == '\'') {
            quote = *p;
        } else if (*p == '#') {
            *p = '\0';
            break;
        }
    }
    if (quote) {
        hc_error("unterminated quoted string");
        return -1;
    }
    return 0;
}

/* Is c allowed in a variable or key name? */
static int hc_name_char(char c)
{
    return isalnum((unsigned char)c) || c == '.' || c == '_' || c == '-';
}

/* Read a name at *pp: "(NAME)" or a run of name chars; advances *pp. */
static int hc_read_name(const char **pp, char *name, size_t size)
{
    const char *p = *pp, *start, *end;
    if (*p == '(') {
        start = p + 1;
        end = strchr(start, ')');
        if (!end) {
            hc_error("Missing close parenthesis.");
            return -1;
        }
        *pp = end + 1;
    } else {
        start = p;
        for (end = p; hc_name_char(*end); end++)
            ;
        *pp = end;
    }
    if (end == start) {
        hc_error("Empty variable name.");
        return -1;
    }
    if ((size_t)(end - start) >= size) {
        hc_error("Variable name too long.");
        return -1;
    }
    memcpy(name, start, end - start);
    name[end - start] = '\0';
    return 0;
}

/* Expand "$NAME" at *pp into a malloc'd value; advances *pp. */
static char *hc_expand_env(const char **pp)
{
    char name[HC_VARNAME_MAX + 1];
    const char *value;
    (*pp)++;
    if (hc_read_name(pp, name, sizeof name) < 0)
        return NULL;
    value = getenv(name);
    if (!value) {
        hc_error("Environment variable '%s' not found.", name);
        return NULL;
    }
    return strdup(value);
}

/* Expand "[SECTION]KEY" at *pp into a malloc'd value; advances *pp. */
static char *hc_expand_ini(const char **pp)
{
    char section[HC_VARNAME_MAX + 1], key[HC_VARNAME_MAX + 1];
    const char *p = *pp + 1, *close = strchr(p, ']');
    char *value;
    if (!close) {
        hc_error("Missing close square bracket.");
        return NULL;
    }
    if ((size_t)(close - p) > HC_VARNAME_MAX) {
        hc_error("Variable name too long.");
        return NULL;
    }
    memcpy(section, p, close - p);
    section[close - p] = '\0';
    *pp = close + 1;
    if (hc_read_name(pp, key, sizeof key) < 0)
        return NULL;
    value = hc_ini_lookup(hc.ini_file, section, key);
    if (!value)
        hc_error("Ini variable '[%s]%s' not found.", section, key);
    return value;
}

/* Append text to out; -1 when the result would be too long. */
static int hc_append(char *out, size_t *len, size_t size, const char *text, size_t n)
{
    if (*len + n >= size || *len + n > HC_LINE_MAX - 3) {
        hc_error("Line too long: more than %d characters after comments and substitutions.",
                 HC_LINE_MAX - 3);
        return -1;
    }
    memcpy(out + *len, text, n);
    *len += n;
    out[*len] = '\0';
    return 0;
}

/* Replace $ENV and [SECTION]KEY references of in, writing the result to out. */
int hc_substitute(const char *in, char *out, size_t out_size)
{
    size_t len = 0;
    const char *p = in;
    out[0] = '\0';
    while (*p) {
        char *value;
        int rc;
        if (*p != '$' && *p != '[') {
            if (hc_append(out, &len, out_size, p, 1) < 0)
                return -1;
            p++;
            continue;
        }
        value = (*p == '$') ? hc_expand_env(&p) : hc_expand_ini(&p);
        if (!value)
            return -1;
        rc = hc_append(out, &len, out_size, value, strlen(value));
        free(value);
        if (rc < 0)
            return -1;
    }
    return 0;
}

/* Check one carriage return at p: warn once at end of line, else fail. */
static int hc_check_cr(const char *p)
{
    const char *q = p + 1;
    if (*q == '\0') {
        if (!hc.dos_warned)
            hc_warning("File contains DOS-style line endings.");
        hc.dos_warned = 1;
        return 0;
    }
    hc_error("File contains embedded carriage returns.");
    return -1;
}

/* Split line in place on blanks; quotes group words and stay in the token. */
int hc_tokenize(char *line, char *tokens[], int *ntokens)
{
    char *p = line, quote = 0;
    int n = 0;
    while (*p) {
        if (*p == '\r' && hc_check_cr(p) < 0)
            return -1;
        if (isspace((unsigned char)*p)) {
            *p++ = '\0';
            continue;
        }
        if (n >= HC_MAX_TOKENS) {
            hc_error("too many tokens on line");
            return -1;
        }
        tokens[n++] = p;
        for (; *p && (quote || !isspace((unsigned char)*p)); p++) {
            if (quote && *p == quote)
                quote = 0;
            else if (!quote && (*p == '"' || *p == '\''))
                quote = *p;
        }
    }
    *ntokens = n;
    return 0;
}
