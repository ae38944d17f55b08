#!/bin/bash
# pwm: PWMGen value/scale/enable/output-type/frequencies as the simulated card sees them (LinuxCNC's
# register values), and a PWM-driven motor on the card feeding an encoder.
. ../lib.sh
sim_start --board 7i92 --motor pwmgen0:encoder0:10000
load_board
B=$BOARD
pwm_has() { sim get pwm 0 | grep -q -- "$1"; }

halcmd setp $B.pwmgen.00.value 0.5
halcmd setp $B.pwmgen.00.enable 1
halcmd start
wait_until "0.5 at 12 bits is register 0x07ff8000" pwm_has "value 0x07ff8000"
check "20 kHz from a 200 MHz clock uses 12 bits" pwm_has "bits 12 freq 19999.6"
check "the card's enable bit is set" pwm_has "enable 1"
check "the /enable pin is driven low" [ "$(sim_field get io 16 16)" = 0 ]
wait_until "the motor runs at half speed" pin_near $B.encoder.00.velocity 5000 100
halcmd setp $B.pwmgen.00.value -0.25
wait_until "negative values set the direction bit" pwm_has "duty -0.2498"
wait_until "the motor reverses" pin_near $B.encoder.00.velocity -2500 100
halcmd setp $B.pwmgen.00.scale 10
halcmd setp $B.pwmgen.00.value 5
wait_until "value is divided by scale" pwm_has "duty 0.4998"
halcmd setp $B.pwmgen.00.value 50
wait_until "the duty is clipped to 1" pwm_has "value 0x0fff0000"
halcmd setp $B.pwmgen.00.enable 0
wait_until "disabled: duty 0 and enable bit clear" pwm_has "duty 0.0000 bits 12 freq 19999.6 enable 0"
check "the /enable pin goes high" [ "$(sim_field get io 16 16)" = 1 ]
wait_until "the motor stops" pin_is $B.encoder.00.velocity 0
halcmd setp $B.pwmgen.pwm_frequency 100000
wait_until "100 kHz needs 10 bits" pwm_has "bits 10 freq 99998"
halcmd setp $B.pwmgen.pwm_frequency 10000000
wait_until "too high a frequency is limited" pin_is $B.pwmgen.pwm_frequency 390619
check "and reported" rt_log_has "hm2/hm2_7i92.0: max PWM frequency is 390619 Hz"
halcmd setp $B.pwmgen.00.output-type 3
halcmd setp $B.pwmgen.pdm_frequency 1000000
halcmd setp $B.pwmgen.00.enable 1
halcmd setp $B.pwmgen.00.value 2.5
wait_until "PDM mode: 12 bits at the PDM rate" pwm_has "duty 0.2498 bits 12 freq 997924.8"
halcmd setp $B.pwmgen.00.output-type 7
wait_until "an invalid output-type falls back to 1" pin_is $B.pwmgen.00.output-type 1
check "with LinuxCNC's message" rt_log_has "hm2/hm2_7i92.0: invalid pwmgen output_type 7 requested"
