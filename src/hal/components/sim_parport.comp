component sim_parport "Stand-in for hal_parport with the same pin names, for simulated machines";
pin in bit pin_01_out "Output pin 01 as written to the port";
pin out bit pin_01_out_fake "Pin 01 as the port would drive it: pin-01-out XOR pin-01-out-invert";
pin in bit pin_02_out "Output pin 02 as written to the port";
pin out bit pin_02_out_fake "Pin 02 as the port would drive it: pin-02-out XOR pin-02-out-invert";
pin in bit pin_03_out "Output pin 03 as written to the port";
pin out bit pin_03_out_fake "Pin 03 as the port would drive it: pin-03-out XOR pin-03-out-invert";
pin in bit pin_04_out "Output pin 04 as written to the port";
pin out bit pin_04_out_fake "Pin 04 as the port would drive it: pin-04-out XOR pin-04-out-invert";
pin in bit pin_05_out "Output pin 05 as written to the port";
pin out bit pin_05_out_fake "Pin 05 as the port would drive it: pin-05-out XOR pin-05-out-invert";
pin in bit pin_06_out "Output pin 06 as written to the port";
pin out bit pin_06_out_fake "Pin 06 as the port would drive it: pin-06-out XOR pin-06-out-invert";
pin in bit pin_07_out "Output pin 07 as written to the port";
pin out bit pin_07_out_fake "Pin 07 as the port would drive it: pin-07-out XOR pin-07-out-invert";
pin in bit pin_08_out "Output pin 08 as written to the port";
pin out bit pin_08_out_fake "Pin 08 as the port would drive it: pin-08-out XOR pin-08-out-invert";
pin in bit pin_09_out "Output pin 09 as written to the port";
pin out bit pin_09_out_fake "Pin 09 as the port would drive it: pin-09-out XOR pin-09-out-invert";
pin in bit pin_14_out "Output pin 14 as written to the port";
pin out bit pin_14_out_fake "Pin 14 as the port would drive it: pin-14-out XOR pin-14-out-invert";
pin in bit pin_16_out "Output pin 16 as written to the port";
pin out bit pin_16_out_fake "Pin 16 as the port would drive it: pin-16-out XOR pin-16-out-invert";
pin in bit pin_17_out "Output pin 17 as written to the port";
pin out bit pin_17_out_fake "Pin 17 as the port would drive it: pin-17-out XOR pin-17-out-invert";
pin in bit pin_02_in_fake "Simulated level of input pin 02";
pin out bit pin_02_in "Input pin 02: pin-02-in-fake";
pin out bit pin_02_in_not "Input pin 02 inverted";
pin in bit pin_03_in_fake "Simulated level of input pin 03";
pin out bit pin_03_in "Input pin 03: pin-03-in-fake";
pin out bit pin_03_in_not "Input pin 03 inverted";
pin in bit pin_04_in_fake "Simulated level of input pin 04";
pin out bit pin_04_in "Input pin 04: pin-04-in-fake";
pin out bit pin_04_in_not "Input pin 04 inverted";
pin in bit pin_05_in_fake "Simulated level of input pin 05";
pin out bit pin_05_in "Input pin 05: pin-05-in-fake";
pin out bit pin_05_in_not "Input pin 05 inverted";
pin in bit pin_06_in_fake "Simulated level of input pin 06";
pin out bit pin_06_in "Input pin 06: pin-06-in-fake";
pin out bit pin_06_in_not "Input pin 06 inverted";
pin in bit pin_07_in_fake "Simulated level of input pin 07";
pin out bit pin_07_in "Input pin 07: pin-07-in-fake";
pin out bit pin_07_in_not "Input pin 07 inverted";
pin in bit pin_08_in_fake "Simulated level of input pin 08";
pin out bit pin_08_in "Input pin 08: pin-08-in-fake";
pin out bit pin_08_in_not "Input pin 08 inverted";
pin in bit pin_09_in_fake "Simulated level of input pin 09";
pin out bit pin_09_in "Input pin 09: pin-09-in-fake";
pin out bit pin_09_in_not "Input pin 09 inverted";
pin in bit pin_10_in_fake "Simulated level of input pin 10";
pin out bit pin_10_in "Input pin 10: pin-10-in-fake";
pin out bit pin_10_in_not "Input pin 10 inverted";
pin in bit pin_11_in_fake "Simulated level of input pin 11";
pin out bit pin_11_in "Input pin 11: pin-11-in-fake";
pin out bit pin_11_in_not "Input pin 11 inverted";
pin in bit pin_12_in_fake "Simulated level of input pin 12";
pin out bit pin_12_in "Input pin 12: pin-12-in-fake";
pin out bit pin_12_in_not "Input pin 12 inverted";
pin in bit pin_13_in_fake "Simulated level of input pin 13";
pin out bit pin_13_in "Input pin 13: pin-13-in-fake";
pin out bit pin_13_in_not "Input pin 13 inverted";
pin in bit pin_15_in_fake "Simulated level of input pin 15";
pin out bit pin_15_in "Input pin 15: pin-15-in-fake";
pin out bit pin_15_in_not "Input pin 15 inverted";
pin in float reset_time "Accepted for hal_parport compatibility; ignored";
param rw bit pin_01_out_invert "Invert output pin 01";
param rw bit pin_02_out_invert "Invert output pin 02";
param rw bit pin_03_out_invert "Invert output pin 03";
param rw bit pin_04_out_invert "Invert output pin 04";
param rw bit pin_05_out_invert "Invert output pin 05";
param rw bit pin_06_out_invert "Invert output pin 06";
param rw bit pin_07_out_invert "Invert output pin 07";
param rw bit pin_08_out_invert "Invert output pin 08";
param rw bit pin_09_out_invert "Invert output pin 09";
param rw bit pin_14_out_invert "Invert output pin 14";
param rw bit pin_16_out_invert "Invert output pin 16";
param rw bit pin_17_out_invert "Invert output pin 17";
param rw bit pin_01_out_reset "Accepted for hal_parport compatibility; ignored";
param rw bit pin_02_out_reset "Accepted for hal_parport compatibility; ignored";
param rw bit pin_03_out_reset "Accepted for hal_parport compatibility; ignored";
param rw bit pin_04_out_reset "Accepted for hal_parport compatibility; ignored";
param rw bit pin_05_out_reset "Accepted for hal_parport compatibility; ignored";
param rw bit pin_06_out_reset "Accepted for hal_parport compatibility; ignored";
param rw bit pin_07_out_reset "Accepted for hal_parport compatibility; ignored";
param rw bit pin_08_out_reset "Accepted for hal_parport compatibility; ignored";
param rw bit pin_09_out_reset "Accepted for hal_parport compatibility; ignored";
param rw bit pin_14_out_reset "Accepted for hal_parport compatibility; ignored";
param rw bit pin_16_out_reset "Accepted for hal_parport compatibility; ignored";
param rw bit pin_17_out_reset "Accepted for hal_parport compatibility; ignored";
function read "Copy each pin-NN-in-fake to pin-NN-in and its inverse to pin-NN-in-not";
function write "Copy each pin-NN-out, inverted if asked, to pin-NN-out-fake";
function reset "Does nothing (hal_parport compatibility)";
description """Load it with the name of the port it replaces (for example
names=parport.0) so HAL files written for hal_parport work unchanged. Pins 02-09
exist both as outputs and as inputs (hal_parport's data port in either direction),
10-13 and 15 are inputs, 01, 14, 16 and 17 outputs. The -fake pins connect the
simulated port to the rest of the simulation: read copies pin-NN-in-fake to
pin-NN-in (and its inverse to pin-NN-in-not), write sets pin-NN-out-fake to
pin-NN-out XOR pin-NN-out-invert. The reset function, the pin-NN-out-reset params
and the reset-time pin exist so that HAL files written for step generation with
hal_parport load unchanged; they do nothing.""";
license "GPL";
author "OpenEMC";
;;

