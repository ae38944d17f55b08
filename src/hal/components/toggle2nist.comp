component toggle2nist "Turn a momentary button into on/off pulses for a device";
pin in bit in "Button input";
pin in bit is_on "Current state of the device";
pin out bit on "Pulses to turn the device on";
pin out bit off "Pulses to turn the device off";
pin in u32 debounce = 2 "Cycles the button must be held";
pin in u32 max_pulse_length = 100 "Longest on/off pulse, in cycles";
variable int held;
variable int state;
variable unsigned pulse;
function _;
license "GPL";
author "OpenEMC";
;;
if (in) {
    if (held < (int)debounce) held++;
} else {
    held = 0;
    state = 0;
}
if (held >= (int)debounce && state == 0 && debounce > 0) {
    state = is_on ? 2 : 1;
    pulse = 0;
}
if (state == 1) {
    on = !is_on && pulse < max_pulse_length;
    off = 0;
} else if (state == 2) {
    off = is_on && pulse < max_pulse_length;
    on = 0;
} else {
    on = 0;
    off = 0;
}
if (state && pulse < max_pulse_length) pulse++;
if (state == 1 && is_on) state = 3;
if (state == 2 && !is_on) state = 3;
