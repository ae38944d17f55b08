#!/bin/bash
# stepgen-encoder: stepgens drive the simulated card's DDS over hm2_eth; the card feeds their steps
# back into encoders (1 and 4 counts per step). Position mode reaches and holds its targets, velocity
# mode runs at the commanded rate (LinuxCNC's rate register value), encoders count what the pins emitted.
. ../lib.sh

# velocity and velocity-rpm of encoder 1 from one snapshot (halcmd reads the two pins one after
# the other while the servo thread runs, so a snapshot that straddles an update is taken again).
rpm_is_60_velocity() {
    halcmd show pin $BOARD.encoder.01.velocity | awk '
        $NF ~ /velocity$/ { v = $(NF - 1) } $NF ~ /velocity-rpm$/ { r = $(NF - 1) }
        END { d = r - 60 * v; if (d < 0) d = -d; exit !(v != 0 && d < 1e-6 * (r < 0 ? -r : r) + 1e-9) }'
}
sim_start --board 7i92 --loop stepgen0:encoder0 --loop stepgen1:encoder1:4
load_board
B=$BOARD
halcmd setp $B.stepgen.00.position-scale 200
halcmd setp $B.stepgen.00.maxvel 20
halcmd setp $B.stepgen.00.maxaccel 400
halcmd setp $B.stepgen.00.steplen 2000
halcmd setp $B.stepgen.00.stepspace 2000
halcmd setp $B.encoder.00.scale 200
halcmd setp $B.stepgen.00.enable 1
halcmd start

halcmd setp $B.stepgen.00.position-cmd 5
wait_until "stepgen 0 reaches 5" pin_near $B.stepgen.00.position-fb 5 0.006
wait_until "encoder 0 follows to 5" pin_near $B.encoder.00.position 5 0.006
sleep 0.2
check "stepgen 0 holds 5" pin_near $B.stepgen.00.position-fb 5 0.006
check "stepgen 0 counts 1000" pin_near $B.stepgen.00.counts 1000 1
check "card emitted 1000 steps" near "$(sim_field get stepgen 0 emitted)" 1000 1
check "encoder 0 counts what was emitted" near "$(halcmd getp $B.encoder.00.count)" \
    "$(sim_field get stepgen 0 emitted)" 1
wait_until "encoder 0 sees the stop (vel-timeout)" pin_is $B.encoder.00.velocity 0

halcmd setp $B.stepgen.00.position-cmd -2.5
wait_until "stepgen 0 reaches -2.5" pin_near $B.stepgen.00.position-fb -2.5 0.006
wait_until "encoder 0 follows to -2.5" pin_near $B.encoder.00.position -2.5 0.006

halcmd setp $B.stepgen.01.position-scale 100
halcmd setp $B.stepgen.01.maxaccel 0
halcmd setp $B.stepgen.01.control-type 1
halcmd setp $B.stepgen.01.velocity-cmd 10
halcmd setp $B.stepgen.01.enable 1
wait_until "rate register for 10 units/s at scale 100 is 42949" pin_is $B.stepgen.01.dbg_step_rate 42949
check "card runs stepgen 1 at that rate" [ "$(sim_field get stepgen 1 rate)" = 42949 ]
halcmd setp $B.stepgen.01.velocity-cmd 2.5
halcmd setp $B.encoder.01.scale 400
wait_until "encoder 1 measures 2.5 units/s" pin_near $B.encoder.01.velocity 2.5 0.1
check "velocity-fb is the command" pin_near $B.stepgen.01.velocity-fb 2.5 1e-9
wait_until "velocity-rpm is 60 x velocity" rpm_is_60_velocity
check "encoder 1 and stepgen 1 agree" pins_near "$B.*.01.position*" $B.encoder.01.position \
    $B.stepgen.01.position-fb 0.02
halcmd setp $B.stepgen.01.velocity-cmd -2.5
wait_until "encoder 1 measures -2.5 units/s" pin_near $B.encoder.01.velocity -2.5 0.1
halcmd setp $B.stepgen.01.enable 0
wait_until "disabled stepgen stops the card" sim_is rate 0 get stepgen 1
check "disabled stepgen reports velocity 0" pin_is $B.stepgen.01.velocity-fb 0
wait_until "encoder 1 sees the stop" pin_is $B.encoder.01.velocity 0

halcmd setp $B.encoder.00.reset 1
wait_until "encoder reset zeroes count" pin_is $B.encoder.00.count 0
halcmd setp $B.encoder.00.reset 0
halcmd setp $B.stepgen.00.position-reset 1
wait_until "position-reset zeroes position-fb" pin_is $B.stepgen.00.position-fb 0
halcmd setp $B.stepgen.00.position-reset 0

halcmd setp $B.stepgen.00.maxvel 1e9
wait_until "impossible maxvel is clipped to 1e9/(steplen+stepspace)/scale" pin_near $B.stepgen.00.maxvel 1250 0.01
check "clipping reported once" [ "$(grep -c 'maxvel is too big' "$RT_LOG")" = 1 ]
halcmd setp $B.stepgen.00.steplen 1000000000
wait_until "impossible steplen is reset to the maximum" pin_is $B.stepgen.00.steplen 163830
check "steplen message names the stepgen" rt_log_has "hm2/hm2_7i92.0: stepgen 0 has invalid steplen, resetting to max"

halcmd setp $B.stepgen.02.table-data-0 0x0a060509
halcmd setp $B.stepgen.02.step_type 4
wait_until "step_type 4 selects table mode" sim_answer_is "reg 0x2208 0x00000003" get reg 0x2208
check "with table length 4 - 1" sim_answer_is "reg 0x2808 0x00000003" get reg 0x2808
halcmd setp $B.stepgen.02.step_type 20
wait_until "a table deeper than 16 reverts to step type 0" pin_is $B.stepgen.02.step_type 0
check "in the card too" sim_answer_is "reg 0x2208 0x00000000" get reg 0x2208
check "with the message" rt_log_has "the firmware only supports tables up to a depth of 16, you requested 20. Reverting to step type 0"
