/* hm2_config.c: parse hostmot2's config= string (tokens by prefix, numbers like strtol base 0). */
#include <stddef.h>
#include <stdlib.h>
#include <string.h>
#include "rtapi.h"
#include "rtapi_errno.h"
#include "hm2_config.h"
#include "hm2_gtag.h"

#define TOKEN_MAX 200

typedef struct {
    const char *prefix;
    int (*apply)(hm2_config_t *cfg, const char *token, const char *value, char *err, int errlen);
    size_t field;     /* offset of the int for count tokens */
} token_rule_t;

/* Defaults: every count -1 (all), stepgen_width 2, every sserial channel mode '0'. */
void hm2_config_defaults(hm2_config_t *cfg)
{
    memset(cfg, 0, sizeof(*cfg));
    int *counts[] = {&cfg->num_encoders, &cfg->num_stepgens, &cfg->num_pwmgens, &cfg->num_3pwmgens,
                     &cfg->num_rcpwmgens, &cfg->num_resolvers, &cfg->num_inms, &cfg->num_inmuxs,
                     &cfg->num_outms, &cfg->num_oneshots, &cfg->num_periodms, &cfg->num_ssrs,
                     &cfg->num_xy2mods, &cfg->num_leds, &cfg->num_bspis, &cfg->num_uarts,
                     &cfg->num_pktuarts, &cfg->num_dplls, &cfg->num_sserials};
    for (size_t i = 0; i < sizeof(counts) / sizeof(counts[0]); i++)
        *counts[i] = -1;
    cfg->stepgen_width = 2;
    memset(cfg->sserial_modes, '0', sizeof(cfg->sserial_modes));
}

/* firmware=NAME (its length is checked only by boards that can be programmed). */
static int apply_firmware(hm2_config_t *cfg, const char *token, const char *value, char *err, int errlen)
{
    (void)token;
    if (strlen(value) >= HM2_FIRMWARE_BUF) {
        rtapi_snprintf(err, errlen, "requested firmware name '%.40s...' is too long (max length is %d)",
                       value, HM2_FIRMWARE_NAME_MAX);
        return -EINVAL;
    }
    strcpy(cfg->firmware, value);
    cfg->have_firmware = true;
    return 0;
}

/* enable_raw (any suffix accepted, as the prefix rule says). */
static int apply_raw(hm2_config_t *cfg, const char *token, const char *value, char *err, int errlen)
{
    (void)token; (void)value; (void)err; (void)errlen;
    cfg->enable_raw = true;
    return 0;
}

/* sserial_port_P=MMMMMMMM: per-channel mode digits or 'x'; sets the sserial count. */
static int apply_sserial(hm2_config_t *cfg, const char *token, const char *value, char *err, int errlen)
{
    const char *p = token + strlen("sserial_port_");
    if (*p < '0' || *p > '3' || p[1] != '=') {
        rtapi_snprintf(err, errlen, "sserial_port tag must be in the form sserial_port_N=0123xx23 "
                       "where N may be 0 to 3");
        return -EINVAL;
    }
    int port = *p - '0';
    bool any_digit = false;
    for (int c = 0, i = 0; value[i]; i++) {
        char ch = value[i];
        bool digit = ch >= '0' && ch <= '9', off = ch == 'x' || ch == 'X';
        if (!digit && !off) {
            rtapi_snprintf(err, errlen, "sserial_port_%d=%s: '%c' is not a channel mode "
                           "(each channel is a digit 0-9, or x to disable it)", port, value, ch);
            return -EINVAL;
        }
        if (c >= HM2_SSERIAL_MAX_CHANNELS) {
            rtapi_snprintf(err, errlen, "sserial_port_%d=%s: more than %d channels", port, value,
                           HM2_SSERIAL_MAX_CHANNELS);
            return -EINVAL;
        }
        cfg->sserial_modes[port][c++] = digit ? ch : 'x';
        any_digit = any_digit || digit;
    }
    if (any_digit && port + 1 > cfg->num_sserials)
        cfg->num_sserials = port + 1;
    return 0;
}

