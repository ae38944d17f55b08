component reset "On a trigger edge, write preset values into IO signals";
description "Between edges the IO pins are not written, so other writers of the same signals keep control.";
pin in bit trigger "Trigger input";
pin in bit rising = 1 "Act on rising edges";
pin in bit falling "Act on falling edges";
pin in bit retriggerable = 1 "Accepted for compatibility; has no effect";
pin in u32 reset_u32 "Value for out-u32";
pin in s32 reset_s32 "Value for out-s32";
pin in float reset_float "Value for out-float";
pin in bit reset_bit "Value for out-bit";
pin io u32 out_u32;
pin io s32 out_s32;
pin io float out_float;
pin io bit out_bit;
variable int last_trigger;
function _;
license "GPL";
author "OpenEMC";
;;
(void)period;
if (trigger != last_trigger && ((rising && trigger) || (falling && !trigger))) {
    out_u32 = reset_u32;
    out_s32 = reset_s32;
    out_float = reset_float;
    out_bit = reset_bit;
}
last_trigger = trigger;
