/* parport_cfg.c: parse hal_parport's cfg= string: address or ppdev device, then an optional type. */
#include <ctype.h>
#include <stdio.h>
#include <string.h>
#include "parport_cfg.h"

#define PP_TOKEN_LEN 128
#define PP_ADDRESS_LIMIT 0x10000UL

static const char *const mode_names[] = { "out", "epp", "in", "x" };

/* The mode's name as cfg spells it. */
const char *pp_mode_name(pp_mode_t mode)
{
    return mode_names[mode];
}

/* Token separators: whitespace and '_' (so cfg can be written without quotes). */
static int is_separator(char c)
{
    return isspace((unsigned char)c) || c == '_';
}

/* Copy the next token of *s into tok and advance *s; returns 0 at the end of the string. */
static int next_token(const char **s, char tok[PP_TOKEN_LEN])
{
    const char *p = *s;
    size_t n = 0;
    while (*p && is_separator(*p))
        p++;
    if (!*p)
        return 0;
    while (*p && !is_separator(*p)) {
        if (n + 1 < PP_TOKEN_LEN)
            tok[n++] = *p;
        p++;
    }
    tok[n] = '\0';
    *s = p;
    return 1;
}

/* Parse an all-hex token (optional 0x); returns 0 and *value, or -1. */
static int parse_hex(const char *tok, unsigned long *value)
{
    const char *p = tok;
    unsigned long v = 0;
    if (p[0] == '0' && (p[1] == 'x' || p[1] == 'X'))
        p += 2;
    if (!*p)
        return -1;
    for (; *p; p++) {
        if (!isxdigit((unsigned char)*p))
            return -1;
        v = v * 16 + (unsigned long)(isdigit((unsigned char)*p) ? *p - '0' : tolower((unsigned char)*p) - 'a' + 10);
        if (v >= PP_ADDRESS_LIMIT)
            return -1;
    }
    *value = v;
    return 0;
}

/* "parportN" (N decimal) names /dev/parportN. */
static int parse_parport_name(const char *tok, pp_port_cfg_t *port)
{
    const char *digits = tok + strlen("parport");
    if (strncmp(tok, "parport", strlen("parport")) != 0 || !*digits || strlen(digits) > 4)
        return -1;
    for (const char *p = digits; *p; p++)
        if (!isdigit((unsigned char)*p))
            return -1;
    snprintf(port->device, sizeof(port->device), "/dev/parport%.4s", digits);
    return 0;
}

/* Fill port from an address token; returns 0 or -1 with a message in err. */
static int parse_address(const char *tok, pp_port_cfg_t *port, char err[PP_ERROR_LEN])
{
    memset(port, 0, sizeof(*port));
    port->mode = PP_MODE_OUT;
    if (tok[0] == '/') {
        if (strlen(tok) >= sizeof(port->device)) {
            snprintf(err, PP_ERROR_LEN, "hal_parport: cfg: device path '%.40s...' is too long", tok);
            return -1;
        }
        port->where = PP_WHERE_DEVICE;
        snprintf(port->device, sizeof(port->device), "%s", tok);
        return 0;
    }
    if (parse_parport_name(tok, port) == 0) {
        port->where = PP_WHERE_DEVICE;
        return 0;
    }
    if (parse_hex(tok, &port->value) != 0) {
        snprintf(err, PP_ERROR_LEN, "hal_parport: cfg: '%.40s' is not a port address (hex, below 0x10000), "
                 "a port number (0-f) or a ppdev device (parportN, /dev/...)", tok);
        return -1;
    }
    port->where = port->value < PP_MAX_LINUX_PORTS ? PP_WHERE_INDEX : PP_WHERE_ADDRESS;
    return 0;
}

/* The mode a type token names (by its first letter), or -1 when it is not a type. */
static int parse_mode(const char *tok)
{
    switch (tolower((unsigned char)tok[0])) {
    case 'o': return PP_MODE_OUT;
    case 'e': return PP_MODE_EPP;
    case 'i': return PP_MODE_IN;
    case 'x': return PP_MODE_X;
    default: return -1;
    }
}

/* Parse cfg into ports[]; returns the port count (0 for an empty cfg) or -1 with a message in err. */
int pp_cfg_parse(const char *cfg, pp_port_cfg_t ports[PP_MAX_PORTS], char err[PP_ERROR_LEN])
{
    char tok[PP_TOKEN_LEN];
    const char *s = cfg ? cfg : "";
    int count = 0, have_token = next_token(&s, tok);

    err[0] = '\0';
    while (have_token) {
        if (count == PP_MAX_PORTS) {
            snprintf(err, PP_ERROR_LEN, "hal_parport: cfg: more than %d ports", PP_MAX_PORTS);
            return -1;
        }
        if (parse_address(tok, &ports[count], err) != 0)
            return -1;
        have_token = next_token(&s, tok);
        if (have_token && parse_mode(tok) >= 0) {
            ports[count].mode = (pp_mode_t)parse_mode(tok);
            have_token = next_token(&s, tok);
        }
        count++;
    }
    return count;
}