/* Pass the simulated input levels to the port input pins. */
FUNCTION(read) {
    pin_02_in = pin_02_in_fake;
    pin_02_in_not = !pin_02_in_fake;
    pin_03_in = pin_03_in_fake;
    pin_03_in_not = !pin_03_in_fake;
    pin_04_in = pin_04_in_fake;
    pin_04_in_not = !pin_04_in_fake;
    pin_05_in = pin_05_in_fake;
    pin_05_in_not = !pin_05_in_fake;
    pin_06_in = pin_06_in_fake;
    pin_06_in_not = !pin_06_in_fake;
    pin_07_in = pin_07_in_fake;
    pin_07_in_not = !pin_07_in_fake;
    pin_08_in = pin_08_in_fake;
    pin_08_in_not = !pin_08_in_fake;
    pin_09_in = pin_09_in_fake;
    pin_09_in_not = !pin_09_in_fake;
    pin_10_in = pin_10_in_fake;
    pin_10_in_not = !pin_10_in_fake;
    pin_11_in = pin_11_in_fake;
    pin_11_in_not = !pin_11_in_fake;
    pin_12_in = pin_12_in_fake;
    pin_12_in_not = !pin_12_in_fake;
    pin_13_in = pin_13_in_fake;
    pin_13_in_not = !pin_13_in_fake;
    pin_15_in = pin_15_in_fake;
    pin_15_in_not = !pin_15_in_fake;
}

/* Drive the simulated output levels from the port output pins. */
FUNCTION(write) {
    pin_01_out_fake = pin_01_out ^ pin_01_out_invert;
    pin_02_out_fake = pin_02_out ^ pin_02_out_invert;
    pin_03_out_fake = pin_03_out ^ pin_03_out_invert;
    pin_04_out_fake = pin_04_out ^ pin_04_out_invert;
    pin_05_out_fake = pin_05_out ^ pin_05_out_invert;
    pin_06_out_fake = pin_06_out ^ pin_06_out_invert;
    pin_07_out_fake = pin_07_out ^ pin_07_out_invert;
    pin_08_out_fake = pin_08_out ^ pin_08_out_invert;
    pin_09_out_fake = pin_09_out ^ pin_09_out_invert;
    pin_14_out_fake = pin_14_out ^ pin_14_out_invert;
    pin_16_out_fake = pin_16_out ^ pin_16_out_invert;
    pin_17_out_fake = pin_17_out ^ pin_17_out_invert;
}

/* hal_parport compatibility: nothing to reset in the simulation. */
FUNCTION(reset) {
}
