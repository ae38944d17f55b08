component max31855 "Read MAX31855 K-type thermocouple converters by bit-banged SPI";
description """
personality is the number of sensors (0..15); they share \\fBclk.out\\fR and \\fBcs.out\\fR and
each has its own \\fBdata.N.in\\fR.  Each call of \\fBbitbang-spi\\fR is one clock half cycle:
65 calls read a 32-bit frame from every sensor (cs low), 65 calls idle (cs high).  The
thermocouple reading is corrected for the cold junction with the NIST K-type polynomials.
""";
pin out bit clk.out "SPI clock";
pin out bit cs.out "SPI chip select (low while reading)";
pin in bit data.#.in[15 : personality] "Data line of sensor N";
pin out float temp_celsius.#[15 : personality] "Temperature of sensor N, degrees C";
pin out float temp_fahrenheit.#[15 : personality] "Temperature of sensor N, degrees F";
pin out float temp_kelvin.#[15 : personality] "Temperature of sensor N, K";
pin out bit fault.#[15 : personality] "Sensor N reports a fault";
pin out u32 fault_flags.#[15 : personality] "1 open thermocouple, 2 short to GND, 4 short to VCC";
variable int step;
variable int samples;
variable unsigned frame[15];
variable unsigned last_flags[15];
option extra_setup yes;
function bitbang_spi;
include <rtapi_math.h>;
license "GPL";
author "OpenEMC";
;;
#include "hal/components/max31855_nist.h"
#define MAX_SENSORS 15
#define READ_CALLS 65
#define CYCLE_CALLS 130
#define FRAME_SAMPLES 33

/* At most 15 sensors. */
EXTRA_SETUP()
{
    (void)prefix;
    (void)extra_arg;
    if (personality > MAX_SENSORS) {
        rtapi_print_msg(RTAPI_MSG_ERR, "max31855: personality must be at most 15 (use personality=N to set "
                        "the number of sensors)\n");
        return -EINVAL;
    }
    return 0;
}

/* Decode the frame of sensor i: fault flags, or the three temperatures. */
static void max31855_decode(struct __comp_state *__comp_inst, int i)
{
    int w = (int)frame[i];
    unsigned flags = (unsigned)w & 7;
    fault_flags(i) = flags;
    fault(i) = flags != 0;
    if (flags) {
        if (flags != last_flags[i])
            rtapi_print("max31855: sensor %d detected fault %x\n", i, flags);
        last_flags[i] = flags;
        return;
    }
    last_flags[i] = 0;
    int internal = (int)((unsigned)w << 16) >> 20; /* signed 12-bit field w[15:4] */
    double t = max31855_celsius((w >> 18) * 0.25, internal * 0.0625);
    temp_celsius(i) = t;
    temp_fahrenheit(i) = t * 1.8 + 32;
    temp_kelvin(i) = t + 273.15;
}

FUNCTION(bitbang_spi)
{
    (void)period;
    clk_out = !clk_out;
    if (step < READ_CALLS) {
        cs_out = 0;
        if (clk_out && samples++ > 0)
            for (int i = 0; i < personality; i++)
                frame[i] = (frame[i] << 1) | (data_in(i) ? 1u : 0u);
        if (samples == FRAME_SAMPLES) {
            for (int i = 0; i < personality; i++)
                max31855_decode(__comp_inst, i);
            cs_out = 1;
            samples = 0;
        }
    }
    if (++step == CYCLE_CALLS)
        step = 0;
}
