#!/bin/bash
# names-7i92: every pin, param, alias and funct of a 7I92 over hm2_eth with LinuxCNC's names,
# types, directions and start values (before the first cycle); the pin usage log.
. ../lib.sh
sim_start --board 7i92
HM2_DEFAULTS=1 load_board
show_items pin 'hm2*'
show_items param 'hm2*'
show_items funct '*'
halcmd show alias | grep hm2 | awk '{ print $1, $2 }'
grep -E 'IO Pin 0(0[0-9]|1[0-7])|I/O Pins used|registered|discovered|Low Level' "$RT_LOG"
