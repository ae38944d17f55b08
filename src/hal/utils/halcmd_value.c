/* halcmd_value.c: parsing and formatting of HAL values and type names for halcmd. */
#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include "hal.h"
#include "halcmd.h"

/* Type words accepted by newsig (case-insensitive) and show -t (exact). */
static const struct { const char *word; int type; } hc_type_words[] = {
    {"bit", HAL_BIT}, {"float", HAL_FLOAT}, {"s32", HAL_S32}, {"u32", HAL_U32},
    {"s64", HAL_S64}, {"u64", HAL_U64}, {"port", HAL_PORT}, {"bool", HAL_BIT},
    {"real", HAL_FLOAT}, {"sint", HAL_S64}, {"uint", HAL_U64},
    {"signed", HAL_S32}, {"unsigned", HAL_U32},
};

/* Map a newsig type word (no signed/unsigned) to a type, or -1. */
int hc_parse_type(const char *word)
{
    for (size_t i = 0; i < 11; i++)
        if (strcasecmp(word, hc_type_words[i].word) == 0)
            return hc_type_words[i].type;
    return -1;
}

/* Map a show -t word (case-sensitive, incl. signed/unsigned) to a type, or -1. */
int hc_parse_filter_type(const char *word)
{
    for (size_t i = 0; i < sizeof hc_type_words / sizeof hc_type_words[0]; i++)
        if (strcmp(word, hc_type_words[i].word) == 0)
            return hc_type_words[i].type;
    return -1;
}

/* Canonical type name (bit float s32 u32 s64 u64 port). */
const char *hc_type_name(int type)
{
    switch (type) {
    case HAL_BIT: return "bit";
    case HAL_FLOAT: return "float";
    case HAL_S32: return "s32";
    case HAL_U32: return "u32";
    case HAL_S64: return "s64";
    case HAL_U64: return "u64";
    case HAL_PORT: return "port";
    default: return "undef";
    }
}

/* Type name padded to five columns, as listings print it. */
const char *hc_type_name5(int type)
{
    switch (type) {
    case HAL_BIT: return "bit  ";
    case HAL_FLOAT: return "float";
    case HAL_S32: return "s32  ";
    case HAL_U32: return "u32  ";
    case HAL_S64: return "s64  ";
    case HAL_U64: return "u64  ";
    case HAL_PORT: return "port ";
    default: return "undef";
    }
}

/* Is the rest after a number acceptable (end or a blank)? */
static int hc_tail_ok(const char *end)
{
    return *end == '\0' || isspace((unsigned char)*end);
}

/* Parse a bit word: 1 0 TRUE FALSE ON OFF YES NO in any case. */
static int hc_parse_bit(const char *text, hc_value_t *out)
{
    static const char *on[] = {"1", "TRUE", "ON", "YES"};
    static const char *off[] = {"0", "FALSE", "OFF", "NO"};
    size_t n = strcspn(text, " \t\r\n");
    for (int i = 0; i < 4; i++) {
        if (strlen(on[i]) == n && strncasecmp(text, on[i], n) == 0) {
            out->b = 1;
            return 0;
        }
        if (strlen(off[i]) == n && strncasecmp(text, off[i], n) == 0) {
            out->b = 0;
            return 0;
        }
    }
    return -EINVAL;
}

/* Parse a signed integer with base 0 and the given range. */
static int hc_parse_signed(const char *text, int64_t lo, int64_t hi, int64_t *out)
{
    char *end;
    long long v;
    errno = 0;
    v = strtoll(text, &end, 0);
    if (end == text || !hc_tail_ok(end))
        return -EINVAL;
    if (errno == ERANGE || v < lo || v > hi)
        return -ERANGE;
    *out = v;
    return 0;
}

/* Parse an unsigned integer with base 0; negative only when wrap is allowed. */
static int hc_parse_unsigned(const char *text, uint64_t hi, int wrap, uint64_t *out)
{
    char *end;
    unsigned long long v;
    const char *p = text;
    while (isspace((unsigned char)*p))
        p++;
    errno = 0;
    v = strtoull(text, &end, 0);
    if (end == text || !hc_tail_ok(end))
        return -EINVAL;
    if (errno == ERANGE || v > hi || (*p == '-' && !wrap))
        return -ERANGE;
    *out = v;
    return 0;
}

