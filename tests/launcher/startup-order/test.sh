#!/bin/bash
# Start-up order and environment: linuxcncsvr, realtime, TPMOD, HOMEMOD, task, halui, HAL
# files (.hal and .tcl with arguments), HALCMD, threads, applications, then the display with
# its arguments; the display's exit status is the launcher's; nothing is left afterwards.
export PATH=$PATH:$(cd ../doubles && pwd)
rm -f app-ran.txt task-record.txt
linuxcnc -r test.ini extra1 extra2 > run.out 2> run.err
echo "exit status $?"
grep -v '^Note: ' run.out | sed -e "s|$PWD|<dir>|g" -e "s|$EMC2_HOME|<top>|g"
python3 ../common/leftovers.py