/* ssi_chan_N=, biss_chan_N=, fanuc_chan_N=: an absolute encoder channel and its format. */
static int apply_absenc(hm2_config_t *cfg, const char *token, const char *value, char *err, int errlen)
{
    int gtag = token[0] == 's' ? HM2_GTAG_SSI : token[0] == 'b' ? HM2_GTAG_BISS : HM2_GTAG_FABS;
    const char *p = strchr(token, '_') + strlen("_chan_");
    char *end;
    long index = strtol(p, &end, 10);
    if (end == p || *end != '=' || !*value || strlen(value) >= HM2_ABSENC_FORMAT_LEN) {
        rtapi_snprintf(err, errlen, "The absolute encoder tag must be in the form "
                       "[ssi / biss / fanuc]_chan_N=abcdefg where N is a number less than 32 "
                       "and abcdefg is a string specifying the bit fields");
        return -EINVAL;
    }
    if (index < 0 || index >= HM2_ABSENC_MAX_CHANNELS) {
        rtapi_snprintf(err, errlen, "Currently only 32 absolute encoders are supported and you "
                       "referred to an index of %li", index);
        return -EINVAL;
    }
    for (int i = 0; i < cfg->num_absencs; i++) {
        if (cfg->absenc[i].gtag == gtag && cfg->absenc[i].index == index) {
            rtapi_snprintf(err, errlen, "Duplicate SSI/BISS/Fanuc definition. "
                           "{Index %li for GTAG %i)exiting", index, gtag);
            return -EINVAL;
        }
    }
    hm2_absenc_chan_t *a = &cfg->absenc[cfg->num_absencs++];
    a->gtag = gtag;
    a->index = (int)index;
    strcpy(a->format, value);
    return 0;
}

/* num_xxx=N and stepgen_width=N: no handler, the int lives at field. */
#define COUNT(prefix, field) {prefix, NULL, offsetof(hm2_config_t, field)}

static const token_rule_t rules[] = {
    {"firmware=", apply_firmware, 0},
    COUNT("num_encoders=", num_encoders),
    COUNT("num_resolvers=", num_resolvers),
    COUNT("num_pwmgens=", num_pwmgens),
    COUNT("num_3pwmgens=", num_3pwmgens),
    COUNT("num_rcpwmgens=", num_rcpwmgens),
    COUNT("num_stepgens=", num_stepgens),
    COUNT("stepgen_width=", stepgen_width),
    COUNT("num_inms=", num_inms),
    COUNT("num_inmuxs=", num_inmuxs),
    COUNT("num_outms=", num_outms),
    COUNT("num_oneshots=", num_oneshots),
    COUNT("num_periodms=", num_periodms),
    COUNT("num_ssrs=", num_ssrs),
    COUNT("num_xy2mods=", num_xy2mods),
    COUNT("num_leds=", num_leds),
    COUNT("num_bspis=", num_bspis),
    COUNT("num_uarts=", num_uarts),
    COUNT("num_pktuarts=", num_pktuarts),
    COUNT("num_dplls=", num_dplls),
    {"sserial_port_", apply_sserial, 0},
    {"ssi_chan_", apply_absenc, 0},
    {"biss_chan_", apply_absenc, 0},
    {"fanuc_chan_", apply_absenc, 0},
    {"enable_raw", apply_raw, 0},
};

/* Apply one token; count rules are handled here, the others by their function. */
static int apply_token(hm2_config_t *cfg, const char *token, char *err, int errlen)
{
    for (size_t i = 0; i < sizeof(rules) / sizeof(rules[0]); i++) {
        const token_rule_t *r = &rules[i];
        size_t n = strlen(r->prefix);
        if (strncmp(token, r->prefix, n) != 0)
            continue;
        const char *eq = strchr(token, '=');
        const char *value = eq ? eq + 1 : "";
        if (!r->apply) {
            *(int *)((char *)cfg + r->field) = (int)strtol(value, NULL, 0);
            return 0;
        }
        return r->apply(cfg, token, value, err, errlen);
    }
    rtapi_snprintf(err, errlen, "invalid token in config string: \"%s\"", token);
    return -EINVAL;
}

/* Split text on whitespace and apply each token in order. */
int hm2_config_parse(hm2_config_t *cfg, const char *text, char *err, int errlen)
{
    char token[TOKEN_MAX + 1];
    hm2_config_defaults(cfg);
    err[0] = '\0';
    if (!text)
        return 0;
    while (*text) {
        while (*text == ' ' || *text == '\t' || *text == '\n' || *text == '\r')
            text++;
        if (!*text)
            break;
        int n = 0;
        while (text[n] && text[n] != ' ' && text[n] != '\t' && text[n] != '\n' && text[n] != '\r')
            n++;
        if (n > TOKEN_MAX) {
            rtapi_snprintf(err, errlen, "invalid token in config string: \"%.*s...\" (too long)",
                           40, text);
            return -EINVAL;
        }
        memcpy(token, text, n);
        token[n] = '\0';
        text += n;
        int r = apply_token(cfg, token, err, errlen);
        if (r < 0)
            return r;
    }
    return 0;
}