/* Parse a float in the C locale. */
static int hc_parse_float(const char *text, double *out)
{
    char *end;
    double v;
    errno = 0;
    v = strtod(text, &end);
    if (end == text || !hc_tail_ok(end))
        return -EINVAL;
    if (errno == ERANGE && isinf(v))
        return -ERANGE;
    *out = v;
    return 0;
}

/* Parse text as a value of the HAL type; 0, -EINVAL or -ERANGE. */
int hc_parse_value(int type, const char *text, hc_value_t *out)
{
    char unquoted[HC_LINE_MAX];
    size_t n = strlen(text);
    int64_t s;
    uint64_t u;
    int rc;
    memset(out, 0, sizeof *out);
    if (n >= 2 && n < sizeof unquoted && (text[0] == '"' || text[0] == '\'') &&
        text[n - 1] == text[0]) {
        memcpy(unquoted, text + 1, n - 2);
        unquoted[n - 2] = '\0';
        text = unquoted;
    }
    switch (type) {
    case HAL_BIT:
        return hc_parse_bit(text, out);
    case HAL_FLOAT:
        return hc_parse_float(text, &out->f);
    case HAL_S32:
        rc = hc_parse_signed(text, INT32_MIN, INT32_MAX, &s);
        out->s32 = (int32_t)s;
        return rc;
    case HAL_S64:
        rc = hc_parse_signed(text, INT64_MIN, INT64_MAX, &s);
        out->s64 = s;
        return rc;
    case HAL_U32:
        rc = hc_parse_unsigned(text, UINT32_MAX, 0, &u);
        out->u32 = (uint32_t)u;
        return rc;
    case HAL_U64:
        rc = hc_parse_unsigned(text, UINT64_MAX, 1, &u);
        out->u64 = u;
        return rc;
    default:
        return -EBADF;
    }
}

/* Format an unsigned value: decimal when hex_digits is 0, else 0x<digits> right-aligned in 20. */
static void hc_format_u64(uint64_t value, int hex_digits, char *buf, size_t size)
{
    if (hex_digits == 0)
        snprintf(buf, size, "%llu", (unsigned long long)value);
    else
        snprintf(buf, size, "%*s0x%0*llX", 18 - hex_digits, "", hex_digits,
                 (unsigned long long)value);
}

/* Format a value cell: the 20-column show field when wide, else getp's plain text. */
static void hc_format_value(int type, const void *cell, int wide, char *buf, size_t size)
{
    int width = wide ? 20 : 0;
    switch (type) {
    case HAL_BIT:
        snprintf(buf, size, "%*s", width, *(const volatile uint8_t *)cell ? "TRUE" : "FALSE");
        break;
    case HAL_FLOAT:
        snprintf(buf, size, "%*.7g", width, *(const volatile double *)cell);
        break;
    case HAL_S32:
        snprintf(buf, size, "%*d", width, (int)*(const volatile int32_t *)cell);
        break;
    case HAL_U32:
        hc_format_u64(*(const volatile uint32_t *)cell, wide ? 8 : 0, buf, size);
        break;
    case HAL_S64:
        snprintf(buf, size, "%*lld", width, (long long)*(const volatile int64_t *)cell);
        break;
    case HAL_U64:
        hc_format_u64(*(const volatile uint64_t *)cell, wide ? 16 : 0, buf, size);
        break;
    default:
        snprintf(buf, size, "%*d", width, *(const volatile int *)cell);
        break;
    }
}

/* Format a value cell in the 20-column field of show and save. */
void hc_format_value20(int type, const void *cell, char *buf, size_t size)
{
    hc_format_value(type, cell, 1, buf, size);
}

/* Format a value cell as getp prints it (no padding, integers decimal). */
void hc_format_value_plain(int type, const void *cell, char *buf, size_t size)
{
    hc_format_value(type, cell, 0, buf, size);
}

/* Format a value for -s listings: the 20-column text without leading blanks. */
void hc_format_value_script(int type, const void *cell, char *buf, size_t size)
{
    char tmp[64];
    const char *p = tmp;
    hc_format_value20(type, cell, tmp, sizeof tmp);
    while (*p == ' ')
        p++;
    snprintf(buf, size, "%s", p);
}
