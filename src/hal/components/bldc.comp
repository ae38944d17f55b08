component bldc "Commutation of 3-phase brushless motors from Hall, Gray-code, absolute or incremental feedback";
description """
Load with \\fBcfg=\\fR one tag string per motor (up to 8): \\fBh\\fR Hall inputs, \\fBa\\fR absolute
encoder, \\fBq\\fR incremental encoder (homes first), \\fBi\\fR use the index, \\fBf\\fR Fanuc 4-bit Gray
inputs; outputs \\fBB\\fR three bits, \\fB6\\fR six outputs (high and low side), \\fBH\\fR emulated Hall,
\\fBF\\fR emulated Gray; \\fBT\\fR forces trapezoidal commutation; \\fBn\\fR (or no input letter) runs
open loop at \\fBfrequency\\fR.  Angles are in electrical revolutions.
""";
pin in bit hall1 if personality & 0x01 "Hall sensor 1 (most significant)";
pin in bit hall2 if personality & 0x01 "Hall sensor 2";
pin in bit hall3 if personality & 0x01 "Hall sensor 3";
pin out bit hall_error if personality & 0x01 "The Hall state skipped a sector (sticky until pattern changes)";
pin in bit C1 if personality & 0x10 "Fanuc Gray input C1";
pin in bit C2 if personality & 0x10 "Fanuc Gray input C2";
pin in bit C4 if personality & 0x10 "Fanuc Gray input C4";
pin in bit C8 if personality & 0x10 "Fanuc Gray input C8";
pin in float value "Commanded amplitude";
pin in float lead_angle = 90 if personality & 0x06 "Phase lead in degrees (encoder modes)";
pin in bit rev "Reverse the motor direction";
pin in float frequency if (personality & 0x0F) == 0 "Open-loop speed, electrical revolutions per second";
pin in float initvalue = 0.2 if personality & 0x04 "Amplitude used while homing";
pin in s32 rawcounts if personality & 0x06 "Encoder counts";
pin io bit index_enable if personality & 0x08 "Encoder index enable";
pin in bit init if (personality & 0x05) == 0x04 "Start magnetic-alignment homing";
pin out bit init_done if (personality & 0x05) == 0x04 "Homing finished";
pin out float A_value if (personality & 0xF00) == 0 "Phase A amplitude";
pin out float B_value if (personality & 0xF00) == 0 "Phase B amplitude";
pin out float C_value if (personality & 0xF00) == 0 "Phase C amplitude";
pin out bit A_on if (personality & 0xF00) == 0x100 "Phase A on";
pin out bit B_on if (personality & 0xF00) == 0x100 "Phase B on";
pin out bit C_on if (personality & 0xF00) == 0x100 "Phase C on";
pin out float A_high if (personality & 0xF00) == 0x200 "Phase A high-side amplitude";
pin out float B_high if (personality & 0xF00) == 0x200 "Phase B high-side amplitude";
pin out float C_high if (personality & 0xF00) == 0x200 "Phase C high-side amplitude";
pin out float A_low if (personality & 0xF00) == 0x200 "Phase A low-side amplitude";
pin out float B_low if (personality & 0xF00) == 0x200 "Phase B low-side amplitude";
pin out float C_low if (personality & 0xF00) == 0x200 "Phase C low-side amplitude";
pin out bit A_high_on if (personality & 0xF00) == 0x300 "Phase A high side on";
pin out bit B_high_on if (personality & 0xF00) == 0x300 "Phase B high side on";
pin out bit C_high_on if (personality & 0xF00) == 0x300 "Phase C high side on";
pin out bit A_low_on if (personality & 0xF00) == 0x300 "Phase A low side on";
pin out bit B_low_on if (personality & 0xF00) == 0x300 "Phase B low side on";
pin out bit C_low_on if (personality & 0xF00) == 0x300 "Phase C low side on";
pin out bit hall1_out if (personality & 0x400) "Emulated Hall output 1";
pin out bit hall2_out if (personality & 0x400) "Emulated Hall output 2";
pin out bit hall3_out if (personality & 0x400) "Emulated Hall output 3";
pin out bit C1_out if (personality & 0x800) "Emulated Gray output C1";
pin out bit C2_out if (personality & 0x800) "Emulated Gray output C2";
pin out bit C4_out if (personality & 0x800) "Emulated Gray output C4";
pin out bit C8_out if (personality & 0x800) "Emulated Gray output C8";
pin out float phase_angle "Phase angle, electrical revolutions";
pin out float rotor_angle "Rotor angle, electrical revolutions";
pin out float out "Amplitude after the direction is applied";
pin out bit out_dir "TRUE when the amplitude is negative";
pin out float out_abs "Absolute amplitude";
param r s32 in_type = -1 "Feedback mode in use (-1 starting, -2 disabled)";
param r s32 out_type = -1 "Output mode in use";
param rw s32 scale = 512 if personality & 0x06 "Encoder counts per mechanical revolution";
param rw s32 poles = 4 if personality & 0x06 "Motor poles";
param rw s32 encoder_offset if personality & 0x0A "Encoder counts from index to phase A";
param r s32 offset_measured if personality & 0x04 "Encoder count measured by homing";
param rw float drive_offset "Offset in degrees between rotor and phase angle while homing";
param rw u32 pattern = 25 if personality & 0x01 "Hall input pattern (0..47)";
param rw u32 output_pattern = 25 if personality & 0x400 "Hall output pattern (0..47)";
variable long long long_counts;
variable long long long_counts_prev;
variable int raw_prev;
variable int init_prev;
variable int ex_prev;
variable int pattern_prev = -1;
variable int gray_prev = -1;
variable int force_trap;
variable double home_clock = 2.4;
variable int ex;
variable int trap;
option count_function yes;
option extra_setup yes;
function _;
include <rtapi_math.h>;
include "bldc_tables.h";
license "GPL";
author "OpenEMC";
;;
#define BLDC_MAX_CHAN 8
static char *cfg[BLDC_MAX_CHAN];
RTAPI_MP_ARRAY_STRING(cfg, BLDC_MAX_CHAN, "feedback and output tags of each motor");

