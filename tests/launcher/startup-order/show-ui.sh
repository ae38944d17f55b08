#!/bin/bash
# the display: reports what the launcher set up, then exits with status 3
echo "display args: $*"
echo "components in load order:"
halcmd -s show comp | awk 'NF >= 3 && $3 !~ /^halcmd/ {print $1, $3}' | sort -n | awk '{print "  " $2}'
echo "gain.gain=$(halcmd getp gain.gain) gain.offset=$(halcmd getp gain.offset) total.gain0=$(halcmd getp total.gain0)"
echo "ini.traj_max_velocity=$(halcmd getp ini.traj_max_velocity)"
sleep 0.1
echo "signal started (gain.out, 4.5 once servo-thread runs)=$(halcmd gets started)"
for i in $(seq 50); do [ -f app-ran.txt ] && break; sleep 0.05; done
cat app-ran.txt
sed -e "s|$PWD|<dir>|g" -e "s|$EMC2_HOME|<top>|g" -e "s|=$OPENEMC_INSTANCE\$|=<instance>|" task-record.txt
exit 3
