/* bldc_outputs.h: bldc's output stages (analogue, bits, six-step, emulated Hall and Gray); included by
 * bldc_modes.h. */

#define BLDC_SRC(ex, bit) (((ex) >> 3) & (bit))
#define BLDC_SNK(ex, bit) ((ex) & (bit))
#define BLDC_PHASE_A 4
#define BLDC_PHASE_B 2
#define BLDC_PHASE_C 1

/* Excitation of the sector the rotor angle is in (non-Hall modes). */
static int bldc_excitation_of(double rotor)
{
    for (int k = 0; k < BLDC_NSECTORS; k++)
        if (rotor <= k / 6.0 - 1.0 / 12)
            return bldc_sector_table[k];
    return bldc_sector_table[1];
}

/* Excitation with source and sink digits exchanged. */
static int bldc_swap(int e)
{
    return ((e & 07) << 3) | ((e >> 3) & 07);
}

/* Sinusoidal phase weights (cos of A, B, C) at the phase angle. */
static void bldc_sin_weights(double phase, double w[3])
{
    double th = 2 * M_PI * phase, c = cos(th), s = sin(th);
    w[0] = c;
    w[1] = -0.5 * c + (sqrt(3.0) / 2) * s;
    w[2] = -0.5 * c - (sqrt(3.0) / 2) * s;
}

/* Out-type 0: three analogue phase values. */
static void bldc_out_values(struct __comp_state *__comp_inst, double v)
{
    static const int bits[3] = {BLDC_PHASE_A, BLDC_PHASE_B, BLDC_PHASE_C};
    double w[3], r[3];
    if (trap) {
        for (int i = 0; i < 3; i++)
            r[i] = BLDC_SRC(ex, bits[i]) ? v : BLDC_SNK(ex, bits[i]) ? -v : 0.0;
    } else {
        bldc_sin_weights(phase_angle, w);
        for (int i = 0; i < 3; i++)
            r[i] = fabs(v) * w[i];
    }
    A_value = r[0];
    B_value = r[1];
    C_value = r[2];
}

/* Out-type 0x100: three bits, first source on, first sink off. */
static void bldc_out_bits(struct __comp_state *__comp_inst)
{
    int e = out_dir ? bldc_swap(ex) : ex;
    if (BLDC_SRC(e, BLDC_PHASE_A)) A_on = 1;
    else if (BLDC_SRC(e, BLDC_PHASE_B)) B_on = 1;
    else if (BLDC_SRC(e, BLDC_PHASE_C)) C_on = 1;
    else A_on = B_on = C_on = 0;
    if (BLDC_SNK(e, BLDC_PHASE_A)) A_on = 0;
    else if (BLDC_SNK(e, BLDC_PHASE_B)) B_on = 0;
    else if (BLDC_SNK(e, BLDC_PHASE_C)) C_on = 0;
    else A_on = B_on = C_on = 0;
}

/* Out-type 0x200: high- and low-side amplitudes of each phase. */
static void bldc_out_six(struct __comp_state *__comp_inst, double v)
{
    static const int bits[3] = {BLDC_PHASE_A, BLDC_PHASE_B, BLDC_PHASE_C};
    double hi[3], lo[3], w[3], a = fabs(v);
    int e = out_dir ? bldc_swap(ex) : ex;
    bldc_sin_weights(phase_angle, w);
    for (int i = 0; i < 3; i++) {
        if (trap) {
            hi[i] = BLDC_SRC(e, bits[i]) ? a : 0.0;
            lo[i] = !BLDC_SRC(e, bits[i]) && BLDC_SNK(e, bits[i]) ? a : 0.0;
        } else {
            hi[i] = w[i] >= 0 ? a * w[i] : 0.0;
            lo[i] = w[i] < 0 ? -a * w[i] : 0.0;
        }
    }
    A_high = hi[0]; B_high = hi[1]; C_high = hi[2];
    A_low = lo[0]; B_low = lo[1]; C_low = lo[2];
}

/* Out-type 0x300: six bits (high and low side on). */
static void bldc_out_six_bits(struct __comp_state *__comp_inst)
{
    int s = out_dir ? BLDC_SNK(ex, 07) : BLDC_SRC(ex, 07), k = out_dir ? BLDC_SRC(ex, 07) : BLDC_SNK(ex, 07);
    A_high_on = (s & BLDC_PHASE_A) != 0; B_high_on = (s & BLDC_PHASE_B) != 0; C_high_on = (s & BLDC_PHASE_C) != 0;
    A_low_on = (k & BLDC_PHASE_A) != 0; B_low_on = (k & BLDC_PHASE_B) != 0; C_low_on = (k & BLDC_PHASE_C) != 0;
}

/* Out-type 0x400: the Hall state that output-pattern gives for this excitation. */
static void bldc_out_hall(struct __comp_state *__comp_inst)
{
    int h = 8;
    if (output_pattern < BLDC_NPATTERNS)
        for (h = 0; h < 8 && bldc_hall_table[output_pattern][h] != ex; h++)
            ;
    hall1_out = h < 8 && (h & 4);
    hall2_out = h < 8 && (h & 2);
    hall3_out = h < 8 && (h & 1);
}

/* Out-type 0x800: the Gray code of the rotor angle. */
static void bldc_out_gray(struct __comp_state *__comp_inst)
{
    int k;
    for (k = 0; k < BLDC_NGRAY - 1 && k / 16.0 + 1.0 / 16 < rotor_angle; k++)
        ;
    int g = bldc_gray_table[k];
    C1_out = (g & 1) != 0; C2_out = (g & 2) != 0; C4_out = (g & 4) != 0; C8_out = (g & 8) != 0;
}

/* Output types without an output stage of their own fall back to one (or disable the motor). */
static void bldc_fallback_out_type(struct __comp_state *__comp_inst)
{
    int t = out_type;
    if (t == 0x500 || t == 0x600 || t == 0x700 || t == 0xC00) {
        rtapi_print_msg(RTAPI_MSG_ERR, "bldc: output type %X is not supported, defaulting to Hall outputs\n", t);
        out_type = 0x400;
    } else if (t == 0x900 || t == 0xA00 || t == 0xB00) {
        rtapi_print_msg(RTAPI_MSG_ERR, "bldc: output type %X is not supported, defaulting to Gray outputs\n", t);
        out_type = 0x800;
    } else {
        rtapi_print_msg(RTAPI_MSG_ERR, "Unsupported output type (%X) in bldc\n", t);
        in_type = BLDC_IN_DISABLED;
    }
}

/* Drive the outputs of the configured type from the amplitude v and the angles. */
static void bldc_outputs(struct __comp_state *__comp_inst, double v)
{
    if (!trap)
        ex = bldc_excitation_of(rotor_angle);
    trap = trap || force_trap;
    out = v;
    out_abs = fabs(v);
    switch (out_type) {
    case 0x000: bldc_out_values(__comp_inst, v); break;
    case 0x100: bldc_out_bits(__comp_inst); break;
    case 0x200: bldc_out_six(__comp_inst, v); break;
    case 0x300: bldc_out_six_bits(__comp_inst); break;
    case 0x400: bldc_out_hall(__comp_inst); break;
    case 0x800: bldc_out_gray(__comp_inst); break;
    default: bldc_fallback_out_type(__comp_inst); break;
    }
}
