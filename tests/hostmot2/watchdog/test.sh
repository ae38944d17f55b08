#!/bin/bash
# watchdog: when the cycle stops the card's watchdog bites and every output goes safe (undriven);
# hostmot2 reports the bite once, keeps the card safe until has_bit is cleared, then recovers.
. ../lib.sh
sim_start --board 7i92 --loop stepgen0:encoder0
load_board
B=$BOARD
io_is() { [ "$(sim_field get io "$1" "$1")" = "$2" ]; }
emitted() { sim_field get stepgen 0 emitted; }
emitting() { local a; a=$(emitted); sleep 0.1; [ "$(emitted)" != "$a" ]; }
not_emitting() { ! emitting; }

halcmd setp $B.watchdog.timeout_ns 200000000
halcmd setp $B.gpio.017.is_output 1
halcmd setp $B.gpio.017.out 1
sim set in 17 0 > /dev/null
halcmd setp $B.stepgen.00.control-type 1
halcmd setp $B.stepgen.00.maxaccel 0
halcmd setp $B.stepgen.00.velocity-cmd 500
halcmd setp $B.stepgen.00.enable 1
halcmd start
wait_until "gpio 17 driven high" io_is 17 1
wait_until "stepgen 0 emits steps" emitting
check "watchdog armed with 200 ms at 100 MHz" [ "$(sim get watchdog)" = "watchdog bitten 0 timer 0x01312cff" ]

halcmd stop
wait_until "the card's watchdog bites when the cycle stops" sim_said bite
check "gpio 17 is released (outside level low)" io_is 17 0
check "the step pin is released" not_emitting
halcmd start
wait_until "hostmot2 sees the bite: has_bit" pin_is $B.watchdog.has_bit TRUE
sleep 0.2
check "the bite is reported once, naming the board" \
    [ "$(grep -c '^hm2/hm2_7i92.0: Watchdog has bit! (set the .has-bit pin to False to resume)$' "$RT_LOG")" = 1 ]
check "outputs stay safe while has_bit is TRUE" io_is 17 0
check "no steps while has_bit is TRUE" not_emitting

halcmd setp $B.watchdog.has_bit 0
wait_until "clearing has_bit recovers: the card clears the bite" sim_said "watchdog cleared"
wait_until "gpio 17 driven high again" io_is 17 1
wait_until "stepgen 0 emits steps again" emitting
check "recovery is logged" rt_log_has "hm2/hm2_7i92.0: trying to recover from IO error or Watchdog bite"
check "and succeeds" rt_log_has "hm2/hm2_7i92.0: error recover successful!"

sim bite > /dev/null
wait_until "a bite while running is seen too" pin_is $B.watchdog.has_bit TRUE
check "reported a second time (one per bite)" \
    [ "$(grep -c 'Watchdog has bit!' "$RT_LOG")" = 2 ]
halcmd setp $B.watchdog.has_bit 0
wait_until "and recovered" io_is 17 1

halcmd setp $B.watchdog.timeout_ns 1000000
wait_until "a timeout under 1.5 write periods is reported" \
    rt_log_has "hm2/hm2_7i92.0: Watchdog timeout (1000000 ns) is dangerously short compared to hm2_write() period (1000000 ns)"
