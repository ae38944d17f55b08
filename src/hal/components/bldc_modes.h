/* bldc_modes.h: bldc's feedback modes (Hall, Gray, encoders, homing) and output stages; included by
 * bldc.comp after its pin macros. */

/* x reduced to [0, 1). */
static double bldc_wrap(double x)
{
    return x - floor(x);
}

/* Sector table entry k, or 0 past its end (LinuxCNC reads beyond the table there). */
static int bldc_sector(int k)
{
    return k >= 0 && k < BLDC_NSECTORS ? bldc_sector_table[k] : 0;
}

/* Counts per electrical revolution used by homing: 2*scale/poles in integer arithmetic. */
static long long bldc_counts_per_erev(struct __comp_state *__comp_inst)
{
    return poles ? (2LL * scale) / poles : 0;
}

/* A rising init while homed asks for homing again. */
static void bldc_check_rehome(struct __comp_state *__comp_inst)
{
    if (init && !init_prev && init_done) {
        init_done = 0;
        in_type = BLDC_IN_STARTING;
        return;
    }
    init_prev = init;
}

/* Extend rawcounts to 64 bits across s32 wrap-around. */
static void bldc_extend_counts(struct __comp_state *__comp_inst)
{
    long_counts_prev = long_counts;
    long_counts += (hal_s32_t)((hal_u32_t)rawcounts - (hal_u32_t)raw_prev);
    raw_prev = rawcounts;
}

/* Homing finished: remember where the rotor is and run as an absolute encoder. */
static void bldc_homed_at(struct __comp_state *__comp_inst, double rotor)
{
    offset_measured = (hal_s32_t)(long_counts - (long long)(rotor * bldc_counts_per_erev(__comp_inst)));
    in_type = BLDC_ABS;
}

/* Hall trapezoidal modes (h, hq, hqi); returns 0 when there is nothing to output. */
static int bldc_hall(struct __comp_state *__comp_inst)
{
    int k, h = (hall1 ? 4 : 0) | (hall2 ? 2 : 0) | (hall3 ? 1 : 0);
    if (pattern > 47) {
        rtapi_print_msg(RTAPI_MSG_ERR, "Only `Hall patterns 0-47 are allowed, you have requested pattern %i\n",
                        (int)pattern);
        pattern = 0;
        return 0;
    }
    ex = bldc_hall_table[pattern][h];
    for (k = 0; k < BLDC_NSECTORS && bldc_sector_table[k] != ex; k++)
        ;
    if (k < BLDC_NSECTORS) {
        rotor_angle = k / 6.0;
        phase_angle = bldc_wrap(rotor_angle + (out_dir ? 0.25 : -0.25));
    }
    if (k == BLDC_NSECTORS || !(ex & ex_prev))
        hall_error = 1;
    if ((int)pattern != pattern_prev)
        hall_error = 0;
    pattern_prev = pattern;
    if (!force_trap && in_type == (BLDC_HALL | BLDC_QEI) && ex_prev && ex && ex != ex_prev) {
        for (k = 1; k < BLDC_NSECTORS && bldc_sector_table[k] != ex; k++)
            ;
        double r = bldc_sector(k - 1) == ex_prev ? (k / 6.0 + (k - 1) / 6.0) / 2 : (k / 6.0 + (k + 1) / 6.0) / 2;
        rotor_angle = bldc_wrap(r);
        phase_angle = bldc_wrap(r + (out_dir ? -0.25 : 0.25));
        bldc_homed_at(__comp_inst, r);
    } else if (!force_trap && in_type == (BLDC_HALL | BLDC_QEI | BLDC_INDEX) && !index_enable) {
        offset_measured = (hal_s32_t)long_counts;
        in_type = BLDC_ABS;
    }
    ex_prev = ex;
    trap = 1;
    return 1;
}

/* Fanuc Gray-code modes (f, fq, fqi), sinusoidal. */
static int bldc_gray(struct __comp_state *__comp_inst)
{
    int k, code = (C1 ? 1 : 0) | (C2 ? 2 : 0) | (C4 ? 4 : 0) | (C8 ? 8 : 0);
    for (k = 0; k < BLDC_NGRAY && bldc_gray_table[k] != code; k++)
        ;
    rotor_angle = bldc_wrap(k / 16.0 + 1.0 / 32);
    phase_angle = bldc_wrap(rotor_angle + (out_dir ? -0.25 : 0.25));
    if (!force_trap && in_type == (BLDC_GRAY | BLDC_QEI) && gray_prev >= 0 && code != gray_prev) {
        for (k = 1; k < BLDC_NGRAY && bldc_gray_table[k] != code; k++)
            ;
        double r = bldc_sector(k - 1) == gray_prev ? k / 16.0 : (k + 1) / 16.0;
        rotor_angle = bldc_wrap(r);
        phase_angle = bldc_wrap(r + (out_dir ? -0.25 : 0.25));
        bldc_homed_at(__comp_inst, r);
    } else if (!force_trap && in_type == (BLDC_GRAY | BLDC_QEI | BLDC_INDEX) && !index_enable) {
        offset_measured = (hal_s32_t)long_counts;
        in_type = BLDC_ABS;
    }
    gray_prev = code;
    return 1;
}

