/* hm2_pwmgen.h: PWMGen register encodings (pure helpers, unit-tested). */
#ifndef HM2_PWMGEN_H
#define HM2_PWMGEN_H

#include <stdbool.h>
#include <stdint.h>

enum {
    HM2_PWMGEN_OUTPUT_TYPE_PWM = 1,      /* PWM on out0, direction on out1 */
    HM2_PWMGEN_OUTPUT_TYPE_UP_DOWN = 2,
    HM2_PWMGEN_OUTPUT_TYPE_PDM = 3,
    HM2_PWMGEN_OUTPUT_TYPE_DIR_PWM = 4,
};

#define HM2_PWMGEN_DEFAULT_FREQUENCY 20000u

enum { HM2_PWMGEN_RATE_OK = 0, HM2_PWMGEN_RATE_TOO_LOW, HM2_PWMGEN_RATE_TOO_HIGH };

/* A master-rate choice: DDS value, PWM bits, frequency achieved (the param's new value). */
typedef struct {
    uint32_t dds, bits, frequency;
    int note;                 /* HM2_PWMGEN_RATE_* : why the frequency was changed */
} hm2_pwmgen_rate_t;

/* PWM: the widest of 12..9 bits whose DDS fits in 16 bits. */
hm2_pwmgen_rate_t hm2_pwmgen_pwm_rate(uint32_t clock_high_hz, uint32_t frequency);
/* PDM: DDS = f * 65536 / clock, limited to 1..65535. */
hm2_pwmgen_rate_t hm2_pwmgen_pdm_rate(uint32_t clock_high_hz, uint32_t frequency);
/* Mode register: width, output mode, double buffering (PWM modes), dither. */
uint32_t hm2_pwmgen_mode_word(int output_type, uint32_t pwm_bits, bool dither);
/* Value register for a duty in -1..1 (clipped). */
uint32_t hm2_pwmgen_value_register(double duty, int bits, bool offset_mode, bool dither);

#endif
