#!/bin/bash
# encoder-index: index-enable arms the card's latch; at the index pulse the count restarts from zero
# and index-enable drops; no_clear_on_index only latches; quadrature errors are reported once.
. ../lib.sh
sim_start --board 7i92 --loop stepgen0:encoder0 --index encoder0:100
load_board
B=$BOARD
above() { [ "$(halcmd getp "$1")" -gt "$2" ]; }
multiple_of_100() { local v; v=$(halcmd getp $B.encoder.00.rawlatch); [ "$v" -ne 0 ] && [ $((v % 100)) -eq 0 ]; }
# count = rawcounts - rawlatch in one snapshot (the index zeroed the count at rawlatch).
zeroed_at_latch() {
    halcmd show pin $B.encoder.00 | awk '
        $NF ~ /\.count$/ { c = $(NF - 1) } $NF ~ /\.rawcounts$/ { r = $(NF - 1) } $NF ~ /\.rawlatch$/ { l = $(NF - 1) }
        END { exit !(c == r - l) }'
}
halcmd setp $B.stepgen.00.control-type 1
halcmd setp $B.stepgen.00.maxaccel 0
halcmd setp $B.stepgen.00.velocity-cmd 300
halcmd setp $B.stepgen.00.enable 1
halcmd start
wait_until "encoder 0 counts" above $B.encoder.00.count 30
halcmd setp $B.encoder.00.index-enable 1
wait_until "the index clears index-enable" pin_is $B.encoder.00.index-enable FALSE
check "rawlatch is where the index is (a multiple of 100)" multiple_of_100
# the motor stops while count, rawcounts and rawlatch are compared (halcmd reads pins one by one
# while the servo thread runs: a moving count can change between them)
halcmd setp $B.stepgen.00.velocity-cmd 0
stopped() { local a; a=$(halcmd getp $B.encoder.00.rawcounts); sleep 0.05; [ "$a" = "$(halcmd getp $B.encoder.00.rawcounts)" ]; }
wait_until "the motor stops" stopped
check "count restarted at the index" zeroed_at_latch
check "count-latched is 0 (the new zero)" pin_is $B.encoder.00.count-latched 0
halcmd setp $B.stepgen.00.velocity-cmd 300
first=$(halcmd getp $B.encoder.00.rawlatch)
halcmd setp $B.encoder.00.no_clear_on_index 1
halcmd setp $B.encoder.00.index-enable 1
wait_until "a second index latches again" pin_is $B.encoder.00.index-enable FALSE
check "at a later index" above $B.encoder.00.rawlatch "$first"
check "without clearing the count (no_clear_on_index)" pin_is $B.encoder.00.count-latched $(( $(halcmd getp $B.encoder.00.rawlatch) - first ))

halcmd setp $B.encoder.00.quad-error-enable 1
sim quad-error 0 > /dev/null
wait_until "a quadrature error sets quad-error" pin_is $B.encoder.00.quad-error TRUE
sleep 0.1
check "reported once, naming the board" [ "$(grep -c '^hm2/hm2_7i92.0: Encoder 0: quadrature count error$' "$RT_LOG")" = 1 ]
halcmd setp $B.encoder.00.quad-error-enable 0
wait_until "disabled: quad-error FALSE" pin_is $B.encoder.00.quad-error FALSE
halcmd setp $B.encoder.00.quad-error-enable 1
wait_until "re-enabling clears the card's error bit" pin_is $B.encoder.00.quad-error FALSE
