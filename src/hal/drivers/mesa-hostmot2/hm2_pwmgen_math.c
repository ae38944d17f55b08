/* hm2_pwmgen_math.c: PWMGen rate, mode and value encodings (pure, unit-tested). */
#include <math.h>
#include "hm2_pwmgen.h"

#define DDS_LIMIT 65536.0
#define DDS_MAX 65535u
#define MODE_DOUBLE_BUFFERED (1u << 5)
#define MODE_DITHER (1u << 6)
#define VALUE_NEGATIVE (1u << 31)

/* Output-mode field (bits 3-4) of each output type. */
static uint32_t output_mode_bits(int output_type)
{
    switch (output_type) {
    case HM2_PWMGEN_OUTPUT_TYPE_UP_DOWN: return 2u << 3;
    case HM2_PWMGEN_OUTPUT_TYPE_PDM: return 3u << 3;
    case HM2_PWMGEN_OUTPUT_TYPE_DIR_PWM: return 1u << 3;
    default: return 0;
    }
}

/* Try 12, 11, 10, 9 bits; too fast for 9 bits pins the DDS at 65535. */
hm2_pwmgen_rate_t hm2_pwmgen_pwm_rate(uint32_t clock_high_hz, uint32_t frequency)
{
    hm2_pwmgen_rate_t r = {0, 0, frequency, HM2_PWMGEN_RATE_OK};
    if (r.frequency < 1) {
        r.frequency = 1;
        r.note = HM2_PWMGEN_RATE_TOO_LOW;
    }
    for (uint32_t bits = 12; bits >= 9; bits--) {
        double dds = (double)r.frequency * DDS_LIMIT * (double)(1u << bits) / clock_high_hz;
        if (dds < DDS_LIMIT) {
            r.dds = (uint32_t)dds;
            r.bits = bits;
            return r;
        }
    }
    r.frequency = (uint32_t)((double)clock_high_hz * DDS_MAX / (DDS_LIMIT * 512.0));
    r.dds = DDS_MAX;
    r.bits = 9;
    r.note = HM2_PWMGEN_RATE_TOO_HIGH;
    return r;
}

/* PDM slot rate DDS, limited to 1..65535. */
hm2_pwmgen_rate_t hm2_pwmgen_pdm_rate(uint32_t clock_high_hz, uint32_t frequency)
{
    hm2_pwmgen_rate_t r = {0, 12, frequency, HM2_PWMGEN_RATE_OK};
    double dds = (double)frequency * DDS_LIMIT / clock_high_hz;
    if (dds < 1.0) {
        r.dds = 1;
        r.frequency = (uint32_t)((double)clock_high_hz / DDS_LIMIT);
        r.note = HM2_PWMGEN_RATE_TOO_LOW;
    } else if (dds >= DDS_LIMIT) {
        r.dds = DDS_MAX;
        r.frequency = (uint32_t)((double)clock_high_hz * DDS_MAX / DDS_LIMIT);
        r.note = HM2_PWMGEN_RATE_TOO_HIGH;
    } else {
        r.dds = (uint32_t)dds;
    }
    return r;
}

/* Width code = bits - 9; PWM modes are double buffered, PDM is not. */
uint32_t hm2_pwmgen_mode_word(int output_type, uint32_t pwm_bits, bool dither)
{
    uint32_t mode = output_mode_bits(output_type);
    if (output_type == HM2_PWMGEN_OUTPUT_TYPE_PDM)
        mode |= 3u;
    else
        mode |= (pwm_bits - 9) | MODE_DOUBLE_BUFFERED;
    if (dither)
        mode |= MODE_DITHER;
    return mode;
}

/* |d|*(2^b - k)*65536 (offset mode: one bit less, centred), bit 31 = negative. */
uint32_t hm2_pwmgen_value_register(double duty, int bits, bool offset_mode, bool dither)
{
    double k = dither ? 1.0625 : 1.0;
    if (duty > 1.0)
        duty = 1.0;
    else if (duty < -1.0)
        duty = -1.0;
    double reg;
    if (offset_mode) {
        double full = ldexp(1.0, bits - 1);
        reg = (duty * (full - k) + full) * 65536.0;
    } else {
        reg = fabs(duty) * (ldexp(1.0, bits) - k) * 65536.0;
    }
    uint32_t value = (uint32_t)reg;
    if (duty < 0)
        value |= VALUE_NEGATIVE;
    return value;
}
