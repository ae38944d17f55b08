component momentary2nist "One momentary button toggles a device that has separate on and off inputs";
description """
A debounced press pulses \\fBon\\fR when \\fBis-on\\fR is FALSE, else \\fBoff\\fR; the pulse ends
when is-on confirms or after about \\fBmax-pulse-length\\fR calls.
""";
pin in bit in "Momentary button";
pin in bit is_on "Device status";
pin out bit on "Pulse to switch on";
pin out bit off "Pulse to switch off";
pin in u32 debounce = 2 "Calls the button must be stable (1..10000, else 2)";
pin in u32 max_pulse_length = 100 "Longest on/off pulse, calls";
variable int level;
variable unsigned counter;
variable unsigned pulse;
function _;
license "GPL";
author "OpenEMC";
;;
unsigned d = debounce >= 1 && debounce <= 10000 ? debounce : 2;
(void)period;
if (in && !level) {
    if (++counter >= d) {
        on = !is_on;
        off = is_on;
        level = 1;
        counter = 0;
    }
} else if (!in && level) {
    if (++counter >= d) {
        level = 0;
        counter = 0;
    }
} else if ((!is_on && off) || (is_on && on) || pulse > max_pulse_length) {
    on = off = 0;
    counter = pulse = 0;
} else {
    counter = 0;
    pulse++;
}
