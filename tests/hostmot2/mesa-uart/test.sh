#!/bin/bash
# mesa-uart: the serial API end to end over hm2_eth: mesa_uart (names= the UART instance) sends bytes
# through the simulated 7I96's UART, whose TX is looped back to its RX, and receives them again.
. ../lib.sh
BOARD=hm2_7i96.0
sim_start --board 7i96
load_board
B=$BOARD
grep -E "created UART|UART Transmit|UART Receive" "$RT_LOG"
halcmd loadrt mesa_uart count=1 > /dev/null 2>&1 && echo "LOADED with count=1"
check "count= is refused" rt_log_has "mesa_uart can not be loaded using the 'count' parameter, see man mesa_uart for details"
halcmd loadrt mesa_uart names=$B.uart.0 || exit 1
halcmd addf $B.uart.0.receive servo 3
halcmd addf $B.uart.0.send servo 4
check "setup: 250000 bit/s (bitrate register = 250000 * 2^20 / 100 MHz)" \
    [ "$(sim get reg 0x6200)" = "reg 0x6200 0x00000a3d" ]
check "setup: TX mode 0x40 (driver enable)" [ "$(sim get reg 0x6300)" = "reg 0x6300 0x00000040" ]
for i in 0 1 2 3 4; do halcmd setp $B.uart.0.tx-data-0$i $(( $(printf '%d' "'$(echo 'HELLO' | cut -c$((i + 1)))") )); done
halcmd setp $B.uart.0.tx-bytes 5
halcmd start
wait_until "every cycle receives the 5 bytes sent the cycle before" pin_is $B.uart.0.rx-bytes 5
received() {
    local s="" i
    for i in 0 1 2 3 4; do s="$s$(printf "\\$(printf '%03o' "$(halcmd getp $B.uart.0.rx-data-0$i)")")"; done
    [ "$s" = "HELLO" ]
}
wait_until "the bytes are HELLO" received
halcmd setp $B.uart.0.tx-bytes 0
wait_until "nothing sent, nothing received" pin_is $B.uart.0.rx-bytes 0
check "reading from the cycle costs a round trip and says so once" \
    [ "$(grep -c 'hm2_eth: ERROR: used llio->read in realtime task' "$RT_LOG")" = 1 ]
halcmd unloadrt mesa_uart
halcmd loadrt mesa_uart names=hm2_7i96.0.uart.5
check "an unknown UART is reported by hostmot2" rt_log_has "hm2: Can not find UART instance hm2_7i96.0.uart.5."