/* Magnetic-alignment homing (q): 2.4 s of pushing the rotor to known angles, then record the offset. */
static int bldc_align(struct __comp_state *__comp_inst, double *v, double period_s)
{
    static const double bp[] = {2.4, 2.0, 1.2, 0.8, 0.4, 0.0};
    static const double amp[] = {0, 1, 1, 1, 1, 1};
    static const double ang[] = {0, 0, -0.25, 0.25, 0, 0};
    int i;
    if (!init) {
        *v = 0;
        return 0;
    }
    if (init_done) {
        rtapi_print_msg(RTAPI_MSG_ERR, "bldc: alignment homing requested although homing is done\n");
        return 0;
    }
    home_clock -= period_s;
    for (i = 1; i < 6 && !(home_clock > bp[i]); i++)
        ;
    if (i == 6) {
        bldc_homed_at(__comp_inst, phase_angle);
        home_clock = 2.4;
        init_done = 1;
        return 0;
    }
    double f = (home_clock - bp[i]) / (bp[i - 1] - bp[i]);
    *v = initvalue * (amp[i] + (amp[i - 1] - amp[i]) * f);
    phase_angle = bldc_wrap(ang[i] + (ang[i - 1] - ang[i]) * f);
    rotor_angle = bldc_wrap(phase_angle - drive_offset / 360.0);
    return 1;
}

/* Homing to the index by turning one electrical revolution per second (qi). */
static int bldc_index_home(struct __comp_state *__comp_inst, double *v, double period_s)
{
    if (!init)
        return 0;
    if (!index_enable) {
        offset_measured = (hal_s32_t)long_counts;
        init_done = 1;
        in_type = BLDC_ABS;
    } else if (!init_done) {
        rotor_angle = bldc_wrap(rotor_angle + (initvalue < 0 ? -period_s : period_s));
        phase_angle = rotor_angle;
        *v = fabs(initvalue);
    }
    return 1;
}

/* Absolute (or homed) encoder, sinusoidal: rotor from the counts, phase = rotor + lead. */
static int bldc_encoder(struct __comp_state *__comp_inst)
{
    double lead = lead_angle / 360.0;
    if (out_dir && !force_trap)
        lead = -lead;
    long long lag = long_counts + (long_counts - long_counts_prev) / 2;
    long long meas = (personality & BLDC_QEI) ? offset_measured : 0;
    long long enc = (personality & (BLDC_ABS | BLDC_INDEX)) ? encoder_offset : 0;
    rotor_angle = scale ? bldc_wrap((double)(((lag - meas - enc) * poles) / 2) / scale) : 0;
    phase_angle = bldc_wrap(rotor_angle + lead);
    return 1;
}

/* Combinations that cannot work: report once and switch mode (or disable). */
static int bldc_bad_combination(struct __comp_state *__comp_inst)
{
    static const struct { int type, next; const char *msg; } bad[] = {
        {0x03, 2, "Both Hall Sensors and Absolute encoder specified on the same motor. Only theEncoder will be used"},
        {0x0B, 2, "Both Hall Sensors and Absolute encoder specified on the same motor. Only theEncoder will be used"},
        {0x06, -2, "Specifying the use of both absolute and incremental encoders on the same motor is an error. Motor disabled"},
        {0x07, -2, "Specifying the use of both absolute and incremental encoders on the same motor is an error. Motor disabled"},
        {0x0E, -2, "Specifying the use of both absolute and incremental encoders on the same motor is an error. Motor disabled"},
        {0x0F, -2, "Specifying the use of both absolute and incremental encoders on the same motor is an error. Motor disabled"},
        {0x08, -2, "Driving an electronically commutatedmotor with only an index for feedback is notpossible. Motor Disabled"},
        {0x09, 1, "The use of an encoder Index with Hall sensors is not supported. Defaulting to trapezoidal commutation"},
        {0x0A, 2, "Index is not needed with an Absoluteencoder and will be ignored"},
    };
    for (unsigned i = 0; i < sizeof(bad) / sizeof(bad[0]); i++) {
        if (bad[i].type == in_type) {
            rtapi_print_msg(RTAPI_MSG_ERR, "%s\n", bad[i].msg);
            in_type = bad[i].next;
            return 0;
        }
    }
    rtapi_print_msg(RTAPI_MSG_ERR, "Unknown input type pattern (%X) in bldc\n", (unsigned)in_type);
    in_type = BLDC_IN_DISABLED;
    return 0;
}

/* Rotor and phase angle from the feedback of the current mode; 0 when nothing is output this call. */
static int bldc_feedback(struct __comp_state *__comp_inst, double *v, double period_s)
{
    trap = 0;
    switch (in_type) {
    case BLDC_IN_DISABLED:
        return 0;
    case BLDC_IN_STARTING:
        in_type = personality & 0xFF;
        out_type = personality & BLDC_OUT_MASK;
        force_trap = (personality & BLDC_FORCE_TRAP) != 0;
        if (personality & BLDC_INDEX)
            index_enable = 1;
        return 0;
    case 0x00:
        phase_angle = bldc_wrap(phase_angle + frequency * period_s);
        rotor_angle = phase_angle;
        return 1;
    case 0x01: case 0x05: case 0x0D:
        return bldc_hall(__comp_inst);
    case 0x10: case 0x14: case 0x1C:
        return bldc_gray(__comp_inst);
    case 0x04:
        return bldc_align(__comp_inst, v, period_s);
    case 0x0C:
        return bldc_index_home(__comp_inst, v, period_s);
    case 0x02:
        return bldc_encoder(__comp_inst);
    default:
        return bldc_bad_combination(__comp_inst);
    }
}

#include "bldc_outputs.h"
