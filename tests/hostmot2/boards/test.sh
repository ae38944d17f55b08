#!/bin/bash
# boards: each simulated board (7I92, 7I76E, 7I96) is discovered by name over LBP16 and gets
# LinuxCNC's HAL board name, connector names and pin numbering; functs and module counts.
. ../lib.sh
rt_start
halcmd loadrt hostmot2 || exit 1
for board in 7i92 7i76e 7i96; do
    sim_start --board $board
    before=$(wc -l < "$RT_LOG")
    halcmd loadrt hm2_eth board_ip=$SIM_IP || { cat "$RT_LOG"; exit 1; }
    tail -n +"$((before + 1))" "$RT_LOG" | grep -E 'discovered|Pins used|IO Pin (000|016|017|034|050)|registered'
    for m in stepgen encoder pwmgen; do
        echo "$board $m: $(halcmd list pin "hm2_$board.0.$m.*.enable" "hm2_$board.0.$m.*.count" | wc -w)"
    done
    echo "$board functs: $(halcmd list funct "hm2_$board.0.*")"
    halcmd unloadrt hm2_eth
    sim_stop
done