#define BLDC_HALL 0x01
#define BLDC_ABS 0x02
#define BLDC_QEI 0x04
#define BLDC_INDEX 0x08
#define BLDC_GRAY 0x10
#define BLDC_OUT_MASK 0x7F00
#define BLDC_FORCE_TRAP 0x8000
#define BLDC_IN_STARTING -1
#define BLDC_IN_DISABLED -2

#include "hal/components/bldc_modes.h"

/* Motors given by cfg=; none prints the tag list (and loads nothing). */
int get_count(void)
{
    int n = 0;
    while (n < BLDC_MAX_CHAN && cfg[n] && cfg[n][0])
        n++;
    if (n == 0) {
        rtapi_print_msg(RTAPI_MSG_ERR, "The bldc component needs at least one feedback type tag.\n");
        rtapi_print_msg(RTAPI_MSG_ERR, "Valid tags are h, a, q, i, b, 6, n\n");
    }
    return n;
}

/* Personality of one motor from the first 8 characters of its tag string. */
EXTRA_SETUP()
{
    static const struct { char tag; int bit; } tags[] = {
        {'h', 0x01}, {'a', 0x02}, {'q', 0x04}, {'i', 0x08}, {'f', 0x10}, {'B', 0x100}, {'6', 0x200},
        {'H', 0x400}, {'F', 0x800}, {'T', 0x8000}};
    const char *c = cfg[extra_arg];
    (void)prefix;
    personality = 0;
    for (int k = 0; k < 8 && c[k]; k++)
        for (unsigned t = 0; t < sizeof(tags) / sizeof(tags[0]); t++)
            if (c[k] == tags[t].tag)
                personality |= tags[t].bit;
    return 0;
}

FUNCTION(_)
{
    double v = rev ? -value : value;
    out_dir = v < 0;
    out_abs = fabs(v);
    if ((personality & (BLDC_QEI | BLDC_HALL)) == BLDC_QEI)
        bldc_check_rehome(__comp_inst);
    if (personality & (BLDC_ABS | BLDC_QEI))
        bldc_extend_counts(__comp_inst);
    if (!bldc_feedback(__comp_inst, &v, fperiod))
        return;
    bldc_outputs(__comp_inst, v);
}
