/* hm2_config.h: the per-board config= string of hostmot2 (pure parser, unit-tested). */
#ifndef HM2_CONFIG_H
#define HM2_CONFIG_H

#include <stdbool.h>

#define HM2_FIRMWARE_NAME_MAX 30      /* longest name a programmable board accepts */
#define HM2_FIRMWARE_BUF 256
#define HM2_SSERIAL_MAX_PORTS 4
#define HM2_SSERIAL_MAX_CHANNELS 8
#define HM2_ABSENC_MAX_CHANNELS 32
#define HM2_ABSENC_FORMAT_LEN 128

/* One absolute-encoder channel from ssi_chan_N=, biss_chan_N= or fanuc_chan_N=. */
typedef struct {
    int gtag;                              /* HM2_GTAG_SSI, _BISS or _FABS */
    int index;                             /* N */
    char format[HM2_ABSENC_FORMAT_LEN];
} hm2_absenc_chan_t;

/* Every setting of a config string; counts are -1 for "all the firmware has". */
typedef struct {
    char firmware[HM2_FIRMWARE_BUF];
    bool have_firmware;
    int num_encoders, num_stepgens, stepgen_width, num_pwmgens, num_3pwmgens;
    int num_rcpwmgens, num_resolvers, num_inms, num_inmuxs, num_outms;
    int num_oneshots, num_periodms, num_ssrs, num_xy2mods, num_leds;
    int num_bspis, num_uarts, num_pktuarts, num_dplls, num_sserials;
    char sserial_modes[HM2_SSERIAL_MAX_PORTS][HM2_SSERIAL_MAX_CHANNELS];  /* '0'-'9' or 'x' */
    hm2_absenc_chan_t absenc[HM2_ABSENC_MAX_CHANNELS];
    int num_absencs;
    bool enable_raw;
} hm2_config_t;

/* Set every field to its default (counts -1, stepgen_width 2, modes '0'). */
void hm2_config_defaults(hm2_config_t *cfg);
/* Parse a whitespace-separated config string into cfg (defaults applied first).
   Returns 0, or -EINVAL with the message (no prefix, no newline) in err. */
int hm2_config_parse(hm2_config_t *cfg, const char *text, char *err, int errlen);

#endif
