#!/bin/bash
# sserial-faults: a remote reporting a fault raises its fault pin; unfinished do-its are counted
# and forgiven; a remote that stops answering counts faults, stops its port once past fault-lim
# with one report naming board, port and channel, its outputs and the board's go safe; run
# FALSE -> TRUE restarts it once the cable is back, and the watchdog reset re-enables the board.
. ../lib.sh
BOARD=hm2_7i76e.0
sim_start --board 7i76e
load_board "sserial_port_0=0"
R=$BOARD.7i76.0.0
P=$BOARD.sserial.port-0
halcmd setp $BOARD.gpio.047.is_output 1
halcmd setp $BOARD.gpio.047.out 0
halcmd setp $R.output-01 1
halcmd start
wait_until "output-01 reaches the 7I76" sim_is output 0x2 get sserial 0
wait_until "board GPIO 47 drives low" sim_is 47 0 get io 47
sim sserial-status 0 2 > /dev/null
wait_until "a remote reporting lost field power sets its fault pin" pin_is $R.fault TRUE
check "comm-state carries its status byte (2)" pin_is $R.comm-state 2
check "the port keeps running (state 3)" pin_is $P.port_state 3
sim sserial-status 0 0 > /dev/null
wait_until "the fault pin clears with the status" pin_is $R.fault FALSE
halcmd setp $P.fault-dec 0        # hold the count while we look (halcmd may be slow)
sim sserial-busy 5 > /dev/null
wait_until "unfinished do-its are counted" [ "$(halcmd getp $P.fault-count)" -ge 40 ]
halcmd setp $P.fault-dec 1
wait_until "the count decays on good cycles" pin_is $P.fault-count 0
check "the port keeps running (state 3)" pin_is $P.port_state 3
grep -o "Smart Serial port 0: DoIt not cleared.*" "$RT_LOG"
sim sserial-unplug 0 > /dev/null
wait_until "the port stops on errors (state 10)" pin_is $P.port_state 10
check "the remote's fault pin is TRUE" pin_is $R.fault TRUE
check "comm-state shows the link timeout (256)" pin_is $R.comm-state 256
check "fault-count is past fault-lim" [ "$(halcmd getp $P.fault-count)" -gt 200 ]
wait_until "the remote's outputs go off (its watchdog)" sim_is outputs-enabled 0 get sserial 0
wait_until "the board's watchdog has bitten" pin_is $BOARD.watchdog.has_bit TRUE
wait_until "board GPIO 47 is released (safe, pulled up)" sim_is 47 1 get io 47
sleep 0.2
echo "reports: $(grep -c 'will be stopped' "$RT_LOG") stop, $(grep -c 'is not answering' "$RT_LOG") channel"
grep -o "Smart Serial \(port 0 channel 0 (hm2_7i76e.0.7i76.0.0) is not answering\|Error: port\|Comms Error\).*" "$RT_LOG"
grep -o "Smart serial card.*" "$RT_LOG"
halcmd setp $P.run 0
wait_until "run FALSE is seen" pin_is $P.port_state 10
sleep 0.1
halcmd setp $P.run 1
wait_until "a restart with the cable still out fails" rt_log_has "restart failed"
check "the port stays stopped" pin_is $P.port_state 10
sim sserial-plug 0 > /dev/null
halcmd setp $P.run 0
wait_until "run FALSE is seen" pin_is $P.port_state 10
sleep 0.1
halcmd setp $P.run 1
wait_until "run FALSE -> TRUE restarts the port" pin_is $P.port_state 3
check "fault-count is reset" pin_is $P.fault-count 0
wait_until "the remote's fault pin clears" pin_is $R.fault FALSE
halcmd setp $BOARD.watchdog.has_bit 0
wait_until "the board recovers after the watchdog reset" pin_is $BOARD.watchdog.has_bit FALSE
wait_until "output-01 reaches the 7I76 again" sim_is output 0x2 get sserial 0
wait_until "the remote drives its outputs again" sim_is outputs-enabled 1 get sserial 0
wait_until "board GPIO 47 drives low again" sim_is 47 0 get io 47
