#!/bin/bash
# Every pin halui exports for the test machine (3 joints, XYZ, 2 spindles, a homing
# sequence, 3 MDI commands, one GUI command): name, type and direction, and the defaults
# of the count-enable pins (TRUE) and units-per-mm (inch).
. "$EMC2_HOME/tests/halui/lib.sh"
start_halui || exit 1
halcmd -s show pin halui | awk '{print $2, $3, $5}' | sort -k3
echo "count $(halcmd -s show pin halui | wc -l)"
halcmd getp halui.feed-override.count-enable
halcmd getp halui.max-velocity.count-enable
halcmd getp halui.machine.units-per-mm
stop_halui
